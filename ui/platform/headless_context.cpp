#include "ui/platform/gl_context.h"

namespace ui {

std::unique_ptr<GLContext> createHeadlessContext(int width, int height, HeadlessBackend backend,
                                                 std::string& error) {
    std::string osmesaError, eglError;
    if (backend == HeadlessBackend::Auto || backend == HeadlessBackend::OSMesa) {
        if (auto c = createOSMesaContext(width, height, osmesaError)) return c;
        if (backend == HeadlessBackend::OSMesa) {
            error = osmesaError;
            return nullptr;
        }
    }
    if (auto c = createEglContext(width, height, eglError)) return c;
    error = osmesaError.empty() ? eglError : osmesaError + "; " + eglError;
    return nullptr;
}

} // namespace ui
