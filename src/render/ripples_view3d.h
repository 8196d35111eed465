// The 3D view of the ripples model: the heightfield surface read from the state buffer,
// refraction to a tiled floor lit by caustics, Schlick Fresnel toward the sky, a sun highlight,
// and glass tank walls clipped at the local water height. Orbit camera.
//
// Default (compute) renderer, all compute passes:
//   caustics  light points -> atomic counts per floor texel -> light texture (ripples_caustics.cpp)
//   tiles     min/max height per 8x8 dual cells and over the grid (render/ripples/tiles.comp)
//   ray cast  per pixel: walls, ball, heightfield surface, shading (render/ripples/raycast.comp)
// Raster renderer (the original, kept as the reference the tests compare against): caustics as
// additive GL_POINTs, walls, ball and a displaced surface mesh drawn with the depth test
// (ripples_view3d_raster.cpp). Both shade with the same shaders/render/ripples/shading.glsl.
#pragma once

#include "base/param.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/framebuffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "render/orbit_camera.h"
#include "render/ripples_view.h"
#include "render/target.h"
#include "sim/ripples/ripples.h"

namespace tidepool {

struct RipplesView3DParams {
  float exaggeration = 4.0f;                  // heights and slopes (1 = physical)
  float waterLevel = 0.3f;                    // rest surface above the floor, tank widths
  int meshCells = 256;                        // surface quads along x (raster renderer)
  int lightGrid = 512;                        // caustic light points along x
  int causticsSize = 256;                     // caustics texels along x
  glm::vec3 sunDir{0.25f, 0.35f, 1.0f};       // towards the sun
  float ambient = 0.3f;                       // floor light without sun
  glm::vec3 waterColor{0.03f, 0.17f, 0.24f};  // linear RGB, what deep water tends to
  float viewDistance = 0.5f;                  // tank widths of water that absorb ~63%
  float tileRepeat = 4.0f;                    // floor tiles across the tank
  bool caustics = true;
  RipplesRenderer renderer = RipplesRenderer::Compute;  // not read from scenes (see RipplesRenderer)
};
void visit(ParamVisitor& v, RipplesView3DParams& p);

class RipplesView3D {
 public:
  explicit RipplesView3D(gl::ShaderLibrary& shaders);  // loads assets/textures/tiles.png
  RipplesView3DParams& params() { return m_params; }
  OrbitCamera& camera() { return m_camera; }
  const gl::Texture2D& caustics() const { return m_caustics; }  // floor light of the last frame (R16F)
  void render(const ripples::Ripples& model, RenderTarget& target, gl::GpuProfiler& profiler);
  // Grid uv in [0,1]^2 where the pixel's view ray meets the rest water level (false: misses the tank).
  bool pick(glm::vec2 pixel, glm::ivec2 viewport, glm::ivec2 gridSize, glm::vec2& uv) const;

 private:
  void setCommon(gl::Program& p, const ripples::Ripples& model) const;   // tank, surface, sun
  void setShading(gl::Program& p, const ripples::Ripples& model) const;  // + eye, floor, water
  glm::vec4 ball(const ripples::Ripples& model) const;                   // world centre, radius; 0: none
  void renderCaustics(const ripples::Ripples& model);                    // ripples_caustics.cpp
  void splatCaustics(const ripples::Ripples& model, glm::ivec2 grid, float weight);
  void drawCaustics(const ripples::Ripples& model, glm::ivec2 grid, float weight);
  void rayCast(const ripples::Ripples& model, RenderTarget& target, const glm::mat4& viewProj);
  void rasterise(const ripples::Ripples& model, RenderTarget& target, const glm::mat4& viewProj);  // _raster.cpp

  gl::ShaderLibrary& m_shaders;
  gl::BufferOps m_ops;
  RipplesView3DParams m_params;
  OrbitCamera m_camera;
  gl::Texture2D m_floor, m_caustics;
  gl::Framebuffer m_causticsFbo;  // raster caustics
  gl::Buffer m_light;             // compute caustics: light points per texel
  gl::Buffer m_tiles, m_range;    // ray caster: height bounds per tile and over the grid
  gl::VertexArray m_vao = gl::VertexArray::create();
};

}  // namespace tidepool
