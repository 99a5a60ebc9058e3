#include "ui/platform/imgui_layer.h"

#include "ui/platform/imgui_gl_loader.h"
#include "ui/platform/sdl_window.h"
#include "ui/render/design_canvas.h"

#include <SDL.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>
#include <imgui_internal.h> // the windows of the last frame, for pressOnWindow

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace ui {

namespace {

// A proportional font reads better than ImGui's built-in bitmap one in screenshots;
// DejaVu is in fonts-dejavu-core (Makefile PACKAGES). Without it, the built-in font.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr float kFontPixels = 16.0f;

// The look at the design size (panelScale 1).
ImGuiStyle designStyle() {
    ImGuiStyle s;
    ImGui::StyleColorsDark(&s);
    s.WindowRounding = 6.0f;
    s.FrameRounding = 4.0f;
    s.GrabRounding = 4.0f;
    s.WindowBorderSize = 0.0f;
    s.WindowPadding = ImVec2(10, 10);
    s.ItemSpacing = ImVec2(8, 5);
    s.Colors[ImGuiCol_WindowBg] = ImVec4(0.08f, 0.10f, 0.14f, 0.86f);
    s.Colors[ImGuiCol_TitleBgActive] = ImVec4(0.16f, 0.29f, 0.48f, 1.0f);
    return s;
}

// The panels' scale in the frames being built (one ImGui context at a time).
float gPanelScale = 1.0f;

// The display the layout was made for, kept in the layout's ini text beside the windows
// ("[ArtilleryDisplay][Display]" Size=W,H), so that a layout saved in a small window
// and loaded in a large one is moved to fit.
void* openDisplayEntry(ImGuiContext*, ImGuiSettingsHandler*, const char* name) {
    return std::strcmp(name, "Display") == 0 ? reinterpret_cast<void*>(1) : nullptr;
}
// A display of at most kMaxDisplay points a side; a damaged file's other sizes (0, -1,
// inf, nan, 1e30) are not one, and the layout is then taken as it is.
constexpr float kMaxDisplay = 16384.0f;
void readDisplayLine(ImGuiContext*, ImGuiSettingsHandler* handler, void*, const char* line) {
    float w = 0.0f, h = 0.0f;
    if (std::sscanf(line, "Size=%f,%f", &w, &h) == 2 && w >= 1.0f && w <= kMaxDisplay &&
        h >= 1.0f && h <= kMaxDisplay)
        *static_cast<Vec2*>(handler->UserData) = {w, h};
}

// A position or size for the layout's settings, which ImGui keeps in shorts.
short settingsShort(float v) {
    return static_cast<short>(std::clamp(std::round(v), -32768.0f, 32767.0f));
}
void writeDisplay(ImGuiContext*, ImGuiSettingsHandler* handler, ImGuiTextBuffer* out) {
    const Vec2 size = *static_cast<const Vec2*>(handler->UserData);
    if (size.x > 0.0 && size.y > 0.0)
        out->appendf("[ArtilleryDisplay][Display]\nSize=%.0f,%.0f\n\n", size.x, size.y);
}

} // namespace

ImGuiLayer::ImGuiLayer(GLContext& context, SdlWindow* window) : context_(context), window_(window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    // Settings persistence is the game's job (written atomically); no imgui.ini litter.
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    setPanelScale(panelScale(context_.width(), context_.height()));
    ImGuiSettingsHandler display;
    display.TypeName = "ArtilleryDisplay";
    display.TypeHash = ImHashStr("ArtilleryDisplay");
    display.ReadOpenFn = openDisplayEntry;
    display.ReadLineFn = readDisplayLine;
    display.WriteAllFn = writeDisplay;
    display.UserData = &layoutDisplay_;
    ImGui::GetCurrentContext()->SettingsHandlers.push_back(display);
    if (window_ && !ImGui_ImplSDL2_InitForOpenGL(window_->window(), window_->glContext()))
        throw std::runtime_error("imgui: the SDL2 backend does not start");
    if (!loadImGuiGL(context_.procAddress()))
        throw std::runtime_error("imgui: cannot load GL 3 functions for the OpenGL3 backend");
    if (!ImGui_ImplOpenGL3_Init("#version 330 core"))
        throw std::runtime_error("imgui: the OpenGL3 backend does not start");
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    if (window_) ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
}

bool ImGuiLayer::processEvent(const SDL_Event& event) {
    // Headless there is no SDL backend to take events (tests hand the screen synthetic
    // ones): they are not ImGui's.
    if (!window_) return false;
    if (taps_.holdBack(event)) return true; // a quick tap's release: next frame
    if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_LEAVE) pointerOut_ = true;
    if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_ENTER) pointerOut_ = false;
    if (event.type == SDL_MOUSEMOTION) {
        pointer_ = Vec2{static_cast<double>(event.motion.x), static_cast<double>(event.motion.y)};
        pointerSeen_ = true;
        pointerOut_ = false;
    }
    return ImGui_ImplSDL2_ProcessEvent(&event);
}

