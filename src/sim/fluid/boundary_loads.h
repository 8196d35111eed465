// The loads the fluid puts on the walls and the obstacles in a step (shaders/fluid/loads.glsl):
// predict and every solver iteration add each work group's shares of the boundaries' position
// corrections to that group's partials, loads_sum.comp adds them in chunks of groups and read()
// the chunks, all in a fixed order, and the force is −m ΣΔ / dt² (the momentum the boundary gave
// the water, per second). The partials take 6 + obstacles slots of 32 B per group of
// FLUID_GROUP_SIZE particles: under 6 B per particle, less than one state array, so they fit
// wherever the state does.
#pragma once

#include <cstddef>
#include <vector>

#include "gl/async_readback.h"
#include "gl/buffer.h"
#include "gl/shader_library.h"
#include "sim/water/particle_water.h"

namespace tidepool::fluid {

class BoundaryLoads {
 public:
  explicit BoundaryLoads(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}

  // A step of `count` particles with `obstacles` obstacles begins. Its first kernel zeroes the
  // partials of its groups (LOADS_FIRST in fluid/loads.glsl); with no particles, this does.
  void begin(std::size_t count, std::size_t obstacles);
  void bind() const;                        // the partials, at FLUID_LOADS
  GLuint slots() const { return m_slots; }  // uLoadSlots
  std::size_t bytes() const { return m_partials.size() + m_sums.size(); }
  void sum();  // the step's sums per chunk of groups and slot (after its last iteration)
  // The sums as forces and torques: `scale` = −m / dt² (kg/s²); walls about nothing (zero torque).
  water::Loads read(double scale) const;
  // The same in two halves, so that the GPU goes on with other work in between: request() copies
  // the step's sums aside, received() waits for that copy and reads it.
  void request();
  water::Loads received(double scale);

 private:
  water::Loads fromSums(const glm::vec4* sums, std::size_t chunks, GLuint slots, double scale) const;

  gl::ShaderLibrary& m_shaders;
  gl::Buffer m_partials, m_sums;
  gl::AsyncReadback m_copy;
  std::size_t m_copyChunks = 0;  // the requesting step's, to read the copy after a later begin()
  GLuint m_copySlots = 0;
  std::size_t m_groups = 0, m_chunks = 0;
  GLuint m_slots = 0;
};

}  // namespace tidepool::fluid
