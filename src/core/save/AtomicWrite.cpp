#include <abalike/save/AtomicWrite.hpp>
#include <abalike/save/SaveError.hpp>
#include <atomic>
#include <cerrno>
#include <fcntl.h>
#include <string>
#include <system_error>
#include <unistd.h>

namespace abalike
{

namespace
{

std::string reason(int error)
{
    return std::error_code(error, std::generic_category()).message();
}

/// Closes a descriptor on every path out of the function.
class FileDescriptor
{
public:
    explicit FileDescriptor(int fd) : m_fd(fd) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor()
    {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    int get() const { return m_fd; }
    /// Closes now and reports the error close() gives (some file systems only report a full disk there).
    int close()
    {
        const int result = ::close(m_fd);
        m_fd = -1;
        return result == 0 ? 0 : errno;
    }

private:
    int m_fd;
};

/// Writes all of data, retrying after signals and short writes; returns 0 or the errno.
int writeAll(int fd, std::string_view data)
{
    while (!data.empty())
    {
        const ssize_t n = ::write(fd, data.data(), data.size());
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return n < 0 ? errno : ENOSPC;
        data.remove_prefix(static_cast<std::size_t>(n));
    }
    return 0;
}

/// Makes the rename itself durable. Some file systems cannot sync a folder; the file is in place either way.
void syncDirectory(const std::filesystem::path& dir)
{
    const FileDescriptor fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (fd.get() >= 0)
        ::fsync(fd.get());
}

} // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents)
{
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    // Hidden, unique per process and call, in the same folder so that rename() cannot cross file systems.
    std::string tempName = ".";
    tempName.append(path.filename().string())
        .append(".tmp-")
        .append(std::to_string(::getpid()))
        .append("-")
        .append(std::to_string(counter++));
    const std::filesystem::path temp = dir / tempName;
    FileDescriptor fd(::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
    if (fd.get() < 0)
        throw SaveIoError("cannot write " + path.string() + ": " + reason(errno));

    int error = writeAll(fd.get(), contents);
    if (error == 0 && ::fsync(fd.get()) != 0)
        error = errno;
    if (const int closeError = fd.close(); error == 0)
        error = closeError;
    if (error == 0 && ::rename(temp.c_str(), path.c_str()) != 0)
        error = errno;
    if (error != 0)
    {
        ::unlink(temp.c_str());
        throw SaveIoError("cannot write " + path.string() + ": " + reason(error));
    }
    syncDirectory(dir);
}

} // namespace abalike
