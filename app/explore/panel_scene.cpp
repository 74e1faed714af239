// Display, objects (with the figure presets), camera, compare and file sections.
#include "explore/panels.h"

#include "explore/figure_scenes.h"
#include "explore/shape_editor.h"
#include "explore/widgets.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <string>

namespace m3055::explore {

bool material_editor(Material& material);  // panel_material.cpp

void display_section(ExplorerState& state, const FrameInfo& info) {
    Display& display = state.scene.display;
    if (ImGui::Button("M3055 (512 x 320, 5 bits)")) set_display_m3055(state);
    ImGui::SameLine();
    if (ImGui::Button("Modern (window, 8 bits)")) set_display_modern(state, info.free_width, info.free_height);
    int size[2] = {display.width, display.height};
    if (ImGui::InputInt2("width, height", size, ImGuiInputTextFlags_EnterReturnsTrue)) {
        display.width = std::clamp(size[0], 1, kMaxDisplaySize);
        display.height = std::clamp(size[1], 1, kMaxDisplaySize);
        state.changed();
    }
    tooltip("the display's size in dots, each in [1, 8192] (Enter applies; spec section 2)");
    if (ImGui::SliderInt("bits", &display.bits, 1, 8, "%d bits", ImGuiSliderFlags_AlwaysClamp)) state.changed();
    tooltip("bits per channel, in [1, 8]: the M3055 has 5 (32 levels; spec section 2)");
    ImGui::SameLine();
    ImGui::TextDisabled("%d levels", 1 << display.bits);
    if (ImGui::Checkbox("ordered dithering (4x4 Bayer)", &display.dither)) state.changed();
    tooltip("a 4x4 Bayer threshold before quantization (spec section 2); off on the paper's figures");
    if (color_edit("background", &state.scene.background)) state.changed();
    tooltip("the colour behind the objects, RGB in [0, 1]; translucent objects blend over it");
}

void objects_section(ExplorerState& state) {
    ImGui::TextUnformatted("figure presets (keys 1-9, 0 = spec example):");
    int n = 0;
    for (const FigureScene& figure : figure_scenes()) {
        std::string label = figure.name;
        if (label.rfind("fig", 0) == 0) label = "Fig. " + std::to_string(std::stoi(label.substr(3)));
        if (n++ % 5) ImGui::SameLine();
        if (ImGui::Button(label.c_str())) load_figure(state, figure.name);
    }
    ImGui::Separator();
    auto& objects = state.scene.objects;
    for (int i = 0; i < static_cast<int>(objects.size()); ++i) {
        ImGui::PushID(i);
        const std::string label = std::string(to_string(objects[i].shape)) + " " + std::to_string(i) + ": " +
                                  objects[i].material.model_name().c_str();
        if (ImGui::Selectable(label.c_str(), state.selected_object == i)) state.selected_object = i;
        if (state.selected_object == i) {
            Object& o = objects[i];
            if (shape_editor(o)) state.changed();  // shape selector and the shape's fields
            ImGui::BeginDisabled(objects.size() <= 1);
            const bool removed = ImGui::SmallButton("remove this object");
            ImGui::EndDisabled();
            if (removed) {
                remove_object(state, i);
                ImGui::PopID();
                break;
            }
        }
        ImGui::PopID();
    }
    ImGui::TextUnformatted("add:");
    for (const char* name : {"sphere", "plane", "cube", "cylinder", "torus"}) {
        ImGui::SameLine();
        if (ImGui::SmallButton((std::string("+ ") + name).c_str())) add_object(state, *parse_shape(name));
    }
}

void camera_section(ExplorerState& state) {
    Camera& camera = state.scene.camera;
    int projection = static_cast<int>(camera.projection);
    if (ImGui::Combo("projection", &projection, "perspective\0orthographic\0")) {
        camera.projection = static_cast<Projection>(projection);
        state.changed();
    }
    if (camera.projection == Projection::perspective) {
        if (slider_double("fov y", &camera.fov_y_deg, 1.0, 170.0, "%.1f deg")) state.changed();
    } else {
        if (slider_double("view height", &camera.height, 0.01, 100.0, "%.3f", true)) state.changed();
    }
    double p[3] = {camera.position.x, camera.position.y, camera.position.z};
    if (ImGui::DragScalarN("position", ImGuiDataType_Double, p, 3, 0.05f)) {
        const dvec3 moved(p[0], p[1], p[2]);
        if (moved != camera.target) camera.position = moved;  // docs/spec.md#7-scene-files: position != target
        state.changed();
    }
    double t[3] = {camera.target.x, camera.target.y, camera.target.z};
    if (ImGui::DragScalarN("target", ImGuiDataType_Double, t, 3, 0.05f)) {
        const dvec3 moved(t[0], t[1], t[2]);
        if (moved != camera.position) camera.target = moved;
        state.changed();
    }
    if (ImGui::Button("Reset camera (R)")) reset_camera(state);
    hint("Drag on the display to orbit around the target; the mouse wheel zooms.");
}

void compare_section(ExplorerState& state) {
    bool on = state.compare;
    if (ImGui::Checkbox("split: A | B side by side", &on)) set_compare(state, on);
    hint("A is the scene as edited above; B is the same scene with the selected object "
         "wearing material B (e.g. metal eq. 12 against metal_blinn eq. 15).");
    if (ImGui::Button("B = copy of A")) copy_a_to_b(state);
    tooltip("The only thing that copies A into B: switching the split on or off keeps B as it is.");
    ImGui::PushID("material_b");
    if (material_editor(state.material_b)) state.changed();
    ImGui::PopID();
}

void file_section(ExplorerState& state) {
    ImGui::Text("scene file: %s", state.scene_file.empty() ? "(none: Ctrl+S asks)" : state.scene_file.c_str());
    if (ImGui::Button("Save (Ctrl+S)")) save_or_ask(state);
    ImGui::SameLine();
    if (ImGui::Button("Save as...")) state.save_as_requested = true;
    ImGui::InputText("screenshot folder", &state.screenshot_dir);
    tooltip("F12 writes the next free NAME-0001.png (and its scene JSON) here; NAME is the scene file's name.");
    if (ImGui::Button("Screenshot PNG + JSON (F12)")) state.screenshot_requested = true;
    ImGui::SameLine();
    ImGui::TextDisabled("next: %s", next_screenshot_path(state).c_str());
    if (ImGui::InputText("load", &state.load_path, ImGuiInputTextFlags_EnterReturnsTrue)) load_scene(state, state.load_path);
    tooltip("A scene JSON file; Enter or the Load button opens it (undoable with Ctrl+Z).");
    ImGui::SameLine();
    if (ImGui::Button("Load")) load_scene(state, state.load_path);
    if (!state.load_error.empty()) {  // here, beside the control the user just used
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 110, 255));
        ImGui::TextWrapped("Could not load: %s", state.load_error.c_str());
        ImGui::PopStyleColor();
    }
    hint("Or drop a .json scene file onto the window.");
}

}  // namespace m3055::explore
