#include "plot/CairoPng.hpp"

#include "plot/PlotError.hpp"

#include <cairo.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace abalike::app
{

namespace
{
cairo_status_t writeToFile(void* closure, const unsigned char* data, unsigned int length)
{
    return std::fwrite(data, 1, length, static_cast<std::FILE*>(closure)) == length ? CAIRO_STATUS_SUCCESS
                                                                                    : CAIRO_STATUS_WRITE_ERROR;
}
} // namespace

void writeSurfacePng(cairo_surface_t* surface, const std::string& path, const std::string& what)
{
    cairo_surface_flush(surface);
    std::unique_ptr<std::FILE, decltype(&std::fclose)> file(std::fopen(path.c_str(), "wb"), std::fclose);
    if (!file)
        throw PlotError("cannot write the " + what + " " + path + " (" + std::strerror(errno) + ")");
    const cairo_status_t status = cairo_surface_write_to_png_stream(surface, writeToFile, file.get());
    const int closed = std::fclose(file.release());
    if (status != CAIRO_STATUS_SUCCESS || closed != 0)
        throw PlotError("cannot write the " + what + " " + path + " (" + std::strerror(errno) + ")");
}

} // namespace abalike::app
