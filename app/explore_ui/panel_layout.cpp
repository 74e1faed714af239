// The two fixed windows and the order of the side panel's sections.
#include "explore_ui/panels.h"

#include "explore/layout.h"
#include "explore_ui/narrow_panel.h"
#include "explore_ui/profile_plot.h"
#include "explore_ui/widgets.h"
#include "scene/area_light.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

namespace m3055::explore {

namespace {
constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
}

// A section's header: open at first when `open_at_start`; a script's
// `section NAME open|closed` opens or closes it as a click would.
bool header(const Explorer& explorer, const char* label, bool open_at_start) {
    const auto request = explorer.view.section_requests.find(label);
    if (request != explorer.view.section_requests.end()) ImGui::SetNextItemOpen(request->second, ImGuiCond_Always);
    else if (open_at_start) ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    return ImGui::CollapsingHeader(label);
}

// Content that shrinks under a scrolled panel (B switched to a model with
// fewer parameters) would pull the scroll back and every control with it,
// under the mouse: the region keeps the room it showed until scrolled up.
void keep_scrolled_room() {
    const float scroll = ImGui::GetScrollY();
    if (scroll <= 0.0f) return;
    const ImGuiWindow* region = ImGui::GetCurrentWindow();
    // (The region's own padding: a child window without a border has none.)
    const float needed = scroll + region->InnerRect.GetHeight() - region->WindowPadding.y;
    const float bottom = ImGui::GetCursorPosY();
    if (bottom < needed) ImGui::Dummy(ImVec2(1.0f, needed - bottom));
}

void draw_side_panel(Explorer& explorer, FrameInfo& info, float x, float y, float width,
                     float height) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("M3055 material explorer", nullptr, kFixed | ImGuiWindowFlags_MenuBar);
    draw_menu_bar(explorer);
    // The sections scroll in a region of their own; an error shows under it
    // (never inserted above the controls: they keep their place).
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const bool error_block = !explorer.session.messages.error.empty() && !explorer.session.platform.error_line_outside;
    const float error_h = error_block ? 4.0f * line : 0.0f;
    ImGui::BeginChild("sections", ImVec2(0.0f, -error_h), false);
    // Room for the labels on the right: 110 px, and what the panel grew by
    // (its width follows its content; the widgets keep theirs).
    ImGui::PushItemWidth(-(110.0f + info.side_extra));
    // Narrower than usual (three panes at 1280 x 720): labels above their widgets.
    set_narrow_panel(width < kSideWidth - 0.5f);

    if (explorer.session.practice.active && header(explorer, "Assignment", true)) assignment_section(explorer);
    if (header(explorer, "Display", true)) display_section(explorer, info);
    if (header(explorer, "Material", true)) material_section(explorer);
    if (header(explorer, "Lights", true)) lights_section(explorer);
    if (header(explorer, "Spectra", false)) spectra_section(explorer);
    if (header(explorer, "Objects and figure presets", false)) objects_section(explorer);
    if (header(explorer, "Camera", false)) camera_section(explorer);
    if (header(explorer, "A/B compare", false)) compare_section(explorer);
    if (header(explorer, "File", true)) file_section(explorer);
    explorer.view.section_requests.clear();
    ImGui::PopItemWidth();
    keep_scrolled_room();
    // Text or a label past the region's visible edge (clip_check.h): the
    // frame loop widens the panel by as much.
    const ImGuiWindow* sections = ImGui::GetCurrentWindow();
    info.side_overflow = std::max(0.0f, sections->DC.CursorMaxPos.x - sections->InnerClipRect.Max.x);
    ImGui::EndChild();

    if (error_block) {
        ImGui::BeginChild("error", ImVec2(0.0f, 0.0f), false);
        ImGui::Separator();
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 110, 255));
        ImGui::TextWrapped("Error: %s", explorer.session.messages.error.c_str());
        ImGui::PopStyleColor();
        if (ImGui::SmallButton("dismiss")) explorer.session.messages.error.clear();
        tooltip("Hides this message (it changes nothing in the scene).");
        ImGui::EndChild();
    }
    ImGui::End();
}

