// The loads the water puts on the walls and the obstacles in a step, all summed in a fixed order:
//   walls      while a wall is probed, the model's measuring kernels add each work group's
//              shares to that group's partials (shaders/water/loads.glsl), and loads_sum.comp
//              adds them in chunks of groups;
//   obstacles  the model's obstacle-loads kernels sum, for each obstacle particle, what it did
//              to the water particles near it (water/obstacle_loads.glsl), and
//              obstacle_loads_sum.comp adds each obstacle's particles.
// The force is `scale` times a sum (the fluid: −m ΣΔ / dt², the momentum its boundaries gave the
// water per second; the balls: −m Σa). The walls' partials take 32 B per work group, under 0.3 B
// per particle; the obstacles' shares and moments 32 B per obstacle particle.
#pragma once

#include <cstddef>
#include <vector>

#include "gl/async_readback.h"
#include "gl/buffer.h"
#include "gl/shader_library.h"
#include "sim/water/obstacles.h"
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
  // `groupSize`: the particles per work group of the kernels that measure the walls.
  BoundaryLoads(gl::ShaderLibrary& shaders, std::size_t groupSize) : m_shaders(shaders), m_groupSize(groupSize) {}

  // A step of `count` water particles begins, measuring the walls or not and the obstacles as
  // built. The step's first measuring kernels zero the walls' partials of their groups
  // (LOADS_FIRST in water/loads.glsl) and store the obstacles' shares; with no water particles,
  // this does. Throws Error when the obstacles' shares pass one storage block.
  void begin(std::size_t count, bool walls, const Obstacles& obstacles);
  bool walls() const { return m_walls; }                      // the step that began last measures the walls
  bool obstacles() const { return m_obstacleParticles > 0; }  // any obstacle particle: shares to sum
  void bindWalls(GLuint binding) const;  // all the walls' partials (the particles fit one storage block)
  // The walls' partials of work groups [firstGroup, firstGroup + groups): a window of particles
  // that starts at a multiple of gl::kWindowGrain (gl/window.h); all of them as bindWalls() when
  // that is all.
  void bindWallGroups(GLuint binding, std::size_t firstGroup, std::size_t groups) const;
  void bindShares(GLuint shares, GLuint moments) const;  // the obstacles' shares and their moments
  std::size_t bytes() const { return m_partials.size() + m_shares.size() + m_moments.size() + m_sums.size(); }
  // The step's sums (after its last measuring kernel): the obstacles' (their pose block bound
  // by obstacles.bind()), then the walls' per chunk of groups.
  void sum(const Obstacles& obstacles);
  // The sums as forces and torques (`scale` times them); walls about nothing (zero torque).
  Loads read(double scale) const;
  // The same in two halves, so that the GPU goes on with other work in between: request() copies
  // the step's sums aside, received() waits for that copy and reads it.
  void request();
  Loads received(double scale);

 private:
  struct Layout {
    std::size_t obstacles = 0, chunks = 0;
    std::size_t vec4s() const { return 2 * (obstacles + chunks); }
  };
  static Loads fromSums(const glm::vec4* sums, Layout layout, double scale);

  gl::ShaderLibrary& m_shaders;
  std::size_t m_groupSize;
  gl::Buffer m_partials, m_shares, m_moments, m_sums;
  gl::AsyncReadback m_copy;
  Layout m_layout, m_copyLayout;  // this step's, and the requesting step's (read after a later begin())
  bool m_walls = false;
  std::size_t m_groups = 0;       // the walls' measuring kernels' work groups
  std::size_t m_chunkGroups = 0;  // work groups per chunk: a chunk's partials fit one storage block
  std::size_t m_obstacleParticles = 0;
};

}  // namespace tidepool::water
