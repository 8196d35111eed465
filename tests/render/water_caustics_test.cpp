// The caustics on the water mode's floor (src/render/water_caustics.h) against refraction in
// double: under a surface whose height is given, the light at a floor point F is 1 / |L'(s)|
// for the point s of the surface whose refracted sunlight lands at F, L(s) = s + h(s) t / (−t_z)
// (Snell's t). From balls: flat water lights the floor evenly, and the light's mean is 1.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "render/water_caustics.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

using WaterCausticsTest = test::GlTest;

constexpr double kIndex = 1.33;

// A height texture of cells x 1 cells over a floor 1 m long in x whose height is h(x) (m).
gl::Texture2D heightOf(int cells, int rows, const std::function<double(double)>& h) {
  std::vector<float> texels(std::size_t(cells) * rows);
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cells; ++x) texels[std::size_t(y) * cells + x] = float(h((x + 0.5) / cells));
  gl::Texture2D t(cells, rows, GL_R32F);
  t.upload(GL_RED, GL_FLOAT, texels.data());
  return t;
}

std::vector<float> lightOf(const WaterCaustics& c) {
  std::vector<float> out(std::size_t(c.light().width()) * c.light().height());
  c.light().download(GL_RED, GL_FLOAT, out.data());
  return out;
}

// The sideways travel to the floor of sunlight (towards `sun`, in the xz plane) refracted at
// height h under slope h' (Snell in vectors, double).
double travel(double h, double slope, glm::dvec3 sun) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(-slope, 0.0, 1.0)), i = -sun;
  const double eta = 1.0 / kIndex, c = -glm::dot(n, i);
  const glm::dvec3 t = eta * i + (eta * c - std::sqrt(1.0 - eta * eta * (1.0 - c * c))) * n;
  return h * t.x / -t.z;
}

}  // namespace

TEST_F(WaterCausticsTest, AWaveFocusesTheSunlightWhereRefractionSendsIt) {
  // 20 cm of water under a standing wave 5 mm high, 25 cm long; the sun straight above and 40°
  // off it. The light at each floor texel against 1 / L'(s), s found by bisection in double.
  const double depth = 0.2, amplitude = 0.005, k = 2.0 * M_PI / 0.25;
  const auto h = [&](double x) { return depth + amplitude * std::sin(k * x); };
  const auto slope = [&](double x) { return amplitude * k * std::cos(k * x); };
  const int cells = 256, rows = 4;
  const gl::Texture2D height = heightOf(cells, rows, h);
  for (double angle : {0.0, 0.7}) {
    SCOPED_TRACE(angle);
    const glm::dvec3 sun(std::sin(angle), 0.0, std::cos(angle));
    WaterCaustics caustics(shaders());
    caustics.light(height,
                   {{0.0f, 0.0f, 0.0f}, {1.0f, float(rows) / cells, 0.5f}, glm::vec3(sun), float(kIndex), 1.0f});
    const std::vector<float> light = lightOf(caustics);
    const auto landing = [&](double s) { return s + travel(h(s), slope(s), sun); };
    double worst = 0, lowest = 10, highest = 0;
    for (int x = 0; x < cells; ++x) {
      const double f = (x + 0.5) / cells;
      // L is increasing here (no folds): bisect L(s) = f over a span wider than any travel.
      double lo = f - 0.3, hi = f + 0.3;
      for (int it = 0; it < 60; ++it) (landing(0.5 * (lo + hi)) < f ? lo : hi) = 0.5 * (lo + hi);
      const double s = 0.5 * (lo + hi), e = 1e-6;
      if (s < 0.02 || s > 0.98) continue;  // light from past the box's edge: the dry floor's
      const double want = 2.0 * e / (landing(s + e) - landing(s - e));
      for (int y = 0; y < rows; ++y) {
        const double got = light[std::size_t(y) * cells + x];
        worst = std::max(worst, std::abs(got - want));
      }
      lowest = std::min(lowest, want), highest = std::max(highest, want);
    }
    EXPECT_LT(lowest, 0.9);
    EXPECT_GT(highest, 1.1);
    // Documented (docs/WATER.md, "Caustics"): 0.0017 with the sun overhead, 0.0035 at 40°.
    EXPECT_LT(worst, 0.005) << "light, of 1 on dry floor";
  }
}

TEST_F(WaterCausticsTest, ASlopingSurfaceSpreadsTheLightAsItsTiltSays) {
  // h = 0.1 + 0.2 x (a plane, so the cells' linear interpolation is exact), the sun 30° off
  // the vertical: the light is 1 / (1 + d travel/dx), the same over the whole floor.
  const auto h = [](double x) { return 0.1 + 0.2 * x; };
  const int cells = 64, rows = 8;
  const glm::dvec3 sun(std::sin(0.5), 0.0, std::cos(0.5));
  WaterCaustics caustics(shaders());
  caustics.light(heightOf(cells, rows, h),
                 {{0.0f, 0.0f, 0.0f}, {1.0f, float(rows) / cells, 0.5f}, glm::vec3(sun), float(kIndex), 1.0f});
  const std::vector<float> light = lightOf(caustics);
  const double want = 1.0 / (1.0 + (travel(h(1.0), 0.2, sun) - travel(h(0.0), 0.2, sun)));
  int checked = 0;
  for (int x = 0; x < cells; ++x) {
    const double f = (x + 0.5) / cells;
    // Light from within three cells of the floor's ends: the height is clamped there, not a plane.
    const double s = f - travel(h(f), 0.2, sun);
    if (s < 3.0 / cells || s > 1.0 - 3.0 / cells) continue;
    for (int y = 0; y < rows; ++y, ++checked) ASSERT_NEAR(light[std::size_t(y) * cells + x], want, 2e-3) << x;
  }
  EXPECT_GT(checked, rows * cells / 2);
  EXPECT_GT(want, 1.03) << "the surface tilted towards the sun gathers its light";
}

