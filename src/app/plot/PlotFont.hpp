#pragma once

#include <memory>
#include <string>

struct _cairo_font_face;

namespace abalike::app
{

/// A font face found through fontconfig, ready for cairo.
class PlotFont
{
public:
    /// The best match fontconfig has for the family; says once on stderr when that is another family (the plot is
    /// then drawn in it). Throws PlotError when fontconfig has no font at all.
    static PlotFont match(const std::string& family);

    _cairo_font_face* face() const { return m_face.get(); }
    const std::string& family() const { return m_family; } ///< the family actually found
    const std::string& file() const { return m_file; }

private:
    std::shared_ptr<_cairo_font_face> m_face;
    std::string m_family;
    std::string m_file;
};

} // namespace abalike::app
