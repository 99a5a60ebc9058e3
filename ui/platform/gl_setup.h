// What every screen does with a fresh GL context before drawing: load the GL 3.3 core
// functions (or say which one is missing) and choose multisampling for the renderer.
#pragma once

#include "ui/platform/gl_context.h"

namespace ui {

/// Loads GL through the context; throws std::runtime_error naming the missing function.
/// Returns true, so it can initialise a member before the members that need GL.
bool loadGLOrThrow(GLContext& context);

/// The requested MSAA sample count, or when 0: 1 on a software rasteriser (llvmpipe,
/// softpipe, swrast: 4 samples cost ~50 ms a frame there) and 4 on a GPU.
int autoSamples(int requested);

} // namespace ui
