// The loads' sums (sim/water/boundary_loads.h): the walls' partials, as the measuring kernels
// leave them, summed on the GPU in chunks of work groups (shaders/water/loads_sum.comp) and on the
// CPU across them, also past one storage block a window of chunks at a time; the obstacles'
// shares summed per obstacle (obstacle_loads_sum.comp); each against a plain double sum.
#include <gtest/gtest.h>

#include <random>

#include "base/error.h"
#include "gl/window.h"
#include "sim/water/boundary_loads.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {
using BoundaryLoadsTest = test::GlTest;
constexpr std::size_t kGroupSize = 128;  // particles per work group of the measuring kernels
constexpr GLuint kBinding = 0, kMoments = 1;
constexpr float kRadius = 0.005f;

// Writes `values` into the buffer bound at `binding`.
void fill(const std::vector<glm::vec4>& values, GLuint binding = kBinding) {
  GLint buffer = 0;
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, binding, &buffer);
  glBindBuffer(GL_COPY_WRITE_BUFFER, GLuint(buffer));
  glBufferSubData(GL_COPY_WRITE_BUFFER, 0, GLsizeiptr(values.size() * sizeof(glm::vec4)), values.data());
}

std::vector<glm::vec4> random(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(-1e-4f, 1e-4f);
  std::vector<glm::vec4> out(n);
  for (glm::vec4& v : out) v = glm::vec4(value(rng), value(rng), value(rng), value(rng));
  return out;
}

// Boxes of about `particles` particles each (radius kRadius), placed.
water::Obstacles boxes(gl::ShaderLibrary& shaders, const std::vector<float>& sides) {
  std::vector<water::ObstacleParams> params;
  for (std::size_t k = 0; k < sides.size(); ++k) {
    water::ObstacleParams o;
    o.shape = water::Shape::Box;
    o.centre = glm::vec3(0.1f + 0.15f * float(k), 0.1f, 0.1f);
    o.size = glm::vec3(sides[k]);
    params.push_back(o);
  }
  water::Obstacles obstacles(shaders);
  obstacles.build(params, kRadius);
  obstacles.place(params, water::posesAt(params, 0.0), glm::vec3(0.0f), glm::vec3(0.6f));
  return obstacles;
}

// Random wall partials of `groups` work groups summed by `loads` against the double sum.
void expectWallSumsOfRandomPartials(water::BoundaryLoads& loads, const water::Obstacles& none, std::size_t groups) {
  loads.begin(groups * kGroupSize - 5, true, none);
  const std::vector<glm::vec4> partials = random(2 * groups, 3);
  loads.bindWalls(kBinding);
  fill(partials);
  loads.sum(none);
  const double scale = -2.5;
  const water::Loads got = loads.read(scale);
  for (std::size_t w = 0; w < water::kWalls; ++w) {
    double push = 0;
    for (std::size_t g = 0; g < groups; ++g) push += scale * double(partials[2 * g + w / 4][int(w % 4)]);
    glm::dvec3 want(0.0);
    want[int(w / 2)] = push;
    // Up to 5000 float terms of up to 2.5e-4 (scaled): rounding far below 1e-8; a chunk lost is ~1e-3.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got.walls[w].force[k], want[k], 1e-8) << "wall " << w;
    EXPECT_EQ(got.walls[w].torque, glm::dvec3(0.0));
  }
}

}  // namespace

TEST_F(BoundaryLoadsTest, ChunkedWallSumsEqualTheDoubleSumOfEveryGroupsPartials) {
  water::BoundaryLoads loads(shaders(), kGroupSize);
  const water::Obstacles none(shaders());
  expectWallSumsOfRandomPartials(loads, none, 2500);  // three chunks
}

// Partials of 5000 groups × 32 B = 156 KiB through a block of 64 KiB: chunks of 1024 groups, two
// per window.
TEST_F(BoundaryLoadsTest, WallPartialsPastOneStorageBlockAreSummedAWindowOfChunksAtATime) {
  gl::overrideStorageBlockBytes(gl::kMinStorageBlockBytes);
  water::BoundaryLoads loads(shaders(), kGroupSize);
  const water::Obstacles none(shaders());
  expectWallSumsOfRandomPartials(loads, none, 5000);
  gl::overrideStorageBlockBytes(0);
}

