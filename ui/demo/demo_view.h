// How the demo scene looks: sky, hills, ground, the cannon and the gallows around the
// physics (drawn by ui/render/world_view.h), shell trails and landing marks.
#pragma once

#include "ui/demo/demo_scene.h"
#include "ui/render/renderer2d.h"
#include "ui/render/world_view.h"

namespace ui {

struct DemoViewOptions {
    bool trails = true;
    bool labels = true;
    WorldDrawOptions world;
};

/// The whole demo frame's geometry and labels (not the panels).
void drawDemo(Renderer2D& r, const DemoScene& scene, const DemoViewOptions& options);

/// A camera that frames the demo's playfield in a viewport of this size.
Camera demoCamera(const DemoScene& scene, int width, int height);

} // namespace ui
