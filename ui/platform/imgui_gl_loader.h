#pragma once

#include "ui/platform/gl_context.h"

namespace ui {

/// Points ImGui's OpenGL3 backend at the current context's GL functions. Call before
/// ImGui_ImplOpenGL3_Init, once per context. False when the context is older than GL 3.
bool loadImGuiGL(ProcAddressFn getProc);

} // namespace ui
