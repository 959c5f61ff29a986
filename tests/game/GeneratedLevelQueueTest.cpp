#include <abalike/design/GeneratedLevelQueue.hpp>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

namespace abalike
{
namespace
{

using namespace std::chrono_literals;

/// A stand-in for generateLevel: a level named by its seed and loss share, made at once (or held until released, or
/// failing for the seeds it is told), recording what it was asked.
struct FakeGenerator
{
    std::mutex mutex;
    std::vector<GeneratorOptions> asked;
    std::vector<std::uint64_t> failingSeeds;
    std::atomic<bool> hold{false};
    std::atomic<bool> sawStop{false};

    GeneratedLevelQueue::Generate function()
    {
        return [this](const GeneratorOptions& options)
        {
            {
                const std::lock_guard lock(mutex);
                asked.push_back(options);
            }
            GeneratedLevel level;
            while (hold)
            {
                if (options.stop != nullptr && options.stop->load())
                {
                    sawStop = true;
                    level.stopped = true;
                    return level;
                }
                std::this_thread::sleep_for(1ms);
            }
            for (const std::uint64_t seed : failingSeeds)
                if (seed == options.seed)
                    return level;
            level.ok = true;
            level.seed = options.seed;
            level.level.id = "generated-" + std::to_string(options.seed);
            level.lossShare = options.lossShare;
            return level;
        };
    }
};

/// Waits (up to 10 s, for a busy machine) until the queue holds `ready` levels and its worker rests.
void waitUntilReady(const GeneratedLevelQueue& queue, std::size_t ready)
{
    for (auto waited = 0ms; waited < 10s; waited += 1ms)
    {
        const GeneratedLevelQueue::Status status = queue.status();
        if (status.ready == ready && !status.working)
            break;
        std::this_thread::sleep_for(1ms);
    }
}

TEST(GeneratedLevelQueue, GeneratesTheWantedSharesInOrderWithSuccessiveSeedsOnOneThread)
{
    FakeGenerator fake;
    GeneratorOptions base;
    base.world = "moon";
    base.threads = 0;
    GeneratedLevelQueue queue(fake.function(), base, 4711);
    queue.want({4, 2});
    waitUntilReady(queue, 2);
    const std::optional<GeneratedLevel> harder = queue.take(4);
    ASSERT_TRUE(harder);
    EXPECT_EQ(harder->level.id, "generated-4711");
    EXPECT_DOUBLE_EQ(harder->lossShare, 0.4);
    const std::optional<GeneratedLevel> easier = queue.take(2);
    ASSERT_TRUE(easier);
    EXPECT_EQ(easier->level.id, "generated-4712");
    EXPECT_DOUBLE_EQ(easier->lossShare, 0.2);
    const std::lock_guard lock(fake.mutex);
    ASSERT_GE(fake.asked.size(), 2u);
    EXPECT_EQ(fake.asked[0].threads, 1) << "one worker thread: the game keeps the other cores";
    EXPECT_EQ(fake.asked[0].world, "moon") << "the base options are kept";
    EXPECT_NE(fake.asked[0].stop, nullptr);
    ASSERT_NE(fake.asked[0].threadsNow, nullptr);
    EXPECT_EQ(fake.asked[0].threadsNow->load(), 1);
    queue.hurry(true);
    EXPECT_EQ(fake.asked[0].threadsNow->load(), 0) << "a waiting player: every core from the next measure on";
    queue.hurry(false);
    EXPECT_EQ(fake.asked[0].threadsNow->load(), 1);
}

TEST(GeneratedLevelQueue, KeepsNoMoreThanAskedAndNothingUnasked)
{
    FakeGenerator fake;
    GeneratedLevelQueue queue(fake.function(), {}, 1, 2);
    queue.want({5, 5});
    waitUntilReady(queue, 2);
    ASSERT_TRUE(queue.take(5));
    queue.want({5, 5});
    waitUntilReady(queue, 2);
    std::this_thread::sleep_for(20ms); // time to make a third, if it wrongly would
    const GeneratedLevelQueue::Status status = queue.status();
    EXPECT_EQ(status.ready, 2u) << "a want() after a take refills the pair, and no more";
    EXPECT_EQ(status.generated, 3u);
    EXPECT_FALSE(queue.take(3)) << "no level of a share that was not asked for";
}

TEST(GeneratedLevelQueue, ASeedThatGivesNoLevelIsSkipped)
{
    FakeGenerator fake;
    fake.failingSeeds = {10, 11};
    GeneratedLevelQueue queue(fake.function(), {}, 10);
    queue.want({3});
    const std::optional<GeneratedLevel> level = queue.takeWaiting(3, 10s);
    ASSERT_TRUE(level);
    EXPECT_EQ(level->level.id, "generated-12");
    EXPECT_EQ(queue.status().failedSeeds, 2u);
}

TEST(GeneratedLevelQueue, NewWantsReplaceOldOnesAndUnwantedLevelsMakeRoom)
{
    FakeGenerator fake;
    GeneratedLevelQueue queue(fake.function(), {}, 1, 2);
    queue.want({4, 2});
    waitUntilReady(queue, 2);
    // Both ready, and the player needs 0.3 (every wanted level is kept, however many): it is made, 0.4 and 0.2
    // stay.
    queue.want({3, 4, 2});
    ASSERT_TRUE(queue.takeWaiting(3, 10s));
    EXPECT_TRUE(queue.take(4));
    EXPECT_TRUE(queue.take(2));
    // A level no longer wanted makes room once the queue holds more than its capacity.
    queue.want({6});
    waitUntilReady(queue, 1);
    queue.want({7, 8});
    waitUntilReady(queue, 2);
    EXPECT_FALSE(queue.take(6)) << "the unwanted 0.6 level gave its room to the wanted 0.7 and 0.8";
    EXPECT_TRUE(queue.take(7));
}

TEST(GeneratedLevelQueue, DestroyingItStopsTheGenerationInProgress)
{
    FakeGenerator fake;
    fake.hold = true;
    const auto start = std::chrono::steady_clock::now();
    {
        GeneratedLevelQueue queue(fake.function(), {}, 1);
        queue.want({3});
        while (!queue.status().working)
            std::this_thread::sleep_for(1ms);
        EXPECT_FALSE(queue.take(3));
    }
    EXPECT_TRUE(fake.sawStop) << "the generation was told to stop, not waited for";
    EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
}

TEST(GeneratedLevelQueue, AGenerationThatThrowsStopsTheWorkerAndSaysWhy)
{
    GeneratedLevelQueue queue([](const GeneratorOptions&) -> GeneratedLevel
                              { throw std::invalid_argument("no castle parts to build with"); },
                              {}, 1);
    queue.want({3});
    EXPECT_FALSE(queue.takeWaiting(3, 10s));
    EXPECT_EQ(queue.status().error, "no castle parts to build with");
}

} // namespace
} // namespace abalike
