// Water that stays incompressible: Position Based Fluids (M. Macklin and M. Müller, "Position
// Based Fluids", ACM SIGGRAPH 2013) on the balls' particles, grid, obstacles, walls and tap, in
// SI units. Each step (stepOnce, fluid_passes.cpp):
// Blocks of water start on a cubic lattice of the spacing (rest_lattice.h says why).
//   predict    v += dt·g, p = x + dt·v                                     (particle order)
//   sort       grid of cell h on p (count, scan), p and x to cell order  (neighbours for the step)
//   bodies     the dynamic obstacles moved by the last step's loads, then every obstacle placed
//   iterate    `iterations` times: λ (density, constraint, λ), then Δp with s_corr, the obstacles
//              (no closer than kObstacleContact) and the walls, then, while measuring, the
//              obstacles' loads from their particles' side (boundary_loads.h)
//   velocity   v = (p − x)/dt, x = p
//   viscosity  XSPH (and the vorticity ω), then vorticity confinement when ε_v > 0
// Densities are ρ/ρ0 throughout (shaders/fluid/kernels.glsl); boundaries take part in the density
// sum: the walls as half spaces at rest density (closed form, sph_kernels.h), the obstacles'
// particles with their rest volumes (Akinci et al. 2012; rest_lattice.h). Renderers read it as
// they read the balls (water::ParticleWater).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "grid/grid.h"
#include "sim/fluid/density_probe.h"
#include "sim/fluid/fluid_params.h"
#include "sim/fluid/rest_lattice.h"
#include "sim/model.h"
#include "sim/particle_memory.h"
#include "sim/water/bodies.h"
#include "sim/water/body_coupling.h"
#include "sim/water/boundary_loads.h"
#include "sim/water/obstacles.h"
#include "sim/water/particle_water.h"
#include "sim/water/water_frame.h"

namespace tidepool::fluid {

class Fluid final : public sim::Model, public water::ParticleWater {
 public:
  // The closest a particle comes to an obstacle particle, in spacings: more than the largest hole of
  // their HCP lattice (an octahedral hole, 1/√2 from its six particles), so none passes through a
  // layer or settles inside a solid.
  static constexpr float kObstacleContact = 0.75f;

  Fluid(gl::ShaderLibrary& shaders, const Params& params);  // throws Error (size, memory, a bad obstacle)

  Params& params() { return m_params; }  // solver edits apply at the next step; "particles" edits at reset()
  const Params& params() const { return m_params; }
  // sim::Model. A frame is water.substeps steps of water.dt.
  void reset() override;
  void step(gl::GpuProfiler& profiler) override;
  double frameSeconds() const override { return m_params.substeps * double(m_params.dt); }
  double time() const override { return m_time; }
  std::size_t count() const override { return m_count; }  // sim::Model and water::ParticleWater
  std::string status() const override;
  std::uint64_t stepCount() const override { return m_steps; }
  std::vector<sim::StateBuffer> stateBuffers() override;  // positions, velocities (and bodies)

  void stepOnce(gl::GpuProfiler* profiler = nullptr);  // one step of water.dt
  Stats stats();                                       // the density probe and energies (blocking)

  // water::ParticleWater
  const gl::Buffer& positions() const override { return m_x; }
  const gl::Buffer& velocities() const override { return m_v; }
  // vec2 (λ, ρ/ρ0) per particle, in the order of positions(): the density of the last step's last
  // solver iteration. Valid once a step has run since reset, upload, restore or recovery.
  const gl::Buffer& densities() const { return m_lambda; }
  bool densitiesValid() const { return m_densitiesValid; }
  // Λ per particle, the sum of λ over the last step's iterations (p = −ρ0 Λ / dt²), in the order
  // of positions(); valid with densities().
  const gl::Buffer& lambdaSums() const { return m_lambdaSum; }
  float radius() const override { return m_params.radius; }
  water::Packing packing() const override { return Params::kPacking; }
  const water::Obstacles& obstacles() const override { return m_obstacles; }
  const water::Bodies& bodies() const { return m_coupling.bodies(); }  // the dynamic obstacles
  water::Bodies& bodies() { return m_coupling.bodies(); }              // the window's mouse pulls them (Bodies::grab)
  const water::Setup& water() const override { return m_params; }
  glm::vec3 wallMin() const override { return m_walls.min; }
  glm::vec3 wallMax() const override { return m_walls.max; }
  float domainRotation() const override;
  // The solver's pressure of the last step at each point (fluid_probes.cpp); NaN before the first step.
  std::vector<double> pressures(const std::vector<glm::vec3>& points) override;
  // The loads of the last step (boundary_loads.h), while the setup lists a force probe.
  water::Loads loads() override;

