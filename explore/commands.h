// What the user asks of the explorer, as values: the widgets, the keys, the
// --script and the page all push these onto one queue, and the frame loop
// applies them in order (explore/apply.h), each through one function. Edits
// of the document become typed edits there (explore/edits.h), named and
// undoable; the rest act on the view, the session or the files. Read-outs of
// the displays (a probe, a profile) wait until the displays are drawn.
#pragma once

#include "explore/edit_values.h"
#include "scene/presets.h"
#include "scene/scene.h"

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace m3055::explore::command {

// ---- The document (one undo step each, or one per drag) -------------------------------
struct SetMaterial {  // the selected object's (or B's) material becomes `value`
    int object;       // an object index, or kMaterialB
    Material value;
    std::string action;  // a button's own name ("rescale weights to eq. 14"), else named after what differs
    int group = -1;      // a mesh's material from its model file, by index (Object::groups); -1: the object's
};
struct SetLight {
    int index;
    Light value;
};
struct ApplyLightPreset {
    LightPreset preset;
};
struct AddLight {};  // a copy of the single-key light, up to kMaxExplorerLights
struct RemoveLight {
    int index;
};
struct SetObject {
    int index;
    Object value;
};
struct AddObject {  // beside the others (a plane: a floor under all)
    Shape shape = Shape::sphere;
};
struct RemoveObject {  // at least one object stays
    int index;
};
// Shift+drag on the display: the selected object follows the mouse in the
// plane through it facing the camera (window units, y down; the display's
// height on screen in the same units).
struct MoveObjectInView {
    double dx, dy, shown_height;
};
struct SetCamera {
    Camera value;
};
struct OrbitCamera {  // a drag on the display, in pixels
    double dx, dy;
};
struct ZoomCamera {  // wheel steps
    double steps;
};
struct ResetCamera {};
struct SetDisplay {
    Display value;
    std::string action;  // "display M3055", "display modern"; empty: named after what differs
};
struct SetBackground {
    dvec3 value;
};
// Any scene value by its JSON path, validated like a load (--script's `set`).
struct SetSceneValue {
    std::string path, value;
};
struct CopyAToB {};
// The selected paper metal as a measured metal, F(lambda, 0) as A and the
// full eq. 19 as B, the split on (docs/spec.md#72-measured-metals).
struct CompareFresnel {};
struct LoadScene {
    std::string path;
    bool error_dialog = false;  // a failed load also shows in a dialog (a drop: where the user looks)
};
struct LoadFigure {  // "fig05" ... "fig13", "spec_example"
    std::string name;
};
struct OpenBrdf {  // a .brdf file on the selected object
    std::string path;
};
struct AddModel {  // an .obj, .gltf or .glb file as a mesh standing on the floor (explore/add_model.h)
    std::string path;
    bool error_dialog = false;  // a failed add also shows in a dialog (a drop)
};
struct Undo {};
struct Redo {};

// ---- Files and the session -------------------------------------------------------------
struct Save {};  // Ctrl+S: to the scene's own file, or Save As
struct SaveAs {  // the Save As dialog's Save: an existing other file only when asked twice
    std::string path;
};
struct SaveTo {  // --script's `save PATH`: at once
    std::string path;
};
struct AskSaveAs {};
struct AskQuit {};  // Esc, closing the window: asks first when there are unsaved edits
struct Quit {};

// ---- The view ----------------------------------------------------------------------------
struct SelectObject {
    int index;
};
struct SelectLight {
    int index;
};
struct SetCompare {  // the A/B split; a B not set yet becomes a copy of A
    bool on;
};
struct TogglePanels {};  // F1

// ---- Read-outs of the displays, answered once they are drawn ----------------------------
struct Probe {  // print the pixel probe of display pixel (x, y)
    int x, y;
};
struct Pick {  // select the object under display pixel (x, y)
    int x, y;
};
struct PrintCompare {};
struct PrintProfile {};
struct SaveDifference {
    std::string path;
};
struct PrintGrade {};
struct SaveDisplay {  // A's pixels as the window shows them now: a preview, or the render's once refined
    std::string path;
};
struct Screenshot {  // the display and its scene JSON ("": the next free NAME-0001.png)
    std::string path;
};

}  // namespace m3055::explore::command

namespace m3055::explore {

using DisplayRequest = std::variant<command::Probe, command::Pick, command::PrintCompare, command::PrintProfile,
                                    command::SaveDifference, command::PrintGrade, command::Screenshot,
                                    command::SaveDisplay>;

using Command = std::variant<
    command::SetMaterial, command::SetLight, command::ApplyLightPreset, command::AddLight, command::RemoveLight,
    command::SetObject, command::AddObject, command::RemoveObject, command::MoveObjectInView, command::SetCamera,
    command::OrbitCamera, command::ZoomCamera, command::ResetCamera, command::SetDisplay, command::SetBackground,
    command::SetSceneValue, command::CopyAToB, command::CompareFresnel, command::LoadScene, command::LoadFigure,
    command::OpenBrdf, command::AddModel, command::Undo, command::Redo, command::Save, command::SaveAs, command::SaveTo,
    command::AskSaveAs, command::AskQuit, command::Quit, command::SelectObject,
    command::SelectLight, command::SetCompare, command::TogglePanels, DisplayRequest>;

// The commands of a frame, in the order they were given.
class CommandQueue {
public:
    void push(Command command) { queue_.push_back(std::move(command)); }
    bool empty() const { return queue_.empty(); }
    std::vector<Command> take() { return std::exchange(queue_, {}); }

private:
    std::vector<Command> queue_;
};

}  // namespace m3055::explore
