#include "explore_ui/clip_check.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <utility>

namespace m3055::explore {

std::vector<ClippedWindow> clipped_windows() {
    std::vector<ClippedWindow> out;
    const ImGuiContext* context = ImGui::GetCurrentContext();
    if (!context) return out;
    constexpr ImGuiWindowFlags kSizedToContent = ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_Popup |
                                                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_HorizontalScrollbar |
                                                 ImGuiWindowFlags_ChildMenu;
    for (const ImGuiWindow* w : context->Windows) {
        if (!w->Active || w->Hidden || (w->Flags & kSizedToContent)) continue;
        // Half a pixel of slack: rounding of the last glyph's advance.
        const float overflow = w->DC.CursorMaxPos.x - w->InnerClipRect.Max.x;
        if (overflow > 0.5f) out.push_back({w->Name, overflow, w->Size.x, false});
        for (const char* whole : kWholeViews) {
            const float under = w->DC.CursorMaxPos.y - w->InnerClipRect.Max.y;
            if (std::strcmp(w->Name, whole) == 0 && under > 0.5f) out.push_back({w->Name, under, w->Size.y, true});
        }
    }
    return out;
}

void report_clipping() {
    static const bool enabled = std::getenv("M3055_CHECK_CLIPPING") != nullptr;
    if (!enabled) return;
    // A window clipped in two frames in a row: the side panel widens after
    // the frame that measured its content (explore.cpp), so one frame may.
    static std::set<std::string> printed, last_frame;
    std::set<std::string> this_frame;
    for (const ClippedWindow& c : clipped_windows()) {
        this_frame.insert(c.name);
        if (!last_frame.count(c.name)) continue;
        char line[512];
        std::snprintf(line, sizeof line, c.below ? "clipped: %s: content %.0f px below its edge at window height %.0f"
                                                 : "clipped: %s: content %.0f px past its edge at window width %.0f",
                      c.name.c_str(), std::ceil(c.overflow), c.width);
        if (printed.insert(line).second) std::fprintf(stderr, "%s\n", line);
    }
    last_frame = std::move(this_frame);
}

}  // namespace m3055::explore
