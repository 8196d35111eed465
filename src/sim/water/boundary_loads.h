// The loads the water puts on the walls and the obstacles in a step (shaders/water/loads.glsl):
// the model's measuring kernels add each work group's shares to that group's partials,
// loads_sum.comp adds them in chunks of groups and read() the chunks, all in a fixed order, and
// the force is `scale` times the sum (the fluid: −m ΣΔ / dt², the momentum its boundaries gave
// the water per second; the balls: −m Σa). The partials take 6 + obstacles slots of 32 B per
// work group: under 6 B per particle of groups of 128, less than one vec4 array.
#pragma once

#include <cstddef>
#include <vector>

#include "gl/async_readback.h"
#include "gl/buffer.h"
#include "gl/shader_library.h"
#include "sim/water/particle_water.h"

namespace tidepool::water {

// What a step measures: the loads while a force probe or a body is listed, and the walls' (which
// cost the most: most work groups touch a wall) only for a probe on a wall.
struct LoadsWanted {
  bool any = false, walls = false;
};
LoadsWanted loadsWanted(const std::vector<ProbeParams>& probes, bool bodies);

class BoundaryLoads {
 public:
  // `groupSize`: the particles per work group of the kernels that measure.
  BoundaryLoads(gl::ShaderLibrary& shaders, std::size_t groupSize) : m_shaders(shaders), m_groupSize(groupSize) {}

  // A step of `count` particles with `obstacles` obstacles begins. Its first measuring kernel
  // zeroes the partials of its groups (LOADS_FIRST in water/loads.glsl); with no particles, this does.
  void begin(std::size_t count, std::size_t obstacles);
  void bind(GLuint binding) const;  // all the partials (the particles fit one storage block)
  // The partials of work groups [firstGroup, firstGroup + groups): a window of particles that
  // starts at a multiple of gl::kWindowGrain (gl/window.h); all of them as bind() when that is all.
  void bindGroups(GLuint binding, std::size_t firstGroup, std::size_t groups) const;
  GLuint slots() const { return m_slots; }  // uLoadSlots
  std::size_t bytes() const { return m_partials.size() + m_sums.size(); }
  void sum();  // the step's sums per chunk of groups and slot (after its last measuring kernel)
  // The sums as forces and torques (`scale` times them); walls about nothing (zero torque).
  Loads read(double scale) const;
  // The same in two halves, so that the GPU goes on with other work in between: request() copies
  // the step's sums aside, received() waits for that copy and reads it.
  void request();
  Loads received(double scale);

 private:
  Loads fromSums(const glm::vec4* sums, std::size_t chunks, GLuint slots, double scale) const;

  gl::ShaderLibrary& m_shaders;
  std::size_t m_groupSize;
  gl::Buffer m_partials, m_sums;
  gl::AsyncReadback m_copy;
  std::size_t m_copyChunks = 0;  // the requesting step's, to read the copy after a later begin()
  GLuint m_copySlots = 0;
  std::size_t m_groups = 0, m_chunks = 0;
  std::size_t m_chunkGroups = 0;  // work groups per chunk: a chunk's partials fit one storage block
  GLuint m_slots = 0;
};

}  // namespace tidepool::water
