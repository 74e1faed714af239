#include "explore/display_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace m3055::explore {

namespace {
constexpr float kSideWidth = 440.0f;
constexpr float kBottomHeight = 270.0f;

// The largest whole-pixel magnification of a w x h image that fits `area`
// (framebuffer pixels); 0 when even 1:1 does not fit.
int whole_pixel_scale(int w, int h, float area_w, float area_h) {
    return static_cast<int>(std::min(std::floor(area_w / w), std::floor(area_h / h)));
}

}  // namespace

Layout layout_for(float width, float height, bool panels) {
    Layout l;
    if (!panels) {
        l.display = {0, 0, width, height};
        return l;
    }
    l.side = {0, 0, std::min(kSideWidth, width), height};
    const float right = std::max(0.0f, width - l.side.w);
    l.bottom = {l.side.w, std::max(0.0f, height - kBottomHeight), right, std::min(kBottomHeight, height)};
    l.display = {l.side.w, 0, right, l.bottom.y};
    return l;
}

int draw_display(const std::vector<unsigned>& textures, int w, int h, const Rect& area,
                 float fb_scale, Rect* shown_a) {
    const int n = static_cast<int>(textures.size());
    const float gap = n > 1 ? kCompareGap : 0.0f;
    const float area_w = (area.w - gap * (n - 1)) * fb_scale / n, area_h = area.h * fb_scale;
    const int scale = whole_pixel_scale(w, h, area_w, area_h);
    // Too big even at 1:1: shrink to fit (no longer whole pixels; the panel says so).
    const float shown = scale >= 1 ? static_cast<float>(scale)
                                   : std::min(area_w / w, area_h / h);
    const float iw = w * shown / fb_scale, ih = h * shown / fb_scale;  // ImGui units
    const float total = iw * n + gap * (n - 1);
    // Snap the corner to a framebuffer pixel so every dot covers whole pixels.
    float x = std::floor((area.x + (area.w - total) * 0.5f) * fb_scale) / fb_scale;
    const float y = std::floor((area.y + (area.h - ih) * 0.5f) * fb_scale) / fb_scale;
    if (shown_a) *shown_a = {x, y, iw, ih};
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const char* labels[2] = {"A: the scene (saved, screenshot)", "B: selected object in material B"};
    for (int i = 0; i < n; ++i) {
        // GL textures store row 0 at the bottom: flip v.
        draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(textures[i])),
                       ImVec2(x, y), ImVec2(x + iw, y + ih), ImVec2(0, 1), ImVec2(1, 0));
        // A thin frame shows the display's extent even where the scene is black.
        draw->AddRect(ImVec2(x - 1, y - 1), ImVec2(x + iw + 1, y + ih + 1), IM_COL32(90, 90, 100, 255));
        // Labels above the pictures, never on them: the display stays exactly the screenshot.
        if (n > 1) draw->AddText(ImVec2(x, y - ImGui::GetTextLineHeight() - 4), IM_COL32(255, 255, 255, 220), labels[i]);
        x += iw + gap;
    }
    return std::max(scale, 0);
}

Rgb8Image read_window(const GlApi& gl, int width, int height) {
    Rgb8Image image;
    image.width = width;
    image.height = height;
    image.pixels.resize(static_cast<std::size_t>(width) * height * 3);
    std::vector<std::uint8_t> rows(image.pixels.size());
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl.ReadBuffer(GL_BACK);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    const std::size_t stride = static_cast<std::size_t>(width) * 3;
    for (int y = 0; y < height; ++y) {  // GL rows are bottom to top, PNG top to bottom
        std::copy_n(rows.data() + (height - 1 - y) * stride, stride, image.pixels.data() + y * stride);
    }
    return image;
}

}  // namespace m3055::explore
