#include "ui/game/sandbox_tools.h"
#include "ui/game/match_view.h"

#include <imgui.h>

namespace ui {

namespace {

using game::Command;
using game::CommandKind;

/// Drags closer than this to the last one send no command (a recording stays small).
constexpr double kDragStep = 0.05; // m

bool twoEnded(const std::string& kind) { return kind == "rope" || kind == "spring"; }

Command make(CommandKind kind, phys::Vec2 at = {}) {
    Command c;
    c.kind = kind;
    c.at = at;
    return c;
}

} // namespace

std::vector<Command> SandboxTools::panel(const game::Match& match) {
    std::vector<Command> out;
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(hudMargin(d.x, d.y), belowLevelHeading(d.x, d.y)),
                            ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowCollapsed(!match.sandbox(), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Sandbox", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::End();
        return out;
    }
    if (!match.sandbox()) {
        ImGui::TextWrapped("Turn this level into a sandbox: no shot budget, no score; spawn "
                           "things and drag them about.");
        if (ImGui::Button("Open as a sandbox")) out.push_back(make(CommandKind::Sandbox));
        ImGui::End();
        return out;
    }
    int tool = static_cast<int>(tool_);
    ImGui::RadioButton("cannon", &tool, static_cast<int>(Tool::Cannon));
    ImGui::SameLine();
    ImGui::RadioButton("hand", &tool, static_cast<int>(Tool::Hand));
    ImGui::SameLine();
    ImGui::RadioButton("spawn", &tool, static_cast<int>(Tool::Spawn));
    tool_ = static_cast<Tool>(tool);
    if (tool_ == Tool::Spawn) {
        if (ImGui::BeginCombo("what", kind_.c_str())) {
            for (const std::string& k : game::spawnKinds())
                if (ImGui::Selectable(k.c_str(), k == kind_)) kind_ = k;
            ImGui::EndCombo();
        }
        if (kind_ == "block" || kind_ == "cloth" || kind_ == "blob")
            ImGui::SliderFloat("size (m)", &size_, 0.0f, 10.0f, size_ > 0.0f ? "%.1f" : "default");
        ImGui::TextDisabled(twoEnded(kind_) ? "press at the anchor, release at the other end"
                                            : "click where it should appear");
    } else if (tool_ == Tool::Hand) {
        ImGui::TextDisabled("press on a block or near a particle, drag, let go");
        if (match.grab().kind != game::GrabState::Kind::None && ImGui::Button("let go"))
            out.push_back(make(CommandKind::Release));
    } else {
        ImGui::TextDisabled("the mouse aims the cannon");
    }
    ImGui::Text("%zu particles, %zu springs, %zu blocks", match.world().particles.count(),
                match.world().springs.size(), match.blocks().size());
    if (ImGui::Button("Save as level")) saveAsLevel_ = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Opens the scene in the level editor: the blocks, ropes and blobs where "
                          "they are now (loose balls are left out); save it from there");
    ImGui::End();
    return out;
}

std::vector<Command> SandboxTools::press(phys::Vec2 at) {
    pointer_ = at;
    if (tool_ == Tool::Hand) {
        holding_ = true;
        lastDrag_ = at;
        return {make(CommandKind::Grab, at)};
    }
    if (tool_ != Tool::Spawn) return {};
    if (twoEnded(kind_)) {
        anchor_ = at;
        return {};
    }
    Command c = make(CommandKind::Spawn, at);
    c.text = kind_;
    c.number = size_;
    return {c};
}

std::vector<Command> SandboxTools::move(phys::Vec2 at) {
    pointer_ = at;
    if (!holding_ || length(at - lastDrag_) < kDragStep) return {};
    lastDrag_ = at;
    return {make(CommandKind::Drag, at)};
}

std::vector<Command> SandboxTools::lift(phys::Vec2 at) {
    pointer_ = at;
    if (holding_) {
        holding_ = false;
        return {make(CommandKind::Release)};
    }
    if (!anchor_) return {};
    Command c = make(CommandKind::Spawn, *anchor_);
    c.text = kind_;
    c.to = at;
    anchor_.reset();
    if (length(c.to - c.at) < 0.2) return {}; // a click, not a drag: nothing to span
    return {c};
}

void SandboxTools::draw(Renderer2D& renderer, const game::Match& match) const {
    const phys::Color ink = phys::Color::hex(0xffd166);
    if (anchor_) {
        renderer.line(*anchor_, pointer_, ink, 2.0f);
        renderer.fillCircle(*anchor_, 0.15, ink, 3.0f);
    }
    const game::GrabState& g = match.grab();
    if (g.kind == game::GrabState::Kind::None) return;
    const phys::Vec2 held = g.kind == game::GrabState::Kind::Particle
                                ? match.world().particles.position(g.particle)
                                : match.rigid().worldPoint(g.body, g.local);
    renderer.line(held, g.target, ink, 1.5f);
    renderer.strokeCircle(g.target, 0.3, ink, 2.0f);
}

} // namespace ui
