#include <abalike/design/GeneratedLevelQueue.hpp>

#include "design/LowPriority.hpp"

#include <algorithm>
#include <exception>
#include <map>
#include <utility>

namespace abalike
{

GeneratedLevelQueue::GeneratedLevelQueue(Generate generate, GeneratorOptions base, std::uint64_t firstSeed,
                                         std::size_t capacity)
    : m_generate(std::move(generate)), m_base(std::move(base)), m_nextSeed(firstSeed),
      m_capacity(std::max<std::size_t>(capacity, 1)), m_worker([this] { work(); })
{
}

GeneratedLevelQueue::~GeneratedLevelQueue()
{
    {
        const std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_changed.notify_all();
    m_worker.join();
}

void GeneratedLevelQueue::want(std::vector<int> lossShareTenths)
{
    {
        const std::lock_guard lock(m_mutex);
        m_wanted = std::move(lossShareTenths);
    }
    m_changed.notify_all();
}

std::optional<GeneratedLevel> GeneratedLevelQueue::take(int lossShareTenths)
{
    return takeWaiting(lossShareTenths, std::chrono::milliseconds(0));
}

std::optional<GeneratedLevel> GeneratedLevelQueue::takeWaiting(int lossShareTenths, std::chrono::milliseconds timeout)
{
    std::unique_lock lock(m_mutex);
    const auto match = [&]
    {
        return std::find_if(m_ready.begin(), m_ready.end(),
                            [&](const Ready& r) { return r.lossShareTenths == lossShareTenths; });
    };
    m_changed.wait_for(lock, timeout, [&] { return match() != m_ready.end() || !m_status.error.empty(); });
    const auto found = match();
    if (found == m_ready.end())
        return std::nullopt;
    GeneratedLevel level = std::move(found->level);
    m_ready.erase(found);
    m_status.ready = m_ready.size();
    return level; // the worker goes on at the caller's next want(), which says what comes after this level
}

GeneratedLevelQueue::Status GeneratedLevelQueue::status() const
{
    const std::lock_guard lock(m_mutex);
    return m_status;
}

std::optional<int> GeneratedLevelQueue::nextJob() const
{
    std::map<int, int> unmatched;
    for (const Ready& r : m_ready)
        ++unmatched[r.lossShareTenths];
    for (const int tenths : m_wanted)
    {
        if (unmatched[tenths] > 0)
            --unmatched[tenths];
        else
            return tenths;
    }
    return std::nullopt;
}

void GeneratedLevelQueue::makeRoom()
{
    // Keep what is wanted (however many that is) and up to the capacity: drop the oldest ready level no longer
    // wanted first, then the oldest.
    while (m_ready.size() > std::max(m_capacity, m_wanted.size()))
    {
        auto drop =
            std::find_if(m_ready.begin(), m_ready.end(),
                         [&](const Ready& r)
                         { return std::find(m_wanted.begin(), m_wanted.end(), r.lossShareTenths) == m_wanted.end(); });
        m_ready.erase(drop != m_ready.end() ? drop : m_ready.begin());
    }
}

void GeneratedLevelQueue::work()
{
    lowerThisThreadsPriority();
    std::unique_lock lock(m_mutex);
    while (true)
    {
        // Sleep until asked for a share not yet ready (or until stopped).
        m_changed.wait(lock, [&] { return m_stop || (m_status.error.empty() && nextJob()); });
        if (m_stop)
            return;
        const int tenths = *nextJob();
        GeneratorOptions options = m_base;
        options.seed = m_nextSeed++;
        options.lossShare = tenths / 10.0;
        options.threads = 1;
        options.threadsNow = &m_threads;
        options.stop = &m_stop;
        m_status.working = true;
        m_status.seed = options.seed;
        m_status.lossShareTenths = tenths;
        lock.unlock();

        GeneratedLevel level;
        std::string error;
        try
        {
            level = m_generate(options);
        }
        catch (const std::exception& e)
        {
            error = e.what();
        }

        lock.lock();
        m_status.working = false;
        if (!error.empty())
            m_status.error = error;
        else if (level.ok)
        {
            m_ready.push_back({tenths, std::move(level)});
            makeRoom();
            ++m_status.generated;
        }
        else if (!level.stopped)
            ++m_status.failedSeeds;
        m_status.ready = m_ready.size();
        lock.unlock();
        m_changed.notify_all();
        lock.lock();
    }
}

} // namespace abalike
