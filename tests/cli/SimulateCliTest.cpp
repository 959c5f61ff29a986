#include "RunAbalike.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace abalike::test
{
namespace
{

const std::string kLevel = sourcePath("levels/1-1-first-flight.json");

TEST(SimulateCli, PrintsTheContractFields)
{
    const RunResult r = runAbalike("simulate " + kLevel + " --shot 55,17 --shot 10,23 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    for (const char* key : {"level", "won", "score", "stars", "pigs_remaining", "birds_used", "sim_time_s", "shots"})
        EXPECT_TRUE(doc.contains(key)) << key;
    EXPECT_EQ(doc["level"], "1-1");
    EXPECT_TRUE(doc["won"].get<bool>());
    EXPECT_EQ(doc["pigs_remaining"], 0);
    EXPECT_EQ(doc["birds_used"], 2);
    EXPECT_GE(doc["stars"].get<int>(), 1);
    ASSERT_EQ(doc["shots"].size(), 2u);
    const auto& shot = doc["shots"][0];
    for (const char* key : {"bird", "angle_deg", "speed", "predicted_contact", "actual_contact", "deviation_m",
                            "predicted_path", "actual_path"})
        EXPECT_TRUE(shot.contains(key)) << key;
    EXPECT_EQ(shot["bird"], "red");
    EXPECT_EQ(shot["angle_deg"], 55.0);
    EXPECT_LT(shot["deviation_m"].get<double>(), 0.01);
    EXPECT_EQ(shot["predicted_path"][0].size(), 3u);
}

TEST(SimulateCli, EveryDefeatHasATimeAShotAndACause)
{
    const RunResult r = runAbalike("simulate " + kLevel + " --shot 55,17 --shot 10,23 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    ASSERT_TRUE(doc.contains("defeats"));
    const auto& defeats = doc["defeats"];
    int pigs = 0;
    int blocks = 0;
    double last = 0.0;
    for (const auto& d : defeats)
    {
        ASSERT_EQ(d.size(), 5u) << d.dump(); // t, shot, kind, index, cause
        const double t = d["t"].get<double>();
        EXPECT_GE(t, last) << "in order of time";
        EXPECT_LE(t, doc["sim_time_s"].get<double>());
        last = t;
        const int shot = d["shot"].get<int>();
        EXPECT_TRUE(shot == 0 || shot == 1);
        const std::string kind = d["kind"];
        (kind == "pig" ? pigs : blocks) += 1;
        EXPECT_TRUE(kind == "pig" || kind == "block");
        const std::string cause = d["cause"]["kind"];
        const bool indexed = cause == "block" || cause == "pig";
        EXPECT_TRUE(indexed || cause == "bird" || cause == "explosion" || cause == "egg" || cause == "ground" ||
                    cause == "out_of_bounds")
            << cause;
        EXPECT_EQ(d["cause"]["index"].is_number_integer(), indexed) << d.dump();
    }
    EXPECT_EQ(pigs, doc["score_breakdown"]["pigs_defeated"].get<int>());
    EXPECT_EQ(blocks, doc["score_breakdown"]["blocks_destroyed"].get<int>());
    // Each shot says how soon the next bird was ready after its first contact (at most 3 s).
    for (const auto& shot : doc["shots"])
    {
        ASSERT_TRUE(shot["ready_after_contact_s"].is_number()) << shot.dump();
        EXPECT_LE(shot["ready_after_contact_s"].get<double>(), 3.0 + 1.0 / 60.0);
        EXPECT_FALSE(shot["launched_into_moving_world"].get<bool>());
    }
}

TEST(SimulateCli, SameArgumentsGiveByteIdenticalOutput)
{
    const std::string args = "simulate " + kLevel + " --shot 30,18 --shot 45,17 --json";
    const RunResult first = runAbalike(args);
    const RunResult second = runAbalike(args);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_FALSE(first.out.empty());
    EXPECT_EQ(first.out, second.out);
}

TEST(SimulateCli, ShotFasterThanTheBirdCanBeLaunchedIsAnError)
{
    const RunResult r = runAbalike("simulate " + kLevel + " --shot 45,80 --json");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("at most 30 m/s"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
}

TEST(SimulateCli, MoreShotsThanBirdsIsAnError)
{
    const RunResult r =
        runAbalike("simulate " + kLevel + " --shot 5,10 --shot 5,10 --shot 5,10 --shot 5,10 --shot 5,10 --json");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("no bird left"), std::string::npos) << r.err;
}

} // namespace
} // namespace abalike::test
