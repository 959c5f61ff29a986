#pragma once

#include <string>
#include <vector>

namespace abalike::app
{

/// A table of results written three ways: aligned text for the terminal, Markdown for the docs, CSV for tools.
class ReportTable
{
public:
    explicit ReportTable(std::vector<std::string> header);

    void addRow(std::vector<std::string> cells);
    std::size_t rows() const { return m_rows.size(); }

    std::string text() const;
    std::string markdown() const;
    std::string csv() const;

private:
    std::vector<std::string> m_header;
    std::vector<std::vector<std::string>> m_rows;
};

/// "42 %": part of whole in whole percent, "-" when whole is 0 (the hit and tower tables' shares).
std::string percentOf(int part, int whole);

/// A number with the given significant digits, in exponent form only when it is very large or small.
std::string formatSignificant(double value, int digits = 3);

/// "load average 1.23 (2 hardware threads)" from /proc/loadavg, or "" where that does not exist: timings taken
/// while other work runs are slower, and a report should say so.
std::string loadAverageNote();

/// Resident memory of this process in kB (VmRSS in /proc/self/status); -1 where there is no such file.
long residentKb();

/// Writes text to dir/name; false (and a line on stderr) if it cannot.
bool writeReportFile(const std::string& dir, const std::string& name, const std::string& content);

} // namespace abalike::app
