#include "ui/platform/gl_setup.h"

#include "ui/render/gl.h"

#include <stdexcept>
#include <string>

namespace ui {

bool loadGLOrThrow(GLContext& context) {
    if (const char* missing = gl::loadGL(context.procAddress()); *missing)
        throw std::runtime_error(std::string(context.name()) + ": OpenGL 3.3 core is needed; " +
                                 missing + " is missing");
    return true;
}

int autoSamples(int requested) {
    if (requested > 0) return requested;
    const auto* renderer = reinterpret_cast<const char*>(gl::fn.GetString(GL_RENDERER));
    const std::string name = renderer ? renderer : "";
    const bool software = name.find("llvmpipe") != std::string::npos ||
                          name.find("softpipe") != std::string::npos ||
                          name.find("swrast") != std::string::npos;
    return software ? 1 : 4;
}

} // namespace ui
