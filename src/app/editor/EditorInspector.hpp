#pragma once

#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/SlingshotBand.hpp>
#include <map>
#include <string>
#include <vector>

namespace abalike::app
{

struct EditorContext;
class PlayTest;
class SceneDrawing;

/// The inspector on the right: the selected objects' fields, the bird and the launch (while playing, the play's
/// controls), the air, the materials, the level's own fields and the checks. Every edit goes to the scene as one
/// undoable step, merged while a widget is held.
class EditorInspector
{
public:
    EditorInspector(EditorContext& context, PlayTest& play, const SceneDrawing& drawing)
        : m_ctx(context), m_play(play), m_drawing(drawing)
    {
    }

    void panel();
    /// Adds a bird of the catalog's to the end of the launch order as one undoable edit (the palette's birds); says
    /// why in the status line when the level already has as many as it may.
    void addBird(const std::string& name);

private:
    void selectionTab();
    /// A multi-selection's common block fields (material, size, angle), edited for all at once.
    void multiSelectionFields(const std::vector<ObjectRef>& selection);
    void environmentTab();
    void birdTab();
    void birdListAndSlingshot(LevelDef& next);
    /// The sliders of a level's own band, starting from the band it has now.
    void ownBandSliders(LevelDef& next, const BandDef& band);
    void materialsTab();
    void levelTab();
    void checksTab();
    /// Applies edited level properties as one undoable edit (merged while a widget is held); says why if refused.
    void setProperties(const LevelDef& properties, const char* label, const char* mergeKey);
    /// Ends the gesture when the last widget was let go.
    void endGestureIfReleased();

    EditorContext& m_ctx;
    PlayTest& m_play;
    const SceneDrawing& m_drawing;
    std::map<unsigned, std::string> m_textFields; ///< text being typed into the level's fields
};

} // namespace abalike::app
