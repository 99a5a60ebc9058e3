// png_check FILE.png [MIN_WIDTH MIN_HEIGHT]: exits 0 when the PNG is a real game frame,
// 1 otherwise (with the reason). "Real" means: it loads, has the size asked for, is not
// one flat colour, has many colours (gradients, shapes, text), and its top (sky) and
// bottom (ground) differ. Used by the window test under Xvfb.
#include <stb_image.h>

#include <cstdio>
#include <cstdlib>
#include <set>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: png_check FILE.png [MIN_WIDTH MIN_HEIGHT]\n");
        return 2;
    }
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(argv[1], &w, &h, &n, 3);
    if (!px) {
        std::fprintf(stderr, "png_check: cannot load %s: %s\n", argv[1], stbi_failure_reason());
        return 1;
    }
    const int minW = argc > 3 ? std::atoi(argv[2]) : 1, minH = argc > 3 ? std::atoi(argv[3]) : 1;
    int failed = 0;
    if (w < minW || h < minH) {
        std::fprintf(stderr, "png_check: %dx%d is smaller than %dx%d\n", w, h, minW, minH);
        failed = 1;
    }
    std::set<unsigned> colours;
    long long top[3] = {}, bottom[3] = {};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const unsigned char* p = px + (static_cast<long long>(y) * w + x) * 3;
            colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
            long long* band = y < h / 10 ? top : (y >= h - h / 10 ? bottom : nullptr);
            if (band)
                for (int c = 0; c < 3; ++c)
                    band[c] += p[c];
        }
    stbi_image_free(px);
    if (colours.size() < 100) {
        std::fprintf(stderr, "png_check: only %zu colours: blank or nearly\n", colours.size());
        failed = 1;
    }
    long long diff = 0;
    for (int c = 0; c < 3; ++c)
        diff += std::llabs(top[c] - bottom[c]);
    const long long bandPixels = static_cast<long long>(w) * (h / 10);
    if (bandPixels == 0 || diff / bandPixels < 60) {
        std::fprintf(stderr, "png_check: the top and bottom of the picture look alike\n");
        failed = 1;
    }
    if (!failed)
        std::printf("png_check: %s %dx%d, %zu colours: ok\n", argv[1], w, h, colours.size());
    return failed;
}
