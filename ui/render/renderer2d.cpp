#include "ui/render/renderer2d.h"

#include "ui/render/design_canvas.h"
#include "ui/render/gl.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ui {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 aPosition;
layout(location = 1) in vec4 aColor;
uniform mat4 uClipFromWorld;
out vec4 vColor;
void main() {
    gl_Position = uClipFromWorld * vec4(aPosition, 0.0, 1.0);
    vColor = aColor;
}
)";

const char* kFragmentShader = R"(#version 330 core
in vec4 vColor;
out vec4 fragColor;
void main() { fragColor = vColor; }
)";

unsigned compile(GLenum kind, const char* source) {
    const GLuint shader = gl::fn.CreateShader(kind);
    gl::fn.ShaderSource(shader, 1, &source, nullptr);
    gl::fn.CompileShader(shader);
    GLint ok = 0;
    gl::fn.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024] = {};
        gl::fn.GetShaderInfoLog(shader, sizeof log, nullptr, log);
        gl::fn.DeleteShader(shader);
        throw std::runtime_error(std::string("renderer: shader does not compile: ") + log);
    }
    return shader;
}

std::uint8_t channel(float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

Color darker(Color c) {
    return {c.r * 0.55f, c.g * 0.55f, c.b * 0.55f, c.a};
}

Vec2 normalized(Vec2 v) {
    const double len = phys::length(v);
    return len > 0.0 ? v / len : Vec2{0.0, 0.0};
}

} // namespace

Renderer2D::Renderer2D() {
    const unsigned vs = compile(GL_VERTEX_SHADER, kVertexShader);
    const unsigned fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    program_ = gl::fn.CreateProgram();
    gl::fn.AttachShader(program_, vs);
    gl::fn.AttachShader(program_, fs);
    gl::fn.LinkProgram(program_);
    gl::fn.DeleteShader(vs);
    gl::fn.DeleteShader(fs);
    GLint ok = 0;
    gl::fn.GetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[1024] = {};
        gl::fn.GetProgramInfoLog(program_, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("renderer: shader does not link: ") + log);
    }
    clipFromWorldLoc_ = gl::fn.GetUniformLocation(program_, "uClipFromWorld");

    gl::fn.GenVertexArrays(1, &vao_);
    gl::fn.GenBuffers(1, &vbo_);
    gl::fn.BindVertexArray(vao_);
    gl::fn.BindBuffer(GL_ARRAY_BUFFER, vbo_);
    gl::fn.EnableVertexAttribArray(0);
    gl::fn.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                               reinterpret_cast<const void*>(offsetof(Vertex, x)));
    gl::fn.EnableVertexAttribArray(1);
    gl::fn.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                               reinterpret_cast<const void*>(offsetof(Vertex, rgba)));
    gl::fn.BindVertexArray(0);
    vertices_.reserve(1 << 16);
}

Renderer2D::~Renderer2D() {
    // The context may already be gone at exit; GL ignores names it does not know.
    if (gl::fn.DeleteBuffers) gl::fn.DeleteBuffers(1, &vbo_);
    if (gl::fn.DeleteVertexArrays) gl::fn.DeleteVertexArrays(1, &vao_);
    if (gl::fn.DeleteProgram) gl::fn.DeleteProgram(program_);
}

void Renderer2D::begin(const Camera& camera) {
    camera_ = camera;
    labelScale_ = panelScale(camera.width, camera.height);
    originX_ = originY_ = 0;
    vertices_.clear();
    labels_.clear();
    stats_ = {};
}

void Renderer2D::beginInset(const Camera& camera, int originXPx, int originYPx) {
    flush();
    camera_ = camera;
    originX_ = originXPx;
    originY_ = originYPx;
    frameLabels_ = labels_.size();
}

void Renderer2D::endInset(const Camera& frame) {
    flush();
    labels_.resize(std::min(labels_.size(), frameLabels_));
    camera_ = frame;
    originX_ = originY_ = 0;
}

