// How a match looks: sky, terrain with its craters, water, obstacles, Box2D blocks,
// ropes, blobs, cloth (ui/game/cloth_view.h), cannons, targets, the shell and its trail,
// the trajectory preview, the firing-solution hint, the effects (ui/game/effects_view.h),
// the wind and the HUD (ui/game/hud.h). One drawing path for the window and for
// headless frames (`artillery run --png`): everything goes through Renderer2D,
// the HUD included (boxes in pixel space, text as labels that ImGui draws).
//
// The view reads the match and keeps only what a picture needs across frames (the
// shell's trail, cached previews); it never changes the match.
//
// Section index
//   options      MatchViewOptions: toggles and what the window adds (pending aim, charge)
//   camera       levelCamera(): the view that frames a level
//   MatchView    observe() after ticks, draw() per frame
#pragma once

#include "game/effects/effects.h"
#include "game/match.h"
#include "ui/render/camera.h"
#include "ui/game/hud.h"
#include "ui/game/level_camera.h"
#include "ui/game/screen_layout.h"
#include "ui/render/design_canvas.h"
#include "ui/render/pixel_rect.h"
#include "ui/render/renderer2d.h"
#include "ui/render/world_view.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ui {

/// An aim the player is still adjusting (drag, keys, charge), not yet sent as commands.
struct PendingAim {
    double angleDeg = 45.0;
    double speedMps = 30.0;
};

struct MatchViewOptions {
    bool trajectoryPreview = true; ///< dotted path the current aim would take
    /// The whole path to the first contact (a learning aid: the window sends an `assist`
    /// command while it shows); off, the preview is the launch arc only, its first
    /// kPreviewArcSeconds.
    bool fullPreview = false;
    bool effects = true;           ///< debris, smoke, flashes, craters, splashes, shot feedback
    bool solutionHint = false;     ///< the computer's aim (aimAt) as a golden ghost barrel
    bool hud = true;               ///< turn, wind, angle, power, shots, score, stars
    bool trails = true;            ///< the shell's path so far
    /// The debug view over the match: velocities, forces, closed-form ghosts, contacts,
    /// grid cells, sleeping state, models (ui/render/world_view.h).
    DebugOverlays overlays;
    /// The aim being edited in the window; the barrel, the power bar and the preview
    /// follow it instead of the cannon's committed aim.
    std::optional<PendingAim> pending;
    /// Where a drag pulls the aim, px (a rubber band from the cannon, with the power and
    /// angle it sets beside the pointer), while one is aiming.
    std::optional<phys::Vec2> rubberBand;
    /// Fraction 0..1 of a Space charge in progress (draws the charge gauge), if any.
    std::optional<double> charge;
    /// Name of who plays each cannon, as the HUD shows it ("Player 1", "Computer").
    std::vector<std::string> playerNames;
    /// The card at the end of the match (stars, score; the winner): a live game's, not a
    /// replay's.
    bool endCard = true;
    /// A line in the middle of the top of the screen ("Paused", "x0.25").
    std::string banner;
    /// A command the match refused ("spawn: spawn point is outside the world"), "" for none.
    std::string notice;
    /// The frame's layout (screen_layout.h): the objects drawn go into it, as seen from
    /// `layoutView` ("main", or "inset" for the close-up, whose picture lies at
    /// `layoutOffset` on the screen and is `layoutClip` there); the HUD's boxes are placed
    /// clear of them and go into it too. Null: nothing is gathered, the boxes stand at
    /// their first places.
    ScreenLayout* layout = nullptr;
    std::string layoutView = "main";
    phys::Vec2 layoutOffset;
    std::optional<PixelRect> layoutClip;
};

/// How much of the path the preview shows when it is not the full one, the launch arc:
/// its first kPreviewArcSeconds of flight, or its first kPreviewArcPixels on screen
/// where the half second is shorter. A map seen whole can be 640 m across 1,280 px, where
/// half a second of a 32 m/s shot is 32 px of screen, most of it under the cannon's
/// ring: a launch arc no one sees. Either way the arc ends at the first contact, and it
/// is computed for at most kPreviewArcMostSeconds.
inline constexpr double kPreviewArcSeconds = 0.5;
inline constexpr double kPreviewArcPixels = 160.0;
inline constexpr double kPreviewArcMostSeconds = 4.0;

/// How many points of `path` (its start, then one a tick of tickSeconds) the launch arc
/// shows where a pixel is metresPerPixel: up to the first point at least
/// kPreviewArcSeconds into the flight and kPreviewArcPixels along the path, both.
std::size_t launchArcPoints(const std::vector<phys::Vec2>& path, double tickSeconds,
                            double metresPerPixel);

