// Section index
//   set-up     LevelEditorView(), framing, choose
//   pointer    press, move, lift: tools become editor calls
//   keys       key: undo, redo, save, play, delete, tools, snap
//   files      save, saveAs
//   drawing    drawWorld, drawHandles
//   panel      panel, toolButtons, fileButtons, verdict
#include "ui/game/editor_screen.h"

#include "ui/game/editor_panels.h"
#include "ui/game/match_frame.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/gl.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <regex>

namespace ui {

namespace {

using game::editor::Item;
using game::editor::ItemKind;
using phys::Color;
using phys::Vec2;

/// A dragged terrain point keeps this far from its neighbours' x: the ground stays a
/// heightfield (the loader wants x to grow by at least 1 mm).
constexpr double kTerrainGap = 0.01; // m

const Color kHandle = Color::hex(0xf4f4f4, 0.9f);
const Color kSelected = Color::hex(0xffd54a);
const Color kProblem = Color::hex(0xff4a4a);
const Color kOutline = Color::hex(0xe8eef8, 0.55f);
const Color kGrid = Color::hex(0xffffff, 0.08f);

struct ToolInfo {
    LevelEditorView::Tool tool;
    const char* name;
    const char* hint;
};

constexpr ToolInfo kTools[] = {
    {LevelEditorView::Tool::Select, "select", "click to pick, drag to move, Del deletes"},
    {LevelEditorView::Tool::Terrain, "terrain",
     "click to add a point on the ground line, drag a point to shape the ground, Del removes it"},
    {LevelEditorView::Tool::Cannon, "cannon", "click to place a cannon; drag one to move it"},
    {LevelEditorView::Tool::Target, "target", "click to place a target; drag one to move it"},
    {LevelEditorView::Tool::Block, "block", "click to place a 1 m wooden block; drag to move"},
    {LevelEditorView::Tool::Rope, "rope",
     "press at one end, drag to the other, let go (an end let go on a block is tied to it)"},
    {LevelEditorView::Tool::Blob, "blob", "click to place a soft blob; drag to move"},
};

ItemKind kindOf(LevelEditorView::Tool tool) {
    switch (tool) {
    case LevelEditorView::Tool::Cannon:
        return ItemKind::Cannon;
    case LevelEditorView::Tool::Target:
        return ItemKind::Target;
    case LevelEditorView::Tool::Block:
        return ItemKind::Block;
    case LevelEditorView::Tool::Rope:
        return ItemKind::Rope;
    case LevelEditorView::Tool::Blob:
        return ItemKind::Blob;
    default:
        return ItemKind::None;
    }
}

std::size_t countOf(const game::Level& l, ItemKind kind) {
    switch (kind) {
    case ItemKind::TerrainPoint:
        return l.terrain.points.size();
    case ItemKind::Cannon:
        return l.cannons.size();
    case ItemKind::Target:
        return l.targets.size();
    case ItemKind::Block:
        return l.blocks.size();
    case ItemKind::Rope:
        return l.ropes.size();
    case ItemKind::Blob:
        return l.blobs.size();
    case ItemKind::None:
        break;
    }
    return 0;
}

bool exists(const game::Level& l, const Item& item) {
    return item && item.index >= 0 && static_cast<std::size_t>(item.index) < countOf(l, item.kind);
}

/// The ground line's height at x (linear between points; flat past the ends).
double groundAt(const std::vector<Vec2>& pts, double x) {
    if (x <= pts.front().x) return pts.front().y;
    for (std::size_t i = 1; i < pts.size(); ++i)
        if (x <= pts[i].x && pts[i].x > pts[i - 1].x) {
            const double s = (x - pts[i - 1].x) / (pts[i].x - pts[i - 1].x);
            return pts[i - 1].y + s * (pts[i].y - pts[i - 1].y);
        }
    return pts.back().y;
}

/// The item the loader's message names ("$.blocks[3]...", "$.terrain.points[2]"), so
/// the view can mark it.
Item itemInProblem(const std::string& problem) {
    static const std::regex path(
        R"(\$\.(terrain\.points|cannons|targets|blocks|ropes|blobs)\[(\d+)\])");
    std::smatch m;
    if (!std::regex_search(problem, m, path)) return {};
    const std::string list = m[1];
    const int index = std::stoi(m[2]);
    const ItemKind kind = list == "terrain.points" ? ItemKind::TerrainPoint
                          : list == "cannons"      ? ItemKind::Cannon
                          : list == "targets"      ? ItemKind::Target
                          : list == "blocks"       ? ItemKind::Block
                          : list == "ropes"        ? ItemKind::Rope
                                                   : ItemKind::Blob;
    return {kind, index, -1};
}

std::vector<Vec2> blockCorners(const game::Block& b) {
    const double a = b.angleDeg * std::numbers::pi / 180.0;
    const Vec2 ux{std::cos(a), std::sin(a)}, uy{-std::sin(a), std::cos(a)};
    const Vec2 hx = ux * (0.5 * b.size.x), hy = uy * (0.5 * b.size.y);
    return {b.position - hx - hy, b.position + hx - hy, b.position + hx + hy, b.position - hx + hy};
}

/// A file name from a level name: letters, digits and underscores.
std::string fileStem(const std::string& name) {
    std::string out;
    for (char c : name) {
        if (std::isalnum(static_cast<unsigned char>(c)))
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        else if (!out.empty() && out.back() != '_')
            out += '_';
    }
    while (!out.empty() && out.back() == '_')
        out.pop_back();
    return out.empty() ? "my_level" : out.substr(0, 48);
}

} // namespace

// ---- set-up ---------------------------------------------------------------------------
LevelEditorView::LevelEditorView(game::Level level, std::string mapsFolder)
    : editor_(std::move(level)), mapsFolder_(std::move(mapsFolder)) {
    const std::string stem = fileStem(editor_.level().name);
    std::snprintf(saveName_, sizeof saveName_, "%s", stem.c_str());
}

void LevelEditorView::choose(Tool tool) {
    tool_ = tool;
    if (dragging_) lift();
}

Camera LevelEditorView::framing(int width, int height) const {
    const game::Level& l = editor_.level();
    const double left = std::min<double>(panelPx(kEditorPanelWidth), 0.5 * width) + 16.0;
    const double availW = std::max(32.0, width - left - 16.0);
    const double availH = std::max(32.0, height - 48.0); // room for the hint line
    const Vec2 span = l.worldMax - l.worldMin;
    Camera c;
    c.width = width;
    c.height = height;
    c.pixelsPerMetre = std::min(availW / span.x, availH / span.y);
    // The world's middle at the middle of the room beside the panel.
    const Vec2 middle = (l.worldMin + l.worldMax) * 0.5;
    const double offsetPx = left + 0.5 * availW - 0.5 * width;
    const double offsetUpPx = 8.0; // hint line at the bottom
    c.center = middle - Vec2{offsetPx, -offsetUpPx} * (1.0 / c.pixelsPerMetre);
    return c;
}

// ---- pointer --------------------------------------------------------------------------
Vec2 LevelEditorView::snapped(Vec2 p) const {
    if (!snap_) return p;
    const double g = gridMetres_;
    return {std::round(p.x / g) * g, std::round(p.y / g) * g};
}

void LevelEditorView::startDrag(const Item& item, Vec2 at) {
    selected_ = item;
    dragging_ = true;
    grabOffset_ = editor_.positionOf(item) - at;
    editor_.beginGesture();
}

void LevelEditorView::press(Vec2 at, double reach) {
    status_.clear();
    const Item hit = editor_.hitTest(at, reach);
    if (tool_ == Tool::Select) {
        selected_ = {};
        if (hit) startDrag(hit, at);
        return;
    }
    if (tool_ == Tool::Terrain) {
        if (hit.kind == ItemKind::TerrainPoint) {
            startDrag(hit, at);
            return;
        }
        // On the ground line at the clicked x (past either end: where clicked), then
        // dragged from there: press, drag, let go shapes the ground.
        const std::vector<Vec2>& pts = editor_.level().terrain.points;
        Vec2 p = snapped(at);
        if (p.x > pts.front().x && p.x < pts.back().x) p.y = groundAt(pts, p.x);
        const int i = editor_.addTerrainPoint(p);
        if (i < 0) {
            status_ = editor_.refusal();
            return;
        }
        startDrag({ItemKind::TerrainPoint, i}, p);
        return;
    }
    if (hit && hit.kind != ItemKind::TerrainPoint) { // another tool still moves things
        startDrag(hit, at);
        return;
    }
    const Vec2 p = snapped(at);
    const Item placed = editor_.place(kindOf(tool_), p);
    if (!placed) return;
    if (placed.kind == ItemKind::Rope) {
        // The rope's far end follows the pointer until the button is let go.
        Item end = placed;
        end.end = 1;
        startDrag(end, p);
        grabOffset_ = {}; // the far end is under the pointer, not 6 m right of it
        editor_.dragTo(end, p + Vec2{gridMetres_, 0.0});
        selected_ = placed;
        selected_.end = 1;
        return;
    }
    startDrag(placed, p);
}

void LevelEditorView::move(Vec2 at, double reach) {
    if (!dragging_) {
        hovered_ = editor_.hitTest(at, reach);
        return;
    }
    if (!exists(editor_.level(), selected_)) {
        lift();
        return;
    }
    Vec2 to = snapped(at + grabOffset_);
    if (selected_.kind == ItemKind::TerrainPoint) {
        const std::vector<Vec2>& pts = editor_.level().terrain.points;
        const auto i = static_cast<std::size_t>(selected_.index);
        if (i > 0) to.x = std::max(to.x, pts[i - 1].x + kTerrainGap);
        if (i + 1 < pts.size()) to.x = std::min(to.x, pts[i + 1].x - kTerrainGap);
    }
    if (selected_.kind == ItemKind::Rope && selected_.end >= 0) {
        // A rope's two ends never meet (the loader refuses it).
        const game::Rope& r = editor_.level().ropes[static_cast<std::size_t>(selected_.index)];
        if (to == (selected_.end == 0 ? r.to : r.from)) return;
    }
    editor_.dragTo(selected_, to);
}

void LevelEditorView::lift() {
    if (!dragging_) return;
    dragging_ = false;
    if (selected_.kind == ItemKind::Rope && selected_.end >= 0 &&
        exists(editor_.level(), selected_))
        tieRopeEnd();
    editor_.endGesture();
}

void LevelEditorView::tieRopeEnd() {
    // As the sandbox's rope does: an end let go inside a block is tied to it (the rope
    // holds the block); let go outside every block, it is untied. Part of the drag's step.
    game::Level l = editor_.level();
    game::Rope& r = l.ropes[static_cast<std::size_t>(selected_.index)];
    const bool from = selected_.end == 0;
    (from ? r.fromBlock : r.toBlock) = editor_.blockAt(from ? r.from : r.to);
    editor_.update(l);
}

void LevelEditorView::deleteSelected() {
    if (!exists(editor_.level(), selected_)) return;
    Item whole = selected_;
    whole.end = -1; // a rope end selected deletes the rope
    if (editor_.remove(whole))
        selected_ = {};
    else
        status_ = editor_.refusal();
}

// ---- keys -----------------------------------------------------------------------------
EditorRequests LevelEditorView::key(SDL_Keycode key, bool ctrl, bool shift) {
    EditorRequests out;
    if (ctrl) {
        if (key == SDLK_z && !shift) editor_.undo();
        if ((key == SDLK_z && shift) || key == SDLK_y) editor_.redo();
        if (key == SDLK_s) status_ = save();
        if (!exists(editor_.level(), selected_)) selected_ = {};
        return out;
    }
    switch (key) {
    case SDLK_DELETE:
    case SDLK_BACKSPACE:
        deleteSelected();
        break;
    case SDLK_ESCAPE:
        if (selected_)
            selected_ = {};
        else
            out.close = true;
        break;
    case SDLK_F5:
        out.play = editor_.valid();
        break;
    case SDLK_g:
        snap_ = !snap_;
        break;
    default:
        if (key >= SDLK_1 && key < SDLK_1 + static_cast<int>(std::size(kTools)))
            choose(kTools[key - SDLK_1].tool);
        break;
    }
    return out;
}

// ---- files ----------------------------------------------------------------------------
std::string LevelEditorView::save() {
    if (editor_.file().empty()) return saveAs(saveName_);
    const std::string why = editor_.save(editor_.file());
    status_ = why.empty() ? "saved " + editor_.file() : why;
    return why;
}

std::string LevelEditorView::saveAs(const std::string& name) {
    std::string stem = name;
    if (std::filesystem::path(stem).extension() == ".json")
        stem = std::filesystem::path(stem).stem().string();
    if (stem.empty() || stem.find_first_of("/\\") != std::string::npos || stem[0] == '.') {
        status_ = "not saved: give a file name (no folder: it goes in " + mapsFolder_ + ")";
        return status_;
    }
    const std::string file = (std::filesystem::path(mapsFolder_) / (stem + ".json")).string();
    std::error_code ec;
    std::filesystem::create_directories(mapsFolder_, ec);
    const std::string why = editor_.save(file);
    status_ = why.empty() ? "saved " + file : why;
    return why;
}

// ---- drawing --------------------------------------------------------------------------
void LevelEditorView::refreshPreview() {
    const game::Level* checked = editor_.checked();
    if (!checked || (preview_ && *checked == previewOf_)) return;
    previewOf_ = *checked;
    preview_ = std::make_unique<game::Match>(previewOf_);
    previewView_.reset();
}

void LevelEditorView::drawWorld(Renderer2D& renderer, const Camera& camera) {
    refreshPreview();
    if (preview_) {
        MatchViewOptions o;
        o.hud = false;
        o.trajectoryPreview = false;
        o.effects = false;
        o.trails = false;
        drawMatchFrame(renderer, previewView_, *preview_, camera, o);
    } else {
        gl::fn.Viewport(0, 0, camera.width, camera.height);
        gl::fn.ClearColor(0.07f, 0.12f, 0.2f, 1.0f);
        gl::fn.Clear(GL_COLOR_BUFFER_BIT);
        renderer.begin(camera);
    }
    drawHandles(renderer, camera);
    renderer.flush();
}

void LevelEditorView::drawHandles(Renderer2D& r, const Camera& camera) const {
    const game::Level& l = editor_.level();
    const Item problem = editor_.valid() ? Item{} : itemInProblem(editor_.problem());
    auto whole = [](Item item) {
        item.end = -1;
        return item;
    };
    auto marked = [&](const Item& item) {
        return whole(item) == problem || whole(item) == whole(selected_) ||
               whole(item) == whole(hovered_);
    };
    auto colourOf = [&](const Item& item, Color normal) {
        if (whole(item) == problem) return kProblem;
        if (whole(item) == whole(selected_)) return kSelected;
        if (whole(item) == whole(hovered_)) return Color::hex(0xffffff);
        return normal;
    };
    // The grid the points snap to, coarsened until its lines are 12 px apart.
    if (snap_) {
        double step = gridMetres_;
        while (step * camera.pixelsPerMetre < 12.0)
            step *= 2.0;
        for (double x = std::ceil(l.worldMin.x / step) * step; x <= l.worldMax.x; x += step)
            r.line({x, l.worldMin.y}, {x, l.worldMax.y}, kGrid, 1.0f);
        for (double y = std::ceil(l.worldMin.y / step) * step; y <= l.worldMax.y; y += step)
            r.line({l.worldMin.x, y}, {l.worldMax.x, y}, kGrid, 1.0f);
    }
    const Vec2 bounds[] = {
        l.worldMin, {l.worldMax.x, l.worldMin.y}, l.worldMax, {l.worldMin.x, l.worldMax.y}};
    r.polyline(bounds, Color::hex(0x9fb3c8, 0.7f), 1.5f, true);
    if (l.physics.water)
        r.line({l.worldMin.x, l.physics.waterLevel}, {l.worldMax.x, l.physics.waterLevel},
               Color::hex(0x5ab4ff, 0.9f), 2.0f);
    // The ground line as edited, and its points.
    r.polyline(l.terrain.points, Color::hex(0xfff3c4, 0.9f), 2.0f);
    for (std::size_t i = 0; i < l.terrain.points.size(); ++i) {
        const Item item{ItemKind::TerrainPoint, static_cast<int>(i)};
        r.fillCircle(l.terrain.points[i], camera.metres(marked(item) ? 5.5 : 3.5),
                     colourOf(item, kHandle));
    }
    for (std::size_t i = 0; i < l.blocks.size(); ++i) {
        const auto corners = blockCorners(l.blocks[i]);
        const Item item{ItemKind::Block, static_cast<int>(i)};
        r.polyline(corners, colourOf(item, kOutline), marked(item) ? 2.5f : 1.0f, true);
    }
    for (std::size_t i = 0; i < l.targets.size(); ++i) {
        const game::Target& t = l.targets[i];
        r.strokeCircle(t.position, t.radius,
                       colourOf({ItemKind::Target, static_cast<int>(i)}, kOutline), 2.0f, 4.0f);
        if (!t.path.empty()) r.polyline(t.path, kOutline, 1.0f);
    }
    for (std::size_t i = 0; i < l.cannons.size(); ++i) {
        const game::Cannon& c = l.cannons[i];
        const Color col = colourOf({ItemKind::Cannon, static_cast<int>(i)}, kOutline);
        r.strokeCircle(c.position, 1.5, col, 2.0f, 10.0f);
        r.label(c.position, c.player == "cpu" ? "CPU" : "P" + c.player, col, {-10.0, -34.0}, 0.9f);
    }
    for (std::size_t i = 0; i < l.ropes.size(); ++i) {
        const game::Rope& rope = l.ropes[i];
        const Color c = colourOf({ItemKind::Rope, static_cast<int>(i)}, kOutline);
        r.line(rope.from, rope.to, c, 1.5f);
        r.fillCircle(rope.from, camera.metres(4.0),
                     rope.pinFrom && rope.fromBlock < 0 ? c : kHandle);
        r.strokeCircle(rope.to, camera.metres(4.0), c, 2.0f);
    }
    for (std::size_t i = 0; i < l.blobs.size(); ++i)
        r.strokeCircle(l.blobs[i].center, l.blobs[i].radius,
                       colourOf({ItemKind::Blob, static_cast<int>(i)}, kOutline), 2.0f, 4.0f);
}

// ---- panel ----------------------------------------------------------------------------
void LevelEditorView::toolButtons() {
    int tool = static_cast<int>(tool_);
    for (std::size_t i = 0; i < std::size(kTools); ++i) {
        if (i % 3 != 0) ImGui::SameLine();
        char label[32];
        std::snprintf(label, sizeof label, "%s (%zu)", kTools[i].name, i + 1);
        ImGui::RadioButton(label, &tool, static_cast<int>(kTools[i].tool));
    }
    if (tool != static_cast<int>(tool_)) choose(static_cast<Tool>(tool));
    ImGui::Checkbox("snap to grid (G)", &snap_);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(panelPx(80));
    const float grids[] = {0.1f, 0.25f, 0.5f, 1.0f, 2.0f, 5.0f};
    char current[16];
    std::snprintf(current, sizeof current, "%g m", static_cast<double>(gridMetres_));
    if (ImGui::BeginCombo("##grid", current)) {
        for (float g : grids) {
            char name[16];
            std::snprintf(name, sizeof name, "%g m", static_cast<double>(g));
            if (ImGui::Selectable(name, g == gridMetres_)) gridMetres_ = g;
        }
        ImGui::EndCombo();
    }
}

void LevelEditorView::verdict() {
    if (editor_.valid()) {
        ImGui::TextColored(ImVec4(0.45f, 0.9f, 0.45f, 1.0f), "passes check");
        return;
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", editor_.problem().c_str());
    ImGui::PopStyleColor();
    if (editor_.checked()) dimWrapped("drawn: the last state that passed");
}

void LevelEditorView::fileButtons(EditorRequests& out) {
    ImGui::BeginDisabled(!editor_.canUndo());
    if (ImGui::Button("Undo")) editor_.undo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!editor_.canRedo());
    if (ImGui::Button("Redo")) editor_.redo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!selected_);
    if (ImGui::Button("Delete")) deleteSelected();
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Levels")) out.close = true;
    if (!exists(editor_.level(), selected_)) selected_ = {};

