#include "plot/TablePng.hpp"

#include "plot/CairoPng.hpp"
#include "plot/PlotError.hpp"
#include "plot/PlotFont.hpp"

#include <algorithm>
#include <cairo.h>
#include <cctype>
#include <memory>

namespace abalike::app
{

namespace
{
constexpr double kFontPx = 13.0;
constexpr double kPadPx = 6.0;
constexpr double kRowPx = 22.0;
constexpr double kMarginPx = 12.0;

/// "A".."Z", "AA".. as a spreadsheet names its columns.
std::string columnName(std::size_t index)
{
    std::string name;
    for (std::size_t n = index + 1; n > 0; n = (n - 1) / 26)
        name.insert(name.begin(), static_cast<char>('A' + (n - 1) % 26));
    return name;
}

/// The table's font, bold for the header row.
void useFont(cairo_t* cr, const PlotFont& font, bool bold)
{
    if (bold)
        cairo_select_font_face(cr, font.family().c_str(), CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    else
        cairo_set_font_face(cr, font.face());
    cairo_set_font_size(cr, kFontPx);
}

double textWidth(cairo_t* cr, const std::string& text)
{
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    return extents.x_advance;
}

void fillRect(cairo_t* cr, double x, double y, double w, double h, double grey)
{
    cairo_set_source_rgb(cr, grey, grey, grey);
    cairo_rectangle(cr, x, y, w, h);
    cairo_fill(cr);
}
} // namespace

void saveTablePng(const Table& table, const std::string& path)
{
    if (table.cells.empty() || table.cells.front().empty())
        throw PlotError("a table needs a header row with at least one column");
    const std::size_t columns = table.cells.front().size();
    for (std::size_t r = 0; r < table.cells.size(); ++r)
        if (table.cells[r].size() != columns)
            throw PlotError("row " + std::to_string(r + 1) + " of the table has " +
                            std::to_string(table.cells[r].size()) + " cells, the header " + std::to_string(columns));
    const PlotFont font = PlotFont::match("DejaVu Sans");

    // Measure on a scratch surface: each column as wide as its widest cell, numbers right-aligned.
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> scratch(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1), cairo_surface_destroy);
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> measure(cairo_create(scratch.get()), cairo_destroy);
    std::vector<double> widths(columns, 0.0);
    for (std::size_t r = 0; r < table.cells.size(); ++r)
    {
        useFont(measure.get(), font, r == 0);
        for (std::size_t c = 0; c < columns; ++c)
            widths[c] = std::max(widths[c], textWidth(measure.get(), table.cells[r][c]) + 2.0 * kPadPx);
    }
    useFont(measure.get(), font, false);
    const std::size_t lastNumber = table.rowNumbers.empty() ? table.cells.size() : table.rowNumbers.back();
    const double numberWidth = textWidth(measure.get(), std::to_string(lastNumber)) + 2.0 * kPadPx;
    double gridWidth = numberWidth;
    for (double w : widths)
        gridWidth += w;
    const double titleHeight = table.title.empty() ? 0.0 : kRowPx + 4.0;
    const double gridHeight = kRowPx * static_cast<double>(table.cells.size() + 1);
    const int width = static_cast<int>(gridWidth + 2.0 * kMarginPx);
    const int height = static_cast<int>(titleHeight + gridHeight + 2.0 * kMarginPx);

    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height), cairo_surface_destroy);
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
        throw PlotError("cannot make a " + std::to_string(width) + "x" + std::to_string(height) + " picture");
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> context(cairo_create(surface.get()), cairo_destroy);
    cairo_t* cr = context.get();
    fillRect(cr, 0, 0, width, height, 1.0);

    const auto text = [&](const std::string& s, double left, double right, double top, bool alignRight, bool bold)
    {
        useFont(cr, font, bold);
        const double x = alignRight ? right - kPadPx - textWidth(cr, s) : left + kPadPx;
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.12);
        cairo_move_to(cr, x, top + kRowPx - 7.0);
        cairo_show_text(cr, s.c_str());
    };
    double top = kMarginPx;
    if (!table.title.empty())
    {
        text(table.title, kMarginPx - kPadPx, 0.0, top, false, true);
        top += titleHeight;
    }
    const double left = kMarginPx;
    // Column letters and row numbers on grey, the header row on light blue: the look of a spreadsheet.
    fillRect(cr, left, top, gridWidth, kRowPx, 0.90);
    fillRect(cr, left, top, numberWidth, gridHeight, 0.90);
    cairo_set_source_rgb(cr, 0.86, 0.91, 0.97);
    cairo_rectangle(cr, left + numberWidth, top + kRowPx, gridWidth - numberWidth, kRowPx);
    cairo_fill(cr);
    double x = left + numberWidth;
    for (std::size_t c = 0; c < columns; ++c)
    {
        text(columnName(c), x, x + widths[c], top, false, false);
        x += widths[c];
    }
    for (std::size_t r = 0; r < table.cells.size(); ++r)
    {
        const double rowTop = top + kRowPx * static_cast<double>(r + 1);
        const std::size_t number = table.rowNumbers.empty() ? r + 1 : table.rowNumbers[r];
        text(std::to_string(number), left, left + numberWidth, rowTop, true, false);
        x = left + numberWidth;
        for (std::size_t c = 0; c < columns; ++c)
        {
            const std::string& cell = table.cells[r][c];
            const bool numeric = !cell.empty() && std::isdigit(static_cast<unsigned char>(cell.back())) != 0;
            text(cell, x, x + widths[c], rowTop, r > 0 && numeric, r == 0);
            x += widths[c];
        }
    }
    // The grid.
    cairo_set_source_rgb(cr, 0.75, 0.75, 0.78);
    cairo_set_line_width(cr, 1.0);
    for (std::size_t r = 0; r <= table.cells.size() + 1; ++r)
    {
        const double y = top + kRowPx * static_cast<double>(r) + 0.5;
        cairo_move_to(cr, left, y);
        cairo_line_to(cr, left + gridWidth, y);
    }
    x = left + 0.5;
    cairo_move_to(cr, x, top);
    cairo_line_to(cr, x, top + gridHeight);
    x += numberWidth;
    for (std::size_t c = 0; c <= columns; ++c)
    {
        cairo_move_to(cr, x, top);
        cairo_line_to(cr, x, top + gridHeight);
        if (c < columns)
            x += widths[c];
    }
    cairo_stroke(cr);
    writeSurfacePng(surface.get(), path, "table");
}

} // namespace abalike::app
