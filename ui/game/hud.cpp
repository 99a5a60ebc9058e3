// Section index
//   drawing     HudSpace: the design canvas in the renderer's world units; star, gauges
//   boxes       the score, wind, aim, banner, notice and end-of-match card, each a box
//   placing     Hud::place: a box's places in order, clear of the layout's objects
#include "ui/game/hud.h"

#include "game/scoring.h"
#include "ui/game/match_view.h"
#include "ui/game/palette.h"
#include "ui/game/screen_layout.h"
#include "ui/game/weapon_look.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/design_canvas.h"
#include "game/shot_model.h"
#include "physics/integrators.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace ui {

namespace {

using namespace palette;
using game::Match;
using phys::Vec2;

// ---- drawing ------------------------------------------------------------------------------
/// The HUD is laid out in design pixels (1280x720, scaled by `u` to the picture); the
/// renderer draws in world units, so convert. A box's origin is its top-left corner.
struct HudSpace {
    Renderer2D& r;
    double u = 1.0;
    double x = 0.0, y = 0.0; ///< the box's top-left corner, design px
    Vec2 w(double px, double py) const { return r.camera().toWorld({(x + px) * u, (y + py) * u}); }
    double metres(double designPx) const { return r.camera().metres(designPx * u); }
    void rect(double x0, double y0, double x1, double y1, Color c) const {
        const Vec2 q[] = {w(x0, y1), w(x1, y1), w(x1, y0), w(x0, y0)};
        r.fillConvex(q, c);
    }
    /// A panel: a rectangle with its corners cut (one convex octagon, so a translucent
    /// fill never overlaps itself) and a faint top rim.
    void panel(double x0, double y0, double x1, double y1, Color c = kPanel) const {
        const double k = 5.0;
        const Vec2 q[] = {w(x0 + k, y1), w(x1 - k, y1), w(x1, y1 - k), w(x1, y0 + k),
                          w(x1 - k, y0), w(x0 + k, y0), w(x0, y0 + k), w(x0, y1 - k)};
        r.fillConvex(q, c);
        r.line(w(x0 + k, y0 + 0.5), w(x1 - k, y0 + 0.5), kPanelEdge, static_cast<float>(u));
    }
    void text(double px, double py, const std::string& s, Color c, float scale = 1.0f,
              float alignX = 0.0f) const {
        r.screenLabel({(x + px) * u, (y + py) * u}, s, c, scale * static_cast<float>(u), alignX);
    }
};

/// A five-pointed star (not convex: a pentagon and five triangles).
void star(Renderer2D& r, Vec2 c, double outer, Color fill) {
    const double inner = outer * 0.42;
    Vec2 o[5], in[5];
    for (int k = 0; k < 5; ++k) {
        const double a = std::numbers::pi / 2 + k * 2 * std::numbers::pi / 5;
        const double b = a + std::numbers::pi / 5;
        o[k] = c + Vec2{std::cos(a), std::sin(a)} * outer;
        in[k] = c + Vec2{std::cos(b), std::sin(b)} * inner;
    }
    r.fillConvex(in, fill);
    for (int k = 0; k < 5; ++k) {
        const Vec2 tri[] = {o[k], in[(k + 4) % 5], in[k]};
        r.fillConvex(tri, fill);
    }
}

std::string playerName(const Match& m, const MatchViewOptions& o, int i) {
    if (static_cast<std::size_t>(i) < o.playerNames.size()) return o.playerNames[static_cast<std::size_t>(i)];
    return defaultPlayerName(m.cannons()[static_cast<std::size_t>(i)].def.player);
}

void drawPowerBar(const HudSpace& s, double x, double y, double w, double fraction, Color colour,
                  std::optional<double> charge) {
    s.rect(x, y, x + w, y + 12, Color::hex(0x000000, 0.45f));
    const double f = std::clamp(fraction, 0.0, 1.0);
    // Green to red as power rises.
    const Color fill = mix(Color::hex(0x4ade80), Color::hex(0xef4444), static_cast<float>(f));
    s.rect(x + 2, y + 2, x + 2 + (w - 4) * f, y + 10, charge ? fill : mix(fill, colour, 0.3f));
    for (int k = 1; k < 4; ++k)
        s.rect(x + w * k / 4.0, y + 1, x + w * k / 4.0 + 1, y + 11, Color::hex(0xffffff, 0.25f));
}

/// `text` in lines no wider than `width` design px at `scale`, broken between words (a
/// word wider than a line stands alone on it); the spaces between words on a line are
/// kept as written (the HUD spaces its fields with runs of them).
std::vector<std::string> wrapped(const std::string& text, double scale, double width) {
    std::vector<std::string> lines;
    std::string line, gap, word;
    auto place = [&] {
        if (word.empty()) return;
        if (line.empty() || designTextWidth(line + gap + word, scale) <= width) {
            line += (line.empty() ? "" : gap) + word;
        } else {
            lines.push_back(line);
            line = word;
        }
        word.clear();
        gap.clear();
    };
    for (const char c : text) {
        if (c != ' ') {
            word += c;
            continue;
        }
        place();
        gap += ' ';
    }
    place();
    if (!line.empty() || lines.empty()) lines.push_back(line);
    return lines;
}

// ---- boxes --------------------------------------------------------------------------------
// Each box: its size in design pixels, and a function drawing it at a HudSpace's origin.
constexpr double kMargin = 12.0;
constexpr double kScoreW = 292.0, kScoreH = 64.0, kDuelH = 70.0;
constexpr double kWindW = 168.0, kWindH = 48.0;
constexpr double kAimW = 312.0, kAimH = 92.0;
constexpr double kCardW = 460.0, kDuelCardH = 150.0;
constexpr double kLineH = 19.0, kSmall = 0.8; ///< a line of the card and the rules, design px
constexpr double kHeadH = 17.0, kNoteH = 14.0, kNote = 0.72; ///< the aim box's lines, design px
constexpr double kPad = 12.0; ///< a box's text from its sides, design px

/// The score box's width: its standard one, or wider for a long level name or player name.
double scoreWidth(const Match& m, const MatchViewOptions& o) {
    double w = designTextWidth(m.level().name, 1.0) + 2 * kPad;
    if (m.level().mode == game::Mode::Duel)
        for (int i = 0; i < static_cast<int>(m.cannons().size()) && i < 2; ++i)
            w = std::max(w, 30 + designTextWidth(playerName(m, o, i), 0.95) + 64);
    return std::max(kScoreW, w);
}

void drawScore(const HudSpace& s, const Match& m, double width) {
    const game::CannonState& cs = m.cannon();
    s.panel(0, 0, width, kScoreH);
    s.text(12, 7, m.level().name, kText, 1.0f);
    char line[96];
    if (m.sandbox()) {
        s.text(12, 35, "sandbox: no score, no shot budget", kGold, 0.85f);
        return;
    }
    std::snprintf(line, sizeof line, "score %d / %d", m.score(), m.maxScore());
    s.text(12, 35, line, kGold, 0.95f);
    // Shots left as pips, the number beside them when there are too many to show.
    const int shown = std::min(cs.shotsLeft, 8);
    for (int k = 0; k < shown; ++k) {
        s.r.fillCircle(s.w(width - 20 - 14 * k, 45), s.metres(4.5), kShell.withAlpha(0.9f));
        s.r.fillCircle(s.w(width - 21 - 14 * k, 44), s.metres(1.6), Color::hex(0x9aa0aa));
    }
    std::snprintf(line, sizeof line, "%d", cs.shotsLeft);
    s.text(width - 28 - 14 * shown, 36, cs.shotsLeft > 8 || shown == 0 ? line : "", kText, 0.85f, 1.0f);
}

void drawPlayers(const HudSpace& s, const Match& m, const MatchViewOptions& o, double width) {
    s.panel(0, 0, width, kDuelH);
    const int cur = m.currentPlayer();
    char line[96];
    for (int i = 0; i < static_cast<int>(m.cannons().size()) && i < 2; ++i) {
        const auto& ci = m.cannons()[static_cast<std::size_t>(i)];
        const double yy = 8 + 28 * i;
        s.r.fillCircle(s.w(18, yy + 10), s.metres(5.5), team(i));
        std::snprintf(line, sizeof line, "%s", playerName(m, o, i).c_str());
        s.text(30, yy + 1, line, i == cur && !m.over() ? kText : kTextDim, 0.95f);
        // Hit points as pips, right-aligned.
        for (int p = 0; p < game::kCannonHitPoints; ++p) {
            const Vec2 at = s.w(width - 18 - 16 * p, yy + 10);
            s.r.fillCircle(at, s.metres(6), Color::hex(0x111111, 0.6f));
            s.r.fillCircle(at, s.metres(4.5), game::kCannonHitPoints - 1 - p < ci.hitPoints
                                                  ? Color::hex(0x4ade80)
                                                  : Color::hex(0x3f3f46));
        }
    }
}

void drawWind(const HudSpace& s, double wind) {
    char text[48];
    if (std::abs(wind) < 0.05)
        std::snprintf(text, sizeof text, "wind calm");
    else
        std::snprintf(text, sizeof text, "wind %.1f m/s", std::abs(wind));
    s.panel(0, 0, kWindW, kWindH);
    // Calm has no arrow under its line: the line sits in the middle of the box instead.
    s.text(kWindW / 2, std::abs(wind) < 0.05 ? 15 : 4, text, kText, 0.85f, 0.5f);
    // Arrow length grows with the wind up to 15 m/s.
    const double len = std::abs(wind) < 0.05 ? 0.0 : 16.0 + std::min(std::abs(wind), 15.0) / 15.0 * 120.0;
    const double sign = wind >= 0 ? 1.0 : -1.0;
    if (len > 1.0) {
        const Color c = std::abs(wind) > 8 ? Color::hex(0xff8a65) : Color::hex(0x9be7ff);
        const double cx = kWindW / 2;
        s.r.arrow(s.w(cx - sign * len / 2, 33), s.w(cx + sign * len / 2, 33), c,
                  static_cast<float>(4.0 * s.u), static_cast<float>(12.0 * s.u));
    }
}

/// The forces, and the model that will fly the shell: the closed form where only gravity
/// acts and the model allows it, else the integrator chosen (game/shot_model.h).
std::string flightModelLine(const Match& m) {
    const phys::WorldDef& d = m.world().def();
    const std::string model = game::shotModelName(m);
    char rate[24] = "";
    if (model != game::kClosedFormModel) std::snprintf(rate, sizeof rate, " %.0f Hz", 1.0 / d.tickSeconds);
    char line[128];
    std::snprintf(line, sizeof line, "g %.2f m/s²  drag %s  flown by %s%s", -d.forces.gravity.y,
                  d.forces.drag == phys::DragModel::None ? "off" : "on",
                  game::shotModelLabel(model).c_str(), rate);
    return line;
}

/// The aim box's text: who fires what (wrapped), and the weapon's summary or the flight
/// model (wrapped in the smaller face), and the box's height for them.
struct AimText {
    std::vector<std::string> head, note;
    double height = kAimH;
};

AimText aimText(const Match& m, const MatchViewOptions& o) {
    const game::CannonState& cs = m.cannon();
    const game::Ammo ammo = m.selectedAmmo();
    const int left = cs.projectile < cs.ammoLeft.size() ? cs.ammoLeft[cs.projectile] : -1;
    const bool duel = m.level().mode == game::Mode::Duel;
    char line[160];
    std::snprintf(line, sizeof line, "%s%s%s   %.3g kg  %.0f mm%s",
                  duel ? playerName(m, o, m.currentPlayer()).c_str() : "", duel ? ":  " : "",
                  ammo.preset.name ? ammo.preset.name : "?", ammo.preset.mass, ammo.preset.diameter * 1000.0,
                  left >= 0 ? ("   x" + std::to_string(left)).c_str() : "");
    AimText t;
    t.head = wrapped(line, 0.85, kAimW - 28 - kPad);
    t.note = wrapped(ammo.weapon ? weaponHudLine(ammo) : flightModelLine(m), kNote, kAimW - 2 * kPad);
    t.height = kAimH + kHeadH * static_cast<double>(t.head.size() - 1) +
               kNoteH * static_cast<double>(t.note.size() - 1);
    return t;
}

void drawAim(const HudSpace& s, const Match& m, const MatchViewOptions& o, const PendingAim& aim,
             const AimText& t) {
    const game::CannonState& cs = m.cannon();
    const int cur = m.currentPlayer();
    s.panel(0, 0, kAimW, t.height);
    s.r.fillCircle(s.w(16, 16), s.metres(5.5), team(cur));
    for (std::size_t i = 0; i < t.head.size(); ++i)
        s.text(28, 7 + kHeadH * static_cast<double>(i), t.head[i], kText, 0.85f);
    const double y = kHeadH * static_cast<double>(t.head.size() - 1); // the rows below move down
    char line[64];
    std::snprintf(line, sizeof line, "%.1f°", aim.angleDeg);
    s.text(12, 28 + y, line, kText, 1.0f);
    std::snprintf(line, sizeof line, "%.1f / %.0f m/s", aim.speedMps, cs.def.maxSpeedMps);
    s.text(kAimW - 12, 28 + y, line, kText, 1.0f, 1.0f);
    const double shown = o.charge ? *o.charge * cs.def.maxSpeedMps : aim.speedMps;
    drawPowerBar(s, 12, 52 + y, kAimW - 24, shown / cs.def.maxSpeedMps, team(cur), o.charge);
    for (std::size_t i = 0; i < t.note.size(); ++i)
        s.text(12, 70 + y + kNoteH * static_cast<double>(i), t.note[i], kTextDim, static_cast<float>(kNote));
}

/// A line in a dark box, `width` design pixels for `text` at `scale`.
double lineWidth(const std::string& text, double scale) { return designTextWidth(text, scale) + 28.0; }

void drawLine(const HudSpace& s, const std::string& text, Color colour, double scale, Color back) {
    const double w = lineWidth(text, scale);
    s.panel(0, 0, w, 30, back);
    s.text(w / 2, 5, text, colour, static_cast<float>(scale), 0.5f);
}

/// A tick (earned) or an empty ring (not yet), centred at (x, y) in the box.
void drawTick(const HudSpace& s, double x, double y, bool earned) {
    if (!earned) {
        s.r.strokeCircle(s.w(x, y), s.metres(6), kTextDim, static_cast<float>(1.5 * s.u));
        return;
    }
    const auto width = static_cast<float>(3.0 * s.u);
    s.r.line(s.w(x - 6, y), s.w(x - 2, y + 5), Color::hex(0x4ade80), width);
    s.r.line(s.w(x - 2, y + 5), s.w(x + 7, y - 6), Color::hex(0x4ade80), width);
}

/// What each star needs, a line each with a tick on the ones earned, from `y` down
/// (3 lines).
std::vector<std::string> starNeedLines(const Match& m) {
    const auto needs = game::starNeeds(game::levelScoring(m.level()));
    std::vector<std::string> lines;
    for (std::size_t k = 0; k < 3; ++k)
        lines.push_back(std::to_string(k + 1) + (k ? " stars: " : " star: ") + needs[k]);
    return lines;
}

void drawStarNeeds(const HudSpace& s, const Match& m, double y) {
    const std::vector<std::string> lines = starNeedLines(m);
    for (int k = 0; k < 3; ++k) {
        const double yy = y + kLineH * k;
        drawTick(s, 26, yy + 8, k < m.stars());
        s.text(40, yy, lines[static_cast<std::size_t>(k)], k < m.stars() ? kText : kTextDim,
               static_cast<float>(kSmall));
    }
}

/// The breakdown's lines on the card: at most four.
std::vector<std::string> cardLines(const Match& m) {
    std::vector<std::string> lines = game::breakdownLines(game::breakdownOf(m), game::levelScoring(m.level()));
    lines.resize(std::min<std::size_t>(lines.size(), 4));
    return lines;
}

/// The card's height: the title and stars, the breakdown, the three stars' needs, and the
/// line that says a learning aid was used.
double cardHeight(const Match& m) {
    if (m.level().mode == game::Mode::Duel) return kDuelCardH;
    return 102 + kLineH * static_cast<double>(cardLines(m).size() + 3) + (m.assisted() ? 28 : 8);
}

constexpr const char* kAssistedNote = "assisted (full preview or hint): no third star";

std::string winnerLine(const Match& m, const MatchViewOptions& o) {
    const int win = m.winner();
    return win < 0 ? std::string("Draw") : playerName(m, o, win) + " wins!";
}

/// The card's width: its standard one, or wider for whatever line of it is longer.
double cardWidth(const Match& m, const MatchViewOptions& o) {
    double w = kCardW;
    if (m.level().mode == game::Mode::Duel) return std::max(w, designTextWidth(winnerLine(m, o), 1.8) + 4 * kPad);
    for (const std::string& line : cardLines(m)) w = std::max(w, 20 + designTextWidth(line, kSmall) + 20);
    for (const std::string& line : starNeedLines(m)) w = std::max(w, 40 + designTextWidth(line, kSmall) + 20);
    if (m.assisted()) w = std::max(w, designTextWidth(kAssistedNote, 0.8) + 4 * kPad);
    return w;
}

void drawCard(Renderer2D& r, const HudSpace& s, const Match& m, const MatchViewOptions& o, double width) {
    const bool duel = m.level().mode == game::Mode::Duel;
    s.panel(0, 0, width, cardHeight(m), Color::hex(0x0e1420, 0.88f));
    const double cx = width / 2;
    if (duel) {
        const int win = m.winner();
        const std::string who = winnerLine(m, o);
        s.text(cx, 22, who, win < 0 ? kText : team(win), 1.8f, 0.5f);
        char line[96];
        std::snprintf(line, sizeof line, "shots fired %d", m.shotsFired());
        s.text(cx, 90, line, kText, 1.1f, 0.5f);
        return;
    }
    s.text(cx, 8, m.stars() > 0 ? "Level complete!" : "Out of shots", kText, 1.4f, 0.5f);
    for (int k = 0; k < 3; ++k) {
        const Vec2 p = s.w(cx + (k - 1) * 52, 64);
        star(r, p, s.metres(23), Color::hex(0x000000, 0.4f));
        star(r, p, s.metres(20), k < m.stars() ? kGold : Color::hex(0x3a4150));
    }
    // The breakdown (targets, bonus, total), then what each star needs.
    const std::vector<std::string> lines = cardLines(m);
    for (std::size_t i = 0; i < lines.size(); ++i)
        s.text(20, 94 + kLineH * static_cast<double>(i), lines[i], i + 1 == lines.size() ? kGold : kText,
               static_cast<float>(kSmall));
    const double needsAt = 102 + kLineH * static_cast<double>(lines.size());
    drawStarNeeds(s, m, needsAt);
    if (m.assisted())
        s.text(cx, needsAt + 3 * kLineH + 4, kAssistedNote, kTextDim, 0.8f, 0.5f);
}

/// The level's scoring before the first shot: what the targets are worth, the bonus, what
/// each star needs; after it, what each star needs stays in view until the end card.
std::vector<std::string> rulesLines(const Match& m) {
    if (m.level().mode != game::Mode::Practice || m.over()) return {};
    std::vector<std::string> lines = game::scoringLines(game::levelScoring(m.level()));
    constexpr std::size_t kStarLines = 3; // the last three: one line a star
    if (m.shotsFired() > 0 && lines.size() > kStarLines)
        lines.erase(lines.begin(), lines.end() - static_cast<std::ptrdiff_t>(kStarLines));
    return lines;
}

void drawRules(const HudSpace& s, const std::vector<std::string>& lines, double w) {
    s.panel(0, 0, w, 12 + kLineH * static_cast<double>(lines.size()));
    for (std::size_t i = 0; i < lines.size(); ++i)
        s.text(12, 6 + kLineH * static_cast<double>(i), lines[i], i + 3 >= lines.size() ? kGold : kText,
               static_cast<float>(kSmall));
}

/// Design-pixel rectangles of a box w x h at each of `corners` (its top-left corner).
std::vector<PixelRect> at(std::initializer_list<Vec2> corners, double w, double h) {
    std::vector<PixelRect> rects;
    for (const Vec2 c : corners) rects.push_back({c.x, c.y, c.x + w, c.y + h});
    return rects;
}

} // namespace