    ImGui::BeginDisabled(!editor_.valid());
    if (ImGui::Button("Save (Ctrl+S)")) save();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", editor_.file().empty() ? "a new level: saved under the name below"
                                                       : editor_.file().c_str());
    ImGui::SameLine();
    if (ImGui::Button("Play (F5)")) out.play = true;
    ImGui::EndDisabled();
    if (!editor_.valid()) {
        ImGui::SameLine();
        dimWrapped("fix the level first");
    }
    ImGui::SetNextItemWidth(panelPx(170));
    ImGui::InputText("##saveas", saveName_, sizeof saveName_);
    ImGui::SameLine();
    ImGui::BeginDisabled(!editor_.valid());
    if (ImGui::Button("Save as")) saveAs(saveName_);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("into %s", mapsFolder_.c_str());
}

EditorRequests LevelEditorView::panel() {
    EditorRequests out;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(
        ImVec2(std::min(panelPx(kEditorPanelWidth), 0.5f * display.x), display.y),
        ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.97f);
    ImGui::Begin("Level editor", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    const game::Level& l = editor_.level();
    ImGui::TextWrapped("%s%s", l.name.c_str(), editor_.modified() ? "  (changed)" : "");
    dimWrapped(editor_.file().empty() ? "new level, not saved yet" : editor_.file());
    ImGui::Separator();
    toolButtons();
    ImGui::Separator();
    fileButtons(out);
    // A fixed room for the verdict and the last action's word, so the fields below do
    // not jump while a message comes and goes under the pointer.
    ImGui::BeginChild("verdict", ImVec2(0.0f, 4.6f * ImGui::GetTextLineHeightWithSpacing()));
    verdict();
    if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
    ImGui::EndChild();
    ImGui::Separator();

    // The fields edit a copy; a change is one undo step however long the field is held.
    game::Level draft = l;
    bool changed = false;
    // The fields take what the labels beside them leave, however deep in a tree.
    ImGui::PushItemWidth(-panelPx(165));
    if (exists(l, selected_)) {
        char title[64];
        std::snprintf(title, sizeof title, "%s %d###selected",
                      game::editor::itemKindName(selected_.kind), selected_.index);
        ImGui::SetNextItemOpen(true, ImGuiCond_Appearing);
        if (ImGui::CollapsingHeader(title)) changed |= itemPropertiesPanel(draft, selected_);
    }
    if (ImGui::CollapsingHeader("level", ImGuiTreeNodeFlags_DefaultOpen))
        changed |= levelPropertiesPanel(draft);
    ImGui::PopItemWidth();
    if (changed) {
        editor_.update(draft);
        widgetGesture_ = true;
    }
    if (widgetGesture_ && !ImGui::IsAnyItemActive()) {
        editor_.endGesture();
        widgetGesture_ = false;
    }
    ImGui::End();

    // What the tool does, under the world: its bottom edge stays put, so a hint that wraps
    // to more lines grows upwards and no line leaves the screen.
    const float left = std::min(panelPx(kEditorPanelWidth), 0.5f * display.x) + panelPx(12);
    const float room = display.x - left - panelPx(12);
    ImGui::SetNextWindowPos(ImVec2(left, display.y - panelPx(8)), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(room, display.y));
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("##editorhint", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                     ImGuiWindowFlags_NoNav);
    ImGui::PushTextWrapPos(room - ImGui::GetStyle().WindowPadding.x);
    ImGui::Text("%s   |  wheel zoom, right drag pan, Home frame  |  Ctrl+Z undo, Ctrl+Y redo",
                kTools[static_cast<int>(tool_)].hint);
    ImGui::PopTextWrapPos();
    ImGui::End();
    return out;
}

} // namespace ui
