#pragma once

namespace m3055 {

// A box of display pixels, [x0, x1) x [y0, y1), rows counted from the bottom
// as GL does: what a render may be limited to (Renderer::render_region).
struct DisplayRegion {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool operator==(const DisplayRegion& o) const { return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1; }
};

}  // namespace m3055