// ---- placing ------------------------------------------------------------------------------
std::optional<PixelRect> Hud::place(const std::string& name, const std::vector<PixelRect>& candidates,
                                    const MatchViewOptions& o, double u, double width,
                                    double height) {
    auto pixels = [&](const PixelRect& d) { return PixelRect{d.x0 * u, d.y0 * u, d.x1 * u, d.y1 * u}; };
    if (!o.layout) return candidates.empty() ? std::nullopt : std::optional(candidates.front());
    const std::vector<PixelRect> avoid = o.layout->taken();
    const PixelRect screen{0.0, 0.0, width, height};
    auto clear = [&](const PixelRect& d) {
        const PixelRect p = pixels(d);
        if (!inside(p, screen)) return false;
        for (const PixelRect& a : avoid)
            if (p.overlaps(a)) return false;
        return true;
    };
    std::optional<std::size_t> chosen;
    if (const auto was = places_.find(name); was != places_.end() && was->second < candidates.size() &&
                                             clear(candidates[was->second]))
        chosen = was->second;
    for (std::size_t i = 0; !chosen && i < candidates.size(); ++i)
        if (clear(candidates[i])) chosen = i;
    if (!chosen) {
        places_.erase(name);
        return std::nullopt;
    }
    places_[name] = *chosen;
    o.layout->addOverlay(name, pixels(candidates[*chosen]));
    return candidates[*chosen];
}

