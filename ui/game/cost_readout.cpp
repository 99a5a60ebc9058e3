#include "ui/game/cost_readout.h"

#include "physics/integrators.h"
#include "ui/platform/imgui_layer.h"

#include <cfloat>
#include <cstdio>

namespace ui {

namespace {

std::string plural(long n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

} // namespace

CostFigures costFigures(const game::Match& m, double frameMs) {
    const phys::World& w = m.world();
    const phys::StepProfile& p = w.profile();
    CostFigures f;
    f.frameMs = frameMs;
    f.particlesUs = p.totalUs;
    f.rigidUs = m.rigid().profile().stepUs;
    f.tickHz = 1.0 / w.def().tickSeconds;
    f.substeps = w.def().substeps;
    f.integrator = phys::info(w.def().integrator).name;
    f.closedForm = p.closedForm;
    f.integrated = p.integrated;
    f.sleeping = p.sleeping;
    f.fixed = p.fixed;
    f.springs = w.springs.size();
    f.rods = w.constraints.size();
    f.bodiesAwake = m.rigid().profile().awakeBodies;
    f.bodiesAsleep = m.rigid().profile().sleepingBodies;
    return f;
}

std::vector<std::string> costLines(const CostFigures& f) {
    std::vector<std::string> out;
    char line[160];
    std::snprintf(line, sizeof line, "frame %.2f ms   tick %.0f Hz x %d", f.frameMs, f.tickHz, f.substeps);
    out.emplace_back(line);
    std::snprintf(line, sizeof line, "physics %.0f us/tick  (particles %.0f, Box2D %.0f)",
                  f.particlesUs + f.rigidUs, f.particlesUs, f.rigidUs);
    out.emplace_back(line);
    out.push_back("closed form  " + plural(f.closedForm, "particle", "particles"));
    std::string integrated = f.integrator + "  " + plural(f.integrated, "particle", "particles");
    if (f.springs) integrated += ", " + plural(static_cast<long>(f.springs), "spring", "springs");
    out.push_back(integrated);
    if (f.rods) out.push_back("projection  " + plural(static_cast<long>(f.rods), "rod or cable", "rods and cables"));
    out.push_back("Box2D  " + plural(f.bodiesAwake, "body", "bodies") + " awake, " +
                  std::to_string(f.bodiesAsleep) + " asleep");
    if (f.sleeping || f.fixed)
        out.push_back("at rest  " + std::to_string(f.sleeping) + " asleep, " +
                      std::to_string(f.fixed) + " fixed");
    return out;
}

ImVec2 costReadoutEstimate() { return ImVec2(panelPx(340), panelPx(130)); }

void costReadout(const CostFigures& f, ImVec2 at) {
    ImGui::SetNextWindowPos(at, ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.7f);
    // At least as wide as its estimate: an auto-sized window takes a frame to grow, and a
    // figure gaining a digit would be cut for that frame.
    ImGui::SetNextWindowSizeConstraints(ImVec2(costReadoutEstimate().x, 0.0f), ImVec2(FLT_MAX, FLT_MAX));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoInputs;
    if (ImGui::Begin("Cost", nullptr, flags)) {
        const std::vector<std::string> lines = costLines(f);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (i < 2)
                ImGui::TextUnformatted(lines[i].c_str());
            else
                ImGui::TextDisabled("%s", lines[i].c_str());
        }
    }
    ImGui::End();
}

} // namespace ui