// Per channel, how many pixels show each of the 2^bits levels, and how many levels are used.
void level_histogram_view(const LevelHistogram& h, int bits) {
    const int levels = 1 << bits;
    ImGui::TextWrapped("levels used: R %d, G %d, B %d of %d", h.used[0], h.used[1], h.used[2], levels);
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

// The statistics, in three parts (one under another in the strip's right
// column, side by side in the band under the display).
namespace {

// What the display's last drawing took, saying what it was: with area lights
// the time of a preview (one sample a light) is no render's, and the refine
// to the render's pixels draws in tiles between frames.
void drawing_time(const FrameInfo& info) {
    if (!info.render_is_preview) ImGui::TextWrapped("render %.1f ms, UI %.1f ms", info.render_ms, info.frame_ms);
    else if (info.refine_ms < 0.0) ImGui::TextWrapped("preview %.1f ms, UI %.1f ms", info.render_ms, info.frame_ms);
    else ImGui::TextWrapped("refined in %.1f ms, UI %.1f ms", info.refine_ms, info.frame_ms);
    tooltip("The display's last drawing, GPU finished (A and B in the split). With area lights: \"preview\", the "
            "preview drawn while edits come (shown until the refine is done); \"refined in\", the refine to the "
            "render's pixels once done: the drawing time of its tiles added up, both passes (not the time since "
            "input stopped: frames and input come between tiles). UI: the last frame's CPU time.");
}

// Timings, the display's scale, the A/B count.
void stats_numbers(const Explorer& explorer, const FrameInfo& info) {
    const Display& d = explorer.doc.scene.display;
    // Short wrapped lines: the column is 220 pixels wide at 1280 x 720.
    drawing_time(info);
    ImGui::TextWrapped("frames %ld, renders %ld", info.frames, info.renders);
    const char* transform = d.view_transform == ViewTransform::srgb ? "sRGB" : "linear";
    if (info.scale >= 1) ImGui::TextWrapped("%d x %d, %d bits, %s, shown %d x", d.width, d.height, d.bits, transform, info.scale);
    else ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "%d x %d, %d bits, %s, shrunk", d.width, d.height, d.bits, transform);
    tooltip("The display's size and bits, and its magnification: whole pixels, nearest-neighbour; shrunk (not "
            "whole pixels) when even 1:1 does not fit.");
    const auto& lights = explorer.doc.scene.lights;
    if (std::any_of(lights.begin(), lights.end(),
                    [](const Light& l) { return l.enabled && l.intensity > 0.0 && is_area_light(l.type); })) {
        const ImVec4 amber(1, 0.8f, 0.3f, 1);
        const int percent = static_cast<int>(100.0 * info.refine_progress);
        if (!info.refining) ImGui::TextWrapped("area lights: the render's pixels");
        else if (!info.refine_started) ImGui::TextColored(amber, "area lights: preview");
        else if (info.sharpening) ImGui::TextColored(amber, "area lights: preview, full size %d %%", percent);
        else ImGui::TextColored(amber, "area lights: render's pixels %d %%", percent);
        tooltip("While edits come the display draws each rect, disk and sky light at one point (two for a highlight "
                "the closed forms integrate) with one shadow ray (hard shadows), at a smaller size when a frame "
                "would take over 35 ms. When input stops it refines (\"refining...\" beside the menu), top down: "
                "a smaller preview first at the display's size (\"preview, full size N %\"), then to what F12 and "
                "m3055 render give, 8 x 8 samples and soft shadows, byte for byte (\"render's pixels N %\": the "
                "share of the display drawn so far; docs/lights.md).");
    }
    if (!info.compare_count.empty()) {
        ImGui::TextWrapped("A/B: %s", info.compare_count.c_str());
        tooltip("Pixels of B whose display level differs from A's in any channel (the count `m3055 compare` "
                "gives for the two PNGs).");
    }
}

// A new message (the text just drawn) scrolled up into view if it ends
// below the column: at 1280 x 720 the statistics' column has room for two
// lines under the histogram, and F12's confirmation with its path takes
// three or four. Watched over its first frames, as it wraps again once the
// column's scrollbar shows; then the column is the user's to scroll.
void scroll_new_message_into_view(const std::string& message) {
    constexpr int kFramesWatched = 3;
    ImGuiStorage* storage = ImGui::GetStateStorage();
    const ImGuiID message_key = ImGui::GetID("##message"), frames_key = ImGui::GetID("##message frames");
    const int hash = static_cast<int>(ImHashStr(message.c_str()));
    if (storage->GetInt(message_key) != hash) {
        storage->SetInt(message_key, hash);
        storage->SetInt(frames_key, 0);
    }
    const int frames = storage->GetInt(frames_key);
    if (frames >= kFramesWatched) return;
    storage->SetInt(frames_key, frames + 1);
    const float visible_bottom = ImGui::GetWindowPos().y + ImGui::GetWindowHeight();
    if (ImGui::GetItemRectMax().y > visible_bottom) ImGui::SetScrollHereY(1.0f);  // its last line at the bottom
}

// The last message (saved, screenshot, loaded: with the full path) where it
// is seen, and the diagnostics.
void stats_messages(const Explorer& explorer, const FrameInfo& info) {
    const std::string& message = explorer.session.messages.status;
    if (!message.empty()) {
        ImGui::TextWrapped("%s", message.c_str());
        scroll_new_message_into_view(message);
    }
    if (ImGui::TreeNode("Diagnostics")) {  // closed by default: for bug reports, not for lessons
        ImGui::TextWrapped("GL renderer: %s", info.gl_renderer.c_str());
        ImGui::TextWrapped("GL version: %s", info.gl_version.c_str());
        ImGui::TextWrapped("backend: GLFW window (%s)", info.window_system.c_str());
        ImGui::TreePop();
    }
}

}  // namespace

// The strip's right column: timings, the display's scale, the A/B count, the
// level histogram, the last message; scrolls on its own when the strip is low.
void stats_column(const Explorer& explorer, const FrameInfo& info) {
    stats_numbers(explorer, info);
    if (info.histogram) level_histogram_view(*info.histogram, explorer.doc.scene.display.bits);
    stats_messages(explorer, info);
}

