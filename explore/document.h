// The document: what the user edits, saves and undoes. The scene, the A/B
// compare's material B, where the scene came from, its undo history and its
// revision. It changes only through explore/edits.h (one typed edit at a
// time, each with its value before and after), so "unsaved edits" is a
// comparison of revision numbers, never of the scene's contents.
#pragma once

#include "explore/history.h"
#include "scene/scene.h"

#include <cstdint>
#include <map>
#include <string>

namespace m3055::explore {

struct Document {
    Scene scene;             // what is rendered and saved
    Material material_b;     // the A/B compare's B (the selected object wears it in B's pane)
    bool b_edited = false;   // B set by the user since the scene: the split keeps it
    Camera camera_home;      // R / "Reset" goes back to this (the loaded scene's camera)
    std::string name = "default";  // shown in the title bar
    std::string file;        // the file the scene came from or was saved to ("" for presets): Ctrl+S

    History history;
    // Every edit gives the document a revision it never had before; undo and
    // redo go back to the revision a step started or ended at.
    std::uint64_t revision = 0;
    std::uint64_t last_revision = 0;
    // The revision each file held when last loaded or saved here (key: its
    // path; a scene without a file: "\n" + its name, e.g. a figure preset).
    std::map<std::string, std::uint64_t> saved_revisions;
};

// The selected object's material in `doc`, clamping `selected` to the objects (nullptr with none).
Material* material_of(Document& doc, int& selected);

// The document is not what its file (or, without one, its origin) held when last loaded or saved here.
bool unsaved(const Document& doc);
// What the document is saved as: its file, or "\n" + its name without one.
std::string saved_key(const Document& doc);
// The document as it is now is what its file (or origin) holds.
void mark_saved(Document& doc);
// "NAME" or "NAME * (unsaved edits)" for the title bar.
std::string title_name(const Document& doc);

}  // namespace m3055::explore
