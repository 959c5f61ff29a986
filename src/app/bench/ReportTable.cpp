#include "bench/ReportTable.hpp"

#include "render/TextFormat.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <thread>

namespace abalike::app
{

ReportTable::ReportTable(std::vector<std::string> header) : m_header(std::move(header)) {}

void ReportTable::addRow(std::vector<std::string> cells)
{
    cells.resize(m_header.size());
    m_rows.push_back(std::move(cells));
}

std::string ReportTable::text() const
{
    std::vector<std::size_t> widths(m_header.size());
    auto measure = [&](const std::vector<std::string>& row)
    {
        for (std::size_t i = 0; i < row.size(); ++i)
            widths[i] = std::max(widths[i], row[i].size());
    };
    measure(m_header);
    for (const auto& row : m_rows)
        measure(row);
    std::ostringstream out;
    auto print = [&](const std::vector<std::string>& row)
    {
        for (std::size_t i = 0; i < row.size(); ++i)
            out << (i == 0 ? "" : "  ") << row[i] << std::string(widths[i] - row[i].size(), ' ');
        out << '\n';
    };
    print(m_header);
    for (std::size_t i = 0; i < widths.size(); ++i)
        out << (i == 0 ? "" : "  ") << std::string(widths[i], '-');
    out << '\n';
    for (const auto& row : m_rows)
        print(row);
    return out.str();
}

std::string ReportTable::markdown() const
{
    std::ostringstream out;
    auto print = [&](const std::vector<std::string>& row)
    {
        out << '|';
        for (const std::string& cell : row)
        {
            out << ' ';
            for (const char c : cell)
                out << (c == '|' ? "\\|" : std::string(1, c)); // a bar inside a cell would end it
            out << " |";
        }
        out << '\n';
    };
    print(m_header);
    out << '|';
    for (std::size_t i = 0; i < m_header.size(); ++i)
        out << "---|";
    out << '\n';
    for (const auto& row : m_rows)
        print(row);
    return out.str();
}

std::string ReportTable::csv() const
{
    std::ostringstream out;
    auto print = [&](const std::vector<std::string>& row)
    {
        for (std::size_t i = 0; i < row.size(); ++i)
        {
            const std::string& cell = row[i];
            const bool quote = cell.find_first_of(",\"\n") != std::string::npos;
            out << (i == 0 ? "" : ",");
            if (!quote)
                out << cell;
            else
            {
                out << '"';
                for (const char c : cell)
                    out << (c == '"' ? "\"\"" : std::string(1, c));
                out << '"';
            }
        }
        out << '\n';
    };
    print(m_header);
    for (const auto& row : m_rows)
        print(row);
    return out.str();
}

std::string percentOf(int part, int whole)
{
    return whole > 0 ? formatFixed(100.0 * part / whole, 0) + " %" : "-";
}

std::string formatSignificant(double value, int digits)
{
    if (!std::isfinite(value))
        return std::isnan(value) ? "NaN" : (value > 0 ? "inf" : "-inf");
    std::ostringstream out;
    const double magnitude = std::abs(value);
    if (value != 0.0 && (magnitude < 1e-3 || magnitude >= 1e6))
        out << std::scientific << std::setprecision(digits - 1) << value;
    else
        out << std::setprecision(digits) << value;
    return out.str();
}

std::string loadAverageNote()
{
    std::ifstream in("/proc/loadavg");
    double load = 0.0;
    if (!(in >> load))
        return "";
    std::ostringstream out;
    out << "load average " << load << " over " << std::thread::hardware_concurrency() << " hardware threads";
    return out.str();
}

long residentKb()
{
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmRSS:", 0) == 0)
            return std::stol(line.substr(6));
    return -1;
}

bool writeReportFile(const std::string& dir, const std::string& name, const std::string& content)
{
    const std::filesystem::path path = std::filesystem::path(dir) / name;
    std::ofstream out(path);
    out << content;
    if (!out)
    {
        std::cerr << "abalike: cannot write " << path.string() << "\n";
        return false;
    }
    return true;
}

} // namespace abalike::app
