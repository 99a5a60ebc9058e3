#include "ui/play/physics_panel.h"

#include "game/settings.h"
#include "physics/integrators.h"
#include "ui/game/match_view.h"
#include "ui/platform/imgui_layer.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace ui {

namespace {

/// A titled divider between groups of controls.
void section(const char* title) {
    ImGui::Spacing();
    ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", title);
    ImGui::Separator();
}

constexpr int kTickRates[] = {30, 60, 120, 240, 480, 960}; // Hz

/// The first row of the integrator list: the `auto` model.
constexpr const char* kClosedFormRow = "closed form (exact, where only gravity acts)";

/// The model and the integrator in one list: its first row is the `auto` model (the closed
/// form flies whatever only gravity reaches, the integrator the rest); any other row sets
/// the `integrate` model and that integrator, so the shell flies by what was picked. Both
/// reach the match as the `set model` and `set integrator` commands they always were.
bool integratorCombo(phys::WorldDef& def) {
    bool changed = false;
    const phys::IntegratorInfo& current = phys::info(def.integrator);
    const bool closedForm = def.model == phys::ModelPolicy::Auto;
    if (ImGui::BeginCombo("integrator", closedForm ? "closed form (exact)" : current.name)) {
        if (ImGui::Selectable(kClosedFormRow, closedForm) && !closedForm) {
            def.model = phys::ModelPolicy::Auto;
            changed = true;
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("p0 + v0 t + g t^2/2: no error at any tick rate.\n"
                              "Drag, wind, water and springs still go through %s.",
                              current.name);
        for (const phys::IntegratorInfo& i : phys::integrators()) {
            const bool selected = !closedForm && i.id == def.integrator;
            if (ImGui::Selectable(i.name, selected) && !selected) {
                def.integrator = i.id;
                def.model = phys::ModelPolicy::Integrate;
                changed = true;
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("order %d, %d force evaluations per step\n%s\n"
                                  "every particle, the shell too, through it",
                                  i.order, i.evaluations, i.summary);
            if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    if (closedForm) ImGui::TextDisabled("where other forces act: %s", current.name);
    return changed;
}

bool tickRateCombo(phys::WorldDef& def) {
    const int hz = static_cast<int>(std::lround(1.0 / def.tickSeconds));
    char preview[32];
    std::snprintf(preview, sizeof preview, "%d Hz (%.2f ms)", hz, 1000.0 * def.tickSeconds);
    bool changed = false;
    if (ImGui::BeginCombo("tick rate", preview)) {
        for (int rate : kTickRates) {
            char item[16];
            std::snprintf(item, sizeof item, "%d Hz", rate);
            if (ImGui::Selectable(item, rate == hz) && rate != hz) {
                def.tickSeconds = 1.0 / rate;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

bool gravityCombo(phys::WorldDef& def) {
    const double g = -def.forces.gravity.y;
    const int index = gravityPresetIndex(g);
    char preview[48];
    if (index >= 0)
        std::snprintf(preview, sizeof preview, "%s (%.2f m/s^2)", phys::kGravityPresets[index].name,
                      g);
    else
        std::snprintf(preview, sizeof preview, "custom (%.2f m/s^2)", g);
    bool changed = false;
    if (ImGui::BeginCombo("gravity", preview)) {
        for (int i = 0; i < static_cast<int>(std::size(phys::kGravityPresets)); ++i) {
            char item[48];
            std::snprintf(item, sizeof item, "%s  %.2f m/s^2", phys::kGravityPresets[i].name,
                          phys::kGravityPresets[i].g);
            if (ImGui::Selectable(item, i == index) && i != index) {
                def.forces.gravity = {0.0, -phys::kGravityPresets[i].g};
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

/// The setting's help from the settings table, as the hovered item's tooltip.
void settingTooltip(const char* name) {
    if (!ImGui::IsItemHovered()) return;
    if (const game::SettingInfo* s = game::findSetting(name))
        ImGui::SetTooltip("%s\n\nset %s: %s", s->help, name, game::expectation(*s).c_str());
}

/// A combo over the names a Choice setting takes; edits go through game::applySetting.
template <class Settings>
bool choiceCombo(const char* label, Settings& s, const std::string& name) {
    const game::SettingInfo* info = game::findSetting(name);
    const game::SettingValue now = game::readSetting(s, name);
    const std::string* current = std::get_if<std::string>(&now);
    bool changed = false;
    if (ImGui::BeginCombo(label, current ? current->c_str() : "custom")) {
        for (const std::string& choice : game::settingChoices(*info)) {
            const bool selected = current && *current == choice;
            if (ImGui::Selectable(choice.c_str(), selected) && !selected)
                changed = game::applySetting(s, name, choice).empty();
        }
        ImGui::EndCombo();
    }
    settingTooltip(info->name);
    return changed;
}

/// Contact model and continuous detection: world settings, in the demo and in matches.
bool contactControls(phys::WorldDef& def) {
    bool changed = choiceCombo("contact model", def, "contact_model");
    bool continuous = def.collision.continuous;
    if (ImGui::Checkbox("continuous detection", &continuous))
        changed |= game::applySetting(def, "continuous", continuous).empty();
    settingTooltip("continuous");
    return changed;
}

/// The last refusal of a typed value, shown under the material controls until the next
/// edit succeeds (the panel has no other state to keep it in).
std::string& materialRefusal() {
    static std::string why;
    return why;
}

/// Applies a typed value; a refusal is kept for display.
bool applyTyped(game::LiveSettings& s, const std::string& name, const game::SettingValue& v) {
    materialRefusal() = game::applySetting(s, name, v);
    return materialRefusal().empty();
}

/// A number typed and confirmed with Enter (dragging would send a command per frame).
bool typedNumber(const char* id, double shown, double& typed) {
    typed = shown;
    ImGui::SetNextItemWidth(panelPx(60));
    return ImGui::InputDouble(id, &typed, 0.0, 0.0, "%.3f", ImGuiInputTextFlags_EnterReturnsTrue);
}

/// Per projectile: which measured restitution preset it bounces with (balls dropped from
/// 92 cm, Claypool, Game Physics (ch. 10)), or its e.
bool projectileRestitution(game::LiveSettings& s, const std::string& projectile) {
    const std::string name = "restitution." + projectile;
    const auto preset = phys::projectileFromName(projectile);
    if (!preset) return false;
    const double e = s.materials[game::projectileMaterial(s.materials, *preset)].restitution;
    bool changed = false;
    ImGui::PushID(projectile.c_str());
    ImGui::SetNextItemWidth(panelPx(140));
    const game::SettingValue now = game::readSetting(s, name);
    const std::string* presetName = std::get_if<std::string>(&now);
    if (ImGui::BeginCombo("##preset", presetName ? presetName->c_str() : "custom e")) {
        for (const phys::RestitutionPreset& p : phys::kRestitutionPresets) {
            char item[64];
            std::snprintf(item, sizeof item, "%s  e %.3f", p.name, p.restitution);
            if (ImGui::Selectable(item, p.restitution == e) && p.restitution != e)
                changed = applyTyped(s, name, std::string(p.name));
        }
        ImGui::EndCombo();
    }
    settingTooltip(name.c_str());
    ImGui::SameLine();
    double typed = e;
    if (typedNumber("##e", e, typed)) changed = applyTyped(s, name, typed);
    ImGui::SameLine();
    ImGui::TextUnformatted(projectile.c_str());
    ImGui::PopID();
    return changed;
}

/// One row of the pair table: the pair's e and friction, its e typed to override it.
bool pairRow(game::LiveSettings& s, phys::MaterialId a, phys::MaterialId b) {
    const std::string name = "pair." + s.materials[a].name + "." + s.materials[b].name;
    const phys::PairProperties& p = s.materials.pair(a, b);
    const bool own = s.materials.pairOverride(a, b) != nullptr;
    bool changed = false;
    ImGui::PushID(name.c_str());
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%s/%s", s.materials[a].name.c_str(), s.materials[b].name.c_str());
    if (ImGui::IsItemHovered()) {
        if (own)
            ImGui::SetTooltip("its own e (%s); \"rule\" gives it back to e_a e_b", name.c_str());
        else
            ImGui::SetTooltip("the rule: e = e_a e_b = %.3f x %.3f; type an e to override it",
                              s.materials[a].restitution, s.materials[b].restitution);
    }
    ImGui::TableNextColumn();
    double typed = p.restitution;
    if (typedNumber("##e", p.restitution, typed)) changed = applyTyped(s, name, typed);
    ImGui::TableNextColumn();
    ImGui::Text("%.2f/%.2f", p.staticFriction, p.dynamicFriction);
    ImGui::TableNextColumn();
    if (own && ImGui::SmallButton("rule")) changed = applyTyped(s, name, std::string("combine"));
    ImGui::PopID();
    return changed;
}

/// The match's materials: each projectile's restitution and the table of pairs that can
/// touch (moving with moving, moving with surfaces).
bool materialControls(game::LiveSettings& s, const game::MaterialsInPlay& in) {
    bool changed = false;
    section("restitution (vs the rigid floor)");
    for (const std::string& p : in.projectiles) changed |= projectileRestitution(s, p);
    section("material pairs");
    if (ImGui::BeginTable("pairs", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("pair");
        ImGui::TableSetupColumn("e");
        ImGui::TableSetupColumn("mu_s/mu_d");
        ImGui::TableSetupColumn("");
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < in.moving.size(); ++i) {
            for (std::size_t j = i; j < in.moving.size(); ++j)
                changed |= pairRow(s, in.moving[i], in.moving[j]);
            for (phys::MaterialId surface : in.surfaces)
                if (std::find(in.moving.begin(), in.moving.end(), surface) == in.moving.end())
                    changed |= pairRow(s, in.moving[i], surface); // else a row above has it
        }
        ImGui::EndTable();
    }
    if (!materialRefusal().empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", materialRefusal().c_str());
    return changed;
}

ImVec4 imColor(phys::Color c) { return ImVec4(c.r, c.g, c.b, 1.0f); }

/// A checkbox with a tooltip; the next one goes on the same line when `sameLine`.
void toggle(const char* label, bool& value, const char* tip, bool sameLine) {
    ImGui::Checkbox(label, &value);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    if (sameLine) ImGui::SameLine();
}

/// The debug view's toggles (ui/render/world_view.h DebugOverlays), with a legend of the
/// models' colours while they are shown.
void overlayControls(DebugOverlays& d) {
    toggle("forces", d.forces,
           "net force of gravity, drag, wind, springs, buoyancy (magenta), in weights:\n"
           "30 px of arrow = m g, clipped past 3; contacts act as impulses, so a resting ball shows its weight",
           true);
    toggle("closed-form ghost", d.ghosts,
           "where the exact parabola p0 + v0 t + g t^2/2 puts each integrated flight (ghost),\n"
           "the parabola itself, and the integrator's error (orange line, metres)",
           false);
    toggle("contacts", d.contacts,
           "contact points and normals of the last tick: particles, particles on bodies,\n"
           "Box2D bodies", true);
    toggle("grid cells", d.cells,
           "broad-phase uniform grid cells that hold particles (grid broad phase only)", false);
    toggle("sleeping", d.sleeping, "sleeping particles and bodies dimmed, marked with a z", true);
    toggle("models", d.models,
           "ring per particle / outline per body in the colour of the model that moves it", false);
    if (!d.models) return;
    const struct {
        phys::Color color;
        const char* name;
    } legend[] = {{modelColor(phys::ParticleModel::ClosedForm), "closed form"},
                  {modelColor(phys::ParticleModel::Integrated), "integrated"},
                  {modelColor(phys::ParticleModel::Sleeping), "asleep"},
                  {modelColor(phys::ParticleModel::Fixed), "fixed"},
                  {kOverlayRigidAwake, "rigid"},
                  {kOverlayRigidAsleep, "rigid asleep"}};
    for (std::size_t i = 0; i < std::size(legend); ++i) {
        if (i % 3 != 0) ImGui::SameLine();
        ImGui::TextColored(imColor(legend[i].color), "%s", legend[i].name);
    }
}

/// Where the method fails: the stiffest spring against the integrator's stable step (the
/// springs go through the integrator under either model), and the energy's trend.
void springLimits(const phys::WorldDef& def, const FrameStats& stats) {
    const phys::StiffestSpring& s = stats.stiffest;
    if (s.stiffness > 0.0) {
        const double h = def.tickSeconds / def.substeps;
        const std::string warning = phys::stiffnessWarning(def.integrator, s.stiffness, s.mass, h);
        ImGui::PushTextWrapPos(0.0f); // the panel's width: these lines are long
        if (!warning.empty())
            ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", warning.c_str());
        else
            ImGui::TextDisabled("stiffest spring %g N/m on %.3g kg: w dt %.2f, stable below %.3g",
                                s.stiffness, s.mass, s.omega * h, phys::stableOmegaDt(def.integrator));
        ImGui::PopTextWrapPos();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("w = sqrt(k/m); stable w dt: explicit Euler and midpoint none,\n"
                              "symplectic Euler and the Verlets 2, RK4 2.83, implicit Euler any");
    }
    if (stats.energyTrend && s.stiffness > 0.0) {
        const double pct = 100.0 * *stats.energyTrend;
        const ImVec4 colour = pct > 1.0 ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.7f, 0.7f, 0.7f, 1.0f);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(colour, "energy %+.1f %% in the last %.0f s%s", pct, stats.energyTrendSeconds,
                           pct > 1.0 ? ": the method is gaining energy" : "");
        ImGui::PopTextWrapPos();
    }
}

/// Tick rate, sub-steps, and the clock: pause, one step, fire, reset, slow motion.
bool timeControls(phys::WorldDef& def, TimeControls& time, SceneRequests& scene) {
    bool changed = tickRateCombo(def);
    changed |= ImGui::SliderInt("sub-steps", &def.substeps, 1, 16);
    if (ImGui::Button(time.paused ? "resume" : "pause")) time.paused = !time.paused;
    ImGui::SameLine();
    ImGui::BeginDisabled(!time.paused);
    if (ImGui::Button("step")) time.stepRequested = true;
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("fire")) scene.fire = true;
    ImGui::SameLine();
    if (ImGui::Button("reset")) scene.reset = true;
    ImGui::SliderFloat("speed", &time.timeScale, 0.05f, 4.0f, "x%.2f",
                       ImGuiSliderFlags_Logarithmic);
    return changed;
}

/// Gravity, air drag and wind.
bool forceControls(phys::WorldDef& def) {
    bool changed = gravityCombo(def);
    bool drag = def.forces.drag == phys::DragModel::Quadratic;
    if (ImGui::Checkbox("quadratic air drag", &drag)) {
        def.forces.drag = drag ? phys::DragModel::Quadratic : phys::DragModel::None;
        changed = true;
    }
    float wind = static_cast<float>(def.forces.wind.x);
    if (ImGui::SliderFloat("wind (m/s)", &wind, -20.0f, 20.0f, "%.1f")) {
        def.forces.wind.x = wind;
        changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("drag acts on v - wind; off when drag is off");
    return changed;
}

/// What to draw: trails, velocities, labels, interpolation and the debug overlays.
void drawingControls(ViewControls& view) {
    ImGui::Checkbox("trails", &view.trails);
    ImGui::SameLine();
    ImGui::Checkbox("velocities", &view.draw.velocities);
    ImGui::Checkbox("labels", &view.labels);
    ImGui::SameLine();
    ImGui::Checkbox("interpolate", &view.interpolate);
    overlayControls(view.draw);
}

} // namespace

int gravityPresetIndex(double g) {
    for (int i = 0; i < static_cast<int>(std::size(phys::kGravityPresets)); ++i)
        if (std::abs(phys::kGravityPresets[i].g - g) < 1e-9) return i;
    return -1;
}

namespace {
/// The panel; `live` and `inPlay` (a match's) add the material controls, and then `def`
/// is live->world.
bool drawPanel(phys::WorldDef& def, game::LiveSettings* live, const game::MaterialsInPlay* inPlay,
               TimeControls& time, ViewControls& view, SceneRequests& scene, const FrameStats& stats) {
    bool changed = false;
    // Top right: the shots rise on the left, and the sky over the landing zone is free; in
    // a match, under the wind gauge when the screen is too narrow for both.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float top =
        live ? topRightPanelsTop(display.x, display.y, panelPx(380), panelPx(10)) : panelPx(10);
    ImGui::SetNextWindowPos(ImVec2(display.x - panelPx(10), top), ImGuiCond_FirstUseEver,
                            ImVec2(1.0f, 0.0f));
    // As wide as the material pairs' table.
    ImGui::SetNextWindowSize(ImVec2(panelPx(380), 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Physics", nullptr, ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PushItemWidth(panelPx(160));
    // Grouped by concern: time, model and integrator, forces, collisions, the materials
    // (folded: a long table), drawing.
    section("time");
    changed |= timeControls(def, time, scene);
    section("model and integrator");
    changed |= integratorCombo(def);
    springLimits(def, stats);
    section("forces");
    changed |= forceControls(def);
    section("collisions");
    changed |= contactControls(def);
    if (live && inPlay && ImGui::CollapsingHeader("materials"))
        changed |= materialControls(*live, *inPlay);
    section("drawing");
    drawingControls(view);
    if (!live) { // a match has the cost readout (F3) for these
        ImGui::Text("frame %.2f ms  physics %.1f us/tick", stats.frameMs, stats.physicsUs);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "integrate %.1f us, springs %.1f us, %d ticks this frame\n%s, %zu vertices",
                stats.integrateUs, stats.springsUs, stats.ticksThisFrame, stats.context,
                stats.vertices);
    }
    if (!stats.status.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", stats.status.c_str());

    ImGui::PopItemWidth();
    ImGui::End();
    return changed;
}
} // namespace

bool physicsPanel(phys::WorldDef& def, TimeControls& time, ViewControls& view, SceneRequests& scene,
                  const FrameStats& stats) {
    return drawPanel(def, nullptr, nullptr, time, view, scene, stats);
}

bool physicsPanel(game::LiveSettings& settings, const game::MaterialsInPlay& inPlay,
                  TimeControls& time, ViewControls& view, SceneRequests& scene,
                  const FrameStats& stats) {
    return drawPanel(settings.world, &settings, &inPlay, time, view, scene, stats);
}

} // namespace ui
