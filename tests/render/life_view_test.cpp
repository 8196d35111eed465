// The life view draws what its formulas say: a disc of radius R·(pixels per unit), a glow of
// alpha intensity·exp(-6 (r / half-size)^2), and the same total brightness whether particles
// are drawn as discs or as sub-pixel splats (zoom across one pixel per unit); the compose pass
// dithers with our own blue noise.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "render/blue_noise.h"
#include "render/life_view.h"
#include "sim/life/life.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::life;

namespace {

class LifeViewTest : public test::GlTest {};

constexpr float kPi = 3.14159265f;

Rules still(int count) {
  Rules r = generateRules({.species = 1, .particleCount = count, .size = {1024.0f, 1024.0f}, .seed = 4});
  r.species[0].forces[0] = {0, 0, 1, 0};
  return r;
}

// The HDR image's alpha channel (coverage summed by additive blending), top row first.
std::vector<float> alpha(const LifeView& view) {
  const gl::Texture2D& t = view.hdr();
  std::vector<float> rgba(std::size_t(t.width()) * t.height() * 4);
  t.download(GL_RGBA, GL_FLOAT, rgba.data());
  std::vector<float> a(std::size_t(t.width()) * t.height());
  for (int y = 0; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x)
      a[std::size_t(y) * t.width() + x] = rgba[(std::size_t(t.height() - 1 - y) * t.width() + x) * 4 + 3];
  return a;
}

void renderAt(Life& model, LifeView& view, RenderTarget& target, float ppu, bool glow, bool discs) {
  gl::GpuProfiler profiler;
  profiler.setEnabled(false);
  view.params().glow = glow;
  view.params().particles = discs;
  view.camera() = {glm::vec2(0.0f), float(target.width()) / (2.0f * ppu)};
  view.render(model, target, profiler);
}

}  // namespace

TEST_F(LifeViewTest, DiscRadiusAndGlowFalloffMatchTheFormulas) {
  Life model(shaders(), still(1));
  model.upload({glm::vec4(0.25f, -0.25f, 0.0f, 0.0f)}, {glm::vec4(0.0f)});  // off the pixel grid
  LifeView view(shaders());
  RenderTarget target(128, 128);
  const float ppu = 8.0f;
  renderAt(model, view, target, ppu, false, true);
  std::vector<float> a = alpha(view);
  double area = 0;
  for (float v : a) area += v;
  EXPECT_NEAR(std::sqrt(area / kPi), 1.0 * ppu, 1.0) << "disc radius in pixels";
  // The half-coverage crossing along the row through the centre.
  const int row = 64 + 2;  // world y = -0.25 is 2 pixels below the centre
  int inside = 0;
  for (int x = 0; x < 128; ++x) inside += a[std::size_t(row) * 128 + x] >= 0.5f;
  EXPECT_NEAR(inside / 2.0, ppu, 1.0);

  const float glowPpu = 2.0f;  // half-size 12 units = 24 pixels
  renderAt(model, view, target, glowPpu, true, false);
  a = alpha(view);
  const int cx = 64 + 0, cy = 64 + 0;
  float peak = 0;
  for (float v : a) peak = std::max(peak, v);
  EXPECT_NEAR(peak, 1.0f / 64.0f, 2e-4f);
  // Where the glow falls to half its peak: 12·sqrt(ln 2 / 6) units.
  int half = 0;
  for (int x = cx; x < 128 && a[std::size_t(cy) * 128 + x] >= 0.5f * peak; ++x) half = x - cx;
  EXPECT_NEAR(half, 12.0 * std::sqrt(std::log(2.0) / 6.0) * glowPpu, 1.0);
  // And the whole profile follows exp(-6 (r/24)^2) / 64.
  for (int x = cx; x < cx + 24; x += 3) {
    const float r = (float(x) + 0.5f - 64.0f - 0.25f * glowPpu) / (12.0f * glowPpu);
    EXPECT_NEAR(a[std::size_t(cy) * 128 + x], std::exp(-6.0f * r * r) / 64.0f, 2e-4f) << "x = " << x;
  }
}

