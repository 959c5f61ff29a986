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
        // Kinetic + potential + the work against the air = the launch's energy, to 0.01 %.
        EXPECT_NEAR(row[9] + row[10] + row[11], launch, 1e-4 * launch) << "t = " << row[1];
        lastFree = row[11];
    }
    // By the first contact the air took what simulate --json's energy balance says (drag_loss_j), to 2 %.
    EXPECT_NEAR(lastFree, shot.energy->dragLossJ, 0.02 * shot.energy->dragLossJ);
    EXPECT_GT(lastFree, 600.0);
}

} // namespace
} // namespace abalike
