#include "explore_ui/display_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace m3055::explore {

int draw_display(const std::vector<Pane>& panes, int w, int h, const Rect& area, float fb_scale, Rect* shown_a) {
    const int n = static_cast<int>(panes.size());
    const float label_h = ImGui::GetTextLineHeight() + 4.0f;
    const Grid g = best_grid(n, w, h, area, fb_scale, label_h);
    const float iw = float(w) * g.shown / fb_scale, ih = float(h) * g.shown / fb_scale;  // ImGui units
    const float total_w = iw * float(g.columns) + kCompareGap * float(g.columns - 1);
    const float row_label_h = g.row_label_h;
    const float first_label_h = g.rows > 1 ? label_h : 0.0f;  // one row: in the margin above
    const float total_h = first_label_h + ih * float(g.rows) + (kCompareGap + row_label_h) * float(g.rows - 1);
    // Snap the corner to a framebuffer pixel so every dot covers whole pixels.
    const float x0 = std::floor((area.x + (area.w - total_w) * 0.5f) * fb_scale) / fb_scale;
    const float y0 =
        std::floor((area.y + (area.h - total_h) * 0.5f + first_label_h) * fb_scale) / fb_scale;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    for (int i = 0; i < n; ++i) {
        const int column = i % g.columns, row = i / g.columns;
        const float x = x0 + float(column) * (iw + kCompareGap), y = y0 + float(row) * (ih + kCompareGap + row_label_h);
        if (i == 0 && shown_a) *shown_a = {x, y, iw, ih};
        // GL textures store row 0 at the bottom: flip v.
        draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(panes[i].texture)), ImVec2(x, y),
                       ImVec2(x + iw, y + ih), ImVec2(0, 1), ImVec2(1, 0));
        // A thin frame shows the display's extent even where the scene is black.
        draw->AddRect(ImVec2(x - 1, y - 1), ImVec2(x + iw + 1, y + ih + 1), IM_COL32(90, 90, 100, 255));
        // Labels beside the pictures, never on them: the display stays exactly the screenshot.
        if (n < 2) continue;
        const char* text = panes[i].label.c_str();
        if (row == 0 || !g.label_right)
            draw->AddText(ImVec2(x, y - ImGui::CalcTextSize(text).y - 4), IM_COL32(255, 255, 255, 220), text);
        else  // in the free cell to its right, wrapped to that cell
            draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(x + iw + kCompareGap, y),
                          IM_COL32(255, 255, 255, 220), text, nullptr, iw);
    }
    return std::max(g.scale, 0);
}

void draw_selection_outline(const std::vector<int>& ids, int selected, int w, int h, const Rect& shown) {
    const float sx = shown.w / w, sy = shown.h / h;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImU32 colour = IM_COL32(255, 230, 0, 255);
    auto is_selected = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && ids[std::size_t(y) * w + x] == selected;
    };
    // Around the selected pixels, on the neighbouring pixels' side: the
    // object's own pixels stay exactly as rendered.
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (is_selected(x, y)) continue;
            if (!(is_selected(x - 1, y) || is_selected(x + 1, y) || is_selected(x, y - 1) || is_selected(x, y + 1)))
                continue;
            const ImVec2 a(shown.x + x * sx, shown.y + y * sy);
            draw->AddRectFilled(a, ImVec2(a.x + sx, a.y + sy), colour);
        }
    }
}

void upload_pane_texture(const GlApi& gl, GlTexture& texture, const Rgb8Image& image) {
    if (!texture) texture = GlTexture(gl);
    gl.BindTexture(GL_TEXTURE_2D, texture.id());
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const std::size_t stride = std::size_t(image.width) * 3;
    std::vector<std::uint8_t> rows(image.pixels.size());
    for (int y = 0; y < image.height; ++y)
        std::copy_n(image.pixels.data() + std::size_t(image.height - 1 - y) * stride, stride,
                    rows.data() + std::size_t(y) * stride);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image.width, image.height, 0, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    gl.BindTexture(GL_TEXTURE_2D, 0);
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
