// The OSMesa headless context: Mesa renders (llvmpipe) into a buffer we own. This is
// the only translation unit that includes GL/osmesa.h: its GL/gl.h declares the
// compatibility-profile functions that clash with the loader headers.
#include "ui/platform/gl_context.h"

#include <GL/osmesa.h>

#include <cstdint>
#include <vector>

namespace ui {

namespace {

void* osmesaProc(const char* name) {
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

class OSMesaContextImpl final : public GLContext {
  public:
    OSMesaContextImpl(OSMesaContext ctx, int w, int h)
        : ctx_(ctx), width_(w), height_(h), pixels_(std::size_t(w) * h * 4) {}
    ~OSMesaContextImpl() override { OSMesaDestroyContext(ctx_); }

    bool makeCurrent() {
        return OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, width_, height_);
    }
    const char* name() const override { return "osmesa"; }
    int width() const override { return width_; }
    int height() const override { return height_; }
    ProcAddressFn procAddress() const override { return osmesaProc; }
    void present() override {
        // glFinish from this context's own table: OSMesa renders into pixels_ and the
        // frame must be complete before anyone reads it.
        using FinishFn = void (*)();
        if (auto finish = reinterpret_cast<FinishFn>(OSMesaGetProcAddress("glFinish"))) finish();
    }

  private:
    OSMesaContext ctx_;
    int width_, height_;
    std::vector<std::uint8_t> pixels_;
};

} // namespace

std::unique_ptr<GLContext> createOSMesaContext(int width, int height, std::string& error) {
    // A core 3.3 context; llvmpipe gives 4.5. No depth or stencil: 2D only.
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!ctx) {
        error = "osmesa: cannot create a GL 3.3 core context";
        return nullptr;
    }
    auto context = std::make_unique<OSMesaContextImpl>(ctx, width, height);
    if (!context->makeCurrent()) {
        error = "osmesa: cannot make the context current";
        return nullptr;
    }
    return context;
}

} // namespace ui
