// Water as N equal balls colliding (DEM), after water-webgpu: a uniform grid finds every pair
// within 2r (27 cells), one of three contact laws acts on it, one of three integrators advances
// it; box walls (one may be a piston; gravity rotates with the domain) and obstacles of fixed
// particles (shapes or voxelised triangle meshes, each moving rigidly: sim/water/obstacles.h) complete the
// scene. The model owns its buffers and passes; renderers read positions() / velocities() (foam
// in velocity w) and obstacles() (bodies, poses, meshes).
//
// One step (stepOnce), a list of passes (balls_passes.cpp):
//   symplectic / explicit Euler:  sortByCell -> move bodies, placeObstacles(t) -> collide (forces, integrate)
//   velocity Verlet:              drift -> sortByCell -> move bodies, placeObstacles(t + dt) -> collide (forces, kick)
// Dynamic obstacles (water/body_coupling.h) move by the loads the balls put on them in the step
// before, to where the step's forces act.
// Euler's collide also counts each ball into the next step's grid as it writes it, so the next
// sortByCell starts at the scan. While a force probe is listed, measureLoads follows the collide
// (the loads of the balls on the walls and the obstacles, from the same inputs).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "gl/buffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "gl/window.h"
#include "grid/grid.h"
#include "io/obj.h"
#include "sim/balls/balls_kernels.h"
#include "sim/balls/balls_params.h"
#include "sim/model.h"
#include "sim/particle_memory.h"
#include "sim/water/body_coupling.h"
#include "sim/water/boundary_loads.h"
#include "sim/water/obstacles.h"
#include "sim/water/particle_water.h"

namespace tidepool::balls {

struct Stats {
  double time = 0;         // simulated s
  std::size_t count = 0;   // balls
  double kinetic = 0;      // Σ ½|v|² (per unit mass, m²/s²)
  double potential = 0;    // Σ −g·(x − domain min)
  double meanOverlap = 0;  // over contacts, fraction of r
  double maxOverlap = 0;   // fraction of r
  double maxSpeed = 0;     // m/s
  double contactsPerBall = 0;
  std::size_t nonFinite = 0;  // balls with NaN or infinite state
  std::size_t outside = 0;    // balls outside the walls
  double front = 0;           // surge front: largest x of balls within 2r of the floor, m (NaN: none)
  double backHeight = 0;      // largest z of balls within 2r of the back (x min) wall, m (NaN: none)
};

class Balls final : public sim::Model, public water::ParticleWater {
 public:
  Balls(gl::ShaderLibrary& shaders, const Params& params);  // throws Error (size, memory)

  Params& params() { return m_params; }  // engine edits apply at the next step
  const Params& params() const { return m_params; }
  // sim::Model. A frame is params().substeps steps of params().dt.
  void reset() override;  // particles from the parameters, t = 0
  void step(gl::GpuProfiler& profiler) override;
  double frameSeconds() const override { return m_params.substeps * double(m_params.dt); }
  double time() const override { return m_time; }
  std::size_t count() const override { return m_count; }  // sim::Model and water::ParticleWater
  std::string status() const override;                    // counts and radius (and a refused obstacle edit above them)
  std::vector<sim::StateBuffer> stateBuffers() override;  // positions, velocities (m_count each)

  void stepOnce(gl::GpuProfiler* profiler = nullptr);  // one step of params().dt
  Stats stats();                                       // reduction on the GPU, read back (blocking)

