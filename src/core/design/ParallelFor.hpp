#pragma once

#include <abalike/util/ProcessCopy.hpp>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace abalike
{

/// Number of worker threads to use: requested if > 0, else every hardware thread.
inline unsigned workerCount(int requested)
{
    if (requested > 0)
        return static_cast<unsigned>(requested);
    return std::max(1u, std::thread::hardware_concurrency());
}

/// Calls work(i) for every i in [0, count) on up to `threads` threads. Each call must write only its own result
/// slot, so the outcome never depends on which thread ran what or when; done(i) is called after each item under
/// a lock (progress reports). The first exception thrown by work or done is rethrown here.
template <typename Work, typename Done>
void parallelFor(std::size_t count, unsigned threads, Work&& work, Done&& done)
{
    std::atomic<std::size_t> next{0};
    std::mutex lock;
    std::exception_ptr failure;
    auto worker = [&]
    {
        while (true)
        {
            const std::size_t i = next.fetch_add(1);
            if (i >= count)
                return;
            try
            {
                work(i);
                const std::lock_guard guard(lock);
                done(i); // may throw too (a progress report that stops the work): every thread is still joined
            }
            catch (...)
            {
                const std::lock_guard guard(lock);
                if (!failure)
                    failure = std::current_exception();
                next = count; // stop handing out work
                return;
            }
        }
    };
    const unsigned n = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(count)));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < n; ++t)
        pool.emplace_back(worker);
    worker();
    for (std::thread& thread : pool)
        thread.join();
    if (failure)
        std::rethrow_exception(failure);
}

/// parallelFor for work that hands its result over as bytes: in copies of the process where it can be copied
/// (runInProcessCopies: each copy is single-threaded, so the process copies that searches make from there do not
/// copy pages this process's other threads are writing), else on threads. take(i, bytes) is called in this process
/// for each item, from one thread at a time in the first case and from the workers in the second; an item whose
/// copy failed is worked here. done(i) as for parallelFor.
template <typename Work, typename Take, typename Done>
void parallelForBytes(std::size_t count, unsigned threads, Work&& work, Take&& take, Done&& done)
{
    if (threads > 1 && count > 1)
        if (const auto copied = runInProcessCopies(
                count, threads, [&](std::size_t i) -> std::string { return work(i); }, [&](std::size_t i) { done(i); }))
        {
            for (std::size_t i = 0; i < count; ++i)
                if ((*copied)[i])
                    take(i, *(*copied)[i]);
                else
                {
                    take(i, work(i));
                    done(i);
                }
            return;
        }
    parallelFor(
        count, threads, [&](std::size_t i) { take(i, work(i)); }, done);
}

} // namespace abalike
