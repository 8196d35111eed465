// The loads' sums (sim/water/boundary_loads.h, shaders/water/loads_sum.comp) over many chunks of
// work groups: random partials, as the measuring kernels leave them, summed on the GPU in chunks
// and on the CPU across them, against a plain double sum; also with partials past one storage
// block, summed a window of chunks at a time.
#include <gtest/gtest.h>

#include <random>

#include "gl/window.h"
#include "sim/water/boundary_loads.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {
using BoundaryLoadsTest = test::GlTest;
constexpr std::size_t kGroupSize = 128;  // particles per work group of the measuring kernels
constexpr GLuint kBinding = 0;

// Writes `partials` where the measuring kernels leave them, and sums them.
void sumPartials(water::BoundaryLoads& loads, const std::vector<glm::vec4>& partials) {
  loads.bind(kBinding);
  GLint buffer = 0;
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, kBinding, &buffer);
  glBindBuffer(GL_COPY_WRITE_BUFFER, GLuint(buffer));
  glBufferSubData(GL_COPY_WRITE_BUFFER, 0, GLsizeiptr(partials.size() * sizeof(glm::vec4)), partials.data());
  loads.sum();
}
// Random partials of `groups` work groups summed by `loads` against the double sum.
void expectSumsOfRandomPartials(water::BoundaryLoads& loads, std::size_t groups, std::size_t obstacles) {
  const std::size_t slots = water::kWalls + obstacles;
  loads.begin(groups * kGroupSize - 5, obstacles);
  ASSERT_EQ(loads.slots(), GLuint(slots));
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
    // Up to 2500 float terms of up to 2.5e-4 (scaled): rounding far below 1e-8; a chunk lost is ~1e-3.
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(l.force[k], force[k], 1e-8) << "slot " << s;
      EXPECT_NEAR(l.torque[k], torque[k], 1e-8) << "slot " << s;
    }
  }
}

}  // namespace

TEST_F(BoundaryLoadsTest, ChunkedSumsEqualTheDoubleSumOfEveryGroupsPartials) {
  water::BoundaryLoads loads(shaders(), kGroupSize);
  expectSumsOfRandomPartials(loads, 2500, 2);  // three chunks
}

// Partials of 800 groups × 9 slots × 32 B = 225 KiB through a block of 64 KiB: chunks of 224
// groups, one per window.
TEST_F(BoundaryLoadsTest, PartialsPastOneStorageBlockAreSummedAWindowOfChunksAtATime) {
  gl::overrideStorageBlockBytes(gl::kMinStorageBlockBytes);
  water::BoundaryLoads loads(shaders(), kGroupSize);
  expectSumsOfRandomPartials(loads, 800, 3);
  gl::overrideStorageBlockBytes(0);
}

// The copy a step requested reads as that step's loads after the next step began with another
// count of chunks (a tap added particles) and obstacles: what the bodies receive is what was summed.
TEST_F(BoundaryLoadsTest, ACopyReadsAsItsStepsLoadsAfterTheNextBeganWithOtherSizes) {
  constexpr std::size_t groups = 1500, obstacles = 1, slots = water::kWalls + obstacles;  // two chunks
  water::BoundaryLoads loads(shaders(), kGroupSize);
  loads.begin(groups * kGroupSize, obstacles);
  std::vector<glm::vec4> partials(groups * slots * 2, glm::vec4(0.0f));
  for (std::size_t g = 0; g < groups; ++g)
    partials[2 * (g * slots + water::kWalls)] = glm::vec4(1e-3f, 0.0f, 0.0f, 0.0f);
  sumPartials(loads, partials);
  const water::Loads summed = loads.read(1.0);
  loads.request();
  loads.begin(3 * groups * kGroupSize, obstacles + 2);  // the next step: more chunks, more slots
  const water::Loads got = loads.received(1.0);
  ASSERT_EQ(got.obstacles.size(), obstacles);
  EXPECT_NEAR(got.obstacles[0].force.x, 1.5, 1e-6);
  EXPECT_EQ(got.obstacles[0].force, summed.obstacles[0].force);
}
