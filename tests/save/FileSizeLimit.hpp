#pragma once

#include <csignal>
#include <sys/resource.h>

namespace abalike::test
{

/// Makes every regular file this process writes stop at maxBytes, as on a full disk: write() fails with EFBIG.
/// Works for root too, unlike a read-only folder. Restores the limit and SIGXFSZ when it goes out of scope.
class FileSizeLimit
{
public:
    explicit FileSizeLimit(rlim_t maxBytes)
    {
        m_oldHandler = std::signal(SIGXFSZ, SIG_IGN); // else the kernel kills the process instead of failing write()
        ::getrlimit(RLIMIT_FSIZE, &m_old);
        rlimit limited = m_old;
        limited.rlim_cur = maxBytes;
        ::setrlimit(RLIMIT_FSIZE, &limited);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;
    ~FileSizeLimit()
    {
        ::setrlimit(RLIMIT_FSIZE, &m_old);
        std::signal(SIGXFSZ, m_oldHandler);
    }

private:
    rlimit m_old{};
    void (*m_oldHandler)(int) = nullptr;
};

} // namespace abalike::test
