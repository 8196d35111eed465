// The checks before allocating (sim/particle_memory.h): what fits is the tightest of the limits,
// named in a one-line error with the numbers; a GL_OUT_OF_MEMORY allocation throws and leaves
// the context usable.
#include <gtest/gtest.h>

#include <limits>

#include "base/error.h"
#include "gl/buffer.h"
#include "gl/gl.h"
#include "sim/particle_memory.h"
#include "sim/water/water_init.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {
class ParticleMemory : public test::GlTest {};

std::size_t maxBlock() {
  GLint64 bytes = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
  return std::size_t(bytes);
}
}  // namespace

TEST_F(ParticleMemory, TheTightestLimitBinds) {
  const sim::ParticleFit byKey =
      sim::particlesThatFit({.maxParticles = 1000, .arrayBytes = 16, .gpuBytes = 96}, "ball");
  EXPECT_EQ(byKey.count, 1000u);
  EXPECT_EQ(byKey.limit, "max_particles = 1000");
  // No max_particles (0, the default): the device's own limits alone.
  const sim::ParticleFit byDevice =
      sim::particlesThatFit({.maxParticles = 0, .arrayBytes = 16, .gpuBytes = 96}, "ball");
  EXPECT_GT(byDevice.count, 0u);
  EXPECT_LE(byDevice.count, maxBlock() / 16);
  EXPECT_EQ(byDevice.limit.find("max_particles"), std::string::npos) << byDevice.limit;
  // One MiB per particle in one array: the storage-block limit binds, whatever the device.
  const sim::ParticleFit byBlock = sim::particlesThatFit(
      {.maxParticles = std::numeric_limits<std::size_t>::max(), .arrayBytes = 1 << 20, .gpuBytes = 1 << 20}, "ball");
  EXPECT_EQ(byBlock.count, maxBlock() >> 20);
  EXPECT_NE(byBlock.limit.find("the storage-block limit, " + std::to_string(maxBlock() >> 20) + " MiB per array"),
            std::string::npos)
      << byBlock.limit;
  // A GiB per particle in a windowed array: the windowed-array limit binds (arrays reaching 4 GiB
  // read wrong on the H100's and H200's driver).
  const sim::ParticleFit byWindowedBuffer = sim::particlesThatFit(
      {.maxParticles = 0, .arrayBytes = 4, .windowedBytes = std::size_t(1) << 30, .gpuBytes = 4}, "ball");
  EXPECT_EQ(byWindowedBuffer.count, 3u);
  EXPECT_EQ(byWindowedBuffer.limit, "the windowed-array limit of 4294901760 bytes, at 1073741824 B per ball");
  // A terabyte of host memory per particle: free host memory binds (Linux reports it).
  ASSERT_TRUE(sim::freeHostBytes().has_value());
  const sim::ParticleFit byHost = sim::particlesThatFit({.maxParticles = std::numeric_limits<std::size_t>::max(),
                                                         .arrayBytes = 4,
                                                         .gpuBytes = 4,
                                                         .hostBytes = 1ull << 40},
                                                        "ball");
  EXPECT_EQ(byHost.count, 0u);
  EXPECT_NE(byHost.limit.find("free host memory"), std::string::npos) << byHost.limit;
}

TEST_F(ParticleMemory, RequestsOverTheFitThrowOneLineWithTheNumbers) {
  const sim::ParticleCost cost{.maxParticles = 5000, .arrayBytes = 16, .gpuBytes = 96};
  EXPECT_NO_THROW(sim::checkParticleRequest("balls", "ball", 5000, "5000 balls", cost, "fix"));
  try {
    sim::checkParticleRequest("balls", "ball", 2.1e11, "particles.radius = 0.0001 m", cost, "raise particles.radius");
    FAIL() << "2.1e11 balls do not fit";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "balls: particles.radius = 0.0001 m would make about 2.1e+11 balls, but at most 5000 fit "
                 "(max_particles = 5000): raise particles.radius");
  }
  EXPECT_THROW(sim::checkParticleRequest("balls", "ball", std::nan(""), "NaN", cost, "fix"), Error);
  EXPECT_THROW(sim::checkParticleRequest("balls", "ball", INFINITY, "inf", cost, "fix"), Error);
}

// A fill that places more balls than its space holds at the densest packing starts them on top of
// each other (every ball in a few grid cells: a first step of O(n^2) pairs that never ends).
TEST_F(ParticleMemory, FillsDenserThanAnyPackingAreRefusedWithTheKeys) {
  const sim::ParticleCost cost{.maxParticles = 0, .arrayBytes = 16, .gpuBytes = 96};
  water::Setup s;
  s.fill = water::Fill::Random;
  s.radius = 0.01f;
  s.domainMin = s.fillMin = glm::vec3(0.0f);
  s.domainMax = s.fillMax = glm::vec3(1.0f);
  // Centres in [r, 1 - r]^3, balls in [0, 1]^3: 1 m^3 / 4 sqrt(2) r^3 = 176776 hexagonally close packed.
  EXPECT_EQ(water::fillCapacity(s), 176776.0);
  EXPECT_NO_THROW(water::checkWaterRequest("balls", "ball", "particles.radius = 0.01 m", 176776, s, cost));
  try {
    water::checkWaterRequest("balls", "ball", "particles.radius = 0.01 m", 176777, s, cost);
    FAIL() << "176777 balls do not fit";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "balls: particles.random_count = 176777 balls do not fit in the random fill's region (1 m^3 with "
                 "particles.radius = 0.01 m): at most 176776 do, even hexagonally close packed (74% of the space); "
                 "lower particles.random_count, widen particles.fill_min .. fill_max or lower particles.radius");
  }
  // A region narrower than a ball still holds one; a lattice fill is bounded by the domain.
  s.fillMax = glm::vec3(1e-4f);
  EXPECT_EQ(water::fillCapacity(s), 1.0);
  s.fill = water::Fill::Lattice;
  EXPECT_EQ(water::fillCapacity(s), 176776.0);
  s.fill = water::Fill::Block;
  EXPECT_EQ(water::fillCapacity(s), INFINITY) << "a block fill places its own lattice";
}

// Asking the driver for a terabyte: GL_OUT_OF_MEMORY becomes a GlError naming the size, the
// half-made buffer is released, and the context goes on working.
TEST_F(ParticleMemory, OutOfGpuMemoryThrowsAndTheContextGoesOn) {
  try {
    gl::Buffer huge(std::size_t(1) << 40);
    FAIL() << "a terabyte buffer was granted";
  } catch (const gl::GlError& e) {
    EXPECT_NE(std::string(e.what()).find("out of GPU memory allocating a buffer of 1099511627776 bytes"),
              std::string::npos)
        << e.what();
  }
  const std::vector<float> values = {1, 2, 3};
  gl::Buffer small{std::span<const float>(values)};
  EXPECT_EQ(small.read<float>(3), values);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}
