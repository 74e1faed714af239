#include "explore_ui/shape_editor.h"

#include "explore_ui/narrow_panel.h"

#include "explore_ui/widgets.h"
#include "geometry/mesh.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace m3055::explore {

namespace {

// A direction edited as three numbers; kept unit and non-zero.
bool direction_edit(const char* label, dvec3* direction) {
    double v[3] = {direction->x, direction->y, direction->z};
    if (!ImGui::DragScalarN(field(label).c_str(), ImGuiDataType_Double, v, 3, 0.01f)) return false;
    const dvec3 d(v[0], v[1], v[2]);
    const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(length > 1e-6)) return false;  // docs/spec.md#7-scene-files: non-zero
    *direction = d / length;
    return true;
}

}  // namespace

bool shape_editor(Object& o) {
    bool changed = false;
    int current = static_cast<int>(o.shape);
    if (o.shape == Shape::mesh) {
        // A model file's mesh keeps its shape and file here; its size and rotation are edited below.
        ImGui::TextUnformatted(("mesh: " + o.file).c_str());
        tooltip("A model file (docs/shapes.md#meshes-from-files): its bounding box centred on the centre, its "
                "largest side the size, then rotated as a cube.");
    } else if (ImGui::Combo(field("shape").c_str(), &current, "sphere\0plane\0cube\0cylinder\0torus\0")) {
        set_shape(o, kAllShapes[current]);
        changed = true;
    }
    tooltip("The object's shape (docs/shapes.md): the sphere is exact; plane, cube, cylinder and torus are "
            "triangle meshes. A new shape keeps the object's place and about its size.");
    double c[3] = {o.center.x, o.center.y, o.center.z};
    if (ImGui::DragScalarN(field("centre").c_str(), ImGuiDataType_Double, c, 3, 0.02f)) {
        o.center = {c[0], c[1], c[2]};
        changed = true;
    }
    tooltip("Where the object is: x, y, z in scene units (any value; drag, or Ctrl+click to type).");
    switch (o.shape) {
        case Shape::sphere:
            changed |= slider_double("radius", &o.radius, 0.01, 10.0, "%.3f", true);
            tooltip("The sphere's radius in scene units, 0.01 to 10 here (the format allows (0, 1e6]; logarithmic).");
            break;
        case Shape::plane:
            changed |= direction_edit("normal", &o.axis);
            tooltip("The side the plane faces: a non-zero direction, kept unit.");
            changed |= slider_double("size", &o.size, 0.01, 100.0, "%.3f", true);
            tooltip("The side of the square in scene units, 0.01 to 100 here ((0, 1e6] in the format; logarithmic).");
            break;
        case Shape::cube:
        case Shape::mesh: {
            const bool cube = o.shape == Shape::cube;
            changed |= slider_double(cube ? "edge" : "size", &o.size, 0.01, 20.0, "%.3f", true);
            tooltip(cube ? "The cube's edge in scene units, 0.01 to 20 here ((0, 1e6] in the format; logarithmic)."
                         : "The model's largest side in scene units, 0.01 to 20 here ((0, 1e6] in the format; "
                           "logarithmic).");
            double r[3] = {o.rotation_deg.x, o.rotation_deg.y, o.rotation_deg.z};
            const double lo = -360.0, hi = 360.0;
            if (ImGui::DragScalarN(field("rotation x,y,z").c_str(), ImGuiDataType_Double, r, 3, 0.5f, &lo, &hi, "%.1f deg",
                                   ImGuiSliderFlags_AlwaysClamp)) {
                o.rotation_deg = {r[0], r[1], r[2]};
                changed = true;
            }
            tooltip("Turns about the world x axis, then y, then z: degrees, each in [-360, 360].");
            break;
        }
        case Shape::cylinder:
            changed |= direction_edit("axis", &o.axis);
            tooltip("The cylinder's axis: a non-zero direction, kept unit.");
            changed |= slider_double("radius", &o.radius, 0.01, 10.0, "%.3f", true);
            tooltip("The cylinder's radius in scene units, 0.01 to 10 here ((0, 1e6] in the format).");
            changed |= slider_double("height", &o.height, 0.01, 20.0, "%.3f", true);
            tooltip("The length along the axis in scene units, 0.01 to 20 here ((0, 1e6] in the format).");
            changed |= checkbox("capped", &o.capped);
            tooltip("On: closed by two discs; off: an open tube (its inside shows).");
            break;
        case Shape::torus:
            changed |= direction_edit("axis", &o.axis);
            tooltip("The axis the ring goes round: a non-zero direction, kept unit.");
            changed |= slider_double("major radius", &o.major_radius, 0.02, 10.0, "%.3f", true);
            tooltip("From the axis to the tube's centre, scene units, 0.02 to 10 here.");
            changed |= slider_double("minor radius", &o.minor_radius, 0.01, 10.0, "%.3f", true);
            tooltip("The tube's radius, scene units, 0.01 to 10 here; kept below the major radius.");
            // The loader's rule: the tube is thinner than the ring.
            o.minor_radius = std::min(o.minor_radius, o.major_radius * 0.99);
            break;
    }
    if (o.shape == Shape::cylinder || o.shape == Shape::torus) {
        int segments = segments_of(o);
        if (ImGui::SliderInt(field("segments").c_str(), &segments, kMinSegments, kMaxSegments, "%d",
                             ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic)) {
            o.segments = segments;
            changed = true;
        }
        tooltip("Segments of a full circle, 3 to 512 (defaults: cylinder 64, torus 128; docs/shapes.md gives "
                "the shading error of each).");
        if (!narrow_panel()) ImGui::SameLine();
        ImGui::TextDisabled("%zu triangles", triangle_count(o));
    }
    return changed;
}

}  // namespace m3055::explore
