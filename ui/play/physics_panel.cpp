#include "ui/play/physics_panel.h"

#include "physics/integrators.h"

#include <imgui.h>

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

bool integratorCombo(phys::WorldDef& def) {
    bool changed = false;
    const phys::IntegratorInfo& current = phys::info(def.integrator);
    if (ImGui::BeginCombo("integrator", current.name)) {
        for (const phys::IntegratorInfo& i : phys::integrators()) {
            const bool selected = i.id == def.integrator;
            if (ImGui::Selectable(i.name, selected) && !selected) {
                def.integrator = i.id;
                changed = true;
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("order %d, %d force evaluations per step\n%s", i.order,
                                  i.evaluations, i.summary);
            if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
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

} // namespace

int gravityPresetIndex(double g) {
    for (int i = 0; i < static_cast<int>(std::size(phys::kGravityPresets)); ++i)
        if (std::abs(phys::kGravityPresets[i].g - g) < 1e-9) return i;
    return -1;
}

bool physicsPanel(phys::WorldDef& def, TimeControls& time, ViewControls& view, SceneRequests& scene,
                  const FrameStats& stats) {
    bool changed = false;
    // Top right: the shots rise on the left, and the sky over the landing zone is free.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, 10.0f), ImGuiCond_FirstUseEver,
                            ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(310, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Physics", nullptr, ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PushItemWidth(160);

    changed |= integratorCombo(def);
    changed |= tickRateCombo(def);
    changed |= ImGui::SliderInt("sub-steps", &def.substeps, 1, 16);
    changed |= gravityCombo(def);
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

    section("time");
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

    section("draw");
    ImGui::Checkbox("trails", &view.trails);
    ImGui::SameLine();
    ImGui::Checkbox("velocities", &view.velocities);
    ImGui::Checkbox("labels", &view.labels);
    ImGui::SameLine();
    ImGui::Checkbox("interpolate", &view.interpolate);

    section("stats");
    ImGui::Text("frame %.2f ms  physics %.1f us/tick", stats.frameMs, stats.physicsUs);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "integrate %.1f us, springs %.1f us, %d ticks this frame\n%s, %zu vertices",
            stats.integrateUs, stats.springsUs, stats.ticksThisFrame, stats.context,
            stats.vertices);
    if (!stats.status.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", stats.status.c_str());

    ImGui::PopItemWidth();
    ImGui::End();
    return changed;
}

} // namespace ui
