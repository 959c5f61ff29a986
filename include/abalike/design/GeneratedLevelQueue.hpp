#pragma once

#include <abalike/design/Generator.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace abalike
{

/// Levels generated ahead of need on one low-priority worker thread: the endless mode asks for the loss shares the
/// next level may need, plays on, and takes a level that is ready when the player is.
///
/// The worker takes seeds firstSeed, firstSeed + 1, ... in the order it starts them (a seed that gives no level is
/// skipped), runs the generation single-threaded at the lowest CPU priority (SCHED_IDLE, else nice 19) so that the
/// game's frames come first, and keeps the wanted levels plus unwanted ones up to `capacity`. Destroying the queue
/// stops the generation in progress at its next check (GeneratorOptions::stop) and joins the worker.
class GeneratedLevelQueue
{
public:
    /// Makes one level; the queue sets seed, lossShare, threads (1, or every core while hurried) and stop of the
    /// options it passes.
    using Generate = std::function<GeneratedLevel(const GeneratorOptions&)>;

    /// Loss shares are given in tenths (EndlessRun's steps), so that equal shares compare equal.
    struct Ready
    {
        int lossShareTenths = 0;
        GeneratedLevel level;
    };

    /// What the worker is doing, for a "generating..." card.
    struct Status
    {
        bool working = false;
        int lossShareTenths = 0;   ///< of the level being generated
        std::uint64_t seed = 0;    ///< ... and its seed
        std::size_t ready = 0;     ///< levels ready to take
        std::size_t generated = 0; ///< levels made since the queue started
        std::size_t failedSeeds = 0;
        std::string error; ///< the generation threw (no parts, a bad world): the worker has stopped
    };

    GeneratedLevelQueue(Generate generate, GeneratorOptions base, std::uint64_t firstSeed, std::size_t capacity = 2);
    ~GeneratedLevelQueue();
    GeneratedLevelQueue(const GeneratedLevelQueue&) = delete;
    GeneratedLevelQueue& operator=(const GeneratedLevelQueue&) = delete;

    /// The loss shares to have a level ready for, the likeliest first (a share listed twice: two levels). Ready
    /// levels no longer wanted stay until a wanted one needs their room.
    void want(std::vector<int> lossShareTenths);
    /// A ready level of that loss share, taken off the queue; none when it is not ready yet. Call want() after it
    /// to say what comes next.
    std::optional<GeneratedLevel> take(int lossShareTenths);
    /// take(), waiting up to `timeout` for the worker to finish one.
    std::optional<GeneratedLevel> takeWaiting(int lossShareTenths, std::chrono::milliseconds timeout);
    Status status() const;
    /// Someone waits for the level in progress: from the next measure on, it uses every core (still at the lowest
    /// priority); false goes back to one.
    void hurry(bool hurry) { m_threads = hurry ? 0 : 1; }

private:
    void work();
    /// The first wanted share without a ready level to match it (under the lock).
    std::optional<int> nextJob() const;
    void makeRoom();

    Generate m_generate;
    GeneratorOptions m_base;
    std::uint64_t m_nextSeed;
    std::size_t m_capacity;

    mutable std::mutex m_mutex;
    std::condition_variable m_changed;
    std::vector<int> m_wanted;
    std::vector<Ready> m_ready;
    Status m_status;
    std::atomic<bool> m_stop{false};
    std::atomic<int> m_threads{1}; ///< GeneratorOptions::threadsNow of every job
    std::thread m_worker;          ///< last: it starts once everything above is built
};

} // namespace abalike
