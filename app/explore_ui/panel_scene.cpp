// Display, objects (with the figure presets), camera, compare and file sections.
#include "explore_ui/panels.h"

#include "explore/figure_scenes.h"
#include "explore/keys.h"
#include "explore_ui/narrow_panel.h"
#include "explore_ui/shape_editor.h"
#include "explore_ui/widgets.h"
#include "grading/ab_compare.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <string>

namespace m3055::explore {

bool material_editor(Material& material, std::string& action);  // panel_material.cpp

void display_section(Explorer& explorer, const FrameInfo& info) {
    Display display = explorer.doc.scene.display;  // edited here, taken by edit_display
    if (ImGui::Button("M3055 (512 x 320, 5 bits)")) explorer.commands.push(command::SetDisplay{m3055_display(explorer.doc.scene.display), "display M3055"});
    tooltip("The paper's display: 512 x 320 dots, 5 bits (32 levels) per channel.");
    same_line_if_fits(button_width("Modern (window, 8 bits)"));
    if (ImGui::Button("Modern (window, 8 bits)")) explorer.commands.push(command::SetDisplay{modern_display(explorer.doc.scene.display, info.free_width, info.free_height), "display modern"});
    tooltip("A display the size of the free area of the window, 8 bits (256 levels) per channel.");
    int size[2] = {display.width, display.height};
    if (typed_ints(field("width, height").c_str(), size, 2, 1, kMaxDisplaySize)) {
        display.width = size[0];
        display.height = size[1];
        explorer.commands.push(command::SetDisplay{display, ""});
    }
    tooltip("the display's size in dots, each in [1, 8192] (Enter, Tab or a click elsewhere applies; Esc restores; "
            "spec section 2)");
    if (ImGui::SliderInt(field("bits").c_str(), &display.bits, 1, 8, "%d bits", ImGuiSliderFlags_AlwaysClamp)) explorer.commands.push(command::SetDisplay{display, ""});
    tooltip("bits per channel, in [1, 8]: the M3055 has 5 (32 levels; spec section 2)");
    if (!narrow_panel()) ImGui::SameLine();  // narrow: the slider has the whole row
    ImGui::TextDisabled("%d levels", 1 << display.bits);
    if (checkbox("ordered dithering (4x4 Bayer)", &display.dither)) explorer.commands.push(command::SetDisplay{display, ""});
    tooltip("a 4x4 Bayer threshold before quantization (spec section 2); off on the paper's figures");
    // The view transform: the M3055 showed levels of the linear value (the
    // paper's figures); a modern display shows sRGB-encoded colour, as other tools do.
    int transform = display.view_transform == ViewTransform::srgb ? 1 : 0;
    if (ImGui::Combo(field("view transform").c_str(), &transform, "none (linear levels)\0sRGB\0")) {
        display.view_transform = transform == 1 ? ViewTransform::srgb : ViewTransform::none;
        explorer.commands.push(command::SetDisplay{display, ""});
    }
    tooltip("What the display does to a colour before its levels: none (the M3055, as the paper's figures: "
            "levels of the linear value), or sRGB's encoding (IEC 61966-2-1), as other tools and screens show "
            "colour: gold's (1.04, 0.73, 0.37) reads (255, 222, 163) instead of (255, 186, 93). Saved as "
            "display.view_transform; m3055 render --view-transform.");
    dvec3 background = explorer.doc.scene.background;
    if (color_edit("background", &background)) explorer.commands.push(command::SetBackground{background});
    tooltip("the colour behind the objects, RGB in [0, 1]; translucent objects blend over it");
}

namespace {

// More objects than this are listed in a scrolling box of their own.
constexpr int kObjectsListedInline = 200;

// Object i's line: a click selects it.
void object_row(Explorer& explorer, int i) {
    const Object& object = explorer.doc.scene.objects[std::size_t(i)];
    const std::string label = std::string(to_string(object.shape)) + " " + std::to_string(i) + ": " +
                              object.material.shown_name();
    if (ImGui::Selectable(label.c_str(), explorer.view.selected_object == i)) explorer.view.selected_object = i;
    tooltip("Select: the Material panel edits this object (a click on it in the display does the same).");
}

// The selected object's shape and fields, and its remove button; true when it was removed.
bool object_fields(Explorer& explorer, int i) {
    const auto& objects = explorer.doc.scene.objects;
    Object edited = objects[std::size_t(i)];
    if (shape_editor(edited)) explorer.commands.push(command::SetObject{i, edited});  // shape selector and the shape's fields
    ImGui::BeginDisabled(objects.size() <= 1);
    const bool removed = ImGui::SmallButton("remove this object");
    tooltip("Removes it from the scene (undoable); the last object stays.");
    ImGui::EndDisabled();
    if (removed) explorer.commands.push(command::RemoveObject{i});
    return removed;
}

}  // namespace

void objects_section(Explorer& explorer) {
    const char* chord = figure_chord_name(explorer.session.platform.figure_chord);
    ImGui::TextWrapped("figure presets (%s+1-9 = Fig. 5-13, %s+0 = spec example) and scenes:", chord, chord);
    int n = 0;
    for (const FigureScene& figure : figure_scenes()) {
        std::string label = figure.name;
        if (label.rfind("fig", 0) == 0) label = "Fig. " + std::to_string(std::stoi(label.substr(3)));
        // Five a row; on a narrow panel as many as fit.
        const bool row_start = n++ % 5 == 0;
        if (n > 1 && (!row_start || narrow_panel())) same_line_if_fits(button_width(label.c_str()));
        if (ImGui::Button(label.c_str())) explorer.commands.push(command::LoadFigure{figure.name});
        tooltip("Replaces the scene with " + figure.name + ".json (undoable with Ctrl+Z).");
    }
    ImGui::Separator();
    const auto& objects = explorer.doc.scene.objects;
    const int count = static_cast<int>(objects.size());
    // A long list scrolls in a box of its own, drawing only the rows in view
    // (a frame costs the same with 100 000 objects as with 10), and the
    // selected object's fields follow under it.
    const bool long_list = count > kObjectsListedInline;
    if (long_list) {
        ImGui::BeginChild("objects", ImVec2(0.0f, ImGui::GetTextLineHeightWithSpacing() * 10.0f), true);
        ImGuiListClipper clipper;
        clipper.Begin(count);
        while (clipper.Step()) {
            for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
                ImGui::PushID(i);
                object_row(explorer, i);
                ImGui::PopID();
            }
        }
        ImGui::EndChild();
        ImGui::TextDisabled("%d objects; object %d:", count, explorer.view.selected_object);
        if (selected_material(explorer)) {  // clamps the selection
            ImGui::PushID(explorer.view.selected_object);
            object_fields(explorer, explorer.view.selected_object);
            ImGui::PopID();
        }
    } else {
        for (int i = 0; i < count; ++i) {
            ImGui::PushID(i);
            object_row(explorer, i);
            const bool removed = explorer.view.selected_object == i && object_fields(explorer, i);
            ImGui::PopID();
            if (removed) break;
        }
    }
    ImGui::TextUnformatted("add:");
    for (const char* name : {"sphere", "plane", "cube", "cylinder", "torus"}) {
        same_line_if_fits(button_width((std::string("+ ") + name).c_str()));
        if (ImGui::SmallButton((std::string("+ ") + name).c_str())) explorer.commands.push(command::AddObject{*parse_shape(name)});
        tooltip(std::string("Adds a ") + name + " beside the others" +
                (std::string(name) == "plane" ? " (a floor under all)." : "."));
    }
}

