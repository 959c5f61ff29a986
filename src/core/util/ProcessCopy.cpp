#include <abalike/util/ProcessCopy.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <exception>
#include <new>

#if defined(__unix__) || defined(__APPLE__)
#include <cerrno>
#include <csignal>
#include <poll.h>
#include <sys/mman.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#define ABALIKE_HAS_FORK 1
#endif

namespace abalike
{

namespace
{

std::atomic<bool> g_allowed{true};
std::atomic<std::size_t> g_made{0};
std::atomic<std::size_t> g_failed{0};

#ifdef ABALIKE_HAS_FORK

/// Moves exactly size bytes with transfer (::read or ::write) however many calls it takes, or returns false.
template <typename Transfer, typename Byte>
bool transferAll(Transfer transfer, int fd, Byte* data, std::size_t size)
{
    while (size > 0)
    {
        const ssize_t n = transfer(fd, data, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

bool writeBytes(int fd, const char* data, std::size_t size)
{
    return transferAll(::write, fd, data, size);
}

/// Reads exactly size bytes, not up to end of file: a copy made by another thread at the same moment may hold the
/// pipe's writing end open too.
bool readBytes(int fd, char* data, std::size_t size)
{
    return transferAll(::read, fd, data, size);
}

/// The copy's side: runs work, sends its length and bytes, and leaves without running anything of the original's
/// (no atexit handlers, no flush of buffers it shares with the original).
[[noreturn]] void runChild(int fd, const std::function<std::string()>& work)
{
    int status = 1;
    try
    {
        const std::string bytes = work();
        const std::uint64_t size = bytes.size();
        if (writeBytes(fd, reinterpret_cast<const char*>(&size), sizeof size) &&
            writeBytes(fd, bytes.data(), bytes.size()))
            status = 0;
    }
    catch (...)
    {
        status = 1;
    }
    ::_exit(status);
}

#endif

} // namespace

bool processCopiesAvailable()
{
#ifdef ABALIKE_HAS_FORK
    return g_allowed.load();
#else
    return false;
#endif
}

ProcessCopyCounts processCopyCounts()
{
    return {g_made.load(), g_failed.load()};
}

void allowProcessCopies(bool allowed)
{
    g_allowed = allowed;
}

std::optional<std::string> runInProcessCopy(const std::function<std::string()>& work)
{
#ifdef ABALIKE_HAS_FORK
    if (!processCopiesAvailable())
        return std::nullopt;
    int fds[2];
    if (::pipe(fds) != 0)
        return std::nullopt;
    const pid_t pid = ::fork();
    if (pid < 0)
    {
        ::close(fds[0]);
        ::close(fds[1]);
        return std::nullopt;
    }
    if (pid == 0)
    {
        ::close(fds[0]);
        runChild(fds[1], work);
    }
    ::close(fds[1]);
    std::optional<std::string> result;
    std::uint64_t size = 0;
    if (readBytes(fds[0], reinterpret_cast<char*>(&size), sizeof size))
    {
        std::string bytes(size, '\0');
        if (readBytes(fds[0], bytes.data(), bytes.size()))
            result = std::move(bytes);
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
    {
    }
    ++g_made;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !result)
    {
        ++g_failed;
        return std::nullopt;
    }
    return result;
#else
    (void)work;
    return std::nullopt;
#endif
}

std::optional<std::vector<std::optional<std::string>>>
runInProcessCopies(std::size_t count, unsigned workers, const std::function<std::string(std::size_t)>& work,
                   const std::function<void(std::size_t)>& done)
{
#ifdef ABALIKE_HAS_FORK
    if (!processCopiesAvailable())
        return std::nullopt;
    std::vector<std::optional<std::string>> results(count);
    if (count == 0)
        return results;
    workers = std::max(1u, std::min<unsigned>(workers, static_cast<unsigned>(count)));
    // The next item to take, shared by the copies: an atomic in memory they all map.
    void* shared =
        ::mmap(nullptr, sizeof(std::atomic<std::size_t>), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (shared == MAP_FAILED)
        return std::nullopt;
    auto* next = new (shared) std::atomic<std::size_t>(0);
    struct Worker
    {
        pid_t pid = -1;
        int fd = -1;
    };
    std::vector<Worker> pool;
    for (unsigned w = 0; w < workers; ++w)
    {
        int fds[2];
        if (::pipe(fds) != 0)
            break;
        const pid_t pid = ::fork();
        if (pid < 0)
        {
            ::close(fds[0]);
            ::close(fds[1]);
            break;
        }
        if (pid == 0)
        {
            ::close(fds[0]);
            for (const Worker& other : pool)
                ::close(other.fd);
            int status = 0;
            for (std::size_t i = next->fetch_add(1); i < count; i = next->fetch_add(1))
            {
                try
                {
                    const std::string bytes = work(i);
                    const std::uint64_t head[2] = {i, bytes.size()};
                    if (!writeBytes(fds[1], reinterpret_cast<const char*>(head), sizeof head) ||
                        !writeBytes(fds[1], bytes.data(), bytes.size()))
                        break;
                }
                catch (...)
                {
                    status = 1; // this item comes back empty; the others still come
                }
            }
            ::_exit(status);
        }
        ::close(fds[1]);
        pool.push_back({pid, fds[0]});
    }
    // Results as they come, from whichever copy sends one.
    std::exception_ptr failure;
    std::vector<pollfd> open;
    for (const Worker& worker : pool)
        open.push_back({worker.fd, POLLIN, 0});
    while (!open.empty())
    {
        if (::poll(open.data(), open.size(), -1) < 0)
        {
            if (errno == EINTR)
                continue;
            break;
        }
        for (std::size_t k = 0; k < open.size();)
        {
            if (open[k].revents == 0)
            {
                ++k;
                continue;
            }
            std::uint64_t head[2];
            bool ok = readBytes(open[k].fd, reinterpret_cast<char*>(head), sizeof head) && head[0] < count;
            std::string bytes;
            if (ok)
            {
                bytes.resize(head[1]);
                ok = readBytes(open[k].fd, bytes.data(), bytes.size());
            }
            if (!ok)
            {
                // This copy is done (or died): what it had not sent stays empty.
                ::close(open[k].fd);
                open.erase(open.begin() + static_cast<std::ptrdiff_t>(k));
                continue;
            }
            results[head[0]] = std::move(bytes);
            try
            {
                done(head[0]);
            }
            catch (...)
            {
                // A report that stops the work: the copies stop too.
                failure = std::current_exception();
                for (const Worker& worker : pool)
                    ::kill(worker.pid, SIGKILL);
                for (const pollfd& p : open)
                    ::close(p.fd);
                open.clear();
                break;
            }
            open[k].revents = 0;
            ++k;
        }
    }
    for (const Worker& worker : pool)
    {
        int status = 0;
        while (::waitpid(worker.pid, &status, 0) < 0 && errno == EINTR)
        {
        }
        ++g_made;
        if (!failure && (!WIFEXITED(status) || WEXITSTATUS(status) != 0))
            ++g_failed;
    }
    next->~atomic();
    ::munmap(shared, sizeof(std::atomic<std::size_t>));
    if (failure)
        std::rethrow_exception(failure);
    if (pool.empty())
        return std::nullopt;
    return results;
#else
    (void)count;
    (void)workers;
    (void)work;
    (void)done;
    return std::nullopt;
#endif
}

} // namespace abalike
