#include <abalike/level/LevelIO.hpp>
#include <abalike/teach/ShotTable.hpp>
#include <cmath>
#include <gtest/gtest.h>
#include <sstream>

namespace abalike
{
namespace
{

constexpr std::size_t kNumberColumns = 12;
constexpr std::size_t kContactActs = 12; ///< where rowsOf puts the contact_acts column (after the 12 numbers)

/// The numeric columns of every row, contact_acts last; the contact column (a name) goes to contacts when asked for.
std::vector<std::vector<double>> rowsOf(const std::string& csv, std::string& header,
                                        std::vector<std::string>* contacts = nullptr)
{
    std::istringstream in(csv);
    std::getline(in, header);
    std::vector<std::vector<double>> rows;
    for (std::string line; std::getline(in, line);)
    {
        std::vector<double> row;
        std::string contact;
        std::istringstream cells(line);
        std::size_t column = 0;
        for (std::string cell; std::getline(cells, cell, ','); ++column)
            if (column == kNumberColumns)
                contact = cell;
            else
                row.push_back(std::stod(cell));
        rows.push_back(std::move(row));
        if (contacts != nullptr)
            contacts->push_back(contact);
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
    EXPECT_EQ(header, "shot,t_s,x_m,y_m,vx_mps,vy_mps,ax_mps2,ay_mps2,speed_mps,kinetic_j,potential_j,drag_work_j,"
                      "contact,contact_acts");
    ASSERT_GT(rows.size(), 100u);
    const ShotRecord& shot = session->shots()[0];
    ASSERT_TRUE(shot.energy && shot.actualContact);
    const double launch = shot.energy->launchKineticJ + shot.energy->launchPotentialJ;
    EXPECT_DOUBLE_EQ(rows[0][9] + rows[0][10], launch);
    double lastFree = 0.0;
    for (const auto& row : rows)
    {
        ASSERT_EQ(row.size(), kNumberColumns + 1);
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

TEST(ShotTable, ARowThroughACollisionCarriesItsAccelerationAndNamesWhatWasHit)
{
    // The teacher's finding: vx went from 9.75 to -0.38 m/s between two rows while both accelerations read 0.
    const LevelDef level = loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/3-1-tailwind.json", Catalog::builtin());
    const auto session = simulateShots(level, {{30.0, 30.0}});
    std::string header;
    std::vector<std::string> contacts;
    const auto rows = rowsOf(shotTableCsv(*session), header, &contacts);
    const ShotRecord& shot = session->shots()[0];
    ASSERT_TRUE(shot.impact);
    const std::string struck = "block " + std::to_string(shot.impact->bodyIndex) + " " + shot.impact->bodyType;
    std::size_t hit = 0;
    while (hit < rows.size() && contacts[hit].empty())
        ++hit;
    ASSERT_LT(hit, rows.size());
    EXPECT_EQ(contacts[hit], struck);
    EXPECT_GE(rows[hit][1], shot.actualContact->t);
    EXPECT_LT(rows[hit][1] - 1.0 / 60.0, shot.actualContact->t) << "the row of the step the contact happened in";
    // After the free flight every row in which a contact acts is marked, and its acceleration is its velocity's
    // change over the step: dv/dt in a spreadsheet agrees with the column, through the collision too. The rows of
    // the steps around a touch are marked; only they carry differences.
    int marked = 0;
    for (std::size_t i = hit; i < rows.size(); ++i)
    {
        const bool touchedNear =
            !contacts[i].empty() || !contacts[i - 1].empty() || (i + 1 < contacts.size() && !contacts[i + 1].empty());
        EXPECT_EQ(rows[i][kContactActs], touchedNear ? 1.0 : 0.0) << "t = " << rows[i][1];
        if (rows[i][kContactActs] != 1.0)
            continue;
        ++marked;
        const double step = rows[i][1] - rows[i - 1][1];
        EXPECT_NEAR(rows[i][6], (rows[i][4] - rows[i - 1][4]) / step, 1e-6 * (1.0 + std::abs(rows[i][6])));
        EXPECT_NEAR(rows[i][7], (rows[i][5] - rows[i - 1][5]) / step, 1e-6 * (1.0 + std::abs(rows[i][7])));
    }
    EXPECT_GT(marked, 10);
    for (std::size_t i = 0; i < hit; ++i)
        EXPECT_EQ(rows[i][kContactActs], 0.0) << "the free flight: t = " << rows[i][1];
    EXPECT_LT(rows[hit][6], -100.0) << "the block stopped the bird";
    int onGround = 0;
    for (const std::string& contact : contacts)
        onGround += contact.find("ground") != std::string::npos ? 1 : 0;
    EXPECT_GT(onGround, 10) << "it rolls out on the ground";
}

TEST(ShotTable, AfterABounceTheFreeFlightIsTheModelsAndTheLastRowAWholeStep)
{
    // The teacher's findings: free fall after a contact read -9.8098 (a difference of float positions), and an
    // export's last row ay = -4.88 (a one-sided half step). In vacuum, a bird that bounces off the ground flies
    // rows of exactly -g again, and the table ends at a row whose central difference had the step after it.
    const LevelDef level =
        loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/lessons/lesson-predict.json", Catalog::builtin());
    const auto session = simulateShots(level, {{35.0, 16.0}});
    std::string header;
    std::vector<std::string> contacts;
    const auto rows = rowsOf(shotTableCsv(*session), header, &contacts);
    const ShotRecord& shot = session->shots()[0];
    ASSERT_TRUE(shot.actualContact);
    int freeAfterContact = 0;
    for (const auto& row : rows)
    {
        if (row[1] <= shot.actualContact->t || row[kContactActs] != 0.0)
            continue;
        ++freeAfterContact;
        EXPECT_EQ(row[6], 0.0) << "t = " << row[1];
        EXPECT_NEAR(row[7], -9.81, 1e-12) << "t = " << row[1];
    }
    EXPECT_GT(freeAfterContact, 0) << "the bird never flew free after its first contact: nothing was checked";
    ASSERT_FALSE(rows.empty());
    EXPECT_LT(rows.back()[1], shot.actualPath.back().timeS) << "the path's last point has no step after it";
}

} // namespace
} // namespace abalike
