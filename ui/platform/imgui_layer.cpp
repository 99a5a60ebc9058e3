#include "ui/platform/imgui_layer.h"

#include "ui/platform/imgui_gl_loader.h"
#include "ui/platform/sdl_window.h"

#include <SDL.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>
#include <imgui_internal.h> // the windows of the last frame, for pressOnWindow

#include <cfloat>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace ui {

namespace {

// A proportional font reads better than ImGui's built-in bitmap one in screenshots;
// DejaVu is in fonts-dejavu-core (Makefile PACKAGES). Without it, the built-in font.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr float kFontPixels = 16.0f;

void applyStyle() {
    ImGui::StyleColorsDark();
    ImGuiStyle& s = ImGui::GetStyle();
    s.WindowRounding = 6.0f;
    s.FrameRounding = 4.0f;
    s.GrabRounding = 4.0f;
    s.WindowBorderSize = 0.0f;
    s.WindowPadding = ImVec2(10, 10);
    s.ItemSpacing = ImVec2(8, 5);
    s.Colors[ImGuiCol_WindowBg] = ImVec4(0.08f, 0.10f, 0.14f, 0.86f);
    s.Colors[ImGuiCol_TitleBgActive] = ImVec4(0.16f, 0.29f, 0.48f, 1.0f);
}

} // namespace

ImGuiLayer::ImGuiLayer(GLContext& context, SdlWindow* window) : context_(context), window_(window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    // Settings persistence is the game's job (written atomically); no imgui.ini litter.
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    if (std::filesystem::exists(kFontPath)) io.Fonts->AddFontFromFileTTF(kFontPath, kFontPixels);
    applyStyle();
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
    return ImGui_ImplSDL2_ProcessEvent(&event);
}

void ImGuiLayer::newFrame(double dtSeconds) {
    ImGui_ImplOpenGL3_NewFrame();
    if (window_) {
        ImGui_ImplSDL2_NewFrame();
    } else {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize =
            ImVec2(static_cast<float>(context_.width()), static_cast<float>(context_.height()));
        io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
        io.DeltaTime = static_cast<float>(dtSeconds > 0.0 ? dtSeconds : 1.0 / 60.0);
    }
    ImGui::NewFrame();
}

void ImGuiLayer::drawLabels(std::span<const Label> labels) {
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    ImFont* font = ImGui::GetFont();
    // Labels are placed in framebuffer pixels; ImGui works in window points.
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    for (const Label& l : labels) {
        const ImU32 colour =
            ImGui::ColorConvertFloat4ToU32(ImVec4(l.color.r, l.color.g, l.color.b, l.color.a));
        const float size = ImGui::GetFontSize() * l.scale;
        const float width =
            l.alignX != 0.0f ? font->CalcTextSizeA(size, FLT_MAX, 0.0f, l.text.c_str()).x : 0.0f;
        const ImVec2 p(std::round(static_cast<float>(l.pixel.x) / scale.x - l.alignX * width),
                       std::round(static_cast<float>(l.pixel.y) / scale.y));
        // A one-pixel dark shadow keeps text readable on sky and ground alike.
        list->AddText(font, size, ImVec2(p.x + 1, p.y + 1), IM_COL32(0, 0, 0, 140), l.text.c_str());
        list->AddText(font, size, p, colour, l.text.c_str());
    }
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
