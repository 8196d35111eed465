// Renderer of the ripples model: the 2D refraction view (top-down, water-simulation-gpu's look).
// Reads the model's state buffer directly; writes only the render target's colour. A compute
// pass shades every pixel (shaders/render/ripples/view_2d.comp); the same shading as one full-screen
// triangle (render/ripples/view_2d.frag) is kept as the "raster" renderer, to check the compute one against.
#pragma once

#include <array>

#include "base/param.h"
#include "gl/framebuffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "render/target.h"
#include "sim/ripples/ripples.h"

namespace tidepool {

// How the ripples views draw: compute passes (raster units are scarce on compute-first GPUs such
// as the H100), or the raster pipeline (the original shaders), which the tests and `bench ripples`
// hold the compute passes against. Not a scene parameter.
enum class RipplesRenderer { Compute, Raster };
inline constexpr std::array<const char*, 2> kRipplesRendererNames = {"compute", "raster"};

struct RipplesViewParams {
  float slopeScale = 10.0f;                             // exaggerates slopes (1 = physical)
  float floorDepth = 0.25f;                             // grid widths below the surface
  float eta = 0.9f;                                     // refraction ratio (seed: 0.9)
  glm::vec3 waterColor{0.10f, 0.16f, 0.45f};            // linear RGB
  float viewDistance = 0.6f;                            // grid widths of water that look opaque
  glm::vec3 lightDir{-1.0f, -1.0f, -4.0f};              // seed's light
  float tileRepeat = 4.0f;                              // floor texture repeats across the grid
  RipplesRenderer renderer = RipplesRenderer::Compute;  // not read from scenes (see RipplesRenderer)
};
void visit(ParamVisitor& v, RipplesViewParams& p);

class RipplesView {
 public:
  explicit RipplesView(gl::ShaderLibrary& shaders);  // loads assets/textures/tiles.png
  RipplesViewParams& params() { return m_params; }
  void render(const ripples::Ripples& model, RenderTarget& target, gl::GpuProfiler& profiler);
  // Screen pixel -> grid coordinates in [0,1]^2 (the same "cover" mapping the view draws with).
  glm::vec2 gridUv(glm::vec2 pixel, glm::ivec2 viewport, glm::ivec2 gridSize) const;

 private:
  void coverMapping(glm::ivec2 viewport, glm::ivec2 gridSize, glm::vec2& scale, glm::vec2& offset) const;
  void setUniforms(gl::Program& p, const ripples::Ripples& model, glm::ivec2 viewport) const;
  gl::ShaderLibrary& m_shaders;
  RipplesViewParams m_params;
  gl::Texture2D m_floor;
  gl::VertexArray m_vao = gl::VertexArray::create();
};

}  // namespace tidepool
