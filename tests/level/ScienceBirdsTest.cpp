#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/ScienceBirds.hpp>
#include <abalike/world/Catalog.hpp>
#include <abalike/world/RestCheck.hpp>

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

namespace abalike
{
namespace
{

// A small Science Birds fort written the way Science Birds writes its files: an unclosed <Camera> and <Slingshot>,
// a rotation of 90.00001, bodies a few centimetres above what holds them (its ground is y = -3.5).
const std::string kFort = R"(<?xml version="1.0" encoding="utf-16"?>
<Level width ="2">
  <Camera x="0" y="2" minWidth="20" maxWidth="30">
  <Birds>
    <Bird type="BirdRed"/>
    <Bird type="BirdBlue"/>
    <Bird type="BirdBlack"/>
  </Birds>
  <Slingshot x="-8" y="-2.5">
  <GameObjects>
    <Block type="RectFat" material="wood" x="2.0" y="-3.075" rotation="90.00001" />
    <Block type="RectFat" material="wood" x="3.5" y="-3.05" rotation="90" />
    <Block type="RectMedium" material="ice" x="2.75" y="-2.54" rotation="0" />
    <Block type="TriangleHole" material="stone" x="2.75" y="-2.02" rotation="0" />
    <Block type="Circle" material="stone" x="5.5" y="-3.08" rotation="0" />
    <Block type="SquareHole" material="wood" x="7" y="-3.05" rotation="0" />
    <Pig type="BasicSmall" material="" x="2.75" y="-3.275" rotation="0" />
    <Pig type="BasicMedium" material="" x="7" y="-2.27" rotation="0" />
    <TNT type="" x="4.4" y="-3.2" rotation="0" />
    <Platform type="Platform" material="" x="10" y="1" rotation="0" scaleX="4" scaleY="1" />
    <Pig type="BasicBig" material="" x="10" y="1.795" rotation="0" />
  </GameObjects>
</Level>
)";

ScienceBirdsLevel import(const std::string& bytes)
{
    return importScienceBirds(bytes, "fort.xml", Catalog::builtin());
}

/// The warning about a pointer, or an empty issue.
LevelIssue warningAbout(const ScienceBirdsLevel& imported, const std::string& pointer)
{
    for (const LevelIssue& issue : imported.warnings)
        if (issue.pointer == pointer)
            return issue;
    return {};
}

std::string toUtf16(const std::string& ascii, bool bigEndian, bool bom)
{
    std::string out;
    if (bom)
        out += bigEndian ? std::string("\xFE\xFF") : std::string("\xFF\xFE");
    for (const char c : ascii)
    {
        if (bigEndian)
            out.append(1, '\0').append(1, c);
        else
            out.append(1, c).append(1, '\0');
    }
    return out;
}

std::string withCrlf(const std::string& text)
{
    std::string out;
    for (const char c : text)
        out += c == '\n' ? std::string("\r\n") : std::string(1, c);
    return out;
}

TEST(ScienceBirdsImport, MapsEveryPieceWithScienceBirdsSizesAndPutsItsGroundAtOurs)
{
    const ScienceBirdsLevel imported = import(kFort);
    const LevelDef& level = imported.level;
    EXPECT_EQ(level.id, "fort");
    EXPECT_EQ(level.birds, (std::vector<std::string>{"red", "blue", "black"}));
    EXPECT_DOUBLE_EQ(level.slingshot.x, -8.0);
    EXPECT_DOUBLE_EQ(level.slingshot.y, 1.0); // -2.5 is 1 m above Science Birds' ground
    ASSERT_EQ(level.blocks.size(), 7u);
    // RectFat 0.85 x 0.43 stood on end: 90.00001 is 90, and its centre 0.425 m up.
    EXPECT_EQ(level.blocks[0].shape, BlockShape::Box);
    EXPECT_DOUBLE_EQ(level.blocks[0].widthM, 0.85);
    EXPECT_DOUBLE_EQ(level.blocks[0].heightM, 0.43);
    EXPECT_EQ(level.blocks[0].angleDeg, 90.0);
    EXPECT_DOUBLE_EQ(level.blocks[0].y, 0.425);
    EXPECT_EQ(level.blocks[2].material, "ice");
    EXPECT_DOUBLE_EQ(level.blocks[2].widthM, 1.68);
    EXPECT_DOUBLE_EQ(level.blocks[2].y, 0.96); // on the posts: 0.85 + 0.11
    EXPECT_EQ(level.blocks[3].shape, BlockShape::Triangle);
    EXPECT_DOUBLE_EQ(level.blocks[3].widthM, 0.82);
    EXPECT_EQ(level.blocks[4].shape, BlockShape::Circle);
    EXPECT_DOUBLE_EQ(level.blocks[4].widthM, 0.8);
    EXPECT_EQ(level.blocks[5].shape, BlockShape::HollowBox);
    EXPECT_DOUBLE_EQ(level.blocks[5].widthM, 0.84);
    EXPECT_EQ(level.blocks[6].material, "tnt");
    EXPECT_DOUBLE_EQ(level.blocks[6].widthM, 0.55);
    ASSERT_EQ(level.pigs.size(), 3u);
    // Science Birds' pigs become ours of their size: 0.43, 0.76 and 0.97 m tall (assets/catalog.json).
    EXPECT_EQ(level.pigs[0].type, "sb-small");
    EXPECT_EQ(level.pigs[1].type, "sb-medium");
    EXPECT_EQ(level.pigs[2].type, "sb-large");
    EXPECT_DOUBLE_EQ(level.pigs[0].y, 0.215); // its bottom where Science Birds' 0.45 m pig has it: on the ground
    ASSERT_EQ(level.terrain.size(), 1u);
    EXPECT_DOUBLE_EQ(level.terrain[0].widthM, 0.62 * 4);
    EXPECT_DOUBLE_EQ(level.terrain[0].heightM, 0.62);
    EXPECT_DOUBLE_EQ(level.terrain[0].y, 4.5);
    EXPECT_DOUBLE_EQ(level.pigs[2].y, 5.295); // the big pig's 0.485 m half height on the platform's top at 4.81

    // What it writes is a level of ours that loads and stands.
    const LevelDef reread = parseLevel(writeLevelJson(level, ""), "fort.json", Catalog::builtin());
    EXPECT_EQ(reread.blocks.size(), 7u);
    const RestReport rest = checkRest(reread);
    EXPECT_TRUE(rest.passed()) << rest.summary();
}

TEST(ScienceBirdsImport, SnapsBodiesOntoTheirSupportsAndSaysWhereEachWas)
{
    const ScienceBirdsLevel imported = import(kFort);
    // The right post stood 2.5 cm above the ground (line 12), the circle 2 cm, the medium pig 2 cm into its box.
    const LevelIssue post = warningAbout(imported, "/blocks/1");
    EXPECT_EQ(post.line, 12);
    EXPECT_EQ(post.column, 5);
    EXPECT_EQ(post.message, "was 2.5 cm above the ground; set onto it (y = 0.425 in our level)");
    EXPECT_EQ(warningAbout(imported, "/blocks/4").message,
              "was 2.0 cm above the ground; set onto it (y = 0.4 in our level)");
    // The medium pig sank 2 cm into its box in the file (the box then came down 3 cm): the gap said is the file's.
    EXPECT_EQ(
        warningAbout(imported, "/pigs/1").message,
        "sank 2.0 cm into block 5 (wood), which Science Birds' physics pushes apart; set onto it (y = 1.22 in our "
        "level)");
    EXPECT_NE(warningAbout(imported, "/blocks/3").message.find("TriangleHole becomes a solid triangle"),
              std::string::npos);
    // A body that sits right (the left post, the small pig) gets no word.
    EXPECT_TRUE(warningAbout(imported, "/blocks/0").message.empty());
    EXPECT_TRUE(warningAbout(imported, "/pigs/0").message.empty());
}

TEST(ScienceBirdsImport, ReadsUnclosedElementsAsScienceBirdsDoesAndSaysWhere)
{
    const ScienceBirdsLevel imported = import(kFort);
    ASSERT_GE(imported.warnings.size(), 2u);
    EXPECT_EQ(imported.warnings[0].line, 3);
    EXPECT_EQ(imported.warnings[0].column, 3);
    EXPECT_EQ(imported.warnings[0].message, "<Camera> is not closed; read as <Camera .../> (as Science Birds does)");
    EXPECT_EQ(imported.warnings[1].line, 9);
    EXPECT_NE(imported.warnings[1].message.find("<Slingshot> is not closed"), std::string::npos);
}

TEST(ScienceBirdsImport, EveryEncodingAndLineEndGivesTheSameLevelAndPlaces)
{
    const ScienceBirdsLevel reference = import(kFort);
    const std::vector<std::pair<std::string, std::string>> variants = {
        {"CRLF", withCrlf(kFort)},
        {"UTF-8 BOM", "\xEF\xBB\xBF" + kFort},
        {"UTF-16LE BOM", toUtf16(withCrlf(kFort), false, true)},
        {"UTF-16BE BOM", toUtf16(kFort, true, true)},
        {"UTF-16LE", toUtf16(kFort, false, false)},
        {"UTF-16BE", toUtf16(withCrlf(kFort), true, false)},
    };
    for (const auto& [name, bytes] : variants)
    {
        const ScienceBirdsLevel imported = import(bytes);
        EXPECT_EQ(imported.level, reference.level) << name;
        ASSERT_EQ(imported.warnings.size(), reference.warnings.size()) << name;
        for (std::size_t i = 0; i < imported.warnings.size(); ++i)
        {
            EXPECT_EQ(imported.warnings[i].line, reference.warnings[i].line) << name;
            EXPECT_EQ(imported.warnings[i].column, reference.warnings[i].column) << name;
        }
    }
}

TEST(ScienceBirdsImport, AcceptsWhatScienceBirdsAcceptsWithAWarning)
{
    // Older files: a count of birds; no rotation, no material, no type on a pig; a file that ends inside <Level>.
    const ScienceBirdsLevel imported = import("<Level>\n"
                                              "  <BirdsAmount> 4 </BirdsAmount>\n"
                                              "  <Slingshot x=\"-7.5\" y=\"-2\"/>\n"
                                              "  <GameObjects>\n"
                                              "    <Block type=\"RectSmall\" x=\"2\" y=\"-3.39\"/>\n"
                                              "    <Pig x=\"2\" y=\"-3.03\"/>\n"
                                              "  </GameObjects>\n");
    const LevelDef& level = imported.level;
    EXPECT_EQ(level.birds, std::vector<std::string>(4, "red"));
    ASSERT_EQ(level.blocks.size(), 1u);
    EXPECT_EQ(level.blocks[0].material, "wood");
    EXPECT_EQ(level.blocks[0].angleDeg, 0.0);
    ASSERT_EQ(level.pigs.size(), 1u);
    EXPECT_EQ(level.pigs[0].type, "sb-small");
    EXPECT_DOUBLE_EQ(level.pigs[0].y, 0.435); // on the plank: 0.22 + 0.215
    std::string all;
    for (const LevelIssue& w : imported.warnings)
        all += std::to_string(w.line) + ":" + std::to_string(w.column) + " " + w.message + "\n";
    EXPECT_NE(all.find("5:5 <Block> has no material; read as material=\"wood\""), std::string::npos) << all;
    EXPECT_NE(all.find("5:5 <Block> has no rotation; read as rotation=\"0\""), std::string::npos) << all;
    EXPECT_NE(all.find("6:5 <Pig> has no type; read as type=\"BasicSmall\""), std::string::npos) << all;
    EXPECT_NE(all.find("the file ends before its elements are closed"), std::string::npos) << all;

    const ScienceBirdsLevel bare = import("<Level><GameObjects><Pig type=\"BasicSmall\" x=\"2\" y=\"-3.25\"/>"
                                          "</GameObjects></Level>");
    EXPECT_EQ(bare.level.birds, std::vector<std::string>(3, "red"));
    EXPECT_DOUBLE_EQ(bare.level.slingshot.x, -8.0);
    EXPECT_DOUBLE_EQ(bare.level.slingshot.y, 1.0);
}

TEST(ScienceBirdsImport, ReadsADecimalCommaAsScienceBirdsDoesInALanguageThatWritesOne)
{
    const ScienceBirdsLevel imported = import("<Level>\n<Slingshot x=\"-8\" y=\"-2,5\"/>\n<GameObjects>\n"
                                              "<Pig type=\"BasicSmall\" x=\"2\" y=\"-3.25\"/>\n"
                                              "</GameObjects></Level>");
    EXPECT_DOUBLE_EQ(imported.level.slingshot.y, 1.0);
    EXPECT_EQ(warningAbout(imported, "/slingshot").message,
              "<Slingshot> y=\"-2,5\" has a decimal comma; read as y=\"-2.5\" (as Science Birds does on a machine "
              "whose language writes decimal commas)");
}

TEST(ScienceBirdsImport, LeavesBodiesFarFromTheirSupportForTheRestCheck)
{
    // 30 cm above the ground is not how Science Birds places things: the import leaves it there, and says so.
    const ScienceBirdsLevel imported = import("<Level><GameObjects>\n"
                                              "<Block type=\"SquareSmall\" material=\"stone\" x=\"2\" y=\"-2.985\" "
                                              "rotation=\"0\"/>\n"
                                              "<Pig type=\"BasicSmall\" x=\"5\" y=\"-3.25\"/>\n"
                                              "</GameObjects></Level>");
    EXPECT_DOUBLE_EQ(imported.level.blocks[0].y, 0.515);
    EXPECT_EQ(warningAbout(imported, "/blocks/0").message,
              "is 30.0 cm above the ground, more than the 20.0 cm the import closes: left where it is (abalike check "
              "reports it)");
}

TEST(ScienceBirdsImport, GapsUpATowerDoNotAddUp)
{
    // Six stone boxes 0.43 m high, each written 2 cm above the one under it (Science Birds' generator spacing): the
    // top one is 12 cm above where it ends, yet each gap in the file is 2 cm, so every box is set down and the
    // tower stands.
    std::string xml = "<Level><GameObjects>\n";
    for (int i = 0; i < 6; ++i)
        xml += "<Block type=\"SquareSmall\" material=\"stone\" x=\"2\" y=\"" +
               shortestNumber(-3.5 + 0.215 + 0.02 + i * 0.45) + "\" rotation=\"0\"/>\n";
    xml += "<Pig type=\"BasicSmall\" x=\"5\" y=\"-3.25\"/>\n</GameObjects></Level>";
    const ScienceBirdsLevel imported = import(xml);
    ASSERT_EQ(imported.level.blocks.size(), 6u);
    for (int i = 0; i < 6; ++i)
        EXPECT_NEAR(imported.level.blocks[static_cast<std::size_t>(i)].y, 0.215 + i * 0.43, 1e-9) << "box " << i;
    EXPECT_EQ(warningAbout(imported, "/blocks/5").message,
              "was 2.0 cm above block 4 (stone); set onto it (y = 2.365 in our level)");
    const RestReport rest = checkRest(imported.level);
    EXPECT_TRUE(rest.passed()) << rest.summary();
}

TEST(ScienceBirdsImport, OverlapsAndBodiesInTheGroundArePushedOutAsScienceBirdsDoes)
{
    // A plank sunk 15 cm into a box, a box 30 cm into the ground, a pig wholly below it: Science Birds' physics
    // pushes each out at once; the import sets each onto what it overlaps, and says how deep it was.
    const ScienceBirdsLevel imported =
        import("<Level><GameObjects>\n"
               "<Block type=\"SquareSmall\" material=\"wood\" x=\"2\" y=\"-3.585\" rotation=\"0\"/>\n"
               "<Block type=\"RectSmall\" material=\"wood\" x=\"2\" y=\"-3.005\" rotation=\"0\"/>\n"
               "<Pig type=\"BasicSmall\" x=\"6\" y=\"-4.5\"/>\n"
               "</GameObjects></Level>");
    EXPECT_DOUBLE_EQ(imported.level.blocks[0].y, 0.215);
    EXPECT_DOUBLE_EQ(imported.level.blocks[1].y, 0.54);
    EXPECT_DOUBLE_EQ(imported.level.pigs[0].y, 0.215);
    EXPECT_EQ(warningAbout(imported, "/blocks/0").message,
              "reaches 30.0 cm below the ground, which pushes it out in Science Birds; set onto the ground (y = 0.215 "
              "in our level)");
    EXPECT_EQ(warningAbout(imported, "/pigs/0").message,
              "reaches 122.5 cm below the ground, which pushes it out in Science Birds; set onto the ground (y = 0.215 "
              "in our level)");
    const RestReport rest = checkRest(imported.level);
    EXPECT_TRUE(rest.passed()) << rest.summary();
}

TEST(ScienceBirdsImport, PigsSunkIntoPigsArePushedApartAsItsPhysicsDoes)
{
    // Science Birds' demo level 3 piles pigs: two side by side, one on them sunk 10 cm in, and a pair that overlap
    // at the same height. Its physics pushes them apart at once; the import does it: the top pig is lifted clear of
    // the two under it, the pair moved apart sideways, each on the millimetre and with a located warning.
    const ScienceBirdsLevel imported = import("<Level><GameObjects>\n"
                                              "<Pig type=\"BasicSmall\" x=\"2\" y=\"-3.275\"/>\n"
                                              "<Pig type=\"BasicSmall\" x=\"2.5\" y=\"-3.275\"/>\n"
                                              "<Pig type=\"BasicSmall\" x=\"2.25\" y=\"-2.95\"/>\n"
                                              "<Pig type=\"BasicSmall\" x=\"6\" y=\"-3.275\"/>\n"
                                              "<Pig type=\"BasicSmall\" x=\"6.3\" y=\"-3.275\"/>\n"
                                              "</GameObjects></Level>");
    const std::vector<PigDef>& pigs = imported.level.pigs;
    ASSERT_EQ(pigs.size(), 5u);
    // Resting on both: centres 0.5 m apart, so its centre is sqrt(0.43^2 - 0.25^2) = 0.350 m above theirs.
    EXPECT_DOUBLE_EQ(pigs[2].x, 2.25);
    EXPECT_NEAR(pigs[2].y, 0.215 + 0.350, 0.0015);
    EXPECT_DOUBLE_EQ(pigs[4].y, 0.215);
    EXPECT_NEAR(pigs[4].x, 6.43, 0.0015);
    const LevelIssue lifted = warningAbout(imported, "/pigs/2");
    EXPECT_EQ(lifted.line, 4);
    EXPECT_NE(lifted.message.find("which Science Birds' physics pushes apart; lifted"), std::string::npos)
        << lifted.message;
    EXPECT_NE(warningAbout(imported, "/pigs/4").message.find("cm right (x = 6.43"), std::string::npos)
        << warningAbout(imported, "/pigs/4").message;
    for (const LevelIssue& issue : checkLevelGeometry(imported.level, Catalog::builtin()))
        EXPECT_EQ(issue.message.find("overlaps"), std::string::npos) << issue.message;
}

TEST(ScienceBirdsImport, PlatformsOfNegativeScaleAreMirroredAndOfZeroScaleLeftOut)
{
    const ScienceBirdsLevel imported = import("<Level><GameObjects>\n"
                                              "<Platform x=\"4\" y=\"0\" scaleX=\"-2\" scaleY=\"1\"/>\n"
                                              "<Platform x=\"8\" y=\"0\" scaleX=\"0\" scaleY=\"1\"/>\n"
                                              "<Pig type=\"BasicSmall\" x=\"4\" y=\"0.56\"/>\n"
                                              "</GameObjects></Level>");
    ASSERT_EQ(imported.level.terrain.size(), 1u);
    EXPECT_DOUBLE_EQ(imported.level.terrain[0].widthM, 1.24);
    std::string all;
    for (const LevelIssue& w : imported.warnings)
        all += std::to_string(w.line) + ":" + std::to_string(w.column) + " " + w.message + "\n";
    EXPECT_NE(all.find("2:1 <Platform> has a negative scale (scaleX=\"-2\" scaleY=\"1\"): Science Birds mirrors it "
                       "and keeps its size; read as 2 by 1 tiles"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("3:1 <Platform> has scaleX=\"0\" scaleY=\"1\": no size, so nothing in Science Birds rests on "
                       "it; left out"),
              std::string::npos)
        << all;
}

TEST(ScienceBirdsImport, APlatformTooThinToSimulateGrowsDownwardsUnderWhatItHolds)
{
    // Phy-Q draws ledges 0.15 tiles thick (9.3 cm): our loader refuses a static body under 10 cm, so the importer
    // makes it 10 cm with its top where it was, and the pig on it stays on it.
    const ScienceBirdsLevel imported = import("<Level><GameObjects>\n"
                                              "<Platform x=\"4\" y=\"0\" scaleX=\"3\" scaleY=\"0.15\"/>\n"
                                              "<Pig type=\"BasicSmall\" x=\"4\" y=\"0.2715\"/>\n"
                                              "</GameObjects></Level>");
    ASSERT_EQ(imported.level.terrain.size(), 1u);
    const TerrainDef& ledge = imported.level.terrain[0];
    EXPECT_DOUBLE_EQ(ledge.heightM, 0.1);
    EXPECT_NEAR(ledge.y + 0.5 * ledge.heightM, imported.level.pigs.at(0).y - 0.215, 1e-9) << "its top where it was";
    EXPECT_EQ(warningAbout(imported, "/terrain/0").message,
              "<Platform> is 9.3 cm thick, less than the 10 cm a static body needs to simulate well: made 10 cm, "
              "growing downwards (its top where it was)");
    EXPECT_TRUE(checkRest(imported.level).passed());
}

TEST(ScienceBirdsImport, AGapJustOverTheSnapReadsAsMoreThanIt)
{
    // Positions are read to the millimetre: a box written 20.06 cm up is 20.1 cm up, never "20.0 cm ... more than
    // the 20.0 cm".
    const ScienceBirdsLevel imported = import("<Level><GameObjects>\n"
                                              "<Block type=\"SquareSmall\" material=\"stone\" x=\"2\" y=\"-3.0844\" "
                                              "rotation=\"0\"/>\n"
                                              "<Pig type=\"BasicSmall\" x=\"5\" y=\"-3.25\"/>\n"
                                              "</GameObjects></Level>");
    EXPECT_EQ(warningAbout(imported, "/blocks/0").message,
              "is 20.1 cm above the ground, more than the 20.0 cm the import closes: left where it is (abalike check "
              "reports it)");
}

/// The one error importing text gives, as "LINE:COL message".
std::string importErrorOf(const std::string& bytes)
{
    try
    {
        import(bytes);
    }
    catch (const LevelLoadError& e)
    {
        std::string text;
        for (const LevelIssue& issue : e.issues())
            text += std::to_string(issue.line) + ":" + std::to_string(issue.column) + " " + issue.message + "\n";
        return text;
    }
    return "no error";
}

TEST(ScienceBirdsImport, RefusesWhatScienceBirdsCannotLoadWithItsPlace)
{
    const std::string head = "<Level>\n<GameObjects>\n";
    EXPECT_EQ(
        importErrorOf(head + "  <Block type=\"RectHuge\" material=\"wood\" x=\"1\" y=\"-3\"/>\n</GameObjects></Level>"),
        "3:3 <Block type=\"RectHuge\"> is not one of Science Birds' 12 blocks (expected one of SquareHole, RectFat, "
        "SquareSmall, SquareTiny, RectTiny, RectSmall, RectMedium, RectBig, Circle, CircleSmall, Triangle, "
        "TriangleHole)\n");
    EXPECT_EQ(
        importErrorOf(head + "<Block type=\"RectSmal\" material=\"wood\" x=\"1\" y=\"-3\"/></GameObjects></Level>"),
        "3:1 <Block type=\"RectSmal\"> is not one of Science Birds' 12 blocks (did you mean \"RectSmall\"?)\n");
    EXPECT_EQ(importErrorOf(head + "<Blok type=\"RectSmall\" x=\"1\" y=\"-3\"/></GameObjects></Level>"),
              "3:1 <Blok> is not a Science Birds object (did you mean <Block>?)\n");
    // Phy-Q's and NovPhy's novelty objects have nothing to become: refused, by name, where they are.
    EXPECT_EQ(importErrorOf(head + "<Pig type=\"BasicSmall\" x=\"1\" y=\"-3.25\"/>\n<NoveltyObject x=\"1\" "
                                   "y=\"-3\"/></GameObjects></Level>"),
              "4:1 <NoveltyObject> is not one of Science Birds' standard objects (Block, Pig, TNT, Platform): a "
              "novelty object (as Phy-Q's and NovPhy's levels add) has nothing to become here\n");
    EXPECT_EQ(
        importErrorOf(head + "<Block type=\"RectBig\" material=\"glass\" x=\"1\" y=\"-3\"/></GameObjects></Level>"),
        "3:1 <Block material=\"glass\"> is not a Science Birds material (expected wood, ice or stone)\n");
    EXPECT_EQ(importErrorOf(head + "<Pig type=\"BasicSmall\" x=\"1,5,0\" y=\"-3\"/></GameObjects></Level>"),
              "3:1 <Pig> x=\"1,5,0\" is not a number (expected e.g. x=\"1.5\")\n");
    EXPECT_EQ(importErrorOf(head + "<Pig type=\"BasicSmall\" y=\"-3\"/></GameObjects></Level>"),
              "3:1 <Pig> has no x (expected a number, e.g. x=\"1.5\")\n");
    EXPECT_EQ(importErrorOf(head + "<Pig type=\"BasicTiny\" x=\"1\" y=\"-3\"/></GameObjects></Level>"),
              "3:1 <Pig type=\"BasicTiny\"> is not a Science Birds pig (did you mean \"BasicBig\"?)\n");
    EXPECT_EQ(importErrorOf("<Level>\n<Birds><Bird type=\"BirdGreen\"/></Birds>\n<GameObjects/></Level>"),
              "2:8 <Bird type=\"BirdGreen\"> is not a Science Birds bird (expected one of BirdBlack, BirdBlue, "
              "BirdRed, BirdWhite, BirdYellow)\n");
    EXPECT_EQ(importErrorOf("<Level>\n<Birds><Bird type=\"BirdYelow\"/></Birds>\n<GameObjects/></Level>"),
              "2:8 <Bird type=\"BirdYelow\"> is not a Science Birds bird (did you mean \"BirdYellow\"?)\n");
    EXPECT_EQ(importErrorOf("<Level>\n<GameObjects>\n</Level>\n<Pig/>"),
              "3:3 not well-formed XML: Start-end tags mismatch\n");
    EXPECT_EQ(importErrorOf("<Levels/>"), "1:1 not a Science Birds level (expected a <Level> element)\n");
    EXPECT_EQ(importErrorOf(head + "<Pig type=\"BasicSmall\" x=\"1e9\" y=\"-3\"/></GameObjects></Level>"),
              "3:1 <Pig> x=\"1e9\" is outside the world (at most 2000 from the origin)\n");
    EXPECT_EQ(importErrorOf("<Level>\n<BirdsAmount>many</BirdsAmount>\n<GameObjects/></Level>"),
              "2:1 <BirdsAmount> is \"many\" (expected a whole number of birds from 1 to 20)\n");
    // A level of ours needs a pig: the refusal names --sandbox, the way to open a structure anyway.
    EXPECT_EQ(importErrorOf(
                  "<Level>\n<GameObjects>\n<Block type=\"RectSmall\" x=\"1\" y=\"-3.39\"/>\n</GameObjects></Level>"),
              "2:1 the file has no <Pig>, and a level without a pig cannot be won: import it with --sandbox to open "
              "the structure in the editor as a sandbox scene\n");
}

TEST(ScienceBirdsImport, RefusesBytesThatAreNotText)
{
    EXPECT_EQ(importErrorOf(std::string("\xFF\xFE<\0L\0x", 7)),
              "0:0 UTF-16 text with an odd number of bytes at byte 6 (expected UTF-8 or UTF-16 text)\n");
    EXPECT_EQ(importErrorOf(std::string("\xFF\xFE<\0\x00\xD8L\0", 8)),
              "0:0 a lone UTF-16 surrogate at byte 4 (expected UTF-8 or UTF-16 text)\n");
}

} // namespace
} // namespace abalike