void Hud::draw(Renderer2D& r, const Match& m, const MatchViewOptions& o, const PendingAim& aim,
               const game::Effects& fx) {
    const Camera& c = r.camera();
    const double u = hudScale(c.width, c.height);
    const double W = c.width / u, H = c.height / u; // the canvas in design pixels
    const double mg = kMargin;
    auto box = [&](const std::optional<PixelRect>& where) { return HudSpace{r, u, where->x0, where->y0}; };
    auto placed = [&](const std::string& name, const std::vector<PixelRect>& candidates) {
        return place(name, candidates, o, u, c.width, c.height);
    };
    const bool duel = m.level().mode == game::Mode::Duel;

    const double scoreH = duel ? kDuelH : kScoreH, scoreW = scoreWidth(m, o);
    if (auto p = placed("hud.score", at({{mg, mg}, {W - mg - scoreW, mg}, {mg, H - mg - scoreH}}, scoreW, scoreH))) {
        if (duel)
            drawPlayers(box(p), m, o, scoreW);
        else
            drawScore(box(p), m, scoreW);
    }
    if (auto p = placed("hud.wind", at({{W / 2 - kWindW / 2, mg}, {W / 2 - kWindW / 2, H - mg - kWindH},
                                        {W * 0.3 - kWindW / 2, mg}, {W * 0.7 - kWindW / 2, mg}},
                                       kWindW, kWindH)))
        drawWind(box(p), m.wind());
    // The aim while it can be changed: no shell in the air, the match not over.
    if (!m.shell() && !m.over()) {
        const AimText text = aimText(m, o);
        const double h = text.height;
        if (auto p = placed("hud.aim", at({{mg, H - mg - h}, {W - mg - kAimW, H - mg - h},
                                           {W - mg - kAimW, mg + kScoreH + mg}},
                                          kAimW, h)))
            drawAim(box(p), m, o, aim, text);
    }
    // The power and angle a drag sets, beside the pointer where it covers nothing.
    if (o.rubberBand && !m.shell() && !m.over()) {
        char text[64];
        std::snprintf(text, sizeof text, "%.1f m/s   %.1f°", aim.speedMps, aim.angleDeg);
        const double w = lineWidth(text, 0.85), px = o.rubberBand->x / u, py = o.rubberBand->y / u;
        if (auto p = placed("hud.pull", at({{px + 16, py + 16}, {px + 16, py - 46}, {px - 16 - w, py + 16},
                                            {px - 16 - w, py - 46}},
                                           w, 30)))
            drawLine(box(p), text, kText, 0.85, Color::hex(0x0e1420, 0.8f));
    }
    if (!o.banner.empty()) {
        const double w = lineWidth(o.banner, 1.0);
        if (auto p = placed("hud.banner", at({{W / 2 - w / 2, mg + kWindH + 8}, {W / 2 - w / 2, H / 2 - 15},
                                              {W / 2 - w / 2, H - mg - 30}},
                                             w, 30)))
            drawLine(box(p), o.banner, kGold, 1.0, Color::hex(0x000000, 0.6f));
    }
    // The shot's verdict, as the match gave it (game/verdict.h).
    if (const std::string verdict = fx.feedback().verdict(); !verdict.empty()) {
        const double w = lineWidth(verdict, 1.0);
        if (auto p = placed("hud.verdict", at({{W / 2 - w / 2, mg + kWindH + 8}, {W / 2 - w / 2, mg + kWindH + 46},
                                               {W / 2 - w / 2, H / 2 - 80}, {W / 2 - w / 2, H - mg - 30}},
                                              w, 30)))
            drawLine(box(p), verdict, kGold, 1.0, Color::hex(0x0e1420, 0.8f));
    }
    if (!o.notice.empty()) {
        const double w = lineWidth(o.notice, 0.8);
        if (auto p = placed("hud.notice", at({{W / 2 - w / 2, H - mg - 30}, {W - mg - w, H - mg - 30},
                                              {W / 2 - w / 2, H / 2 + 40}},
                                             w, 30)))
            drawLine(box(p), o.notice, kNotice, 0.8, Color::hex(0x0e1420, 0.8f));
    }
    drawRulesAndCard(r, m, o);
}

