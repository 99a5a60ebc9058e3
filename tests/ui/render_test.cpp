// Headless rendering: the renderer draws a world where the camera says it does, on
// every headless context, and the demo frame is a real picture (sky, ground, shell).
#include "physics/world.h"
#include "ui/demo/demo_scene.h"
#include "ui/demo/demo_view.h"
#include "ui/platform/gl_context.h"
#include "ui/play/play_screen.h"
#include "ui/render/camera.h"
#include "ui/render/gl.h"
#include "ui/render/renderer2d.h"
#include "ui/render/screenshot.h"
#include "ui/render/world_view.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>

namespace {

using phys::Color;
using phys::Vec2;

constexpr int kW = 320;
constexpr int kH = 240;

std::unique_ptr<ui::GLContext> makeContext(ui::HeadlessBackend backend, int w = kW, int h = kH) {
    std::string error;
    auto ctx = ui::createHeadlessContext(w, h, backend, error);
    if (ctx) {
        const char* missing = ui::gl::loadGL(ctx->procAddress());
        EXPECT_STREQ(missing, "");
    }
    return ctx;
}

struct Rgb {
    int r, g, b;
};
Rgb at(const ui::Image& img, Vec2 pixel) {
    const auto* p = img.pixel(static_cast<int>(pixel.x), static_cast<int>(pixel.y));
    return {p[0], p[1], p[2]};
}
Rgb rgb(Color c) {
    return {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
            static_cast<int>(std::lround(c.b * 255))};
}
bool near(Rgb a, Rgb b, int tolerance = 3) {
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
           std::abs(a.b - b.b) <= tolerance;
}
std::size_t distinctColours(const ui::Image& img) {
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i + 3 < img.rgba.size(); i += 4)
        colours.insert(img.rgba[i] << 16 | img.rgba[i + 1] << 8 | img.rgba[i + 2]);
    return colours.size();
}

/// Draws one particle and one fixed anchor on black and checks each lands on the pixel
/// the camera maps it to, in its state's colour, and that empty space stays black.
void checkParticlesLandWhereTheCameraSays(ui::GLContext& ctx) {
    phys::World world;
    phys::ParticleDef shell;
    shell.position = {3.0, 2.0};
    shell.radius = 0.5;
    shell.flags = phys::kProjectile;
    const auto id = world.particles.add(shell);
    phys::ParticleDef anchor;
    anchor.position = {-4.0, -1.5};
    anchor.mass = 0.0;
    anchor.radius = 0.4;
    const auto fixedId = world.particles.add(anchor);

    ui::Camera cam = ui::Camera::framing({-8.0, -6.0}, {8.0, 6.0}, ctx.width(), ctx.height());
    ui::Renderer2D renderer;
    ui::gl::fn.BindFramebuffer(GL_FRAMEBUFFER, ctx.framebuffer());
    ui::gl::fn.Viewport(0, 0, ctx.width(), ctx.height());
    ui::gl::fn.ClearColor(0, 0, 0, 1);
    ui::gl::fn.Clear(GL_COLOR_BUFFER_BIT);
    renderer.begin(cam);
    ui::drawWorld(renderer, world, {});
    renderer.flush();
    ctx.present();
    const ui::Image img = ui::readFramebuffer(ctx.framebuffer(), ctx.width(), ctx.height());

    // 16 m across 320 px: 20 px/m, so the shell is a 20 px disc centred at (220, 80).
    const Vec2 shellPx = cam.toPixel(world.particles.position(id));
    EXPECT_NEAR(shellPx.x, 220.0, 1e-9);
    EXPECT_NEAR(shellPx.y, 80.0, 1e-9);
    const Rgb shellColour = rgb(ui::particleColor(phys::kAlive | phys::kProjectile, 1.0));
    EXPECT_TRUE(near(at(img, shellPx), shellColour))
        << "shell pixel " << at(img, shellPx).r << "," << at(img, shellPx).g << ","
        << at(img, shellPx).b;
    // Inside the disc, 6 px off centre, still the shell; 15 px off (past r = 10 px), black.
    EXPECT_TRUE(near(at(img, shellPx + Vec2{6.0, 0.0}), shellColour));
    EXPECT_TRUE(near(at(img, shellPx + Vec2{15.0, 0.0}), {0, 0, 0}));
    EXPECT_TRUE(near(at(img, shellPx + Vec2{0.0, -15.0}), {0, 0, 0}));

    const Vec2 fixedPx = cam.toPixel(world.particles.position(fixedId));
    EXPECT_TRUE(near(at(img, fixedPx), rgb(ui::particleColor(phys::kAlive, 0.0))));
    // y up: the anchor is below and left of the middle in the picture.
    EXPECT_LT(fixedPx.x, kW / 2.0);
    EXPECT_GT(fixedPx.y, kH / 2.0);
    EXPECT_TRUE(near(at(img, {5.0, 5.0}), {0, 0, 0}));
}

} // namespace

