#include <abalike/world/SettleCache.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>

namespace abalike
{

namespace
{

constexpr char kMagic[] = "abalike settled state 1\n";
constexpr std::uint32_t kMaxCount = 10'000'000; ///< a count beyond this is a damaged file, not a level

static_assert(std::is_trivially_copyable_v<SettledState::Body>);
static_assert(std::is_trivially_copyable_v<SettledState::Contact>);

template <typename T>
void writeRaw(std::ostream& out, const T& value)
{
    out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T>
bool readRaw(std::istream& in, T& value)
{
    return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof(T)));
}

template <typename T>
void writeVector(std::ostream& out, const std::vector<T>& items)
{
    writeRaw(out, static_cast<std::uint32_t>(items.size()));
    out.write(reinterpret_cast<const char*>(items.data()), static_cast<std::streamsize>(items.size() * sizeof(T)));
}

template <typename T>
bool readVector(std::istream& in, std::vector<T>& items)
{
    std::uint32_t count = 0;
    if (!readRaw(in, count) || count > kMaxCount)
        return false;
    items.resize(count);
    return static_cast<bool>(
        in.read(reinterpret_cast<char*>(items.data()), static_cast<std::streamsize>(count * sizeof(T))));
}

/// A checksum of a state's numbers, so that a damaged file is never restored.
std::uint64_t checksumOf(const SettledState& state)
{
    SettleKey sum;
    for (const SettledState::Body& b : state.bodies)
        sum.add(b);
    for (const SettledState::Contact& c : state.contacts)
        sum.add(c);
    return sum.value();
}

} // namespace

SettleKey& SettleKey::addText(const std::string& text)
{
    add(text.size());
    for (const char c : text)
        add(c);
    return *this;
}

SettleCache& SettleCache::shared()
{
    static SettleCache cache;
    return cache;
}

void SettleCache::setDirectory(const std::string& dir, const std::string& buildId)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_dir = dir;
    m_buildId = buildId;
}

std::shared_ptr<const SettledState> SettleCache::find(std::uint64_t key)
{
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        const auto it = m_states.find(key);
        if (it != m_states.end())
            return it->second;
    }
    std::shared_ptr<const SettledState> state = readFile(key);
    if (state)
        remember(key, state);
    return state;
}

void SettleCache::store(std::uint64_t key, std::shared_ptr<const SettledState> state)
{
    writeFile(key, *state);
    remember(key, std::move(state));
}

void SettleCache::remember(std::uint64_t key, std::shared_ptr<const SettledState> state)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_states.emplace(key, std::move(state)).second)
        return;
    m_order.push_back(key);
    while (m_order.size() > kMaxStates)
    {
        m_states.erase(m_order.front());
        m_order.pop_front();
    }
}

void SettleCache::clear()
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_states.clear();
    m_order.clear();
}

std::size_t SettleCache::size() const
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    return m_states.size();
}

std::string SettleCache::pathOf(std::uint64_t key) const
{
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.settled", static_cast<unsigned long long>(key));
    return (std::filesystem::path(m_dir) / name).string();
}

std::shared_ptr<const SettledState> SettleCache::readFile(std::uint64_t key) const
{
    std::string path;
    std::string buildId;
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        if (m_dir.empty())
            return nullptr;
        path = pathOf(key);
        buildId = m_buildId;
    }
    // A missing, foreign or damaged file is a miss: the settle step is solved again and the file rewritten.
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return nullptr;
    std::string magic(sizeof kMagic - 1, '\0');
    std::string fileBuild;
    std::uint64_t fileKey = 0;
    if (!in.read(magic.data(), static_cast<std::streamsize>(magic.size())) || magic != kMagic ||
        !std::getline(in, fileBuild) || fileBuild != buildId || !readRaw(in, fileKey) || fileKey != key)
        return nullptr;
    auto state = std::make_shared<SettledState>();
    std::uint64_t checksum = 0;
    if (!readVector(in, state->bodies) || !readVector(in, state->contacts) || !readRaw(in, checksum) ||
        in.peek() != std::char_traits<char>::eof() || checksum != checksumOf(*state))
        return nullptr;
    return state;
}

void SettleCache::writeFile(std::uint64_t key, const SettledState& state) const
{
    std::string path;
    std::string buildId;
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        if (m_dir.empty())
            return;
        path = pathOf(key);
        buildId = m_buildId;
    }
    // Written beside and renamed over, so a reader never sees half a file. A cache that cannot be written only
    // costs the next start its settle step again, so failures are not reported.
    std::error_code error;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), error);
    std::ostringstream name;
    name << path << ".tmp" << std::hex << reinterpret_cast<std::uintptr_t>(&state);
    const std::string temporary = name.str();
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(kMagic, sizeof kMagic - 1);
        out << buildId << '\n';
        writeRaw(out, key);
        writeVector(out, state.bodies);
        writeVector(out, state.contacts);
        writeRaw(out, checksumOf(state));
        if (!out.flush())
        {
            out.close();
            std::filesystem::remove(temporary, error);
            return;
        }
    }
    std::filesystem::rename(temporary, path, error);
    if (error)
        std::filesystem::remove(temporary, error);
}

} // namespace abalike