void Renderer2D::flush() {
    stats_.vertices = vertices_.size();
    if (vertices_.empty()) return;
    gl::fn.Viewport(originX_, originY_, camera_.width, camera_.height);
    gl::fn.Enable(GL_BLEND);
    gl::fn.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl::fn.Disable(GL_DEPTH_TEST);
    gl::fn.Disable(GL_CULL_FACE);
    gl::fn.Disable(GL_SCISSOR_TEST);
    gl::fn.UseProgram(program_);
    const auto m = camera_.clipFromWorld();
    gl::fn.UniformMatrix4fv(clipFromWorldLoc_, 1, GL_FALSE, m.data());
    gl::fn.BindVertexArray(vao_);
    gl::fn.BindBuffer(GL_ARRAY_BUFFER, vbo_);
    // Re-specifying the whole store each flush lets the driver orphan the old one
    // instead of waiting for the GPU to finish reading it.
    gl::fn.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices_.size() * sizeof(Vertex)),
                      vertices_.data(), GL_STREAM_DRAW);
    gl::fn.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices_.size()));
    gl::fn.BindVertexArray(0);
    gl::fn.UseProgram(0);
    ++stats_.drawCalls;
    vertices_.clear();
}

void Renderer2D::push(Vec2 p, Color c) {
    vertices_.push_back({static_cast<float>(p.x),
                         static_cast<float>(p.y),
                         {channel(c.r), channel(c.g), channel(c.b), channel(c.a)}});
}

void Renderer2D::quad(Vec2 a, Vec2 b, Vec2 c, Vec2 d, Color color) {
    triangle(a, b, c, color, color, color);
    triangle(a, c, d, color, color, color);
}

int Renderer2D::circleSegments(double radiusPx) {
    // Keep each chord's sagitta r (1 - cos(pi/n)) under about a quarter pixel.
    const double r = std::max(radiusPx, 1.0);
    const double n = std::numbers::pi / std::acos(std::max(1.0 - 0.25 / r, -1.0));
    return std::clamp(static_cast<int>(std::ceil(n)), 8, 128);
}

void Renderer2D::line(Vec2 a, Vec2 b, Color color, float widthPx) {
    const Vec2 d = normalized(b - a);
    if (d == Vec2{}) return;
    const double hw = camera_.metres(0.5 * widthPx);
    const Vec2 n = phys::perp(d) * hw;
    const Vec2 e = d * hw * 0.5; // short square caps so joined segments leave no gap
    quad(a - e + n, a - e - n, b + e - n, b + e + n, color);
}

void Renderer2D::polyline(std::span<const Vec2> points, Color color, float widthPx, bool closed) {
    const std::size_t n = points.size();
    if (n < 2) return;
    const double hw = camera_.metres(0.5 * widthPx);
    // Offset of each point: the mitre of its two neighbouring segment normals, its
    // length capped at 2 half-widths so sharp turns do not spike.
    scratch_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool hasPrev = closed || i > 0;
        const bool hasNext = closed || i + 1 < n;
        const Vec2 prev = points[(i + n - 1) % n];
        const Vec2 next = points[(i + 1) % n];
        const Vec2 nIn = hasPrev ? phys::perp(normalized(points[i] - prev)) : Vec2{};
        const Vec2 nOut = hasNext ? phys::perp(normalized(next - points[i])) : Vec2{};
        Vec2 m = normalized(nIn + nOut);
        if (m == Vec2{}) m = hasPrev ? nIn : nOut;
        const double cosHalf = std::max(phys::dot(m, hasNext ? nOut : nIn), 0.5);
        scratch_[i] = m * (hw / cosHalf);
    }
    const std::size_t segments = closed ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i) {
        const std::size_t j = (i + 1) % n;
        quad(points[i] + scratch_[i], points[i] - scratch_[i], points[j] - scratch_[j],
             points[j] + scratch_[j], color);
    }
}

void Renderer2D::fillCircle(Vec2 center, double radius, Color color, float minRadiusPx) {
    const double r = std::max(radius, camera_.metres(minRadiusPx));
    const int n = circleSegments(r * camera_.pixelsPerMetre);
    const double step = 2.0 * std::numbers::pi / n;
    Vec2 prev = center + Vec2{r, 0.0};
    for (int i = 1; i <= n; ++i) {
        const Vec2 p = center + Vec2{r * std::cos(i * step), r * std::sin(i * step)};
        triangle(center, prev, p, color, color, color);
        prev = p;
    }
}