TEST_F(LifeViewTest, SubPixelModeConservesBrightnessAcrossOnePixelPerUnit) {
  const int n = 300;
  Life model(shaders(), still(n));
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-40.0f, 40.0f);
  std::vector<glm::vec4> pos;
  for (int i = 0; i < n; ++i) pos.emplace_back(u(rng), u(rng), 0.0f, 0.0f);
  model.upload(pos, std::vector<glm::vec4>(n, glm::vec4(0.0f)));
  LifeView view(shaders());
  RenderTarget target(256, 256);
  for (float ppu : {2.0f, 1.25f, 1.0f, 0.999f, 0.8f, 0.5f, 0.3f}) {
    renderAt(model, view, target, ppu, false, true);
    double total = 0;
    for (float v : alpha(view)) total += v;
    const double expected = n * kPi * ppu * ppu;  // pi·R^2 pixels per particle, R = 1 unit
    EXPECT_NEAR(total / expected, 1.0, 0.05) << "pixels per unit " << ppu;
  }
}

TEST_F(LifeViewTest, BlueNoiseIsAPermutationOfThresholds) {
  const std::vector<float> a = voidAndCluster(16), b = voidAndCluster(16);
  EXPECT_EQ(a, b);  // deterministic
  std::vector<float> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_FLOAT_EQ(sorted[i], (float(i) + 0.5f) / 256.0f);
  // Blue, not white: the lowest 10% of thresholds are spread out (no two are 4-neighbours).
  int touching = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      if (a[std::size_t(y) * 16 + x] >= 0.1f) continue;
      touching += a[std::size_t(y) * 16 + (x + 1) % 16] < 0.1f;
      touching += a[std::size_t((y + 1) % 16) * 16 + x] < 0.1f;
    }
  EXPECT_EQ(touching, 0);
}

TEST_F(LifeViewTest, ComposeTonemapsAndDithersToEightBits) {
  Life model(shaders(), generateRules({.species = 4, .particleCount = 2000, .size = {256, 256}, .seed = 2}));
  LifeView view(shaders());
  RenderTarget target(96, 64);
  renderAt(model, view, target, 0.5f, true, true);
  const std::vector<std::uint8_t> rgba = target.readRgba8();
  int lit = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) lit += rgba[i] + rgba[i + 1] + rgba[i + 2] > 30;
  EXPECT_GT(lit, int(rgba.size() / 4) / 4) << "glow covers the box";
}

// The view controls: C fits the whole box (one axis exactly, the other inside), the wheel zooms
// about the cursor (the world point under it stays), right drag moves the world with the cursor.
TEST_F(LifeViewTest, CentreFitsTheBoxWheelZoomsAboutTheCursorDragPans) {
  const glm::ivec2 viewport(800, 450);
  for (glm::vec2 box : {glm::vec2(1024, 576), glm::vec2(1024, 1024), glm::vec2(2000, 300)}) {
    LifeView view(shaders());
    view.camera() = LifeView::fit(box, viewport);
    const glm::vec2 lo = view.toWorld({0, float(viewport.y)}, viewport),
                    hi = view.toWorld({float(viewport.x), 0}, viewport);
    EXPECT_LE(lo.x, -0.5f * box.x + 1e-3f);
    EXPECT_LE(lo.y, -0.5f * box.y + 1e-3f);
    EXPECT_GE(hi.x, 0.5f * box.x - 1e-3f);
    EXPECT_GE(hi.y, 0.5f * box.y - 1e-3f);
    EXPECT_TRUE(std::abs(hi.x - 0.5f * box.x) < 1e-3f || std::abs(hi.y - 0.5f * box.y) < 1e-3f)
        << "one axis fits exactly: the box fills the image as far as the aspect allows";
  }
  LifeView view(shaders());
  view.camera() = LifeView::fit({1024, 576}, viewport);
  const glm::vec2 cursor(600, 100);
  const glm::vec2 anchor = view.toWorld(cursor, viewport);
  const float extent = view.camera().extentX;
  view.zoomAbout(cursor, 3.0f, viewport);
  view.glide(10.0f, viewport);  // long enough to arrive
  EXPECT_NEAR(view.camera().extentX, extent / std::pow(1.25f, 3.0f), 1e-3f);
  EXPECT_NEAR(view.toWorld(cursor, viewport).x, anchor.x, 1e-3f);
  EXPECT_NEAR(view.toWorld(cursor, viewport).y, anchor.y, 1e-3f);
  view.zoomAbout(cursor, -3.0f, viewport);
  view.glide(10.0f, viewport);
  EXPECT_NEAR(view.camera().extentX, extent, 1e-3f);

  const glm::vec2 grabbed = view.toWorld(cursor, viewport), delta(-120, 45);
  view.pan(cursor + delta, delta, viewport);
  EXPECT_NEAR(view.toWorld(cursor + delta, viewport).x, grabbed.x, 1e-3f);
  EXPECT_NEAR(view.toWorld(cursor + delta, viewport).y, grabbed.y, 1e-3f);
}