  glm::vec3 gravity() const;                                                          // current, turned with the domain
  double h() const { return m_params.h(); }                                           // smoothing radius, m
  double mass() const { return m_params.restDensity * m_rest.volume; }                // kg per particle
  double loadScale() const { return -mass() / (double(m_params.dt) * m_params.dt); }  // ΣΔ to N: −m / dt²
  const RestLattice& rest() const { return m_rest; }
  std::size_t obstacleCount() const { return m_obstacles.particles(); }
  std::size_t cells() const { return m_grid ? m_grid->cells() : 0; }                // of the neighbour grid (cell h)
  const grid::UniformGrid* neighbourGrid() const override { return m_grid.get(); }  // water::ParticleWater
  std::size_t bytesPerParticle() const;  // GPU memory of the state, the solver and the grid, per particle
  double speedBound() const;             // m/s: faster moves more than h per step (neighbours missed)

  // Tests and the window's model switch: all particles (vec4 position, vec4 velocity), and the
  // order of the last step (lastOrder()[k] = index before the step of particle k after it).
  void upload(const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel);
  std::vector<glm::vec4> downloadPositions() const { return m_x.read<glm::vec4>(m_count); }
  std::vector<glm::vec4> downloadVelocities() const { return m_v.read<glm::vec4>(m_count); }
  void trackOrder(bool on) { m_trackOrder = on; }
  std::vector<GLuint> lastOrder() const { return m_permutation.read<GLuint>(m_count); }

 private:
  // The divergence watch: NaN particles, particles outside the walls, speed above speedBound().
  void checkHealth(const gl::Window& w) override;
  std::optional<std::string> unhealthy(const sim::DivergenceWatch::Words& words) override;
  std::string method() const override;
  void resume(const sim::StateStamp& good) override;
  // Checkpoints: the clock, the count and the tap's counters (the bodies are a state buffer; other
  // obstacles' poses and the walls follow from the time and the parameters; λ and the
  // predictions are made anew every step).
  void visitOwnState(sim::StateVisitor& v) override;

  void allocate(std::size_t count, std::size_t capacity);
  sim::ParticleCost cost() const;  // per particle, for the checks before allocating (sim/particle_memory.h)
  void calibrate();                // the rest lattice for the current spacing and smoothing
  // The neighbour grid's cells are h/2: the 125 cells around a particle's hold 1.7 times fewer
  // candidates than the 27 cells of h.
  static constexpr int kGridReach = 2;  // cells each way that cover h
  float cellSize() const { return float(m_params.h()) / float(kGridReach); }
  // The passes of stepOnce(), in order.
  void emitFromTap();
  void predict(gl::GpuProfiler* profiler);
  void sortByCell(gl::GpuProfiler* profiler);
  void solve(gl::GpuProfiler* profiler);  // the iterations
  void updateVelocities(gl::GpuProfiler* profiler);
  // While the walls' loads are measured: binds their partials and returns LOADS_WALLS, for
  // predict and Δp.
  std::vector<gl::ShaderDefine> bindWallLoads() const;
  void measureObstacleLoads(bool add, gl::GpuProfiler* profiler);  // after each Δp, while measuring
  // What the kernels share (fluid_kernels.h); bindNeighbours() binds the grid's cell starts.
  SphUniforms sph() const;
  WallUniforms walls() const;
  NeighbourUniforms bindNeighbours() const;

  gl::ShaderLibrary& m_shaders;
  Params m_params;
  RestLattice m_rest;                            // the fluid's cubic fill
  double m_solidVolume = 0;                      // V0 of a solid obstacle's particles (HCP lattice)
  float m_restSpacing = 0, m_restSmoothing = 0;  // what m_rest was measured for
  std::size_t m_count = 0, m_capacity = 0, m_tapEmitted = 0;
  double m_tapNextLayer = 0;
  // State x, v (cell order after a step); the predicted positions p; scratch for the Jacobi
  // iterations and the velocity passes; (λ, ρ/ρ0) per particle.
  gl::Buffer m_x, m_v, m_pred, m_scratch[2], m_lambda, m_lambdaSum, m_permutation;
  gl::Buffer m_unpushed;  // vec4 per particle while the obstacles' loads are measured (fluid/delta.comp)
  std::unique_ptr<grid::UniformGrid> m_grid;
  water::Obstacles m_obstacles;
  std::string m_obstacleError;
  water::Walls m_walls;
  DensityProbe m_probe;
  water::BoundaryLoads m_loads;
  // A force probe or a dynamic obstacle is listed: the step measures the loads, the walls' only
  // for a probe on a wall (theirs cost the most: most work groups touch a wall; m_loads.walls());
  // after it, m_loads holds its sums.
  bool m_loadsOn = false;
  // The dynamic obstacles: moved after predict and the sort are queued, the step's loads on them
  // requested at its end (water/body_coupling.h).
  water::BodyCoupling m_coupling;
  double m_time = 0;
  std::uint64_t m_steps = 0;
  bool m_trackOrder = false;
  bool m_densitiesValid = false;  // m_lambda and m_lambdaSum belong to the particles in m_x
};

}  // namespace tidepool::fluid