namespace abalike
{
namespace
{

TEST(ScienceBirdsImport, ACorpusInBothConventionsImportsToLevelsThatStand)
{
    // tests/level/science-birds/: files made by the project the way Science Birds' generator writes them (its ground
    // at y = -3.5) and the way its hand-made levels are (their ground 0.7 m higher), and phy-q/: three real Phy-Q
    // task templates (MIT; the rest of the real corpus is measured in docs/science-birds-corpus.md). Every one
    // imports to a level that stands without edits; the hand-made ones are read with their own ground, and one
    // warning says so; a structure without pigs imports as a sandbox scene.
    const std::filesystem::path folder = std::filesystem::path(ABALIKE_SOURCE_DIR) / "tests/level/science-birds";
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    {
        if (entry.path().extension() != ".xml")
            continue;
        ++files;
        const std::string name = entry.path().filename().string();
        SCOPED_TRACE(name);
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const bool hasPigs = bytes.find("<Pig") != std::string::npos;
        const ScienceBirdsLevel imported =
            importScienceBirds(bytes, name, Catalog::builtin(), ScienceBirdsOptions{!hasPigs});
        EXPECT_EQ(imported.level.sandbox, !hasPigs);
        const RestReport rest = checkRest(imported.level);
        EXPECT_TRUE(rest.passed()) << rest.summary();
        std::size_t ownGround = 0;
        for (const LevelIssue& warning : imported.warnings)
            ownGround += warning.message.find("read with a ground of its own at y = -2.78") != std::string::npos;
        EXPECT_EQ(ownGround, name.rfind("handmade-", 0) == 0 ? 1u : 0u);
        EXPECT_FALSE(imported.level.blocks.empty());
    }
    EXPECT_GE(files, 5u);
    // Without --sandbox a structure with no pig is refused, with the reason.
    std::ifstream in(folder / "handmade-structure.xml", std::ios::binary);
    const std::string structure{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_THROW(importScienceBirds(structure, "handmade-structure.xml", Catalog::builtin()), LevelLoadError);
}

} // namespace
} // namespace abalike
