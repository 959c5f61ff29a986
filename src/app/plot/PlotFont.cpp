#include "plot/PlotFont.hpp"
#include "plot/PlotError.hpp"

#include <cairo-ft.h>
#include <fontconfig/fontconfig.h>

#include <iostream>
#include <mutex>
#include <set>

namespace abalike::app
{

namespace
{

std::string patternString(FcPattern* pattern, const char* object)
{
    FcChar8* value = nullptr;
    if (FcPatternGetString(pattern, object, 0, &value) == FcResultMatch && value != nullptr)
        return reinterpret_cast<const char*>(value);
    return {};
}

/// Each family that is missing is reported once per run, not once per plot.
void warnOnce(const std::string& wanted, const std::string& found)
{
    static std::mutex mutex;
    static std::set<std::string> warned;
    const std::lock_guard lock(mutex);
    if (warned.insert(wanted).second)
        std::cerr << "abalike: the font \"" << wanted << "\" is not installed (Debian: fonts-dejavu-core); plots use \""
                  << found << "\"\n";
}

} // namespace

PlotFont PlotFont::match(const std::string& family)
{
    FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>(family.c_str()));
    if (pattern == nullptr)
        throw PlotError("cannot look up the font \"" + family + "\" through fontconfig");
    FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result = FcResultNoMatch;
    FcPattern* matched = FcFontMatch(nullptr, pattern, &result);
    FcPatternDestroy(pattern);
    if (matched == nullptr)
        throw PlotError("fontconfig found no font at all for the plots (Debian: install fonts-dejavu-core)");

    PlotFont font;
    font.m_family = patternString(matched, FC_FAMILY);
    font.m_file = patternString(matched, FC_FILE);
    // cairo keeps its own reference to the pattern for as long as the face lives.
    font.m_face.reset(cairo_ft_font_face_create_for_pattern(matched), cairo_font_face_destroy);
    FcPatternDestroy(matched);
    if (cairo_font_face_status(font.m_face.get()) != CAIRO_STATUS_SUCCESS)
        throw PlotError("cairo cannot use the font " + font.m_file);
    if (font.m_family != family)
        warnOnce(family, font.m_family);
    return font;
}

} // namespace abalike::app
