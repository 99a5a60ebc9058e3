#include "ui/render/gl.h"

namespace ui::gl {

Functions fn;

const char* loadGL(ProcAddressFn getProc) {
    // Function pointers are cast from void* through the proc-address convention that
    // every GL window system uses (POSIX guarantees the round trip).
#define UI_GL_LOAD(ret, name, params)                                                              \
    fn.name = reinterpret_cast<ret(APIENTRYP) params>(getProc("gl" #name));                        \
    if (!fn.name) return "gl" #name;
    UI_GL_FUNCTIONS(UI_GL_LOAD)
#undef UI_GL_LOAD
    return "";
}

} // namespace ui::gl
