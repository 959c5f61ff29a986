#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/RestCheck.hpp>

#include <filesystem>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

TEST(CastleParts, EveryPartIsASandboxSceneThatStandsAndInsertsWhole)
{
    // levels/parts/: the campaign's prefabs (tools/levelgen/parts.py) as the editor's Insert > Castle parts lists them.
    const std::filesystem::path folder = std::filesystem::path(ABALIKE_SOURCE_DIR) / "levels" / "parts";
    std::size_t parts = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
    {
        if (entry.path().extension() != ".json")
            continue;
        ++parts;
        SCOPED_TRACE(entry.path().filename().string());
        const LevelDef part = loadLevel(entry.path().string(), Catalog::builtin());
        EXPECT_TRUE(part.sandbox);
        EXPECT_FALSE(part.blocks.empty());
        EXPECT_TRUE(checkRest(part).passed()) << checkRest(part).summary();
        // Inserted into an empty scene at x = 30 on the ground, every body comes along.
        LevelDef scene;
        scene.id = "scene";
        scene.title = "Scene";
        scene.sandbox = true;
        scene.birds = {"red"};
        SceneEditor editor(scene);
        ASSERT_EQ(editor.insertBodies(part, Vec2{30.0, 0.0}, "Insert"), "");
        EXPECT_EQ(editor.level().blocks.size(), part.blocks.size());
        EXPECT_EQ(editor.level().pigs.size(), part.pigs.size());
    }
    EXPECT_GE(parts, 12u) << "frames, towers, pyramids, columns, cages, gates, castles, keeps, fortresses ...";
}

} // namespace
} // namespace abalike
