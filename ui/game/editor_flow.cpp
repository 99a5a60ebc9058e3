#include "ui/game/editor_flow.h"

#include "game/level_write.h"
#include "ui/platform/imgui_layer.h"

#include <SDL.h>

#include <algorithm>
#include <filesystem>

namespace ui {

void EditorFlow::open(game::Level level, const std::string& mapsFolder) {
    view_ = std::make_unique<LevelEditorView>(std::move(level), mapsFolder);
    editing_ = true;
    playtest_ = false;
}

void EditorFlow::resume() {
    editing_ = true;
    playtest_ = false;
}

std::optional<std::string> EditorFlow::writePlaytest(const std::string& mapsFolder,
                                                     std::string& error) {
    const game::editor::LevelEditor& edited = view_->editor();
    if (!edited.valid()) return std::nullopt;
    const std::string file = (std::filesystem::path(mapsFolder) / "playtest.json").string();
    try {
        std::filesystem::create_directories(mapsFolder);
        game::saveLevel(file, edited.level());
    } catch (const std::exception& e) {
        error = e.what();
        return std::nullopt;
    }
    return file;
}

void EditorFlow::mouse(const SDL_Event& e, const ImGuiLayer& imgui, CameraControl& camera,
                       phys::Vec2 pixelsPerPoint, int windowWidth) {
    LevelEditorView& view = *view_;
    // The panel takes the mouse over it, but a drag begun in the world ends in the world.
    if ((imgui.wantsMouse() || imgui.pressOnWindow(e)) && !view.dragging() && !camera.panning())
        return;
    const Camera& c = camera.camera();
    auto world = [&](int x, int y) { return c.toWorld({x * pixelsPerPoint.x, y * pixelsPerPoint.y}); };
    const double reach = c.metres(8.0); // a handle takes clicks 8 px around it
    // Over the panel a press is the panel's, even on the frame the editor comes back
    // (ImGui learns what is under the pointer only from the frame it draws).
    const bool overPanel = e.type == SDL_MOUSEBUTTONDOWN &&
                           e.button.x * pixelsPerPoint.x <
                               std::min<double>(panelPx(kEditorPanelWidth), 0.5 * windowWidth);
    if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button == SDL_BUTTON_LEFT && !overPanel)
        view.press(world(e.button.x, e.button.y), reach);
    else if (e.type == SDL_MOUSEBUTTONUP && e.button.button == SDL_BUTTON_LEFT)
        view.lift();
    else {
        if (e.type == SDL_MOUSEMOTION) view.move(world(e.motion.x, e.motion.y), reach);
        camera.event(e, pixelsPerPoint, false); // wheel zooms, right (or middle) drag pans
    }
}

} // namespace ui
