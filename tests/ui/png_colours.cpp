// png_colours FILE.png RRGGBB>=N ... | RRGGBB<=N ...: exits 0 when, for every argument,
// the number of pixels within 12 per channel of the colour is at least (>=) or at most
// (<=) N; 1 otherwise, 2 on bad usage. It prints every count. Used to check that a picture
// shows the debug view's colours (ui/render/world_view.h kOverlay*) and that one drawn
// without the overlays does not.
#include <stb_image.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: png_colours FILE.png RRGGBB>=N|RRGGBB<=N ...\n");
        return 2;
    }
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(argv[1], &w, &h, &n, 3);
    if (!px) {
        std::fprintf(stderr, "png_colours: cannot load %s: %s\n", argv[1], stbi_failure_reason());
        return 1;
    }
    constexpr int kTolerance = 12;
    int failed = 0;
    for (int a = 2; a < argc; ++a) {
        const std::string arg = argv[a];
        const std::size_t op = arg.find_first_of("<>");
        if (op != 6 || arg.size() < 9 || arg[7] != '=') {
            std::fprintf(stderr, "png_colours: expected RRGGBB>=N or RRGGBB<=N, got '%s'\n", arg.c_str());
            stbi_image_free(px);
            return 2;
        }
        const unsigned long rgb = std::strtoul(arg.substr(0, 6).c_str(), nullptr, 16);
        const long limit = std::atol(arg.c_str() + 8);
        const int want[3] = {static_cast<int>(rgb >> 16 & 0xff), static_cast<int>(rgb >> 8 & 0xff),
                             static_cast<int>(rgb & 0xff)};
        long count = 0;
        for (long i = 0; i < static_cast<long>(w) * h; ++i) {
            const unsigned char* p = px + i * 3;
            count += std::abs(p[0] - want[0]) <= kTolerance && std::abs(p[1] - want[1]) <= kTolerance &&
                     std::abs(p[2] - want[2]) <= kTolerance;
        }
        const bool atLeast = arg[6] == '>';
        const bool ok = atLeast ? count >= limit : count <= limit;
        std::printf("png_colours: %s has %ld pixels of #%s (want %s %ld): %s\n", argv[1], count,
                    arg.substr(0, 6).c_str(), atLeast ? ">=" : "<=", limit, ok ? "ok" : "FAILED");
        failed |= !ok;
    }
    stbi_image_free(px);
    return failed;
}
