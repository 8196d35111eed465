// Particle life ("life"): S species of particles in a 2D box, each pair of species with its own
// asymmetric attraction and collision forces (life_rules.h), friction and an optional central
// force; walls or a torus. Owns the particle buffers and the passes; renderers read them.
//   After lisyarus, "Particle life" (lisyarus.github.io/webgpu/particle-life.html, 2025).
//
// One step (symplectic Euler):  grid.build + reorder (pos, vel) -> forces -> integrate
//                (Verlet):       drift -> grid.build + reorder -> forces -> kick
// The neighbour search is the shared uniform grid (grid/grid.h) with cell = the largest force
// radius; particles are kept in cell order between steps (double-buffered, no copy back), so
// the order of particles changes every step: compare sets, not indices (or track ids).
//
// Storage (Params::storage): fp32 keeps (x, y, 0, species) and (vx, vy, ax, ay) as vec4s; fp16
// packs each pair into one packHalf2x16 word (positions uvec2 (xy, species), velocities uvec2
// (v, a)), and the grid then reads half positions and moves 8-byte elements. Every pass
// computes in fp32; only what is stored between passes is rounded. A change converts the state.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "grid/grid.h"
#include "sim/divergence.h"
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
  void step(double frameSeconds, gl::GpuProfiler& profiler);  // one step of min(maxDt, frame), then watch
  void stepOnce(float dt);                                    // applies a storage change first
  void computeForces() {                                      // at the current positions -> accelerations()
    sortByCell();
    evaluateForces();
  }
  void sortByCell();      // grid build (count + scan) and reorder of positions and velocities
  void evaluateForces();  // the force pass alone, on positions already in cell order
  // Mouse brush for the next step: velocity (world units/s) added with a Gaussian of `radius`.
  void push(glm::vec2 point, glm::vec2 velocity, float radius);

  std::size_t count() const { return m_count; }
  Storage storage() const { return m_storage; }                      // of the buffers now (params() may differ)
  const gl::Buffer& positions() const { return m_pos[m_current]; }   // (x, y, 0, species), see storage()
  const gl::Buffer& velocities() const { return m_vel[m_current]; }  // (vx, vy, ax, ay), see storage()
  const gl::Buffer& accelerations() const { return m_accel; }        // vec2, same order as positions()
  const gl::Buffer& speciesColors() const { return m_colors; }       // vec4 per species
  const gl::Buffer& forceTable() const { return m_table; }           // vec4 per pair, see life/bindings.glsl
  const grid::UniformGrid& grid() const { return *m_grid; }
  void upload(const std::vector<glm::vec4>& positions, const std::vector<glm::vec4>& velocities);
  std::vector<glm::vec4> downloadPositions() const;   // (x, y, 0, species), in the current (cell) order
  std::vector<glm::vec4> downloadVelocities() const;  // (vx, vy, ax, ay), same order
  // Particle identity across the grid's reorders (studies, tests; costs a third reordered array):
  // ids()[k] = the index, at the last upload() or trackIds(true), of the particle now in slot k.
  void trackIds(bool on);
  std::vector<std::uint32_t> ids() const;
  double time() const { return m_time; }
  std::uint64_t stepCount() const { return m_steps; }
  // Candidate pairs the force pass examines at the current (sorted) positions: one extra
  // run of the counting variant (benchmarks).
  std::uint64_t countCandidatePairs();
  std::string status() const;

  // Divergence watch (sim/divergence.h): a non-blocking check every 8 frames of step().
  std::optional<DivergenceReport> divergence() const { return m_divergence; }
  bool recover();             // back to the last good state with half the last dt; false if none
  void flushChecks();         // waits for the check in flight (end of a headless run)
  double speedBound() const;  // world units/s: faster means more than 10 grid cells (>= max radius) per step
  float lastDt() const { return m_lastDt; }  // s, of the last step

 private:
  void allocate();
  void makeGrid();
  void applyStorage();  // converts the state when params().storage changed
  void resetIds();
  void uploadTable();
  void forcePass(bool countPairs);
  void integrate(const char* variant, float dt);
  std::vector<gl::ShaderDefine> defines() const;
  void watch();  // polls the check in flight, starts the next one
  void judge(const CheckCycle::Words& words, double time);

  gl::ShaderLibrary& m_shaders;
  gl::BufferOps m_ops;  // checkpoint copies of the divergence watch
  Rules m_rules;
  Params m_params;
  std::size_t m_count = 0;
  std::unique_ptr<grid::UniformGrid> m_grid;
  Storage m_storage = Storage::Fp32;
  gl::Buffer m_pos[2], m_vel[2], m_ids[2], m_accel, m_table, m_colors, m_groupPairs;
  bool m_trackIds = false;
  int m_current = 0;
  bool m_needAccel = true;  // Verlet: the forces at the current positions are not in vel.zw yet
  glm::vec2 m_pushPoint{0.0f}, m_pushVelocity{0.0f};
  float m_pushRadius = 1.0f;
  double m_time = 0;
  float m_lastDt = 0;
  std::uint64_t m_steps = 0;
  // Divergence watch: reduced values, the state copied at the check, the last state judged good
  // (no copies above kMaxCheckpointParticles: a blow-up is still reported, recovery is refused).
  gl::Buffer m_health, m_pendingPos, m_pendingVel, m_goodPos, m_goodVel;
  CheckCycle m_checks{8};  // a check every 8 frames
  double m_goodTime = 0;
  std::uint64_t m_pendingSteps = 0, m_goodSteps = 0;
  bool m_hasGood = false;
  std::optional<DivergenceReport> m_divergence;
};

}  // namespace tidepool::life