  std::size_t obstacleCount() const { return m_obstacles.particles(); }  // fixed particles, all obstacles
  float radius() const override { return m_radius; }                     // after lattice scaling
  glm::vec3 gravity() const;                                             // current, rotated with the domain
  glm::vec3 wallMin() const override { return m_wallMin; }
  glm::vec3 wallMax() const override { return m_wallMax; }
  float domainRotation() const override;  // radians about x
  // Pressure probes: the balls have no pressure field (throws Error saying so).
  std::vector<double> pressures(const std::vector<glm::vec3>& points) override;
  // The loads of the last step (water/boundary_loads.h), while the setup lists a force probe; the
  // cuda-sample law's walls clamp rather than push: theirs read NaN.
  water::Loads loads() override;
  double mass() const;  // kg per ball: ρ0 times volumePerParticle
  water::Packing packing() const override { return Params::kPacking; }
  const water::Setup& water() const override { return m_params; }
  std::size_t bytesPerBall() const;                                   // GPU memory per ball, grid included
  std::size_t cells() const { return m_grid ? m_grid->cells() : 0; }  // of the neighbour grid
  const grid::UniformGrid* neighbourGrid() const override { return m_grid.get(); }  // water::ParticleWater
  double speedBound() const;  // m/s: faster means more than 2r per step, balls can pass through each other

  const gl::Buffer& positions() const override { return m_pos[m_posIndex]; }   // vec4 (m, w = 1)
  const gl::Buffer& velocities() const override { return m_vel[m_velIndex]; }  // vec4 (m/s, w = foam)
  const water::Obstacles& obstacles() const override { return m_obstacles; }   // as placed at the last step
  const water::Bodies& bodies() const { return m_coupling.bodies(); }          // the dynamic obstacles
  water::Bodies& bodies() { return m_coupling.bodies(); }  // the window's mouse pulls them (Bodies::grab)
  // Why the last edit of the obstacles was refused (e.g. a missing mesh file); empty if it was not.
  // A refused edit leaves that obstacle, and its parameters, as they were.
  const std::string& obstacleError() const { return m_obstacleError; }
  // Tests: upload/download all balls (vec4 position, vec4 velocity) and the order of the last step.
  void upload(const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel);
  std::vector<glm::vec4> downloadPositions() const { return positions().read<glm::vec4>(m_count); }
  std::vector<glm::vec4> downloadVelocities() const { return velocities().read<glm::vec4>(m_count); }
  void trackOrder(bool on) { m_trackOrder = on; }
  // Windows the last collide ran in: 1 while the vec4 arrays fit one storage block (gl/window.h).
  std::size_t collideWindows() const { return m_windows.size(); }
  std::vector<GLuint> lastOrder() const;  // lastOrder()[k] = index before the step of ball k after it

 private:
  // The divergence watch (sim::Model): NaN balls, balls outside the walls, speed above speedBound().
  void checkHealth(const gl::Window& w) override;
  std::vector<gl::Window> healthWindows(std::size_t count) const override;
  std::optional<std::string> unhealthy(const sim::DivergenceWatch::Words& words) override;
  std::string method() const override;
  void resume(const sim::StateStamp& good) override;
  // Checkpoints: the clock, the count and the tap's counters, Verlet's a(x) (obstacle poses and
  // walls follow from the time and the parameters).
  void visitOwnState(sim::StateVisitor& v) override;

  // What a collide pass does after summing the accelerations (collide.comp).
  enum class Collide {
    Integrate,     // explicit or symplectic Euler: the whole step
    VerletKick,    // velocity Verlet's second half: a(x + dt·v½), v += dt/2·a
    VerletForces,  // a(x) alone, for the first drift of a run (or after a restore)
  };

