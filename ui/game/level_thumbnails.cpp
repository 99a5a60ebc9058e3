#include "ui/game/level_thumbnails.h"

#include "game/level.h"
#include "game/match.h"
#include "ui/render/gl.h"

namespace ui {

const TextureTarget* LevelThumbnails::picture(const std::string& file, int width, int height,
                                              unsigned restoreFbo) {
    const std::string key = file + "@" + std::to_string(width) + "x" + std::to_string(height);
    if (const auto it = pictures_.find(key); it != pictures_.end()) return it->second.get();
    std::unique_ptr<TextureTarget>& slot = pictures_[key]; // a failure is kept too: not tried again
    std::optional<game::Match> match;
    try {
        match.emplace(game::loadLevel(file));
    } catch (const std::exception&) {
        return nullptr; // the tile says why (the level list has the loader's message)
    }
    auto target = std::make_unique<TextureTarget>();
    if (!target->create(width, height, 4)) return nullptr;
    if (!renderer_) renderer_ = std::make_unique<Renderer2D>();
    target->bind();
    const Camera camera = levelCamera(*match, width, height);
    gl::fn.Viewport(0, 0, width, height);
    gl::fn.ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl::fn.Clear(GL_COLOR_BUFFER_BIT);
    renderer_->begin(camera);
    MatchViewOptions o;
    o.hud = false;
    o.trajectoryPreview = false;
    o.effects = false;
    view_.reset();
    view_.draw(*renderer_, *match, o);
    renderer_->flush();
    target->finish(restoreFbo);
    slot = std::move(target);
    return slot.get();
}

} // namespace ui