/// The level's scoring before the first shot, and the card at the match's end.
void Hud::drawRulesAndCard(Renderer2D& r, const Match& m, const MatchViewOptions& o) {
    const Camera& c = r.camera();
    const double u = hudScale(c.width, c.height);
    const double W = c.width / u, H = c.height / u, mg = kMargin;
    auto box = [&](const std::optional<PixelRect>& where) { return HudSpace{r, u, where->x0, where->y0}; };
    auto placed = [&](const std::string& name, const std::vector<PixelRect>& candidates) {
        return place(name, candidates, o, u, c.width, c.height);
    };
    if (const std::vector<std::string> rules = rulesLines(m); !rules.empty()) {
        double w = 0.0;
        for (const std::string& line : rules) w = std::max(w, lineWidth(line, kSmall));
        const double h = 12 + kLineH * static_cast<double>(rules.size());
        if (auto p = placed("hud.rules", at({{W - mg - w, mg}, {W - mg - w, H - mg - h}, {mg, mg + kScoreH + mg},
                                             {W / 2 - w / 2, H - mg - h}},
                                            w, h)))
            drawRules(box(p), rules, w);
    }
    if (m.over() && o.endCard) {
        const double ch = cardHeight(m), cw = cardWidth(m, o);
        if (auto p = placed("card", at({{W / 2 - cw / 2, H / 2 - ch / 2}, {W / 2 - cw / 2, mg + kWindH + 8},
                                        {W / 2 - cw / 2, H - mg - ch}, {mg, H / 2 - ch / 2},
                                        {W - mg - cw, H / 2 - ch / 2}, {mg, mg}, {W - mg - cw, mg},
                                        {mg, H - mg - ch}, {W - mg - cw, H - mg - ch}},
                                       cw, ch)))
            drawCard(r, box(p), m, o, cw);
    }
}

} // namespace ui