namespace {

// Balls of radius r packed inside [lo, hi] (a jittered lattice, as a settled pool's) but not in
// the box [holeLo, holeHi].
std::vector<glm::vec4> pool(float r, glm::vec3 lo, glm::vec3 hi, glm::vec3 holeLo = glm::vec3(1e9f),
                            glm::vec3 holeHi = glm::vec3(1e9f)) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> jitter(-0.3f * r, 0.3f * r);
  std::vector<glm::vec4> balls;
  for (float z = lo.z + r; z < hi.z; z += 2.0f * r)
    for (float y = lo.y + r; y < hi.y; y += 2.0f * r)
      for (float x = lo.x + r; x < hi.x; x += 2.0f * r) {
        const glm::vec3 p(x + jitter(rng), y + jitter(rng), z + jitter(rng));
        if (glm::all(glm::greaterThan(p, holeLo)) && glm::all(glm::lessThan(p, holeHi))) continue;
        balls.emplace_back(p, 1.0f);
      }
  return balls;
}

struct Spread {
  double mean = 0, rms = 0, worst = 0;
};

// The light over the floor's cells at least four cells from its edges.
Spread spread(const WaterCaustics& caustics) {
  const std::vector<float> light = lightOf(caustics);
  const int w = caustics.light().width(), h = caustics.light().height();
  double sum = 0, sum2 = 0, worst = 0;
  int n = 0;
  for (int y = 4; y < h - 4; ++y)
    for (int x = 4; x < w - 4; ++x, ++n) {
      const double l = light[std::size_t(y) * w + x];
      sum += l, sum2 += l * l, worst = std::max(worst, std::abs(l - 1.0));
    }
  const double mean = sum / n;
  return {mean, std::sqrt(sum2 / n - mean * mean), worst};
}

const CausticsFloor kPoolFloor{
    {0.0f, 0.0f, 0.0f}, {0.4f, 0.3f, 0.3f}, glm::normalize(glm::vec3(0.5f, 0.3f, 1.0f)), 1.33f, 1.0f};

}  // namespace

TEST_F(WaterCausticsTest, FlatWaterOfBallsLightsTheFloorEvenly) {
  // Balls packed 15 cm deep over a 40 x 30 cm floor, jittered by ±0.3 r: their smoothed top is
  // flat enough that the light stays within 2% of 1.
  const float r = 0.005f;
  const std::vector<glm::vec4> balls = pool(r, glm::vec3(0.0f), {0.4f, 0.3f, 0.15f});
  const gl::Buffer positions{std::span<const glm::vec4>(balls)};
  WaterCaustics caustics(shaders());
  caustics.run({&positions, nullptr, balls.size(), r, glm::mat4(1.0f)}, {}, glm::mat4(1.0f), kPoolFloor);
  std::vector<float> height(std::size_t(caustics.height().width()) * caustics.height().height());
  caustics.height().download(GL_RED, GL_FLOAT, height.data());
  for (int y = 4; y < caustics.height().height() - 4; ++y)
    for (int x = 4; x < caustics.height().width() - 4; ++x)
      ASSERT_NEAR(height[std::size_t(y) * caustics.height().width() + x], 0.15, 2.0 * r) << "the water's top, smoothed";
  const Spread s = spread(caustics);
  // Documented: mean 0.999, rms 0.0085, worst 0.019.
  EXPECT_NEAR(s.mean, 1.0, 0.005);
  EXPECT_LT(s.rms, 0.01);
  EXPECT_LT(s.worst, 0.025);
}

TEST_F(WaterCausticsTest, TheFloorUnderAnObstacleIsLitAsDryFloor) {
  // A block 10 cm on a side floating in the pool, its top 5 cm out of the water: the water's top
  // dips to its bottom under it, which would focus the sun into a bright ring round it. The
  // obstacle's balls cover those cells: the floor keeps the flat pool's light.
  const float r = 0.005f;
  const glm::vec3 lo(0.15f, 0.1f, 0.1f), hi(0.25f, 0.2f, 0.2f);
  const std::vector<glm::vec4> balls = pool(r, glm::vec3(0.0f), {0.4f, 0.3f, 0.15f}, lo, hi);
  const std::vector<glm::vec4> block = pool(r, lo, hi);
  const gl::Buffer water{std::span<const glm::vec4>(balls)}, cover{std::span<const glm::vec4>(block)};
  WaterCaustics caustics(shaders());
  caustics.run({&water, nullptr, balls.size(), r, glm::mat4(1.0f)}, {}, glm::mat4(1.0f), kPoolFloor);
  const Spread open = spread(caustics);
  caustics.run({&water, nullptr, balls.size(), r, glm::mat4(1.0f)}, {&cover, nullptr, block.size(), r, glm::mat4(1.0f)},
               glm::mat4(1.0f), kPoolFloor);
  const Spread covered = spread(caustics);
  EXPECT_GT(open.worst, 0.3) << "uncovered, the dip under the block focuses the sun";
  EXPECT_LT(covered.worst, 0.04) << "measured 0.032 (docs/WATER.md, \"Caustics\")";
  EXPECT_NEAR(covered.mean, 1.0, 0.005);
}
