// GPU limits: particles at, on and past every domain face, edge and corner, and on
// every grid-cell border, step without an out-of-bounds index (the grid clamps them into its
// border cells; the walls bring them back inside) and come out finite and inside the walls, for
// balls, fluid and life (walls and looping borders). An index past an array would crash llvmpipe or
// leave garbage that the checks below catch.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "io/json.h"
#include "scene/scene.h"
#include "sim/balls/balls.h"
#include "sim/fluid/fluid.h"
#include "sim/life/life.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class DomainEdges : public test::GlTest {};

// Points of the box [lo, hi] at each of `offsets` outside every face (negative: inside), its
// 27 face/edge/corner combinations, plus every cell border along each axis.
std::vector<glm::vec4> edgePoints(glm::vec3 lo, glm::vec3 hi, float cell, const std::vector<float>& offsets) {
  std::vector<glm::vec4> out;
  const glm::vec3 mid = 0.5f * (lo + hi);
  for (float d : offsets)
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          const glm::ivec3 side(x, y, z);
          glm::vec3 p;
          for (int a = 0; a < 3; ++a) p[a] = side[a] < 0 ? lo[a] - d : side[a] > 0 ? hi[a] + d : mid[a];
          if (lo.z == hi.z) p.z = lo.z;
          out.emplace_back(p, 1.0f);
        }
  for (int a = 0; a < 3; ++a)
    for (float t = lo[a]; t <= hi[a] + 0.5f * cell; t += cell) {
      glm::vec3 p = mid;
      p[a] = std::min(t, hi[a]);
      if (lo.z == hi.z) p.z = lo.z;
      out.emplace_back(p, 1.0f);
    }
  return out;
}

// Every position finite and within `slack` of [lo, hi].
void expectInside(const std::vector<glm::vec4>& pos, glm::vec3 lo, glm::vec3 hi, float slack, std::size_t count) {
  ASSERT_EQ(pos.size(), count) << "the particle count holds";
  for (std::size_t i = 0; i < pos.size(); ++i) {
    const glm::vec3 p(pos[i]);
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << "particle " << i;
    ASSERT_TRUE(glm::all(glm::greaterThanEqual(p, lo - slack)) && glm::all(glm::lessThanEqual(p, hi + slack)))
        << "particle " << i << " at " << p.x << ", " << p.y << ", " << p.z;
  }
}

const std::vector<float> kOffsets = {-1e-3f, 0.0f, 1e-6f, 1e-3f, 0.05f};

}  // namespace

TEST_F(DomainEdges, Balls) {
  balls::Params p;
  p.radius = 0.01f;
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(0.4f, 0.2f, 0.3f);
  p.fill = water::Fill::None;
  p.substeps = 4;
  balls::Balls model(shaders(), p);
  const std::vector<glm::vec4> pos = edgePoints(p.domainMin, p.domainMax, 2 * p.radius, kOffsets);
  model.upload(pos, std::vector<glm::vec4>(pos.size(), glm::vec4(0.0f)));
  gl::GpuProfiler profiler;
  for (int f = 0; f < 10; ++f) model.step(profiler);
  expectInside(model.downloadPositions(), p.domainMin, p.domainMax, 1e-5f, pos.size());
  EXPECT_FALSE(model.divergence()) << model.divergence()->message;
}

TEST_F(DomainEdges, Fluid) {
  fluid::Params p;
  p.setSpacing(0.02f);
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(0.4f, 0.2f, 0.3f);
  p.fill = water::Fill::None;
  p.substeps = 2;
  fluid::Fluid model(shaders(), p);
  const std::vector<glm::vec4> pos = edgePoints(p.domainMin, p.domainMax, 0.5f * p.h(), kOffsets);
  model.upload(pos, std::vector<glm::vec4>(pos.size(), glm::vec4(0.0f)));
  gl::GpuProfiler profiler;
  for (int f = 0; f < 10; ++f) model.step(profiler);
  expectInside(model.downloadPositions(), p.domainMin, p.domainMax, 1e-5f, pos.size());
}

TEST_F(DomainEdges, Life) {
  for (bool looping : {false, true}) {
    SCOPED_TRACE(looping ? "looping borders" : "walls");
    life::Rules rules = life::generateRules({.species = 3, .particleCount = 1, .size = {256, 160}, .seed = 3});
    rules.loopingBorders = looping;
    const glm::vec3 lo(-128, -80, 0), hi(128, 80, 0);
    std::vector<glm::vec4> pos = edgePoints(lo, hi, rules.maxRadius(), {-0.5f, 0.0f, 1e-4f, 0.5f, 3.0f});
    rules.particleCount = int(pos.size());
    for (std::size_t i = 0; i < pos.size(); ++i) pos[i].w = float(i % 3);  // species
    life::Life model(shaders(), rules, {.maxDt = 1.0f / 60});
    model.upload(pos, std::vector<glm::vec4>(pos.size(), glm::vec4(0.0f)));
    gl::GpuProfiler profiler;
    for (int f = 0; f < 30; ++f) model.step(profiler);
    expectInside(model.downloadPositions(), lo, hi, 1e-3f, pos.size());
  }
}
