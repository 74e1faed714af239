// The typed values of the document's edits: which part of the document an
// edit changes and that part's value before and after (or, for a load, the
// whole document before and after). Plain data: explore/edits.h applies them.
#pragma once

#include "scene/scene.h"

#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace m3055::explore {

// The object index of the A/B compare's material B in a MaterialEdit.
inline constexpr int kMaterialB = -1;

struct MaterialEdit {
    int object;  // an index into scene.objects, or kMaterialB
    Material before, after;
    int group = -1;  // a model file's material of a mesh (Object::groups), -1: the object's own
};
struct LightEdit {
    int index;
    Light before, after;
};
// The whole list of lights: a preset, a light added or removed (at most kMaxLights).
struct LightListEdit {
    std::vector<Light> before, after;
};
struct ObjectEdit {
    int index;
    Object before, after;
};
struct ObjectInsert {
    int index;
    Object object;
};
struct ObjectErase {
    int index;
    Object object;
};
struct CameraEdit {
    Camera before, after;
};
struct DisplayEdit {
    Display before, after;
};
struct BackgroundEdit {
    dvec3 before, after;
};

// What a load replaces: everything but the history.
struct DocumentContent {
    Scene scene;
    Material material_b;
    bool b_edited = false;
    Camera camera_home;
    std::string name, file;
};
// A load, a figure preset, a share link, a value set by its JSON path: the document replaced.
struct DocumentEdit {
    std::shared_ptr<const DocumentContent> before, after;
};

using EditValue = std::variant<MaterialEdit, LightEdit, LightListEdit, ObjectEdit, ObjectInsert, ObjectErase,
                               CameraEdit, DisplayEdit, BackgroundEdit, DocumentEdit>;

struct Edit {
    EditValue value;
    // The edit's own name ("add cube", "orbit camera", "figure preset fig05");
    // empty: named after what differs ("objects[0].material.m 10 -> 40").
    std::string action;
};

}  // namespace m3055::explore
