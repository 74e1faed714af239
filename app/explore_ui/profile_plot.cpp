#include "explore_ui/profile_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace m3055::explore {

namespace {

// Grid lines at every level when they are at least 3 pixels apart (the 32
// steps of 5 bits), else at every 8th; the top and bottom levels labelled.
void draw_level_grid(ImDrawList* draw, const ImVec2& lo, const ImVec2& hi, int top) {
    const float step = (hi.y - lo.y) / float(std::max(top, 1));
    const int every = step >= 3.0f ? 1 : 8;
    for (int level = 0; level <= top; level += every) {
        const float y = hi.y - step * float(level);
        draw->AddLine(ImVec2(lo.x, y), ImVec2(hi.x, y), IM_COL32(255, 255, 255, level % 8 ? 18 : 45));
    }
    char label[16];
    std::snprintf(label, sizeof label, "%d", top);
    draw->AddText(ImVec2(lo.x + 2, lo.y - 1), IM_COL32(255, 255, 255, 140), label);
    draw->AddText(ImVec2(lo.x + 2, hi.y - ImGui::GetTextLineHeight()), IM_COL32(255, 255, 255, 140), "0");
}

// One channel: a horizontal run per pixel, joined by vertical risers; dashed:
// every other run of three pixels.
void draw_steps(ImDrawList* draw, const std::vector<int>& levels, const ImVec2& lo, const ImVec2& hi, int top,
                ImU32 colour, float offset, bool dashed) {
    const float dx = (hi.x - lo.x) / float(levels.size()), dy = (hi.y - lo.y) / float(std::max(top, 1));
    std::vector<ImVec2> points;
    points.reserve(levels.size() * 2);
    for (std::size_t x = 0; x < levels.size(); ++x) {
        const float y = hi.y - dy * float(levels[x]) + offset;
        points.emplace_back(lo.x + dx * float(x), y);
        points.emplace_back(lo.x + dx * float(x + 1), y);
    }
    if (!dashed) {
        draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, 0, 1.2f);
        return;
    }
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        if ((i / 6) % 2 == 0) draw->AddLine(points[i], points[i + 1], colour, 1.2f);
}

}  // namespace

void profile_plot(const RowProfile* profile, const RowProfile* b, float width, float height) {
    if (!profile) {
        ImGui::TextDisabled("scanline profile: hover the display (A)");
        ImGui::Dummy(ImVec2(width, height));
        return;
    }
    const int top = (1 << profile->bits) - 1;
    ImGui::Text("scanline, row %d%s", profile->row, b ? " (dashed: B)" : "");
    const ImVec2 lo = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##profile", ImVec2(width, height));
    const ImVec2 hi(lo.x + width, lo.y + height);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(lo, hi, IM_COL32(0, 0, 0, 90));
    draw_level_grid(draw, lo, hi, top);
    // Offset by a pixel each so equal channels (grey) stay visible side by side.
    const ImU32 colours[3] = {IM_COL32(255, 80, 80, 230), IM_COL32(80, 230, 80, 230), IM_COL32(90, 140, 255, 230)};
    for (std::size_t c = 0; c < 3; ++c) {
        draw_steps(draw, profile->levels[c], lo, hi, top, colours[c], float(c) - 1.0f, false);
        if (b && b->levels[c].size() == profile->levels[c].size())
            draw_steps(draw, b->levels[c], lo, hi, top, colours[c], float(c) - 1.0f, true);
    }
    const int columns = static_cast<int>(profile->levels[0].size());
    if (ImGui::IsItemHovered() && columns > 0) {
        const int x = std::clamp(int((ImGui::GetIO().MousePos.x - lo.x) / width * float(columns)), 0, columns - 1);
        const std::size_t i = std::size_t(x);
        char b_line[64] = "";
        if (b && i < b->levels[0].size())
            std::snprintf(b_line, sizeof b_line, "\nB (dashed):  R %d  G %d  B %d", b->levels[0][i], b->levels[1][i],
                          b->levels[2][i]);
        ImGui::SetTooltip("Display levels along row %d of A (the last row the mouse was on), left to right.\n"
                          "column %d: R %d  G %d  B %d (of 0-%d)%s", profile->row, x, profile->levels[0][i],
                          profile->levels[1][i], profile->levels[2][i], top, b_line);
    }
}

}  // namespace m3055::explore