// The wheel's zoom glides as the original's: nothing moves at the wheel step; each frame the
// extent covers 1 - exp(-20 dt) of what is left toward 1.25^-clicks of it, the world point under
// the cursor stays under it all the way, and the glide arrives (exactly) within a second.
TEST_F(LifeViewTest, WheelZoomGlidesToItsTargetKeepingThePointUnderTheCursor) {
  const glm::ivec2 viewport(800, 450);
  LifeView view(shaders());
  view.camera() = LifeView::fit({1024, 576}, viewport);
  view.camera().centre = {40.0f, -25.0f};
  const glm::vec2 cursor(610, 95);
  const glm::vec2 anchor = view.toWorld(cursor, viewport);
  const float start = view.camera().extentX;
  view.zoomAbout(cursor, 2.0f, viewport);  // two steps in
  view.zoomAbout(cursor, 1.0f, viewport);  // and one more while the first glides: 1.25^-3 in all
  const float target = start / std::pow(1.25f, 3.0f);
  EXPECT_TRUE(view.gliding());
  EXPECT_EQ(view.camera().extentX, start) << "the wheel step itself moves nothing";
  const float dt = 1.0f / 60.0f;
  float before = start;
  for (int frame = 0; frame < 60 && view.gliding(); ++frame) {
    view.glide(dt, viewport);
    const float extent = view.camera().extentX;
    if (frame == 0) EXPECT_NEAR((before - extent) / (before - target), 1.0f - std::exp(-20.0f * dt), 1e-4f);
    EXPECT_LT(extent, before) << "frame " << frame;
    EXPECT_GE(extent, target) << "frame " << frame << ": no overshoot";
    EXPECT_NEAR(view.toWorld(cursor, viewport).x, anchor.x, 2e-3f) << "frame " << frame;
    EXPECT_NEAR(view.toWorld(cursor, viewport).y, anchor.y, 2e-3f) << "frame " << frame;
    before = extent;
  }
  EXPECT_FALSE(view.gliding()) << "arrived within a second";
  EXPECT_EQ(view.camera().extentX, target);
  // A pan during a glide moves the anchor with the world: the point under the wheel's pixel
  // after the pan stays there until the glide ends.
  view.zoomAbout(cursor, -1.0f, viewport);
  view.glide(dt, viewport);
  const glm::vec2 delta(30, -12);
  view.pan(cursor + delta, delta, viewport);
  const glm::vec2 held = view.toWorld(cursor, viewport);
  for (int frame = 0; frame < 60; ++frame) view.glide(dt, viewport);
  EXPECT_NEAR(view.toWorld(cursor, viewport).x, held.x, 2e-3f);
  EXPECT_NEAR(view.toWorld(cursor, viewport).y, held.y, 2e-3f);
  EXPECT_NEAR(view.camera().extentX, target * 1.25f, 1e-3f);
}
