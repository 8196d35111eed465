// The balls' G-buffer and the sphere passes that fill it (after water-webgpu's deferred sphere
// renderer, with float depth instead of its 8-bit one):
//   surface  RGBA32F  RG = view-space normal xy of the nearest ball (its billboard-local position),
//                     B = water thickness along the eye ray (m, additive), A = view depth (m, 0 = empty);
//                     32-bit because the water's normals are differences of neighbouring depths
//                     (a half float steps by 1 mm at 1.5 m, about a pixel's footprint there)
//   foam     R16F     the nearest ball's foam
//   depth    the nearest ball's window depth (exact, 1 = none; the compose pass writes it):
//            DEPTH32F from the fragment raster, R32F from the compute one
// Fragment raster: pass 1 (impostors) writes R, G, A and foam with its own depth test; pass 2
// (thickness) writes B only, blending ONE + ONE and depth-testing against the scene's depth
// without writing it. Compute raster (src/render/balls_splat.h): the same values from atomics.
#pragma once

#include <vector>

#include "gl/framebuffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "render/balls_splat.h"
#include "render/balls_view_params.h"

namespace tidepool {

class BallsGBuffer {
 public:
  explicit BallsGBuffer(gl::ShaderLibrary& shaders);
  void resize(int width, int height);  // no-op when unchanged
  // Clears, then draws the impostor pass and, when `thickness`, the thickness pass against
  // `scene` (the opaque meshes' DEPTH32F, same size, and where it holds them; no texture: nothing
  // opaque). The fragment raster tests the whole texture: its rectangle must be the window.
  void draw(const SphereBatch& balls, const BallsCamera& camera, const SceneDepth& scene, bool thickness,
            BallsRaster raster, gl::GpuProfiler& profiler);

  const gl::Texture2D& surface() const { return m_surface; }
  const gl::Texture2D& foam() const { return m_foam; }
  const gl::Texture2D& depth() const { return m_compute ? m_depthImage : m_depth; }  // the last frame's
  std::vector<float> readDepth() const;  // depth(), row by row from the bottom (tests)

 private:
  void drawSpheres(gl::Program& program, const SphereBatch& balls, const BallsCamera& camera);
  void drawFragments(const SphereBatch& balls, const BallsCamera& camera, const gl::Texture2D* sceneDepth,
                     bool thickness, gl::GpuProfiler& profiler);
  gl::ShaderLibrary& m_shaders;
  BallsSplat m_splat;
  gl::Texture2D m_surface, m_foam, m_depth, m_depthImage;  // m_depthImage: R32F, the compute raster's
  bool m_compute = false;                                  // the last frame used the compute raster
  gl::Framebuffer m_impostorFbo, m_thicknessFbo;
  GLuint m_thicknessDepthId = 0;  // the scene depth m_thicknessFbo was built with (0: none)
  gl::VertexArray m_vao = gl::VertexArray::create();
};

}  // namespace tidepool
