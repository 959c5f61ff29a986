#include "save/ReadFile.hpp"

#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace abalike
{

namespace
{

ReadResult unreadable(int error)
{
    return {ReadResult::Status::Unreadable, {}, std::error_code(error, std::generic_category()).message()};
}

} // namespace

ReadResult readSmallFile(const std::filesystem::path& path, std::size_t maxBytes)
{
    // O_NONBLOCK: opening a FIFO someone left in place of the file must not hang the game.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        // ENOTDIR: part of the folder path is a file, so there is no save file there to protect.
        return errno == ENOENT || errno == ENOTDIR ? ReadResult{} : unreadable(errno);
    ReadResult result;
    struct stat info
    {
    };
    if (::fstat(fd, &info) != 0)
        result = unreadable(errno);
    else if (!S_ISREG(info.st_mode))
        result = {ReadResult::Status::Unreadable, {}, "not a regular file"};
    else if (static_cast<std::size_t>(info.st_size) > maxBytes)
        result.status = ReadResult::Status::TooLarge;
    else
    {
        result.status = ReadResult::Status::Read;
        char buffer[16384];
        while (true)
        {
            const ssize_t n = ::read(fd, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR)
                continue;
            if (n < 0)
            {
                result = unreadable(errno);
                break;
            }
            if (n == 0)
                break;
            result.text.append(buffer, static_cast<std::size_t>(n));
            // The file may grow while it is read; the limit holds anyway.
            if (result.text.size() > maxBytes)
            {
                result = {ReadResult::Status::TooLarge, {}, {}};
                break;
            }
        }
    }
    ::close(fd);
    return result;
}

} // namespace abalike
