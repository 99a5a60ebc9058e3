#include "ui/game/match_frame.h"

#include "ui/render/gl.h"

namespace ui {

void drawMatchFrame(Renderer2D& renderer, MatchView& view, const game::Match& match,
                    const Camera& camera, const MatchViewOptions& options) {
    gl::fn.Viewport(0, 0, camera.width, camera.height);
    gl::fn.ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl::fn.Clear(GL_COLOR_BUFFER_BIT);
    renderer.begin(camera);
    view.draw(renderer, match, options);
    renderer.flush();
}

} // namespace ui
