#pragma once

#include <filesystem>
#include <string>

namespace abalike
{

/// What reading a save file gave.
struct ReadResult
{
    enum class Status
    {
        Read,       ///< text holds the file
        Missing,    ///< there is no such file
        TooLarge,   ///< a regular file over the limit; text is empty
        Unreadable, ///< it exists (or may) but cannot be read; error says why
    };
    Status status = Status::Missing;
    std::string text;
    std::string error;
};

/// Reads a regular file of at most maxBytes without ever blocking (a FIFO or a device is Unreadable).
ReadResult readSmallFile(const std::filesystem::path& path, std::size_t maxBytes);

} // namespace abalike
