#include "shell/Trace.hpp"

namespace abalike::app
{

bool Trace::open(const std::string& path)
{
    m_out.open(path, std::ios::out | std::ios::trunc);
    return m_out.is_open();
}

void Trace::write(const std::string& event, const nlohmann::json& fields)
{
    if (!m_out.is_open())
        return;
    nlohmann::ordered_json line;
    line["frame"] = m_frame;
    line["event"] = event;
    for (const auto& [key, value] : fields.items())
        line[key] = value;
    // Flushed per line so a test can read what happened even if the game is killed.
    m_out << line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n' << std::flush;
}

} // namespace abalike::app
