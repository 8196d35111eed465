// Particle life ("life"): S species of particles in a 2D box, each pair of species with its own
// asymmetric attraction and collision forces (life_rules.h), friction and an optional central
// force; walls or a torus. Owns the particle buffers and the passes; renderers read them.
//   After lisyarus, "Particle life" (lisyarus.github.io/webgpu/particle-life.html, 2025).
//
// One step (symplectic Euler):  grid.build + reorder (pos, vel) -> forces -> integrate
//                (Verlet):       drift -> grid.build + reorder -> forces -> kick
// The neighbour search is the shared uniform grid (grid/grid.h) with cell = the largest force
// radius; particles are kept in cell order between steps (double-buffered, no copy back), so
// the order of particles changes every step: compare sets, not indices.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "grid/grid.h"
#include "sim/life/life_params.h"
#include "sim/life/life_rules.h"

namespace tidepool::life {

class Life {
 public:
  Life(gl::ShaderLibrary& shaders, const Rules& rules, const Params& params = {});  // throws Error

  Params& params() { return m_params; }  // read at the next step
  const Params& params() const { return m_params; }
  const Rules& rules() const { return m_rules; }
  // New rules: validated (throws Error, nothing changes), buffers and grid rebuilt, particles
  // respawned when the count, box or species changed or `respawn` is set.
  void setRules(const Rules& rules, bool respawn = true);

  void reset();                                               // the seed's initial particles
  void step(double frameSeconds, gl::GpuProfiler& profiler);  // one step of min(maxDt, frame)
  void stepOnce(float dt);
  void computeForces() {  // at the current positions -> accelerations()
    sortByCell();
    evaluateForces();
  }
  void sortByCell();      // grid build (count + scan) and reorder of positions and velocities
  void evaluateForces();  // the force pass alone, on positions already in cell order
  // Mouse brush for the next step: velocity (world units/s) added with a Gaussian of `radius`.
  void push(glm::vec2 point, glm::vec2 velocity, float radius);

  std::size_t count() const { return m_count; }
  const gl::Buffer& positions() const { return m_pos[m_current]; }   // vec4 (x, y, 0, species)
  const gl::Buffer& velocities() const { return m_vel[m_current]; }  // vec4 (vx, vy, ax, ay)
  const gl::Buffer& accelerations() const { return m_accel; }        // vec2, same order as positions()
  const gl::Buffer& speciesColors() const { return m_colors; }       // vec4 per species
  const gl::Buffer& forceTable() const { return m_table; }           // vec4 per pair, see life/bindings.glsl
  const grid::UniformGrid& grid() const { return *m_grid; }
  void upload(const std::vector<glm::vec4>& positions, const std::vector<glm::vec4>& velocities);
  double time() const { return m_time; }
  std::uint64_t stepCount() const { return m_steps; }
  // Candidate pairs the force pass examines at the current (sorted) positions: one extra
  // run of the counting variant (benchmarks).
  std::uint64_t countCandidatePairs();
  std::string status() const;

 private:
  void allocate();
  void uploadTable();
  void forcePass(bool countPairs);
  void integrate(const char* variant, float dt);
  std::vector<gl::ShaderDefine> defines() const;

  gl::ShaderLibrary& m_shaders;
  Rules m_rules;
  Params m_params;
  std::size_t m_count = 0;
  std::unique_ptr<grid::UniformGrid> m_grid;
  gl::Buffer m_pos[2], m_vel[2], m_accel, m_table, m_colors, m_groupPairs;
  int m_current = 0;
  bool m_needAccel = true;  // Verlet: the forces at the current positions are not in vel.zw yet
  glm::vec2 m_pushPoint{0.0f}, m_pushVelocity{0.0f};
  float m_pushRadius = 1.0f;
  double m_time = 0;
  std::uint64_t m_steps = 0;
};

}  // namespace tidepool::life
