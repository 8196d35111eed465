// Deferred renderer of the balls model, after water-webgpu's sphere renderer without
// its shortcuts. It only reads the model's SSBOs. One frame:
//   1. scene:     each obstacle as a mesh placed by its pose (a mesh obstacle's own triangles,
//                 flat-shaded; any other shape the surface of its balls), their balls too on
//                 request, into the target (raster; skipped when there is no obstacle to draw)
//   2. gbuffer:   ray-traced sphere impostors -> normal xy, view depth, foam, exact depth
//   3. thickness: the same spheres, additive into B, depth-tested against the scene
//                 (water mode, and the thickness debug view)
//                 2 and 3 run on the raster units (quads, write masks, blending) or, by default,
//                 as compute kernels with atomics (src/render/balls_splat.h), same G-buffer
//   4. blur:      water mode only, depth-aware separable Gaussian (row and column compute
//                 passes, two rounds by default)
//      caustics:  water mode under the environment only: the sunlight the water's surface
//                 sends onto the floor (src/render/water_caustics.h), which the compose reads
//   5. compose:   a compute pass: the scene (or the background when step 1 was skipped) and the
//                 domain box's lines, and over them, where the balls are nearer, their shading
//                 (balls or water) or a debug view, into the target's colour. The target's depth
//                 stays the obstacles' (stale when step 1 was skipped): nothing draws after it
//                 but the grid cells debug overlay (6).
//   6. cells:     on request, the model's non-empty grid cells as wire cubes over the picture
//                 (src/render/balls_grid_cells.h; render(model) only: a BallsScene has no grid)
#pragma once

#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "render/balls_compose.h"
#include "render/balls_gbuffer.h"
#include "render/balls_grid_cells.h"
#include "render/obstacle_mesh.h"
#include "render/orbit_camera.h"
#include "render/target.h"
#include "render/water_blur.h"
#include "render/water_caustics.h"
#include "sim/water/particle_water.h"

namespace tidepool {

// The scene pass's rectangle: the window pixels the scene's obstacle meshes can cover, a pixel
// wider on each side (the projected corners of each mesh's bounds), clamped to the window; empty
// when there is nothing to draw; the whole window when the obstacles' balls are drawn, a mesh's
// bounds are unknown, or a mesh reaches the near plane.
WindowRect meshesWindowRect(const BallsScene& scene, const BallsCamera& camera);

class BallsView {
 public:
  explicit BallsView(gl::ShaderLibrary& shaders);
  BallsViewParams& params() { return m_params; }
  OrbitCamera& camera() { return m_camera; }
  // The model's particles (balls or fluid), obstacles and walls from the orbit camera (near/far fitted to the domain).
  void render(const water::ParticleWater& model, RenderTarget& target, gl::GpuProfiler& profiler);
  // Any spheres from any camera (tests, benchmarks); camera size = target size.
  void render(const BallsScene& scene, const BallsCamera& camera, RenderTarget& target, gl::GpuProfiler& profiler);

  // Read-only, for tests and debugging: the last frame's G-buffer and the surface compose read
  // (the blurred one in water mode).
  const BallsGBuffer& gbuffer() const { return m_gbuffer; }
  const gl::Texture2D& composedSurface() const;
  const ObstacleMeshes& obstacleMeshes() const { return m_meshes; }
  const BallsGridCells& gridCells() const { return m_cells; }  // the last overlay's compacted cells

 private:
  // Clears the target's depth and draws the obstacles inside the returned rectangle only (the
  // whole window for the fragment raster, whose passes test against the depth attachment).
  WindowRect drawScene(const BallsScene& scene, const BallsCamera& camera, RenderTarget& target);
  BallsScene sceneOf(const water::ParticleWater& model);  // builds the meshes of new or reshaped obstacles
  gl::ShaderLibrary& m_shaders;
  BallsViewParams m_params;
  OrbitCamera m_camera;
  BallsGBuffer m_gbuffer;
  WaterBlur m_blur;
  WaterCaustics m_caustics;
  ObstacleMeshes m_meshes;
  BallsCompose m_compose;
  BallsGridCells m_cells;
  bool m_blurred = false;  // the last frame composed the blurred surface
  gl::VertexArray m_vao = gl::VertexArray::create();
};

}  // namespace tidepool