/// Where the panels beside the aim readout at the bottom left start, in screen pixels:
/// right of it, whatever the HUD's scale (the readout ends at 324 design pixels).
inline float besideAimReadout(double width, double height) {
    return static_cast<float>(336.0 * hudScale(width, height));
}
/// The HUD's margin to the screen's edges (12 design pixels), which the panels beside it
/// keep too.
inline float hudMargin(double width, double height) {
    return static_cast<float>(12.0 * hudScale(width, height));
}
/// Where the panels at the top right start, in screen pixels: at the top, `margin` from
/// it, or under the wind gauge (the middle 180 design pixels of the top, 68 deep) when a
/// panel `panelWidth` wide at the right edge would reach over it (screens narrower than
/// about 940 pixels).
inline float topRightPanelsTop(double width, double height, float panelWidth, float margin) {
    const double u = hudScale(width, height);
    const bool overGauge = width - margin - panelWidth < 0.5 * width + 90.0 * u + margin;
    return overGauge ? static_cast<float>(68.0 * u) + margin : margin;
}
/// Where the panels under the score box at the top left start, in screen pixels (the box
/// ends at 82 design pixels in a duel, 76 otherwise).
inline float belowLevelHeading(double width, double height) {
    return static_cast<float>(90.0 * hudScale(width, height));
}

/// Seen from far, a 1.5 m barrel is a few pixels: cannons are drawn scaled by this
/// factor (>= 1) so the barrel is at least 24 px long and the aim reads at a glance.
/// The shell still leaves from the true muzzle.
double cannonDrawScale(const Camera& camera);

/// A target's radius as drawn, m: never under 6 px, so a far target is still a bullseye.
double targetDrawRadius(const game::TargetState& target, const Camera& camera);
/// The shell's radius as drawn, m: never under 4 px, so a shell smaller than 6 px across
/// on screen is drawn larger than life (its glow reaches kShellGlow times that).
double shellDrawRadius(double radius, const Camera& camera);
/// How far the shell's glow reaches, in shell radii as drawn: the layout reports the
/// shell by its glow.
inline constexpr double kShellGlow = 1.6;

/// Half extents of the axis-aligned box around a block turned by its body's angle, m.
phys::Vec2 turnedHalf(const game::Match& match, const game::BlockState& block);

/// The colour of cannon `index`'s team (its band, carriage, shells' trails, HUD rows).
phys::Color teamColor(int index);
/// A target's paint: the red rings, and the white ones.
phys::Color targetRed();
phys::Color targetWhite();

/// How the HUD names a cannon's `player` field: "Computer" for "cpu", else "Player N".
std::string defaultPlayerName(const std::string& player);

class MatchView {
  public:
    /// Call after each tick (or each rendered tick headless): extends the shell's trail
    /// and, while the last draw() showed them, follows the closed-form ghosts.
    void observe(const game::Match& match);
    /// Forgets the trails and caches (a new match).
    void reset();
    /// Follows the closed-form ghosts from the next observe() on, before any draw() asks
    /// for them (a warm-up, a replay's first seconds); draw() then keeps it up to date.
    void followGhosts(bool on) { ghostsShown_ = on; }
    /// Draws the match through `r` (begin() must have been called with the camera).
    void draw(Renderer2D& r, const game::Match& match, const MatchViewOptions& options);
    /// What the effects are doing (the window's screen shake and camera read it).
    const game::Effects& effects() const { return effects_; }

  private:
    void drawPreview(Renderer2D& r, const game::Match& match, const PendingAim& aim, bool full);
    void drawHint(Renderer2D& r, const game::Match& match);
    void drawTrails(Renderer2D& r, const game::Match& match);
    /// Puts what the player must see, as drawn, into `options.layout`.
    void addObjects(const Renderer2D& r, const game::Match& match, const MatchViewOptions& options) const;

    struct Trail {
        std::vector<phys::Vec2> points;
        int player = 0;
    };
    Trail current_;
    std::vector<Trail> old_; ///< the last few shots, fading
    phys::ParticleId trailShell_ = phys::kNoParticle;
    int trailShot_ = -1;
    phys::ClosedFormGhosts ghosts_;
    bool ghostsShown_ = false;

    // The preview and the hint are re-simulated only when what they depend on changes.
    struct AimKey {
        double angle = 0, speed = 0, wind = 0, gravity = 0, tick = 0;
        int player = -1, shots = -1, integrator = -1, projectile = -1, drag = -1;
        double moment = 0; ///< for an aim that changes with time (a moving target's lead)
        bool operator==(const AimKey&) const = default;
    };
    AimKey previewKey_, hintKey_;
    bool previewFull_ = false;
    game::Effects effects_;
    std::vector<phys::Vec2> preview_;
    std::optional<PendingAim> hint_;
    bool hintExact_ = false;
    Hud hud_;
};

} // namespace ui