void camera_section(Explorer& explorer) {
    Camera camera = explorer.doc.scene.camera;  // edited here, taken by edit_camera
    int projection = static_cast<int>(camera.projection);
    if (ImGui::Combo(field("projection").c_str(), &projection, "perspective\0orthographic\0")) {
        camera.projection = static_cast<Projection>(projection);
        explorer.commands.push(command::SetCamera{camera});
    }
    tooltip("Perspective (a field of view) or orthographic (a view height): spec section 3.");
    if (camera.projection == Projection::perspective) {
        if (slider_double("fov y", &camera.fov_y_deg, 1.0, 170.0, "%.1f deg")) explorer.commands.push(command::SetCamera{camera});
        tooltip("The vertical field of view in degrees, 1 to 170 here (the format allows (0, 180)).");
    } else {
        if (slider_double("view height", &camera.height, 0.01, 100.0, "%.3f", true)) explorer.commands.push(command::SetCamera{camera});
        tooltip("The world-space height the view shows, 0.01 to 100 here (> 0 in the format; logarithmic).");
    }
    double p[3] = {camera.position.x, camera.position.y, camera.position.z};
    if (ImGui::DragScalarN(field("position").c_str(), ImGuiDataType_Double, p, 3, 0.05f)) {
        const dvec3 moved(p[0], p[1], p[2]);
        if (moved != camera.target) camera.position = moved;  // docs/spec.md#7-scene-files: position != target
        explorer.commands.push(command::SetCamera{camera});
    }
    tooltip("The eye: x, y, z in scene units; it must differ from the target (drag on the display orbits it).");
    double t[3] = {camera.target.x, camera.target.y, camera.target.z};
    if (ImGui::DragScalarN(field("target").c_str(), ImGuiDataType_Double, t, 3, 0.05f)) {
        const dvec3 moved(t[0], t[1], t[2]);
        if (moved != camera.position) camera.target = moved;
        explorer.commands.push(command::SetCamera{camera});
    }
    tooltip("The point looked at and orbited around: x, y, z in scene units.");
    if (ImGui::Button("Reset camera (R)")) explorer.commands.push(command::ResetCamera{});
    tooltip("Back to the camera the scene was loaded with.");
    hint("Drag on the display to orbit around the target; the mouse wheel zooms.");
}