void draw_stats_band(const Explorer& explorer, const FrameInfo& info, float x, float y, float width, float height) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    // Scrolls when the diagnostics are open (or a message is long).
    ImGui::Begin("Statistics", nullptr, kFixed | ImGuiWindowFlags_NoTitleBar);
    if (ImGui::BeginTable("statistics", 3, ImGuiTableFlags_SizingStretchSame | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableNextColumn();
        stats_numbers(explorer, info);
        ImGui::TableNextColumn();
        if (info.histogram) level_histogram_view(*info.histogram, explorer.doc.scene.display.bits);
        ImGui::TableNextColumn();
        stats_messages(explorer, info);
        ImGui::EndTable();
    }
    ImGui::End();
}

void draw_profile_band(const FrameInfo& info, float x, float y, float width, float height) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("Scanline", nullptr, kFixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
    const ImVec2 room = ImGui::GetContentRegionAvail();
    profile_plot(info.profile, info.profile_b, room.x, room.y - ImGui::GetTextLineHeightWithSpacing());
    ImGui::End();
}

// Three columns sized from the room there is (1280 x 720 included): the polar
// plot, the scanline profile, the statistics.
void draw_bottom_strip(Explorer& explorer, const FrameInfo& info, float x, float y,
                       float width, float height, StripShape shape) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    // The strip under the display fits without scrolling; the column beside
    // the panes (or in the free cell of three) scrolls when it is low, so the
    // statistics under the plots stay reachable.
    const ImGuiWindowFlags scrolling = shape != StripShape::row
                                           ? ImGuiWindowFlags_None
                                           : ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;
    if (shape == StripShape::plots || shape == StripShape::polar) {
        // Under the side panel: its title bar's arrow folds it (explore.cpp
        // then gives the column to the side panel).
        ImGui::SetNextWindowCollapsed(explorer.view.plots_folded, ImGuiCond_Always);
        const bool open = ImGui::Begin(kPlotsTitle, nullptr, (kFixed & ~ImGuiWindowFlags_NoCollapse) | scrolling);
        explorer.view.plots_folded = ImGui::IsWindowCollapsed();
        if (!open) {
            ImGui::End();
            return;
        }
    } else {
        ImGui::Begin(kPlotsTitle, nullptr, kFixed | scrolling);
    }
    const ImVec2 room = ImGui::GetContentRegionAvail();
    // Beside the stacked panes or in the free cell beside the third of three
    // (explore/layout.h): the three one under another, each the column's width.
    if (shape == StripShape::polar) {  // under the side panel: the profile and the statistics are under the display
        plot_section(explorer, info.plane_curves, room.x, room.y);
        ImGui::End();
        return;
    }
    if (shape == StripShape::plots) {  // under the side panel: the statistics are under the display
        const float line = ImGui::GetTextLineHeightWithSpacing();
        const float plot_h = std::max(200.0f, room.y * 0.7f);
        ImGui::BeginGroup();
        plot_section(explorer, info.plane_curves, room.x, plot_h);
        ImGui::EndGroup();
        profile_plot(info.profile, info.profile_b, room.x,
                     std::max(40.0f, ImGui::GetContentRegionAvail().y - 1.5f * line));
        ImGui::End();
        return;
    }
    if (shape == StripShape::column) {
        const float line = ImGui::GetTextLineHeightWithSpacing();
        const float plot_h = std::max(200.0f, room.y * 0.45f), profile_h = std::max(100.0f, room.y * 0.22f);
        ImGui::BeginGroup();
        plot_section(explorer, info.plane_curves, room.x, plot_h);
        ImGui::EndGroup();
        profile_plot(info.profile, info.profile_b, room.x, profile_h - 2.0f * line);
        // At least eight lines of statistics: below the window's edge when the
        // column is low, where the column's scrolling reaches them.
        const float stats_h = std::max(ImGui::GetContentRegionAvail().y, 8.0f * line);
        ImGui::BeginChild("stats", ImVec2(0.0f, stats_h));
        stats_column(explorer, info);
        ImGui::EndChild();
        ImGui::End();
        return;
    }
    const float gap = 16.0f, stats_w = std::clamp(room.x * 0.28f, 220.0f, 330.0f);
    const float plots_w = std::max(200.0f, room.x - stats_w - 2.0f * gap);

    ImGui::BeginGroup();  // at least the width of its header's three controls
    plot_section(explorer, info.plane_curves, std::max(plots_w * 0.55f, 320.0f), room.y);
    ImGui::EndGroup();

    ImGui::SameLine(0.0f, gap);
    ImGui::BeginGroup();  // what the polar plot left, less the statistics
    const float profile_w = std::max(120.0f, ImGui::GetContentRegionAvail().x - stats_w - gap);
    profile_plot(info.profile, info.profile_b, profile_w, room.y - 2.0f * ImGui::GetTextLineHeightWithSpacing());
    ImGui::EndGroup();

    ImGui::SameLine(0.0f, gap);
    ImGui::BeginChild("stats", ImVec2(0.0f, room.y));
    stats_column(explorer, info);
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace m3055::explore
