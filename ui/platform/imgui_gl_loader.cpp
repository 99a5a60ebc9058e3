// ImGui's OpenGL3 backend is compiled with IMGUI_IMPL_OPENGL_LOADER_CUSTOM (see
// ui/CMakeLists.txt), so its GL functions come from the stripped gl3w loader that ships
// with it, implemented here. Its own imgl3wInit() would open libGL.so.1 and ask GLX,
// which has no current context under OSMesa or EGL; imgl3wInit2 takes the context's
// own proc-address function instead.
#define IMGL3W_IMPL
#include "backends/imgui_impl_opengl3_loader.h"

#include "ui/platform/imgui_gl_loader.h"

namespace ui {

namespace {
ProcAddressFn currentProc = nullptr;
GL3WglProc trampoline(const char* name) {
    return reinterpret_cast<GL3WglProc>(currentProc(name));
}
} // namespace

bool loadImGuiGL(ProcAddressFn getProc) {
    currentProc = getProc;
    return imgl3wInit2(trampoline) == GL3W_OK;
}

} // namespace ui
