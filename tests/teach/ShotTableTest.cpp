#include <abalike/level/LevelIO.hpp>
#include <abalike/teach/ShotTable.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <sstream>

namespace abalike
{
namespace
{

std::vector<std::vector<double>> rowsOf(const std::string& csv, std::string& header)
{
    std::istringstream in(csv);
    std::getline(in, header);
    std::vector<std::vector<double>> rows;
    for (std::string line; std::getline(in, line);)
    {
        std::vector<double> row;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');)
            row.push_back(std::stod(cell));
        rows.push_back(std::move(row));
    }
    return rows;
}

TEST(ShotTable, EnergyCloseToTheLaunchsAlongTheFreeFlightWithDrag)
{
    const LevelDef level =
        loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/3-2-thick-air.json", Catalog::builtin());
    const auto session = simulateShots(level, {{40.0, 25.0}});
    std::string header;
    const auto rows = rowsOf(shotTableCsv(*session), header);
    EXPECT_EQ(header, "shot,t_s,x_m,y_m,vx_mps,vy_mps,ax_mps2,ay_mps2,speed_mps,kinetic_j,potential_j,drag_work_j");
    ASSERT_GT(rows.size(), 100u);
    const ShotRecord& shot = session->shots()[0];
    ASSERT_TRUE(shot.energy && shot.actualContact);
    const double launch = shot.energy->launchKineticJ + shot.energy->launchPotentialJ;
    EXPECT_DOUBLE_EQ(rows[0][9] + rows[0][10], launch);
    double lastFree = 0.0;
    for (const auto& row : rows)
    {
        ASSERT_EQ(row.size(), 12u);
        EXPECT_EQ(row[0], 1.0);
        EXPECT_NEAR(row[8], std::hypot(row[4], row[5]), 1e-6);
        if (row[1] > shot.actualContact->t - 2.0 / 60.0)
            continue;
        // Kinetic + potential + the work against the air = the launch's energy: the RK4 flight's own balance.
        EXPECT_NEAR(row[9] + row[10] + row[11], launch, 1e-6 * launch) << "t = " << row[1];
        lastFree = row[11];
    }
    // By the first contact the air took what simulate --json's energy balance says (drag_loss_j), to 2 %.
    EXPECT_NEAR(lastFree, shot.energy->dragLossJ, 0.02 * shot.energy->dragLossJ);
    EXPECT_GT(lastFree, 600.0);
}

TEST(ShotTable, FreeFlightRowsAreTheExactFlightNotRoundedDifferences)
{
    // In vacuum the acceleration before the first contact is (0, -g) exactly, and x grows by vx dt every row: no
    // float rounding of the world's positions leaks into a teacher's spreadsheet.
    const LevelDef level =
        loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/lessons/lesson-predict.json", Catalog::builtin());
    const auto session = simulateShots(level, {{35.0, 16.0}});
    std::string header;
    const auto rows = rowsOf(shotTableCsv(*session), header);
    const ShotRecord& shot = session->shots()[0];
    ASSERT_TRUE(shot.actualContact);
    const double vx = 16.0 * std::cos(35.0 * M_PI / 180.0);
    int free = 0;
    for (const auto& row : rows)
    {
        if (row[1] >= shot.actualContact->t)
            break;
        ++free;
        EXPECT_EQ(row[6], 0.0) << "t = " << row[1];
        EXPECT_NEAR(row[7], -9.81, 1e-8) << "t = " << row[1];
        EXPECT_NEAR(row[2], vx * row[1], 1e-7) << "t = " << row[1];
        EXPECT_NEAR(row[4], vx, 1e-7); // the CSV keeps 10 digits
    }
    EXPECT_GT(free, 100);
}

} // namespace
} // namespace abalike