void compare_section(Explorer& explorer) {
    bool on = explorer.view.compare;
    if (checkbox("split: A | B side by side", &on)) explorer.commands.push(command::SetCompare{on});
    tooltip("Off/on: show the scene twice, B with the selected object in material B. Both at the largest "
            "whole magnification that fits; B's curve is dashed in the polar plot.");
    hint("A is the scene as edited above; B is the same scene with the selected object "
         "wearing material B (e.g. metal eq. 12 against metal_blinn eq. 15).");
    ImGui::BeginDisabled(!explorer.view.compare);
    checkbox("difference pane |A - B|", &explorer.view.compare_diff);
    tooltip("A third pane: per channel the absolute difference of A's and B's display values (0-255) times "
            "the scale, clamped to 255; its label gives the scale and how many pixels are on another level.");
    bool automatic = explorer.view.diff_scale == 0;
    if (checkbox("auto scale", &automatic)) explorer.view.diff_scale = automatic ? 0 : 8;
    tooltip("Auto: the largest whole scale that keeps the largest difference within 255 (1 when A = B).");
    if (!automatic) {
        if (!narrow_panel()) {
            ImGui::SameLine();
            ImGui::SetNextItemWidth(120.0f);
        }
        ImGui::SliderInt(field("scale").c_str(), &explorer.view.diff_scale, 1, grading::kMaxDifferenceScale, "x %d",
                         ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
        tooltip("Whole factor, 1 to 255: at 5 bits one level is 8 PNG values, so x 4 shows it at 32.");
    }
    ImGui::EndDisabled();
    if (ImGui::Button("B = copy of A")) explorer.commands.push(command::CopyAToB{});
    tooltip("The only thing that copies A into B: switching the split on or off keeps B as it is.");
    ImGui::PushID("material_b");
    Material edited = explorer.doc.material_b;
    std::string action;
    if (material_editor(edited, action)) explorer.commands.push(command::SetMaterial{kMaterialB, edited, action});
    ImGui::PopID();
}

namespace {

// The next screenshot's path beside its button when it fits, else wrapped on
// a line of its own. It holds the scene file's name: beside the button,
// "next: softbox_three_point-0001.png" reached 39 px past the panel's edge at
// 1280 x 720, and the panel widened to 480 px a frame after the start.
void next_screenshot_line(const Explorer& explorer) {
    const std::string next = "next: " + next_screenshot_path(explorer);
    same_line_if_fits(ImGui::CalcTextSize(next.c_str()).x);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", next.c_str());
    ImGui::PopTextWrapPos();
}

}  // namespace

void file_section(Explorer& explorer) {
    // Without a file, the name the title bar shows (a figure preset, the spec example): what Ctrl+S saves.
    if (explorer.doc.file.empty())
        ImGui::TextWrapped("scene file: none (%s); Ctrl+S asks where to save", explorer.doc.name.c_str());
    else
        ImGui::TextWrapped("scene file: %s", explorer.doc.file.c_str());
    if (ImGui::Button("Save (Ctrl+S)")) explorer.commands.push(command::Save{});
    tooltip("Writes the scene JSON to its own file (asks for one when it has none).");
    same_line_if_fits(button_width("Save as..."));
    if (ImGui::Button("Save as...")) explorer.commands.push(command::AskSaveAs{});
    tooltip("Writes the scene JSON to a file you name; it becomes the scene's own file.");
    // (A label of at most the 110 px the panel leaves labels: "screenshot
    // folder" reached 7 px past its edge and widened it for every scene.)
    ImGui::InputText(field("screenshot dir").c_str(), &explorer.session.files.screenshot_dir);
    tooltip("F12 writes the next free NAME-0001.png (and its scene JSON) here; NAME is the scene file's name (or the preset's).");
    if (ImGui::Button("Screenshot PNG + JSON (F12)")) explorer.commands.push(command::Screenshot{});
    tooltip("Display A at its own resolution, exactly the bytes `m3055 render` writes for the JSON beside it.");
    next_screenshot_line(explorer);
    if (ImGui::InputText(field("load").c_str(), &explorer.view.load_path, ImGuiInputTextFlags_EnterReturnsTrue)) explorer.commands.push(command::LoadScene{explorer.view.load_path});
    tooltip("A scene JSON file; Enter or the Load button opens it (undoable with Ctrl+Z).");
    same_line_if_fits(button_width("Load"));
    if (ImGui::Button("Load")) explorer.commands.push(command::LoadScene{explorer.view.load_path});
    tooltip("Opens the scene file named in the field (undoable with Ctrl+Z).");
    if (!explorer.session.messages.load_error.empty()) {  // here, beside the control the user just used
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 110, 255));
        ImGui::TextWrapped("Could not load: %s", explorer.session.messages.load_error.c_str());
        ImGui::PopStyleColor();
    }
    hint("Or drop a .json scene file onto the window.");
}

}  // namespace m3055::explore
