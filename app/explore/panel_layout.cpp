// The two fixed windows and the order of the side panel's sections.
#include "explore/panels.h"

#include "explore/widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

namespace m3055::explore {

namespace {
constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
}

// A section's header: open at first when `open_at_start`; a script's
// `section NAME open|closed` opens or closes it as a click would.
bool header(const ExplorerState& state, const char* label, bool open_at_start) {
    const auto request = state.section_requests.find(label);
    if (request != state.section_requests.end()) ImGui::SetNextItemOpen(request->second, ImGuiCond_Always);
    else if (open_at_start) ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    return ImGui::CollapsingHeader(label);
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

    if (state.practice.active && header(state, "Assignment", true)) assignment_section(state);
    if (header(state, "Display", true)) display_section(state, info);
    if (header(state, "Material", true)) material_section(state);
    if (header(state, "Lights", true)) lights_section(state);
    if (header(state, "Objects and figure presets", false)) objects_section(state);
    if (header(state, "Camera", false)) camera_section(state);
    if (header(state, "A/B compare", false)) compare_section(state);
    if (header(state, "File", true)) file_section(state);
    state.section_requests.clear();

    ImGui::PopItemWidth();
    ImGui::End();
}

// Per channel, how many pixels show each of the 2^bits levels, and how many levels are used.
void level_histogram_view(const LevelHistogram& h, int bits) {
    const int levels = 1 << bits;
    ImGui::Text("levels used: R %d, G %d, B %d of %d", h.used[0], h.used[1], h.used[2], levels);
    const ImVec4 colours[3] = {ImVec4(1, 0.35f, 0.35f, 1), ImVec4(0.35f, 0.9f, 0.35f, 1), ImVec4(0.4f, 0.55f, 1, 1)};
    for (int c = 0; c < 3; ++c) {
        // Square roots: the background's level would flatten every other bar.
        std::vector<float> bars(h.counts[std::size_t(c)].size());
        for (std::size_t i = 0; i < bars.size(); ++i) bars[i] = std::sqrt(float(h.counts[std::size_t(c)][i]));
        ImGui::PushStyleColor(ImGuiCol_PlotHistogram, colours[c]);
        ImGui::PushID(c);
        ImGui::PlotHistogram("##levels", bars.data(), static_cast<int>(bars.size()), 0, nullptr, 0.0f, FLT_MAX,
                             ImVec2(std::min(ImGui::GetContentRegionAvail().x, 320.0f), 16.0f));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("pixels per display level (0 ... %d), square-root scale", levels - 1);
        ImGui::PopID();
        ImGui::PopStyleColor();
    }
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
    if (info.histogram) level_histogram_view(*info.histogram, state.scene.display.bits);
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