ImFont* largeFont() {
    ImFontAtlas* fonts = ImGui::GetIO().Fonts;
    return fonts->Fonts.Size > 1 ? fonts->Fonts[1] : ImGui::GetFont();
}

float panelPx(float designPixels) {
    return designPixels * gPanelScale;
}

void dimWrapped(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (ImGui::GetCurrentWindow()->DC.TextWrapPos < 0.0f) {
        ImGui::TextWrapped("%s", text.c_str());
    } else {
        ImGui::TextUnformatted(text.c_str()); // wraps at the position pushed
    }
    ImGui::PopStyleColor();
}

void keepPanelOnScreen(float margin) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    ImVec2 in = pos;
    if (pos.x + size.x > display.x) in.x = std::max(0.0f, display.x - margin - size.x);
    if (pos.y + size.y > display.y) in.y = std::max(0.0f, display.y - margin - size.y);
    if (in.x != pos.x || in.y != pos.y) ImGui::SetWindowPos(in);
}

// The font is rasterized at the scaled size, not magnified (crisp text), and every size
// of the style (padding, spacing, rounding) scales with it.
void ImGuiLayer::setPanelScale(float scale) {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    // The text the game writes: Latin, Greek (theta, omega), punctuation (the dashes),
    // super- and subscripts, arrows, mathematical operators (the root, the minus) and the
    // stars of the results card. ImGui's ranges are pairs, ended by a zero.
    static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F,
                                      0x2070, 0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF,
                                      0x25A0, 0x25FF, 0x2600, 0x26FF, 0};
    // The layout of every panel and label is measured in this font: without it the game
    // would draw another layout than the one it was made for.
    if (!std::filesystem::exists(kFontPath))
        throw std::runtime_error(std::string("the font ") + kFontPath +
                                 " is missing: install the package fonts-dejavu-core");
    io.Fonts->AddFontFromFileTTF(kFontPath, kFontPixels * scale, nullptr, kRanges);
    // The same face twice as large, for what is read from across the room: a lesson's
    // formula, a banner.
    io.Fonts->AddFontFromFileTTF(kFontPath, 2.0f * kFontPixels * scale, nullptr, kRanges);
    ImGui::GetStyle() = designStyle();
    ImGui::GetStyle().ScaleAllSizes(scale);
    if (io.Fonts->TexID) { // else the backend's first frame builds it
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
    scale_ = gPanelScale = scale;
}

