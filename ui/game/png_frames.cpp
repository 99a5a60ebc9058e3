#include "ui/game/png_frames.h"

#include "ui/render/screenshot.h"
#include "ui/video/video_frames.h"

#include <stb_image_write.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string_view>

namespace ui {

std::unique_ptr<PngFrameSink> PngFrameSink::create(const std::string& folder, int width,
                                                   int height, bool hud, HeadlessBackend backend,
                                                   std::string& why) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) {
        why = "cannot create folder '" + folder + "': " + ec.message();
        return nullptr;
    }
    std::unique_ptr<PngFrameSink> sink(new PngFrameSink());
    sink->canvas_ = OffscreenMatch::create(width, height, hud, backend, why);
    if (!sink->canvas_) return nullptr;
    sink->folder_ = folder;
    // A run writes many frames: zlib level 2 instead of stb's 8 and one filter for
    // every row make encoding much faster for slightly larger files.
    stbi_write_png_compression_level = 2;
    stbi_write_force_png_filter = 1; // "sub" for every row: no per-row trial of all five
    return sink;
}

PngFrameSink::~PngFrameSink() {
    if (std::getenv("ARTILLERY_FRAME_TIMES") && written_ > 0)
        std::fprintf(
            stderr,
            "png frames: %d, drawing %.1f ms/frame, reading back and encoding %.1f ms/frame\n",
            written_, drawMs_ / written_, writeMs_ / written_);
}

void PngFrameSink::frame(const game::Match& match) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    canvas_->draw(match, 1.0 / 60.0);
    const auto t1 = Clock::now();
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06llu.png",
                  static_cast<unsigned long long>(match.tick()));
    const std::string path = (std::filesystem::path(folder_) / name).string();
    const std::string err = writePng(path, canvas_->readBack());
    drawMs_ += std::chrono::duration<double, std::milli>(t1 - t0).count();
    writeMs_ += std::chrono::duration<double, std::milli>(Clock::now() - t1).count();
    if (!err.empty()) {
        // The frames are the run's output: one that cannot be written (a full disk, the
        // folder removed) stops the run, which says so, rather than leave a gap in them.
        if (error_.empty()) error_ = err;
        throw std::runtime_error("frame " + path + " was not written: " + err);
    }
    ++written_;
}

game::cli::FrameSinkFactory pngFrameSinkFactory() {
    return [](const std::string& folder, int width, int height, bool hud,
              std::string& why) -> std::unique_ptr<game::FrameSink> {
        return PngFrameSink::create(folder, width, height, hud, HeadlessBackend::Auto, why);
    };
}

namespace {

int runWithRenderer(const game::cli::Args& args, std::ostream& out) {
    static const game::cli::FrameSinkFactory factory = pngFrameSinkFactory();
    static const game::cli::VideoSinkFactory videos = videoSinkFactory();
    return game::cli::runHeadlessVerb(args, out, &factory, &videos);
}

} // namespace

game::cli::Verb runVerbWithRenderer() {
    for (const game::cli::Verb& v : game::cli::verbs()) {
        if (std::string_view(v.name) != "run") continue;
        game::cli::Verb withRenderer = v; // same name, summary, help and flags
        withRenderer.run = runWithRenderer;
        return withRenderer;
    }
    // The game layer always has `run`; an empty entry would hide a renamed verb.
    throw std::logic_error("game::cli::verbs() has no 'run' verb to give the renderer to");
}

} // namespace ui