TEST(Camera, MapsWorldToPixelsWithYUpAndBack) {
    ui::Camera c;
    c.center = {10.0, 5.0};
    c.pixelsPerMetre = 20.0;
    c.width = 200;
    c.height = 100;
    EXPECT_EQ(c.toPixel({10.0, 5.0}), (Vec2{100.0, 50.0}));
    EXPECT_EQ(c.toPixel({11.0, 6.0}), (Vec2{120.0, 30.0})); // up in the world is up on screen
    const Vec2 w = c.toWorld({37.0, 81.0});
    const Vec2 back = c.toPixel(w);
    EXPECT_NEAR(back.x, 37.0, 1e-12);
    EXPECT_NEAR(back.y, 81.0, 1e-12);
}

TEST(Camera, ZoomKeepsThePointUnderTheMouse) {
    ui::Camera c;
    const Vec2 mouse{900.0, 200.0};
    const Vec2 before = c.toWorld(mouse);
    c.zoomAt(mouse, 1.7);
    const Vec2 after = c.toWorld(mouse);
    EXPECT_NEAR(after.x, before.x, 1e-9);
    EXPECT_NEAR(after.y, before.y, 1e-9);
    EXPECT_NEAR(c.pixelsPerMetre, 20.0 * 1.7, 1e-12);
}

TEST(Camera, ClipMatrixAgreesWithPixelMapping) {
    const ui::Camera c = ui::Camera::framing({-3.0, -1.0}, {7.0, 4.0}, 640, 360);
    const auto m = c.clipFromWorld();
    const Vec2 p{2.5, 3.0};
    const double xClip = m[0] * p.x + m[12], yClip = m[5] * p.y + m[13];
    const Vec2 px = c.toPixel(p);
    EXPECT_NEAR((xClip + 1.0) * 0.5 * 640, px.x, 1e-3);
    EXPECT_NEAR((1.0 - yClip) * 0.5 * 360, px.y, 1e-3);
}

TEST(Render, ParticleAppearsWhereTheCameraMapsItOSMesa) {
    auto ctx = makeContext(ui::HeadlessBackend::OSMesa);
    ASSERT_TRUE(ctx) << "OSMesa is the default headless context and must work here";
    EXPECT_STREQ(ctx->name(), "osmesa");
    checkParticlesLandWhereTheCameraSays(*ctx);
}

TEST(Render, ParticleAppearsWhereTheCameraMapsItEGL) {
    auto ctx = makeContext(ui::HeadlessBackend::EGL);
    // The fallback for systems without OSMesa; the Makefile installs libegl-mesa0, so it
    // must work wherever the suite runs.
    ASSERT_TRUE(ctx) << "EGL surfaceless Mesa failed to give a context";
    EXPECT_STREQ(ctx->name(), "egl-surfaceless");
    checkParticlesLandWhereTheCameraSays(*ctx);
}

