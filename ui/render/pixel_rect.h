// A rectangle of the screen in pixels, origin top-left, y down (as ImGui and
// screenshots): what a panel covers, and what the game draws beside it.
#pragma once

namespace ui {

struct PixelRect {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
    bool overlaps(const PixelRect& o) const {
        return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
};

} // namespace ui
