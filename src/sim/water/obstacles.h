// The obstacles of the water (balls and fluid): each one's fixed particles are built once in its own frame
// (shape, size, mesh; water_init.h) and placed every step by its rigid pose (centre, orientation,
// spin, path; obstacle_pose.h), evaluated from the time, or a dynamic one's (bodies.h). On the GPU:
//   bodies    all obstacles' particles in their own frames, one after the other, w = obstacle index
//   place     obstacle_place.comp: world = centre_k + R_k·body for particle of obstacle k
//   grid      the placed particles of every obstacle in one grid of cell 2r over their reach,
//             read by the kernels through buffer textures (common/obstacle_grid.glsl)
//   poses     a uniform block: each obstacle's pose and velocity, so a contact sees the moving
//             particle's velocity v_k + ω_k × (x − c_k) (obstacle_poses.glsl)
// Placing and the grid run only when a pose changed (animated obstacles: every step). Edits while
// running rebuild only the obstacles whose shape changed; moving or turning one rebuilds nothing.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/obstacle_bindings.glsl"
#include "gl/buffer.h"
#include "gl/gpu_profiler.h"
#include "gl/kernel.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "grid/grid.h"
#include "io/obj.h"
#include "sim/water/obstacle_pose.h"
#include "sim/water/setup.h"

namespace tidepool::water {

class Obstacle;  // water_init.h

// One obstacle's particles in its own frame, as built.
struct ObstacleBody {
  ObstacleParams built;                          // the parameters it was built from
  std::vector<glm::vec4> particles;              // own frame, m; w = 0
  std::shared_ptr<const io::TriangleMesh> mesh;  // a mesh shape's triangles, own frame; else null
  std::shared_ptr<const Obstacle> shape;         // inside tests (the water fill)
  std::size_t first = 0;                         // its first particle in the bodies buffer
  float reach = 0;                               // largest |particle| + r, m
  unsigned id = 0;                               // new with every build: renderers cache by it
};

// The uniforms of common/obstacle_grid.glsl: the obstacles' grid and the sampler units of their
// particles and cell starts. Kernels built without HAS_OBSTACLE read none of them.
struct ObstacleUniforms {
  glm::vec3 origin{0.0f};  // world, m
  float invCell = 0;       // 1/m
  glm::uvec3 dims{0u};
  GLint particles = OBSTACLE_POS_UNIT, cellStarts = OBSTACLE_CELL_START_UNIT;
  static constexpr auto fields() {
    using U = ObstacleUniforms;
    return std::tuple{gl::field("uObstacleOrigin", &U::origin), gl::field("uObstacleInvCell", &U::invCell),
                      gl::field("uObstacleDims", &U::dims), gl::field("obstaclePos", &U::particles),
                      gl::field("obstacleCellStart", &U::cellStarts)};
  }
};

class Obstacles {
 public:
  explicit Obstacles(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}

  // Every obstacle built anew (reset). Throws Error naming it ("obstacles[1]: mesh 'x' not found
  // ..."), and then keeps the obstacles it had.
  void build(const std::vector<ObstacleParams>& params, float radius);
  // Edits while running: added, removed and reshaped obstacles are (re)built. An edit that fails
  // (a missing or open mesh) is undone in `params`. Returns whether anything was rebuilt or
  // refused; `error` then says what was refused (empty: nothing).
  bool update(std::vector<ObstacleParams>& params, float radius, std::string& error);
  // The obstacles at `poses` (posesAt(params, time), or a model's bodies for the dynamic ones):
  // when one changed (or the bodies did), the particles' world positions and the grid (bounded
  // by the domain, where particles can be; all of it while a dynamic obstacle is listed).
  void place(const std::vector<ObstacleParams>& params, std::vector<ObstaclePose> poses, glm::vec3 domainMin,
             glm::vec3 domainMax, gl::GpuProfiler* profiler = nullptr);
  bool occupied(glm::vec3 world) const;  // inside an obstacle at its placed pose
  // What common/obstacle_grid.glsl reads: its uniforms (defaults when none is active()), and
  // bind() binds its pose block and buffer textures (when active()).
  ObstacleUniforms uniforms() const;
  void bind() const;

  // Rest volumes of every obstacle particle (the fluid's boundary particles): `volumes` gives them
  // for one body at each (re)build; they are placed and sorted with the particles, and
  // refreshVolumes() recomputes them (the kernel changed). Unset: no volumes kept.
  using VolumeFn = std::function<std::vector<float>(const ObstacleBody&)>;
  void setVolumes(VolumeFn volumes) { m_volumeFn = std::move(volumes); }
  void refreshVolumes();
  const gl::Buffer* volumes() const { return m_volumeFn ? &m_volumeSorted : nullptr; }    // vec4 (x), grid order
  const gl::Buffer* bodyVolumes() const { return m_volumeFn ? &m_volumeBody : nullptr; }  // vec4 (x), as bodies()
  float cellSize() const { return 2.0f * m_radius; }                                      // of the obstacle grid
  float radius() const { return m_radius; }                                               // r they were built for

  bool active() const { return m_grid != nullptr; }  // any particles: the kernels' HAS_OBSTACLE
  std::size_t size() const { return m_bodies.size(); }
  std::size_t particles() const { return m_particles; }
  const ObstacleBody& body(std::size_t k) const { return m_bodies[k]; }
  const ObstaclePose& pose(std::size_t k) const { return m_poses[k]; }  // as placed
  const gl::Buffer& bodies() const { return m_body; }                   // vec4 own frame, w = obstacle index
  const gl::Buffer& placed() const { return m_world; }                  // vec4 world, same order as bodies()

 private:
  ObstacleBody buildOne(const ObstacleParams& o, float radius);
  void upload();  // bodies -> GPU, after any rebuild

  gl::ShaderLibrary& m_shaders;
  std::vector<ObstacleBody> m_bodies;
  std::vector<ObstaclePose> m_poses;
  std::size_t m_particles = 0;
  float m_radius = 0;
  unsigned m_nextId = 1;
  bool m_dirty = true;  // bodies changed since the last place()
  gl::Buffer m_body, m_world, m_sorted, m_poseBlock;
  mutable gl::BufferTexture m_textures[3];  // positions, cell starts, volumes (bind())
  VolumeFn m_volumeFn;
  gl::Buffer m_volumeBody, m_volumeSorted;  // with m_volumeFn: vec4 (x = m³) in body and grid order
  std::unique_ptr<grid::UniformGrid> m_grid;
};

}  // namespace tidepool::water
