// Screenshots: read the framebuffer back and write it as PNG (stb_image_write).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ui {

/// An RGBA8 picture, rows top to bottom (as image files and screens have them).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;

    const std::uint8_t* pixel(int x, int y) const {
        return &rgba[(std::size_t(y) * width + x) * 4];
    }
};

/// Reads the colour buffer of framebuffer `fbo` (0: the default one). GL's rows run
/// bottom to top; they are flipped here so row 0 is the top of the picture.
Image readFramebuffer(unsigned fbo, int width, int height);

/// Writes a PNG. Returns "" on success, else why not (with the path).
std::string writePng(const std::string& path, const Image& image);

} // namespace ui
