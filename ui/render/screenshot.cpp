#include "ui/render/screenshot.h"

#include "ui/render/gl.h"

#include <cstring>
#include <stb_image_write.h>

namespace ui {

Image readFramebuffer(unsigned fbo, int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.resize(std::size_t(width) * height * 4);
    gl::fn.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    gl::fn.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::fn.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    // Flip rows in place: GL's origin is bottom-left.
    const std::size_t row = std::size_t(width) * 4;
    std::vector<std::uint8_t> tmp(row);
    for (int y = 0; y < height / 2; ++y) {
        std::uint8_t* a = &image.rgba[std::size_t(y) * row];
        std::uint8_t* b = &image.rgba[std::size_t(height - 1 - y) * row];
        std::memcpy(tmp.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, tmp.data(), row);
    }
    // The window's alpha channel is whatever blending left; a screenshot is opaque.
    for (std::size_t i = 3; i < image.rgba.size(); i += 4)
        image.rgba[i] = 255;
    return image;
}

std::string writePng(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0) return "screenshot: empty image, nothing written";
    const int ok = stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(),
                                  image.width * 4);
    if (!ok) return "screenshot: cannot write " + path + " (does the directory exist?)";
    return "";
}

} // namespace ui