TEST(Render, DemoFrameHasSkyGroundAndTheShellInFlight) {
    auto ctx = makeContext(ui::HeadlessBackend::OSMesa, 640, 360);
    ASSERT_TRUE(ctx);
    ui::DemoScene scene;
    // 0.1 s to the first shot, then 1.4 s of flight: the shell is high over the field.
    for (int i = 0; i < 180; ++i)
        scene.tick();
    ASSERT_FALSE(scene.shells().empty());
    const ui::ShellTrack* shell = nullptr;
    for (const auto& s : scene.shells())
        if (!s.vacuum) shell = &s;
    ASSERT_NE(shell, nullptr);

    const ui::Camera cam = ui::demoCamera(scene, ctx->width(), ctx->height());
    ui::Renderer2D renderer;
    ui::gl::fn.BindFramebuffer(GL_FRAMEBUFFER, ctx->framebuffer());
    renderer.begin(cam);
    ui::DemoViewOptions o;
    o.labels = false;
    ui::drawDemo(renderer, scene, o);
    renderer.flush();
    ctx->present();
    const ui::Image img = ui::readFramebuffer(ctx->framebuffer(), ctx->width(), ctx->height());

    EXPECT_GT(distinctColours(img), 50u) << "a real frame has gradients, hills and shapes";
    const Rgb sky = at(img, {320.0, 5.0});
    const Rgb soil = at(img, {320.0, 355.0});
    EXPECT_GT(sky.b, sky.r + 40) << "blue sky at the top";
    EXPECT_GT(soil.r, soil.b) << "brown soil at the bottom";
    const Vec2 shellPx = cam.toPixel(scene.world.particles.position(shell->id));
    ASSERT_GT(shellPx.y, 0.0);
    EXPECT_TRUE(
        near(at(img, shellPx), rgb(ui::particleColor(phys::kAlive | phys::kProjectile, 1.0))));
}

TEST(Render, PlayScreenDrawsThePanelHeadless) {
    auto ctx = makeContext(ui::HeadlessBackend::Auto, 800, 600);
    ASSERT_TRUE(ctx);
    ui::PlayScreen screen(*ctx, nullptr);
    screen.frame(1.0 / 60.0);
    screen.frame(1.0 / 60.0); // ImGui lays a new window out on its second frame
    ctx->present();
    const ui::Image img = screen.capture();
    // The panel sits top right: its dark translucent background over the blue sky.
    const Rgb panel = at(img, {700.0, 150.0});
    const Rgb sky = at(img, {300.0, 150.0});
    EXPECT_LT(panel.r + panel.g + panel.b, 200) << "dark panel";
    EXPECT_GT(sky.r + sky.g + sky.b, 300) << "bright sky";
    EXPECT_EQ(screen.stats().tick, 4u); // two frames of 1/60 s at 120 Hz: 2 ticks each
}

TEST(Screenshot, PngRoundTripsExactly) {
    auto ctx = makeContext(ui::HeadlessBackend::Auto, 64, 48);
    ASSERT_TRUE(ctx);
    ui::gl::fn.BindFramebuffer(GL_FRAMEBUFFER, ctx->framebuffer());
    ui::Renderer2D r;
    ui::Camera cam = ui::Camera::framing({0.0, 0.0}, {64.0, 48.0}, 64, 48);
    ui::gl::fn.ClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    ui::gl::fn.Clear(GL_COLOR_BUFFER_BIT);
    r.begin(cam);
    // Bottom half red: after the row flip, the last rows of the file are red.
    r.fillRectGradient({0.0, 0.0}, {64.0, 24.0}, Color(1, 0, 0), Color(1, 0, 0));
    r.flush();
    ctx->present();
    const ui::Image img = ui::readFramebuffer(ctx->framebuffer(), 64, 48);
    const auto path = (std::filesystem::temp_directory_path() / "artillery_ui_test.png").string();
    ASSERT_EQ(ui::writePng(path, img), "");
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    ASSERT_NE(data, nullptr);
    EXPECT_EQ(w, 64);
    EXPECT_EQ(h, 48);
    EXPECT_EQ(data[0], 0); // top-left: blue
    EXPECT_EQ(data[2], 255);
    EXPECT_EQ(data[(47 * 64) * 4], 255); // bottom-left: red
    EXPECT_EQ(std::vector<unsigned char>(data, data + 64 * 48 * 4), img.rgba);
    stbi_image_free(data);
    std::filesystem::remove(path);
}
