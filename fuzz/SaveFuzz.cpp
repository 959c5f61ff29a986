#include "FuzzInput.hpp"

#include <abalike/save/Progress.hpp>
#include <abalike/save/SaveError.hpp>
#include <abalike/save/Settings.hpp>

namespace
{

/// Whatever parse accepts, write must turn into text that parse reads back as the same value: otherwise saving
/// would turn a good file into one the next start sets aside as damaged.
template <class T>
void checkRoundTrip(std::string_view text, T (*parse)(std::string_view), std::string (*write)(const T&))
{
    T value;
    try
    {
        value = parse(text);
    }
    catch (const abalike::SaveFormatError&)
    {
        return;
    }
    const std::string written = write(value);
    try
    {
        if (!(parse(written) == value))
            abalike::fuzz::fail("a saved file reads back different");
    }
    catch (const abalike::SaveFormatError&)
    {
        abalike::fuzz::fail("a saved file cannot be read back");
    }
    if (write(parse(written)) != written)
        abalike::fuzz::fail("saving unchanged data writes different bytes");
}

} // namespace

/// The progress and settings loaders: any bytes give a value or a SaveFormatError, and what they accept survives a
/// save and a load unchanged.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text = abalike::fuzz::asText(data, size);
    checkRoundTrip(text, &abalike::parseProgress, &abalike::progressToJson);
    checkRoundTrip(text, &abalike::parseSettings, &abalike::settingsToJson);
    return 0;
}
