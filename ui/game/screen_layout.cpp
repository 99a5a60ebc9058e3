#include "ui/game/screen_layout.h"

#include <cmath>
#include <cstdio>

namespace ui {

void ScreenLayout::clear(int w, int h) {
    width = w;
    height = h;
    overlays.clear();
    objects.clear();
}

void ScreenLayout::addOverlay(std::string name, const PixelRect& rect) {
    overlays.push_back({std::move(name), rect});
}

void ScreenLayout::addObject(std::string kind, std::string view, const PixelRect& rect) {
    // Off screen, an object is not seen, and nothing can cover it.
    if (!rect.overlaps(PixelRect{0.0, 0.0, static_cast<double>(width), static_cast<double>(height)}))
        return;
    objects.push_back({std::move(kind), std::move(view), rect});
}

std::vector<PixelRect> ScreenLayout::objectRects() const {
    std::vector<PixelRect> rects;
    for (const LayoutObject& o : objects) rects.push_back(o.rect);
    return rects;
}

std::vector<PixelRect> ScreenLayout::overlayRects() const {
    std::vector<PixelRect> rects;
    for (const LayoutOverlay& o : overlays) rects.push_back(o.rect);
    return rects;
}

std::vector<PixelRect> ScreenLayout::taken() const {
    std::vector<PixelRect> rects = objectRects();
    for (const LayoutOverlay& o : overlays) rects.push_back(o.rect);
    return rects;
}

std::optional<PixelRect> ScreenLayout::placeOverlay(std::string name,
                                                    std::span<const PixelRect> candidates) {
    const auto clear = firstClear(candidates, taken(),
                                  PixelRect{0.0, 0.0, static_cast<double>(width), static_cast<double>(height)});
    if (clear) addOverlay(std::move(name), *clear);
    return clear;
}

std::vector<Covering> coverings(const ScreenLayout& layout) {
    std::vector<Covering> found;
    for (std::size_t i = 0; i < layout.overlays.size(); ++i)
        for (std::size_t j = 0; j < layout.objects.size(); ++j) {
            const LayoutObject& object = layout.objects[j];
            // The close-up's own copies lie inside it by design.
            if (object.view == "inset" && layout.overlays[i].name == "inset") continue;
            if (layout.overlays[i].rect.overlaps(object.rect)) found.push_back({i, j});
        }
    return found;
}

namespace {

/// [x, y, w, h] in whole pixels, the rectangle's pixels all inside; `separator` between.
std::string rectText(const PixelRect& r, const char* separator = ", ") {
    char text[112];
    std::snprintf(text, sizeof text, "[%.0f%s%.0f%s%.0f%s%.0f]", std::floor(r.x0), separator,
                  std::floor(r.y0), separator, std::ceil(r.x1) - std::floor(r.x0), separator,
                  std::ceil(r.y1) - std::floor(r.y0));
    return text;
}

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
    return out + "\"";
}

} // namespace

std::string describe(const ScreenLayout& layout, const Covering& c) {
    const LayoutOverlay& o = layout.overlays[c.overlay];
    const LayoutObject& b = layout.objects[c.object];
    return o.name + " " + rectText(o.rect) + " covers " + b.kind + " (" + b.view + ") " +
           rectText(b.rect);
}

std::string layoutJson(const ScreenLayout& layout) {
    std::string out = "{\"size\":[";
    out += std::to_string(layout.width);
    out += ',';
    out += std::to_string(layout.height);
    out += "],\"overlays\":[";
    for (std::size_t i = 0; i < layout.overlays.size(); ++i) {
        if (i > 0) out += ',';
        out += "{\"name\":";
        out += quoted(layout.overlays[i].name);
        out += ",\"rect\":";
        out += rectText(layout.overlays[i].rect, ",");
        out += '}';
    }
    out += "],\"objects\":[";
    for (std::size_t i = 0; i < layout.objects.size(); ++i) {
        if (i > 0) out += ',';
        out += "{\"kind\":";
        out += quoted(layout.objects[i].kind);
        out += ",\"view\":";
        out += quoted(layout.objects[i].view);
        out += ",\"rect\":";
        out += rectText(layout.objects[i].rect, ",");
        out += '}';
    }
    out += "]}";
    return out;
}

bool inside(const PixelRect& inner, const PixelRect& outer) {
    return inner.x0 >= outer.x0 && inner.y0 >= outer.y0 && inner.x1 <= outer.x1 && inner.y1 <= outer.y1;
}

PixelRect grown(const PixelRect& r, double px) {
    return {r.x0 - px, r.y0 - px, r.x1 + px, r.y1 + px};
}

std::optional<PixelRect> firstClear(std::span<const PixelRect> candidates,
                                    std::span<const PixelRect> avoid, const PixelRect& screen) {
    for (const PixelRect& c : candidates) {
        if (!inside(c, screen)) continue;
        bool clear = true;
        for (const PixelRect& a : avoid) clear = clear && !c.overlaps(a);
        if (clear) return c;
    }
    return std::nullopt;
}

} // namespace ui
