// Water as N equal balls colliding (DEM), after water-webgpu: a uniform grid finds every pair
// within 2r (27 cells), one of three contact laws acts on it, one of three integrators advances
// it; box walls (one may be a piston; gravity rotates with the domain) and obstacles of fixed
// particles (shapes or voxelised triangle meshes, each moving rigidly: obstacles.h) complete the
// scene. The model owns its buffers and passes; renderers read positions() / velocities() (foam
// in velocity w) and obstacles() (bodies, poses, meshes).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "grid/grid.h"
#include "io/obj.h"
#include "sim/balls/balls_params.h"
#include "sim/balls/obstacles.h"
#include "sim/divergence.h"

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

class Balls {
 public:
  Balls(gl::ShaderLibrary& shaders, const Params& params);  // throws Error (size, memory)

  Params& params() { return m_params; }  // engine edits apply at the next step
  const Params& params() const { return m_params; }
  void reset();                          // particles from the parameters, t = 0
  void step(gl::GpuProfiler& profiler);  // one frame: params().substeps steps
  void stepOnce(gl::GpuProfiler* profiler = nullptr);
  Stats stats();  // reduction on the GPU, read back (blocking)

  std::size_t count() const { return m_count; }
  std::size_t obstacleCount() const { return m_obstacles.particles(); }  // fixed particles, all obstacles
  float radius() const { return m_radius; }                              // after lattice scaling
  glm::vec3 gravity() const;                                             // current, rotated with the domain
  glm::vec3 wallMin() const { return m_wallMin; }
  glm::vec3 wallMax() const { return m_wallMax; }
  float domainRotation() const;  // radians about x
  double time() const { return m_time; }
  std::size_t bytesPerBall() const;                                   // GPU memory per ball, grid included
  std::size_t cells() const { return m_grid ? m_grid->cells() : 0; }  // of the neighbour grid

  // Divergence watch (sim/divergence.h): non-blocking checks every few frames (step()).
  std::optional<DivergenceReport> divergence() const { return m_divergence; }
  bool recover();             // back to the last good state with half the time step; false if none
  void flushChecks();         // waits for the check in flight
  double speedBound() const;  // m/s: faster means more than 2r per step, balls can pass through each other

  const gl::Buffer& positions() const { return m_pos[m_posIndex]; }   // vec4 (m, w = 1)
  const gl::Buffer& velocities() const { return m_vel[m_velIndex]; }  // vec4 (m/s, w = foam)
  const Obstacles& obstacles() const { return m_obstacles; }          // as placed at the last step
  // Why the last edit of the obstacles was refused (e.g. a missing mesh file); empty if it was not.
  // A refused edit leaves that obstacle, and its parameters, as they were.
  const std::string& obstacleError() const { return m_obstacleError; }
  // Tests: upload/download all balls (vec4 position, vec4 velocity) and the order of the last step.
  void upload(const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel);
  std::vector<glm::vec4> downloadPositions() const { return positions().read<glm::vec4>(m_count); }
  std::vector<glm::vec4> downloadVelocities() const { return velocities().read<glm::vec4>(m_count); }
  void trackOrder(bool on) { m_trackOrder = on; }
  std::vector<GLuint> lastOrder() const;  // lastOrder()[k] = index before the step of ball k after it

 private:
  void allocate(std::size_t count, std::size_t capacity);
  void emitFromTap();  // appends a layer of balls when the jet has advanced one spacing
  void watch();        // polls the check in flight, starts the next one
  void judge(const GLuint values[4], double time);
  CheckCycle::Judge judgeFn();  // judge() for the watch's CheckCycle
  void updateWalls();
  std::vector<gl::ShaderDefine> defines(bool verlet) const;
  void bindCommon(gl::Program& p) const;
  // Grid build + reorder, then the collide pass (Verlet: force and kick of `kick`·dt·a).
  void gridAndCollide(gl::GpuProfiler* profiler, bool verlet, float kick);

  gl::ShaderLibrary& m_shaders;
  gl::BufferOps m_ops;  // checkpoint copies of the divergence watch
  Params m_params;
  float m_radius = 0;
  std::size_t m_count = 0, m_capacity = 0;
  std::size_t m_tapEmitted = 0;
  double m_tapNextLayer = 0;  // simulated time of the next layer
  gl::Buffer m_pos[2], m_vel[2], m_acc, m_permutation, m_stats;
  int m_posIndex = 0, m_velIndex = 0;
  std::unique_ptr<grid::UniformGrid> m_grid;
  Obstacles m_obstacles;
  std::string m_obstacleError;
  glm::vec3 m_wallMin{0.0f}, m_wallMax{1.0f}, m_wallMinVel{0.0f}, m_wallMaxVel{0.0f};
  double m_time = 0;
  bool m_trackOrder = false, m_accValid = false;
  // Divergence watch: reduced values, the state copied at the check, the last state judged good.
  gl::Buffer m_health, m_pendingPos, m_pendingVel, m_goodPos, m_goodVel;
  CheckCycle m_checks{8};  // a check every 8 frames
  double m_goodTime = 0;
  std::size_t m_pendingCount = 0, m_goodCount = 0;
  bool m_hasGood = false;
  std::optional<DivergenceReport> m_divergence;
};

}  // namespace tidepool::balls
