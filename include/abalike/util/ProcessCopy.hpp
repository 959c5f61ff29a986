#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace abalike
{

/// Whether runInProcessCopy can copy this process: on POSIX systems (fork), unless allowProcessCopies(false).
/// Where it cannot (Windows), callers do the work in place instead, the slower way.
bool processCopiesAvailable();

/// How many copies this process has made, and how many of those did not finish (they crashed, or their work
/// threw): the work was then done in place, so a search gives the same answer, but a copy that fails hides its
/// reason (tests check that none fails).
struct ProcessCopyCounts
{
    std::size_t made = 0;
    std::size_t failed = 0;
};
ProcessCopyCounts processCopyCounts();

/// Lets runInProcessCopy copy the process (the default) or not (tests compare both ways).
void allowProcessCopies(bool allowed);

/// Runs work in a copy of this whole process (fork): work may change anything, and this process sees none of it;
/// the bytes work returns come back. The copy has only the calling thread, so work must not wait for a lock another
/// thread may hold (a progress report, a cache). Returns nullopt when no copy could be made or the copy did not
/// finish (it crashed, or work threw): the caller then does the work itself.
///
/// Why: Box2D 2.4 cannot copy a world, and a world rebuilt from its bodies' places does not go on bit for bit as the
/// original would (contacts, their warm-start impulses and the broad phase's tree are history). A copied process
/// goes on exactly as the original would have.
std::optional<std::string> runInProcessCopy(const std::function<std::string()>& work);

} // namespace abalike

namespace abalike
{

/// Calls work(i) for every i in [0, count) in up to `workers` copies of this process (runInProcessCopy's fork), each
/// taking the next item when it is done with one, and returns what each call returned, by item. done(i) is called
/// here, in this process, as each result arrives (progress reports). A copy is single-threaded, so a work that copies
/// the process again (SessionBranch::trial) does not make this process's other threads copy the pages they write.
/// Returns nullopt, having called nothing, when the process cannot be copied; items whose copy died (or threw) come
/// back empty (nullopt in the vector), for the caller to do itself.
std::optional<std::vector<std::optional<std::string>>>
runInProcessCopies(std::size_t count, unsigned workers, const std::function<std::string(std::size_t)>& work,
                   const std::function<void(std::size_t)>& done);

} // namespace abalike
