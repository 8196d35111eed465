// The loads' sums (sim/fluid/boundary_loads.h, shaders/fluid/loads_sum.comp) over many chunks of
// work groups: random partials, as predict and Δp leave them, summed on the GPU in chunks and on
// the CPU across them, against a plain double sum.
#include <gtest/gtest.h>

#include <random>

#include "fluid/bindings.glsl"
#include "sim/fluid/boundary_loads.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {
using BoundaryLoadsTest = test::GlTest;

// Writes `partials` where predict and Δp leave them, and sums them.
void sumPartials(fluid::BoundaryLoads& loads, const std::vector<glm::vec4>& partials) {
  loads.bind();
  GLint buffer = 0;
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, FLUID_LOADS, &buffer);
  glBindBuffer(GL_COPY_WRITE_BUFFER, GLuint(buffer));
  glBufferSubData(GL_COPY_WRITE_BUFFER, 0, GLsizeiptr(partials.size() * sizeof(glm::vec4)), partials.data());
  loads.sum();
}
}  // namespace

TEST_F(BoundaryLoadsTest, ChunkedSumsEqualTheDoubleSumOfEveryGroupsPartials) {
  constexpr std::size_t groups = 2500, obstacles = 2, slots = water::kWalls + obstacles;  // three chunks
  fluid::BoundaryLoads loads(shaders());
  loads.begin(groups * FLUID_GROUP_SIZE - 5, obstacles);
  ASSERT_EQ(loads.slots(), slots);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> value(-1e-4f, 1e-4f);
  std::vector<glm::vec4> partials(groups * slots * 2);
  for (glm::vec4& p : partials) p = glm::vec4(value(rng), value(rng), value(rng), 0.0f);
  sumPartials(loads, partials);
  const double scale = -2.5;
  const water::Loads got = loads.read(scale);
  ASSERT_EQ(got.obstacles.size(), obstacles);
  for (std::size_t s = 0; s < slots; ++s) {
    glm::dvec3 force(0.0), torque(0.0);
    for (std::size_t g = 0; g < groups; ++g) {
      force += scale * glm::dvec3(glm::vec3(partials[2 * (g * slots + s)]));
      torque += scale * glm::dvec3(glm::vec3(partials[2 * (g * slots + s) + 1]));
    }
    const water::Load& l = s < water::kWalls ? got.walls[s] : got.obstacles[s - water::kWalls];
    // 2500 float terms of up to 2.5e-4 (scaled): rounding far below 1e-8; a chunk lost is ~1e-3.
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(l.force[k], force[k], 1e-8) << "slot " << s;
      EXPECT_NEAR(l.torque[k], torque[k], 1e-8) << "slot " << s;
    }
  }
}

// The copy a step requested reads as that step's loads after the next step began with another
// count of chunks (a tap added particles) and obstacles: what the bodies receive is what was summed.
TEST_F(BoundaryLoadsTest, ACopyReadsAsItsStepsLoadsAfterTheNextBeganWithOtherSizes) {
  constexpr std::size_t groups = 1500, obstacles = 1, slots = water::kWalls + obstacles;  // two chunks
  fluid::BoundaryLoads loads(shaders());
  loads.begin(groups * FLUID_GROUP_SIZE, obstacles);
  std::vector<glm::vec4> partials(groups * slots * 2, glm::vec4(0.0f));
  for (std::size_t g = 0; g < groups; ++g)
    partials[2 * (g * slots + water::kWalls)] = glm::vec4(1e-3f, 0.0f, 0.0f, 0.0f);
  sumPartials(loads, partials);
  const water::Loads summed = loads.read(1.0);
  loads.request();
  loads.begin(3 * groups * FLUID_GROUP_SIZE, obstacles + 2);  // the next step: more chunks, more slots
  const water::Loads got = loads.received(1.0);
  ASSERT_EQ(got.obstacles.size(), obstacles);
  EXPECT_NEAR(got.obstacles[0].force.x, 1.5, 1e-6);
  EXPECT_EQ(got.obstacles[0].force, summed.obstacles[0].force);
}