void Renderer2D::strokeCircle(Vec2 center, double radius, Color color, float widthPx,
                              float minRadiusPx) {
    const double r = std::max(radius, camera_.metres(minRadiusPx));
    const double hw = camera_.metres(0.5 * widthPx);
    const double ro = r + hw;
    const double ri = std::max(r - hw, 0.0);
    const int n = circleSegments(ro * camera_.pixelsPerMetre);
    const double step = 2.0 * std::numbers::pi / n;
    for (int i = 0; i < n; ++i) {
        const Vec2 u0{std::cos(i * step), std::sin(i * step)};
        const Vec2 u1{std::cos((i + 1) * step), std::sin((i + 1) * step)};
        quad(center + u0 * ro, center + u0 * ri, center + u1 * ri, center + u1 * ro, color);
    }
}

void Renderer2D::fillConvex(std::span<const Vec2> points, Color color) {
    for (std::size_t i = 1; i + 1 < points.size(); ++i)
        triangle(points[0], points[i], points[i + 1], color, color, color);
}

void Renderer2D::triangle(Vec2 a, Vec2 b, Vec2 c, Color ca, Color cb, Color cc) {
    push(a, ca);
    push(b, cb);
    push(c, cc);
}

void Renderer2D::fillRectGradient(Vec2 lo, Vec2 hi, Color bottom, Color top) {
    const Vec2 a = lo, b{hi.x, lo.y}, c = hi, d{lo.x, hi.y};
    triangle(a, b, c, bottom, bottom, top);
    triangle(a, c, d, bottom, top, top);
}

void Renderer2D::arrow(Vec2 from, Vec2 to, Color color, float widthPx, float headPx) {
    const Vec2 d = to - from;
    const double len = phys::length(d);
    if (len <= 0.0) return;
    const Vec2 u = d / len;
    // The head never takes more than half the arrow, so short vectors still read as arrows.
    const double head = std::min(camera_.metres(headPx), 0.5 * len);
    const Vec2 base = to - u * head;
    line(from, base, color, widthPx);
    const Vec2 side = phys::perp(u) * (0.5 * head);
    triangle(to, base + side, base - side, color, color, color);
}

void Renderer2D::label(Vec2 p, std::string text, Color color, Vec2 offsetPx, float scale,
                       float alignX) {
    labels_.push_back({camera_.toPixel(p) + offsetPx * labelScale_, std::move(text), color,
                       scale * labelScale_, alignX, true});
}

void Renderer2D::screenLabel(Vec2 pixel, std::string text, Color color, float scale, float alignX) {
    labels_.push_back({pixel, std::move(text), color, scale, alignX});
}

void Renderer2D::circle(Vec2 center, double radius, Color color) {
    strokeCircle(center, radius, color);
}

void Renderer2D::solidCircle(Vec2 center, double radius, Vec2 axis, Color color) {
    const Color rim = darker(color);
    fillCircle(center, radius, color);
    // The rim sits inside the radius so the disc covers exactly what the physics does.
    strokeCircle(center, std::max(radius - camera_.metres(0.6), 0.0), rim, 1.2f);
    if (axis != Vec2{}) line(center, center + axis * radius, rim);
}

void Renderer2D::polygon(std::span<const Vec2> vertices, Color color) {
    polyline(vertices, color, 1.5f, true);
}

void Renderer2D::solidPolygon(std::span<const Vec2> vertices, Color color) {
    fillConvex(vertices, color);
    polyline(vertices, darker(color), 1.5f, true);
}

void Renderer2D::point(Vec2 p, float sizePixels, Color color) {
    fillCircle(p, 0.0, color, 0.5f * sizePixels);
}

void Renderer2D::text(Vec2 p, std::string_view text, Color color) {
    label(p, std::string(text), color);
}

} // namespace ui
