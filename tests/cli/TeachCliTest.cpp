#include "RunAbalike.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <unistd.h>

namespace abalike::test
{
namespace
{

nlohmann::ordered_json jsonOf(const std::string& args)
{
    const RunResult r = runAbalike(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    return nlohmann::ordered_json::parse(r.out);
}

void expectVector(const nlohmann::ordered_json& actual, const std::vector<double>& expected)
{
    ASSERT_EQ(actual.size(), expected.size()) << actual;
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_NEAR(actual[i].get<double>(), expected[i], 1e-12) << actual;
}

// ------------------------------------------------------------------ walkthrough

TEST(WalkthroughCli, ReproducesTheSpecsExample)
{
    const auto doc = jsonOf("walkthrough --x0 0 --y0 0 --vx 10 --vy 10 --dt 1 --json");
    const std::vector<std::string> keys{"stepper", "dt", "state", "k1", "k2", "k3", "k4", "next", "exact"};
    std::vector<std::string> actual;
    for (const auto& item : doc.items())
        actual.push_back(item.key());
    EXPECT_EQ(actual, keys); // exactly these, in this order
    EXPECT_EQ(doc["stepper"], "rk4");
    EXPECT_EQ(doc["dt"], 1.0);
    expectVector(doc["state"], {0.0, 0.0, 10.0, 10.0});
    expectVector(doc["k1"], {10.0, 10.0, 0.0, -9.81});
    expectVector(doc["k2"], {10.0, 5.095, 0.0, -9.81});
    expectVector(doc["k3"], {10.0, 5.095, 0.0, -9.81});
    expectVector(doc["k4"], {10.0, 0.19, 0.0, -9.81});
    expectVector(doc["next"], {10.0, 5.095, 10.0, 0.19});
    expectVector(doc["exact"], {10.0, 5.095, 10.0, 0.19});
}

TEST(WalkthroughCli, ExactIsNullWithoutAClosedForm)
{
    EXPECT_TRUE(jsonOf("walkthrough --vx 10 --vy 10 --quadratic-drag 0.05 --json")["exact"].is_null());
    EXPECT_TRUE(jsonOf("walkthrough --vx 10 --vy 10 --linear-drag 0.1 --gust-sine 2,0,3 --json")["exact"].is_null());
    const auto linear = jsonOf("walkthrough --vx 10 --vy 10 --linear-drag 0.5 --wind 3,0 --dt 0.1 --json");
    ASSERT_TRUE(linear["exact"].is_array());
    EXPECT_NEAR(linear["next"][2].get<double>(), linear["exact"][2].get<double>(), 1e-6);
    EXPECT_EQ(linear["dt"], 0.1);
    // Default step: the physics step.
    EXPECT_EQ(jsonOf("walkthrough --vx 1 --vy 1 --json")["dt"], 1.0 / 60.0);
}

TEST(WalkthroughCli, GustsDependOnTheStartTime)
{
    const std::string base = "walkthrough --vx 10 --vy 0 --quadratic-drag 0.1 --gust-step 1,5,0 --dt 0.1 --json";
    const auto before = jsonOf(base + " --t0 0");
    const auto after = jsonOf(base + " --t0 2");
    EXPECT_NE(before["k1"][2], after["k1"][2]); // the gust blows from 1 s on
}

TEST(WalkthroughCli, WithoutJsonPrintsATable)
{
    const RunResult r = runAbalike("walkthrough --vx 10 --vy 10 --dt 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* word : {"k1", "k2", "k3", "k4", "next", "exact", "5.095", "0.19"})
        EXPECT_NE(r.out.find(word), std::string::npos) << word << "\n" << r.out;
}

// ------------------------------------------------------------------ chart range

TEST(ChartRangeCli, VacuumFromTheGroundIs45Degrees)
{
    const auto doc = jsonOf("chart range --speed 20 --json");
    std::vector<std::string> keys;
    for (const auto& item : doc.items())
        keys.push_back(item.key());
    EXPECT_EQ(keys, (std::vector<std::string>{"angles_deg", "ranges_m", "best_angle_deg", "best_range_m"}));
    ASSERT_EQ(doc["angles_deg"].size(), 181u); // -90..90 in 1 degree steps by default
    EXPECT_EQ(doc["angles_deg"][0], -90.0);
    EXPECT_EQ(doc["ranges_m"][0], 0.0); // into the ground
    EXPECT_NEAR(doc["ranges_m"][90 + 30].get<double>(), 400.0 * std::sin(std::numbers::pi / 3.0) / 9.81, 1e-9);
    EXPECT_NEAR(doc["best_angle_deg"].get<double>(), 45.0, 0.05);
    EXPECT_NEAR(doc["best_range_m"].get<double>(), 400.0 / 9.81, 1e-9);
}

TEST(ChartRangeCli, DragAndHeightLowerTheBestAngle)
{
    const double drag =
        jsonOf("chart range --speed 30 --mass 4 --quadratic-drag 0.055 --from 0 --to 90 --json")["best_angle_deg"]
            .get<double>();
    EXPECT_LT(drag, 44.0);
    const auto high = jsonOf("chart range --speed 20 --y0 10 --from 0 --to 90 --step 5 --json");
    EXPECT_EQ(high["angles_deg"].size(), 19u);
    const double v = 20.0;
    const double expected = std::asin(v / std::sqrt(2.0 * (v * v + 9.81 * 10.0))) * 180.0 / std::numbers::pi;
    EXPECT_NEAR(high["best_angle_deg"].get<double>(), expected, 0.05);
}

TEST(ChartRangeCli, AFlightStillUpAtMaxTIsNull)
{
    const auto doc = jsonOf("chart range --speed 100 --from 60 --to 90 --step 30 --max-t 5 --json");
    EXPECT_TRUE(doc["ranges_m"][0].is_null());
    EXPECT_TRUE(doc["ranges_m"][1].is_null());
    EXPECT_TRUE(doc["best_angle_deg"].is_null());
    EXPECT_TRUE(doc["best_range_m"].is_null());
}

TEST(ChartRangeCli, WithoutJsonPrintsATable)
{
    const RunResult r = runAbalike("chart range --speed 20 --from 0 --to 90 --step 15");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("best angle 45.00 deg"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("40.774720"), std::string::npos) << r.out;
}

TEST(ChartRangeCli, OutDrawsAPng)
{
    const auto path = std::filesystem::temp_directory_path() / ("abalike-range-" + std::to_string(::getpid()) + ".png");
    const auto doc = jsonOf("chart range --speed 27 --mass 4 --quadratic-drag 0.055 --from 0 --to 90 --out " +
                            path.string() + " --json");
    EXPECT_FALSE(doc["best_angle_deg"].is_null()); // --out adds the picture, the JSON is still printed
    std::ifstream png(path, std::ios::binary);
    std::string signature(8, '\0');
    png.read(signature.data(), 8);
    EXPECT_EQ(signature, "\x89PNG\r\n\x1a\n");
    EXPECT_GT(std::filesystem::file_size(path), 10000u);
    std::filesystem::remove(path);
}

TEST(LessonLevelsCli, EveryLessonPassesCheckAndIsSolvable)
{
    const RunResult r = runAbalike("check --solve --player-runs 0 " + sourcePath("levels/lessons/") + "*.json");
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 9) << r.out; // one PASS line per lesson and the tutorial
}

// ------------------------------------------------------------------ simulate: energy and impact

TEST(SimulateTeachCli, EnergyAndImpactPerShot)
{
    const auto doc = jsonOf("simulate " + sourcePath("levels/3-1-tailwind.json") + " --shot 10,8 --shot 30,30 --json");
    const auto& hit = doc["shots"][1];
    const auto& energy = hit["energy"];
    std::vector<std::string> keys;
    for (const auto& item : energy.items())
        keys.push_back(item.key());
    EXPECT_EQ(keys, (std::vector<std::string>{"kinetic_j", "potential_j", "drag_loss_j", "launch_kinetic_j",
                                              "launch_potential_j"}));
    const double launch = energy["launch_kinetic_j"].get<double>() + energy["launch_potential_j"].get<double>();
    EXPECT_EQ(energy["launch_kinetic_j"], 0.5 * 4.0 * 30.0 * 30.0);
    EXPECT_NEAR(energy["kinetic_j"].get<double>() + energy["potential_j"].get<double>() +
                    energy["drag_loss_j"].get<double>(),
                launch, 1e-8 * launch);

    const auto& impact = hit["impact"];
    keys.clear();
    for (const auto& item : impact.items())
        keys.push_back(item.key());
    EXPECT_EQ(keys, (std::vector<std::string>{"t",
                                              "body",
                                              "bird_before",
                                              "bird_after",
                                              "body_before",
                                              "body_after",
                                              "body_mass_kg",
                                              "momentum_before",
                                              "momentum_after",
                                              "kinetic_before_j",
                                              "kinetic_after_j",
                                              "damage_ns",
                                              "strength_before_ns",
                                              "broke",
                                              "bird_change",
                                              "body_change",
                                              "push_on_body",
                                              "from_supports",
                                              "bird_other_contacts",
                                              "gravity",
                                              "break_through",
                                              "balance_residual",
                                              "exchanged",
                                              "partners",
                                              "handed_on"}));
    // Told as physics: the bird's change is what it got from the body (minus the exchange) and from everything
    // else it pushed (minus each partner's impulse), from the JSON alone.
    for (std::size_t i = 0; i < 2; ++i)
    {
        double pushed = impact["exchanged"][i].get<double>();
        for (const auto& partner : impact["partners"])
            pushed += partner["impulse"][i].get<double>();
        EXPECT_NEAR(impact["bird_change"][i].get<double>(), -pushed, 1e-3);
    }
    // The balance, from the JSON alone: the two changes less the pushes from outside the pair are zero.
    for (std::size_t i = 0; i < 2; ++i)
    {
        const double left = impact["bird_change"][i].get<double>() + impact["body_change"][i].get<double>() -
                            impact["from_supports"][i].get<double>() - impact["bird_other_contacts"][i].get<double>() -
                            impact["gravity"][i].get<double>() - impact["break_through"][i].get<double>();
        EXPECT_NEAR(left, impact["balance_residual"][i].get<double>(), 1e-9);
        EXPECT_LT(std::abs(left), 1e-3);
    }
    EXPECT_EQ(impact["body"]["kind"], "block");
    EXPECT_TRUE(impact["body"]["index"].is_number_integer());
    EXPECT_EQ(impact["bird_before"].size(), 2u);
    EXPECT_EQ(impact["body_before"].size(), 3u);
    EXPECT_GT(impact["damage_ns"].get<double>(), 0.0);
    EXPECT_NEAR(impact["t"].get<double>(), hit["actual_contact"]["t"].get<double>(), 1e-12);

    // A flat shot into the ground: energy, but no impact.
    const auto& ground = doc["shots"][0];
    EXPECT_EQ(ground["first_touched"], "ground");
    EXPECT_TRUE(ground["impact"].is_null());
    EXPECT_TRUE(ground["energy"].is_object());
}

TEST(SimulateTeachCli, EnergyIsNullAfterAnAbilityBeforeContact)
{
    const auto doc = jsonOf("simulate " + sourcePath("levels/4-7-hard-hats.json") + " --shot 35,20,0.3 --json");
    EXPECT_TRUE(doc["shots"][0]["energy"].is_null());
}

} // namespace
} // namespace abalike::test
