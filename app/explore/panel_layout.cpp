// The two fixed windows and the order of the side panel's sections.
#include "explore/panels.h"

#include "explore/widgets.h"

#include <imgui.h>

#include <algorithm>

namespace m3055::explore {

namespace {
constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
}

void draw_side_panel(ExplorerState& state, const FrameInfo& info, float x, float y, float width,
                     float height) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("M3055 material explorer", nullptr, kFixed | ImGuiWindowFlags_MenuBar);
    draw_menu_bar(state);
    ImGui::PushItemWidth(-110.0f);  // room for the labels on the right

    if (!state.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 110, 255));
        ImGui::TextWrapped("Error: %s", state.error.c_str());
        ImGui::PopStyleColor();
        if (ImGui::SmallButton("dismiss")) state.error.clear();
        ImGui::Separator();
    }

    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    if (ImGui::CollapsingHeader("Display")) display_section(state, info);
    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    if (ImGui::CollapsingHeader("Material")) material_section(state);
    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    if (ImGui::CollapsingHeader("Lights")) lights_section(state);
    if (ImGui::CollapsingHeader("Objects and figure presets")) objects_section(state);
    if (ImGui::CollapsingHeader("Camera")) camera_section(state);
    if (ImGui::CollapsingHeader("A/B compare")) compare_section(state);
    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    if (ImGui::CollapsingHeader("File")) file_section(state);

    ImGui::PopItemWidth();
    ImGui::End();
}

void draw_bottom_strip(ExplorerState& state, const FrameInfo& info, float x, float y,
                       float width, float height) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("Plane of incidence", nullptr, kFixed);

    ImGui::BeginGroup();
    plot_section(state, width, height);
    ImGui::EndGroup();

    ImGui::SameLine(0.0f, 24.0f);
    ImGui::BeginGroup();
    ImGui::Text("frame  %.2f ms (UI)", info.frame_ms);
    ImGui::Text("render %.2f ms (%d x %d, %d bits)", info.render_ms, state.scene.display.width,
                state.scene.display.height, state.scene.display.bits);
    ImGui::Text("frames drawn %ld, scene renders %ld", info.frames, info.renders);
    if (info.scale >= 1) ImGui::Text("shown at %d x (whole pixels, nearest)", info.scale);
    else ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "shrunk to fit the window (not whole pixels)");
    // The last message (saved, screenshot, loaded: with the full path) where it is seen.
    if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());
    ImGui::Separator();
    hint("Left: the red, green and blue value (CPU reference) for every view direction in the plane of "
         "the plotted light L (yellow) and N; dashed: the mirror direction R. Translucent objects: the "
         "displayed blend over the background colour.");
    if (ImGui::TreeNode("Diagnostics")) {  // closed by default: for bug reports, not for lessons
        ImGui::TextWrapped("GL renderer: %s", info.gl_renderer.c_str());
        ImGui::TextWrapped("GL version: %s", info.gl_version.c_str());
        ImGui::TextWrapped("backend: GLFW window (%s)", info.window_system.c_str());
        ImGui::TreePop();
    }
    ImGui::EndGroup();
    ImGui::End();
}

}  // namespace m3055::explore