void ImGuiLayer::newFrame(double dtSeconds) {
    // The window's size in ImGui's units (points), which a resize changes.
    int w = context_.width(), h = context_.height();
    if (window_) SDL_GetWindowSize(window_->window(), &w, &h);
    if (const float scale = panelScale(w, h); scale != scale_) setPanelScale(scale);
    gPanelScale = scale_;
    ImGui_ImplOpenGL3_NewFrame();
    if (window_) {
        for (const SDL_Event& release : taps_.releasesDue())
            ImGui_ImplSDL2_ProcessEvent(&release);
        ImGui_ImplSDL2_NewFrame();
        // The pointer where its last motion event put it, as later ImGui backends take it:
        // this backend reads the global pointer state, which SDL may not refresh (no raw
        // input events under some X servers), or the last place inside a focused window
        // the pointer has left. After it left (and no button drags it), nothing is
        // hovered, so a tooltip closes.
        const ImVec2 seen(static_cast<float>(pointer_.x), static_cast<float>(pointer_.y));
        if (pointerSeen_)
            ImGui::GetIO().MousePos = pointerOut_ && !ImGui::IsAnyMouseDown() ? ImVec2(-FLT_MAX, -FLT_MAX) : seen;
    } else {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize =
            ImVec2(static_cast<float>(context_.width()), static_cast<float>(context_.height()));
        io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
        io.DeltaTime = static_cast<float>(dtSeconds > 0.0 ? dtSeconds : 1.0 / 60.0);
    }
    ImGui::NewFrame();
    const Vec2 now{ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y};
    if (layoutDisplay_.x > 0.0 && layoutDisplay_ != now) keepPanelsInPlace(layoutDisplay_, now);
    layoutDisplay_ = now;
}

float keepToNearestEdge(float pos, float size, float was, float now, float k) {
    if (pos + 0.5f * size <= 0.5f * was) return pos * k; // its margin to the start, scaled
    return now - (was - pos) * k; // its margin to the end and its size, both scaled
}

// Every panel, open or only in the loaded layout, keeps to its nearest edges: its margins
// and its size scale with the panels' text (a panel at the top right stays there, and
// the text in it still fits).
void ImGuiLayer::keepPanelsInPlace(Vec2 was, Vec2 now) {
    const float k = panelScale(now.x, now.y) / panelScale(was.x, was.y);
    auto place = [&](ImVec2 pos, ImVec2 size) {
        return ImVec2(keepToNearestEdge(pos.x, size.x, static_cast<float>(was.x),
                                        static_cast<float>(now.x), k),
                      keepToNearestEdge(pos.y, size.y, static_cast<float>(was.y),
                                        static_cast<float>(now.y), k));
    };
    ImGuiContext& g = *ImGui::GetCurrentContext();
    for (ImGuiWindow* w : g.Windows) {
        if (w->ParentWindow || (w->Flags & ImGuiWindowFlags_ChildWindow)) continue;
        ImGui::SetWindowPos(w, place(w->Pos, w->SizeFull));
        const bool fits = (w->Flags & ImGuiWindowFlags_AlwaysAutoResize) != 0;
        ImGui::SetWindowSize(w, fits ? ImVec2(0.0f, 0.0f)
                                     : ImVec2(w->SizeFull.x * k, w->SizeFull.y * k));
    }
    // The layout's panels not drawn yet this run take their place from their settings.
    for (ImGuiWindowSettings* s = g.SettingsWindows.begin(); s;
         s = g.SettingsWindows.next_chunk(s)) {
        if (ImGui::FindWindowByID(s->ID)) continue;
        const ImVec2 size(s->Size.x, s->Size.y);
        const ImVec2 at = place(ImVec2(s->Pos.x, s->Pos.y), size);
        s->Pos = ImVec2ih(settingsShort(at.x), settingsShort(at.y));
        s->Size = ImVec2ih(settingsShort(size.x * k), settingsShort(size.y * k));
    }
}

