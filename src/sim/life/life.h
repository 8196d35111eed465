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
#include "gl/gpu_profiler.h"
#include "gl/kernel.h"
#include "grid/grid.h"
#include "sim/life/life_params.h"
#include "sim/life/life_rules.h"
#include "sim/model.h"

namespace tidepool::life {

// The uniforms of life/forces_brute.comp; life/forces.comp adds the grid's.
struct PairUniforms {
  glm::vec2 boxSize{0.0f};    // uBoxSize, world units
  GLuint count = 0;           // particles
  GLuint species = 0;         // S
  float centralForce = 0.0f;  // 1/s^2
  static constexpr auto fields() {
    return std::tuple{gl::field("uBoxSize", &PairUniforms::boxSize), gl::field("uCount", &PairUniforms::count),
                      gl::field("uSpecies", &PairUniforms::species),
                      gl::field("uCentralForce", &PairUniforms::centralForce)};
  }
};

class Life final : public sim::Model {
 public:
  Life(gl::ShaderLibrary& shaders, const Rules& rules, const Params& params = {});  // throws Error

  Params& params() { return m_params; }  // read at the next step
  const Params& params() const { return m_params; }
  const Rules& rules() const { return m_rules; }
  // New rules: validated (throws Error, nothing changes), buffers and grid rebuilt, particles
  // respawned when the count, box or species changed or `respawn` is set.
  void setRules(const Rules& rules, bool respawn = true);

  // sim::Model. A frame is one generation: one step of params().maxDt.
  void reset() override { respawn(0); }  // the seed's initial particles
  void respawn(std::uint32_t stream);    // t = 0 with spawnParticles(rules, stream): same rules, other particles
  void step(gl::GpuProfiler& profiler) override;
  double frameSeconds() const override { return m_params.maxDt; }
  double time() const override { return m_time; }
  std::size_t count() const override { return m_count; }
  std::string status() const override;
  std::uint64_t stepCount() const override { return m_steps; }
  std::vector<sim::StateBuffer> stateBuffers() override;  // positions, velocities (see storage())

  void stepOnce(float dt);  // applies a storage change first
  void computeForces() {    // at the current positions -> accelerations()
    sortByCell();
    evaluateForces();
  }
  void sortByCell();      // grid build (count + scan) and reorder of positions and velocities
  void evaluateForces();  // the force pass alone, on positions already in cell order
  // Mouse brush for the next step: velocity (world units/s) added with a Gaussian of `radius`.
  void push(glm::vec2 point, glm::vec2 velocity, float radius);

  Storage storage() const { return m_storage; }                      // of the buffers now (params() may differ)
  const gl::Buffer& positions() const { return m_pos[m_current]; }   // (x, y, 0, species), see storage()
  const gl::Buffer& velocities() const { return m_vel[m_current]; }  // (vx, vy, ax, ay), see storage()
  const gl::Buffer& accelerations() const { return m_accel; }        // vec2, same order as positions()
  const gl::Buffer& speciesColors() const { return m_colors; }       // vec4 per species
  PairUniforms pairUniforms() const;                                 // of the current rules and count
  const gl::Buffer& forceTable() const { return m_table; }           // vec4 per pair, see life/bindings.glsl
  const grid::UniformGrid& grid() const { return *m_grid; }
  void upload(const std::vector<glm::vec4>& positions, const std::vector<glm::vec4>& velocities);
  std::vector<glm::vec4> downloadPositions() const;   // (x, y, 0, species), in the current (cell) order
  std::vector<glm::vec4> downloadVelocities() const;  // (vx, vy, ax, ay), same order
  // Particle identity across the grid's reorders (studies, tests; costs a third reordered array):
  // ids()[k] = the index, at the last upload() or trackIds(true), of the particle now in slot k.
  void trackIds(bool on);
  std::vector<std::uint32_t> ids() const;
  // Candidate pairs the force pass examines at the current (sorted) positions: one extra
  // run of the counting variant (benchmarks).
  std::uint64_t countCandidatePairs();

  // The divergence watch (sim::Model): recover() goes back to the last good state with half the last dt.
  double speedBound() const;  // world units/s: faster means more than 10 grid cells (>= max radius) per step

 private:
  // The divergence watch (sim::Model): NaN particles, speed above speedBound().
  void checkHealth(const gl::Window& w) override;
  std::optional<std::string> unhealthy(const sim::DivergenceWatch::Words& words) override;
  std::string method() const override;
  void resume(const sim::StateStamp& good) override;
  // Checkpoints: the clock, the storage of the buffers, whether Verlet's a(x) is in vel.zw, the
  // brush and the last dt (the rules are the stage's to save).
  void visitOwnState(sim::StateVisitor& v) override;

  void allocate();
  // Throws when the count does not fit in `storage` (sim/particle_memory.h).
  static void checkCount(const Rules& rules, Storage storage);
  void makeGrid();
  void applyStorage();  // converts the state when params().storage changed
  void resetIds();
  void uploadTable();
  void forcePass(bool countPairs);
  void integrate(const char* variant, float dt);
  std::vector<gl::ShaderDefine> defines() const;

  gl::ShaderLibrary& m_shaders;
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
};

}  // namespace tidepool::life
