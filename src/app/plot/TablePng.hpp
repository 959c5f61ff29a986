#pragma once

#include <string>
#include <vector>

namespace abalike::app
{

/// A table of text cells as a spreadsheet shows it: column letters, row numbers, a bold header row, a grid. The
/// first row of `cells` is the header; every row has the header's number of cells.
struct Table
{
    std::string title; ///< above the grid ("" for none)
    std::vector<std::vector<std::string>> cells;
    std::vector<std::size_t> rowNumbers; ///< the spreadsheet's number of each row of cells (empty: 1, 2, 3, ...)
};

/// Draws the table into a PNG file sized to fit it, headless (cairo, text through fontconfig). Throws PlotError when
/// the table is empty or ragged, the file cannot be written or no font is installed.
void saveTablePng(const Table& table, const std::string& path);

} // namespace abalike::app