std::vector<PixelRect> ImGuiLayer::drawLabels(std::span<const Label> labels) {
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    ImFont* font = ImGui::GetFont();
    // Labels are placed in framebuffer pixels; ImGui works in window points.
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    std::vector<PixelRect> drawn;
    drawn.reserve(labels.size());
    for (const Label& l : labels) {
        const ImU32 colour =
            ImGui::ColorConvertFloat4ToU32(ImVec4(l.color.r, l.color.g, l.color.b, l.color.a));
        const float size = ImGui::GetFontSize() / scale_ * l.scale; // the design size
        const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, 0.0f, l.text.c_str());
        const ImVec2 p(std::round(static_cast<float>(l.pixel.x) / scale.x - l.alignX * extent.x),
                       std::round(static_cast<float>(l.pixel.y) / scale.y));
        // A one-pixel dark shadow keeps text readable on sky and ground alike.
        list->AddText(font, size, ImVec2(p.x + 1, p.y + 1), IM_COL32(0, 0, 0, 140), l.text.c_str());
        list->AddText(font, size, p, colour, l.text.c_str());
        drawn.push_back({p.x * scale.x, p.y * scale.y, (p.x + extent.x + 1) * scale.x,
                         (p.y + extent.y + 1) * scale.y});
    }
    return drawn;
}

PixelRect labelRect(const Label& l) {
    ImFont* font = ImGui::GetFont();
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    const float size = ImGui::GetFontSize() / gPanelScale * l.scale;
    const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, 0.0f, l.text.c_str());
    const double x0 = l.pixel.x - l.alignX * extent.x * scale.x;
    return {x0, l.pixel.y, x0 + (extent.x + 1) * scale.x, l.pixel.y + (extent.y + 1) * scale.y};
}

double designTextWidth(const std::string& text, double scale) {
    // The labels' face, measured at its design size: its advances scale with the size.
    const ImGuiIO& io = ImGui::GetIO();
    const ImFont* font = io.Fonts->Fonts.empty() ? nullptr : io.Fonts->Fonts[0];
    if (!font || !io.Fonts->IsBuilt())
        throw std::runtime_error("text measured before the panels' font is loaded");
    return font->CalcTextSizeA(static_cast<float>(kFontPixels * scale), FLT_MAX, 0.0f, text.c_str()).x;
}

void ImGuiLayer::render() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiLayer::wantsMouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}
bool ImGuiLayer::wantsKeyboard() const {
    return ImGui::GetIO().WantCaptureKeyboard;
}

namespace {

// Whether the window was drawn in the last frame: its Active flag until the next frame
// starts (NewFrame clears it), its WasActive flag from then until it begins again.
bool drawnLastFrame(const ImGuiWindow& w) {
    return (ImGui::GetCurrentContext()->WithinFrameScope ? w.WasActive : w.Active) && !w.Hidden;
}

} // namespace

std::optional<PixelRect> openWindowRect(const char* name) {
    const ImGuiWindow* w = ImGui::FindWindowByName(name);
    if (!w || !drawnLastFrame(*w) || w->Collapsed) return std::nullopt;
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    return PixelRect{w->Pos.x * scale.x, w->Pos.y * scale.y, (w->Pos.x + w->Size.x) * scale.x,
                     (w->Pos.y + w->Size.y) * scale.y};
}

std::vector<std::pair<std::string, PixelRect>> drawnWindowRects() {
    std::vector<std::pair<std::string, PixelRect>> rects;
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
        if (!drawnLastFrame(*w) || (w->Flags & ImGuiWindowFlags_ChildWindow)) continue;
        // The fallback window ImGui keeps for widgets outside any window, never shown here.
        if (std::string_view(w->Name).starts_with("Debug##")) continue;
        const ImRect r = w->Rect(); // a folded window: its title bar
        rects.emplace_back(w->Name, PixelRect{r.Min.x * scale.x, r.Min.y * scale.y,
                                              r.Max.x * scale.x, r.Max.y * scale.y});
    }
    return rects;
}

// ImGui's own hover test (FindHoveredWindow, run at the next frame's start) on the
// windows the last frame drew.
bool ImGuiLayer::pressOnWindow(const SDL_Event& event) const {
    if (event.type != SDL_MOUSEBUTTONDOWN) return false;
    const ImVec2 at(static_cast<float>(event.button.x), static_cast<float>(event.button.y));
    for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
        if (drawnLastFrame(*w) && !(w->Flags & ImGuiWindowFlags_NoMouseInputs) &&
            w->OuterRectClipped.Contains(at))
            return true;
    return false;
}

} // namespace ui
