// The lessons' pictures: the idea of a chapter drawn by the game's renderer from the
// chapter's own formula, not from a file: the two trajectories of the firing solution,
// the same shot on the Moon and on Earth, a bounce losing height by e squared each time,
// a shot in air against the same shot in vacuum, a mass on a spring, a block that tips,
// explicit Euler drifting off the parabola. Each is drawn once into a texture and kept.
#pragma once

#include "ui/render/renderer2d.h"
#include "ui/render/texture_target.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ui {

/// The names a chapter's "picture" may take (levels/README.md).
const std::vector<std::string>& lessonPictureNames();

/// What the picture shows, in a line under it ("39.1° and 75.2°: two angles reach the
/// flag"); "" for a name it does not know.
std::string lessonPictureCaption(const std::string& name);

class LessonPictures {
  public:
    /// The picture `name`, width x height px: drawn now if it is new (then `restoreFbo`
    /// is bound for drawing again). Null for a name it does not know.
    const TextureTarget* picture(const std::string& name, int width, int height, unsigned restoreFbo);

  private:
    std::map<std::string, std::unique_ptr<TextureTarget>> pictures_;
    std::unique_ptr<Renderer2D> renderer_;
};

} // namespace ui
