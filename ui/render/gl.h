// The OpenGL 3.3 core functions the renderer calls, loaded at run time through the
// current context's proc-address function (SDL_GL_GetProcAddress in the window,
// OSMesaGetProcAddress or eglGetProcAddress headless).
//
// Why our own table: linking libGL directly binds GLX entry points, which have no
// current context under OSMesa or EGL. Only type
// definitions come from the Khronos header; every function is a pointer filled by
// loadGL(). ImGui's backend has its own loader (imgui_gl_loader.cpp); the two never
// share a translation unit because their headers define the same names.
#pragma once

#include <GL/glcorearb.h>

namespace ui::gl {

using ProcAddressFn = void* (*)(const char* name);

// X(return type, name, parameter list) for every function the renderer needs.
#define UI_GL_FUNCTIONS(X)                                                                         \
    X(void, Viewport, (GLint, GLint, GLsizei, GLsizei))                                            \
    X(void, ClearColor, (GLfloat, GLfloat, GLfloat, GLfloat))                                      \
    X(void, Clear, (GLbitfield))                                                                   \
    X(void, Enable, (GLenum))                                                                      \
    X(void, Disable, (GLenum))                                                                     \
    X(void, BlendFuncSeparate, (GLenum, GLenum, GLenum, GLenum))                                   \
    X(void, Finish, (void))                                                                        \
    X(GLenum, GetError, (void))                                                                    \
    X(const GLubyte*, GetString, (GLenum))                                                         \
    X(void, GetIntegerv, (GLenum, GLint*))                                                         \
    X(void, PixelStorei, (GLenum, GLint))                                                          \
    X(void, ReadPixels, (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*))                   \
    X(GLuint, CreateShader, (GLenum))                                                              \
    X(void, ShaderSource, (GLuint, GLsizei, const GLchar* const*, const GLint*))                   \
    X(void, CompileShader, (GLuint))                                                               \
    X(void, GetShaderiv, (GLuint, GLenum, GLint*))                                                 \
    X(void, GetShaderInfoLog, (GLuint, GLsizei, GLsizei*, GLchar*))                                \
    X(void, DeleteShader, (GLuint))                                                                \
    X(GLuint, CreateProgram, (void))                                                               \
    X(void, AttachShader, (GLuint, GLuint))                                                        \
    X(void, BindAttribLocation, (GLuint, GLuint, const GLchar*))                                   \
    X(void, LinkProgram, (GLuint))                                                                 \
    X(void, GetProgramiv, (GLuint, GLenum, GLint*))                                                \
    X(void, GetProgramInfoLog, (GLuint, GLsizei, GLsizei*, GLchar*))                               \
    X(void, DeleteProgram, (GLuint))                                                               \
    X(void, UseProgram, (GLuint))                                                                  \
    X(GLint, GetUniformLocation, (GLuint, const GLchar*))                                          \
    X(void, UniformMatrix4fv, (GLint, GLsizei, GLboolean, const GLfloat*))                         \
    X(void, GenBuffers, (GLsizei, GLuint*))                                                        \
    X(void, DeleteBuffers, (GLsizei, const GLuint*))                                               \
    X(void, BindBuffer, (GLenum, GLuint))                                                          \
    X(void, BufferData, (GLenum, GLsizeiptr, const void*, GLenum))                                 \
    X(void, GenVertexArrays, (GLsizei, GLuint*))                                                   \
    X(void, DeleteVertexArrays, (GLsizei, const GLuint*))                                          \
    X(void, BindVertexArray, (GLuint))                                                             \
    X(void, EnableVertexAttribArray, (GLuint))                                                     \
    X(void, VertexAttribPointer, (GLuint, GLint, GLenum, GLboolean, GLsizei, const void*))         \
    X(void, DrawArrays, (GLenum, GLint, GLsizei))                                                  \
    X(void, GenFramebuffers, (GLsizei, GLuint*))                                                   \
    X(void, DeleteFramebuffers, (GLsizei, const GLuint*))                                          \
    X(void, BindFramebuffer, (GLenum, GLuint))                                                     \
    X(GLenum, CheckFramebufferStatus, (GLenum))                                                    \
    X(void, GenRenderbuffers, (GLsizei, GLuint*))                                                  \
    X(void, DeleteRenderbuffers, (GLsizei, const GLuint*))                                         \
    X(void, BindRenderbuffer, (GLenum, GLuint))                                                    \
    X(void, RenderbufferStorage, (GLenum, GLenum, GLsizei, GLsizei))                               \
    X(void, RenderbufferStorageMultisample, (GLenum, GLsizei, GLenum, GLsizei, GLsizei))           \
    X(void, FramebufferRenderbuffer, (GLenum, GLenum, GLenum, GLuint))                             \
    X(void, GenTextures, (GLsizei, GLuint*))                                                       \
    X(void, DeleteTextures, (GLsizei, const GLuint*))                                              \
    X(void, BindTexture, (GLenum, GLuint))                                                         \
    X(void, TexImage2D, (GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void*)) \
    X(void, TexParameteri, (GLenum, GLenum, GLint))                                                \
    X(void, FramebufferTexture2D, (GLenum, GLenum, GLenum, GLuint, GLint))                         \
    X(void, BlitFramebuffer,                                                                       \
      (GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLbitfield, GLenum))

struct Functions {
#define UI_GL_DECLARE(ret, name, params) ret(APIENTRYP name) params = nullptr;
    UI_GL_FUNCTIONS(UI_GL_DECLARE)
#undef UI_GL_DECLARE
};

/// The loaded table; valid after loadGL() succeeded on the current context.
extern Functions fn;

/// Fills `fn` from the current context. Returns "" on success, else the first missing
/// function's name (the context is older than GL 3.3 core).
const char* loadGL(ProcAddressFn getProc);

} // namespace ui::gl