  void allocate(std::size_t count, std::size_t capacity);
  sim::ParticleCost cost() const;  // per ball, for the checks before allocating (sim/particle_memory.h)
  // The passes of stepOnce(), in order.
  void updateWalls();       // the piston's wall positions and velocities at t
  void rebuildObstacles();  // obstacles added, removed or reshaped since the last step
  void emitFromTap();       // appends a layer of balls when the jet has advanced one spacing
  void beginLoads();        // whether this step measures the loads (a force probe or a body is listed)
  void placeObstacles(double time, gl::GpuProfiler* profiler);  // their fixed particles, at `time`
  void drift(gl::GpuProfiler* profiler);                        // Verlet: v½ = v + dt/2·a, x += dt·v½
  void sortByCell(gl::GpuProfiler* profiler);             // grid count + scan, positions and velocities to cell order
  void collide(gl::GpuProfiler* profiler, Collide what);  // contacts, walls, gravity on the sorted balls
  void measureLoads(gl::GpuProfiler* profiler);           // the collide's inputs, its windows: the loads
  // Balls whose vec4 arrays pass one storage block are stepped a window at a time (gl/window.h):
  // each window of the cell-ordered balls with the window of balls in reach of its cells, which a
  // kernel finds from the grid's cellStart right after the scan (planReachWindows) and the collide
  // reads back (reachWindows: two words per window). One window of all balls when they fit.
  struct ReachWindow {
    gl::Window balls, sources;
  };
  void planReachWindows(std::size_t windowSize = 0);  // 0: half a storage block of balls
  std::vector<ReachWindow> reachWindows();
  void ensureGrid();  // the grid of cells 2r for the current radius
  std::vector<gl::ShaderDefine> defines(bool verlet) const;
  // What the kernels share (balls_kernels.h); bindNeighbours() binds the grids' buffers for a
  // window of inputs starting at sources.first.
  WallUniforms wallUniforms() const;
  ContactUniforms contactUniforms() const;
  float foamDecayPerStep() const;
  NeighbourUniforms bindNeighbours(const gl::Window& sources) const;
  // The grid's counts taken by the last Euler collide hold for the positions it wrote: the next
  // sortByCell skips its count pass while the key still matches. Any other write of the positions
  // (an upload, a restore, the tap) changes their buffer's version (gl::Buffer::version()).
  struct CountKey {
    std::uint64_t positions = 0;  // version of the positions' buffer; 0: no counts
    std::size_t count = 0;
    const grid::UniformGrid* grid = nullptr;
    bool operator==(const CountKey&) const = default;
  };
  CountKey countKey() const;  // now

  gl::ShaderLibrary& m_shaders;
  Params m_params;
  float m_radius = 0;
  std::size_t m_count = 0, m_capacity = 0;
  std::size_t m_tapEmitted = 0;
  double m_tapNextLayer = 0;  // simulated time of the next layer
  // State: the current pos/vel are m_pos[m_posIndex] / m_vel[m_velIndex]; sortByCell writes the
  // cell-ordered copies to the other ones, which collide reads.
  // The accelerations (velocity Verlet) and the order of the last step (trackOrder()) are
  // allocated when first needed, for the capacity: Euler without them saves 20 bytes per ball.
  gl::Buffer& accelerations();
  gl::Buffer& permutation();
  gl::Buffer m_pos[2], m_vel[2], m_acc, m_permutation, m_stats;
  int m_posIndex = 0, m_velIndex = 0;
  std::unique_ptr<grid::UniformGrid> m_grid;
  water::Obstacles m_obstacles;
  std::string m_obstacleError;
  glm::vec3 m_wallMin{0.0f}, m_wallMax{1.0f}, m_wallMinVel{0.0f}, m_wallMaxVel{0.0f};
  double m_time = 0;
  bool m_trackOrder = false, m_accValid = false;
  std::vector<ReachWindow> m_windows;  // the last collide's
  // A force probe or a body is listed: the step measures the loads (the walls' only for a probe on a wall:
  // m_loads.walls()); after it, m_loads holds its sums.
  water::BoundaryLoads m_loads;
  bool m_loadsOn = false, m_loadsValid = false;
  water::BodyCoupling m_coupling;  // the dynamic obstacles
  gl::Buffer m_reachBounds;        // uvec2 per window (balls/reach_windows.comp)
  std::size_t m_reachSize = 0;     // balls per window of the plan in m_reachBounds; 0: none planned
  std::size_t m_reachCount = 0;    // balls when it was planned
  CountKey m_countedAhead;
};

}  // namespace tidepool::balls