// Each obstacle's sum is of its own particles' shares, whatever their number (fewer than a work
// group, several groups' worth).
TEST_F(BoundaryLoadsTest, ObstacleSumsEqualTheDoubleSumOfTheirParticlesShares) {
  const water::Obstacles obstacles = boxes(shaders(), {0.02f, 0.05f, 0.08f});
  ASSERT_LT(obstacles.body(0).particles.size(), kGroupSize);
  ASSERT_GT(obstacles.body(2).particles.size(), 4 * kGroupSize);
  water::BoundaryLoads loads(shaders(), kGroupSize);
  loads.begin(1000, false, obstacles);
  ASSERT_TRUE(loads.obstacles());
  const std::vector<glm::vec4> shares = random(obstacles.particles(), 4), moments = random(obstacles.particles(), 5);
  loads.bindShares(kBinding, kMoments);
  fill(shares);
  fill(moments, kMoments);
  loads.sum(obstacles);
  const double scale = 3.0;
  const water::Loads got = loads.read(scale);
  ASSERT_EQ(got.obstacles.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    glm::dvec3 force(0.0), torque(0.0);
    const water::ObstacleBody& b = obstacles.body(k);
    for (std::size_t j = b.first; j < b.first + b.particles.size(); ++j) {
      force += scale * glm::dvec3(glm::vec3(shares[j]));
      torque += scale * glm::dvec3(glm::vec3(moments[j]));
    }
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(got.obstacles[k].force[c], force[c], 1e-8) << "obstacle " << k;
      EXPECT_NEAR(got.obstacles[k].torque[c], torque[c], 1e-8) << "obstacle " << k;
    }
  }
}

// More obstacle particles than one storage block holds shares for: one line naming the limit.
TEST_F(BoundaryLoadsTest, ObstacleSharesPastOneStorageBlockAreRefusedInOneLine) {
  const water::Obstacles obstacles = boxes(shaders(), {0.2f});
  ASSERT_GT(obstacles.particles() * sizeof(glm::vec4), gl::kMinStorageBlockBytes);
  gl::overrideStorageBlockBytes(gl::kMinStorageBlockBytes);
  water::BoundaryLoads loads(shaders(), kGroupSize);
  try {
    loads.begin(1000, false, obstacles);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("loads: " + std::to_string(obstacles.particles()) +
                                              " obstacle particles, over the 4096 whose shares one storage block holds",
                                          0),
              0u)
        << e.what();
  }
  gl::overrideStorageBlockBytes(0);
}

// The copy a step requested reads as that step's loads after the next step began with another
// count of chunks (a tap added particles) and other obstacles: what the bodies receive is what was summed.
TEST_F(BoundaryLoadsTest, ACopyReadsAsItsStepsLoadsAfterTheNextBeganWithOtherSizes) {
  constexpr std::size_t groups = 1500;  // two chunks
  const water::Obstacles one = boxes(shaders(), {0.02f}), three = boxes(shaders(), {0.02f, 0.03f, 0.04f});
  water::BoundaryLoads loads(shaders(), kGroupSize);
  loads.begin(groups * kGroupSize, true, one);
  std::vector<glm::vec4> partials(2 * groups, glm::vec4(0.0f)), shares(one.particles(), glm::vec4(0.0f));
  for (std::size_t g = 0; g < groups; ++g) partials[2 * g] = glm::vec4(1e-3f, 0.0f, 0.0f, 0.0f);
  shares[0] = glm::vec4(0.25f, 0.0f, 0.0f, 0.0f);
  loads.bindWalls(kBinding);
  fill(partials);
  loads.bindShares(kBinding, kMoments);
  fill(shares);
  fill(shares, kMoments);
  loads.sum(one);
  const water::Loads summed = loads.read(1.0);
  loads.request();
  loads.begin(3 * groups * kGroupSize, true, three);  // the next step: more chunks, more obstacles
  const water::Loads got = loads.received(1.0);
  ASSERT_EQ(got.obstacles.size(), 1u);
  EXPECT_NEAR(got.walls[0].force.x, 1.5, 1e-6);
  EXPECT_EQ(got.walls[0].force, summed.walls[0].force);
  EXPECT_EQ(got.obstacles[0].force, glm::dvec3(0.25, 0.0, 0.0));
}
