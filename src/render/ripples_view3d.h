// The 3D view of the ripples model: a displaced surface mesh read from the state buffer,
// refraction to a tiled floor lit by caustics, Schlick Fresnel toward the sky, a sun highlight,
// and glass tank walls clipped at the local water height. Orbit camera.
#pragma once

#include "gl/framebuffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "render/orbit_camera.h"
#include "render/target.h"
#include "scene/param.h"
#include "sim/ripples/ripples.h"

namespace tidepool {

struct RipplesView3DParams {
  float exaggeration = 4.0f;                  // heights and slopes (1 = physical)
  float waterLevel = 0.3f;                    // rest surface above the floor, tank widths
  int meshCells = 256;                        // surface quads along x
  int lightGrid = 512;                        // caustic light points along x
  int causticsSize = 256;                     // caustics texels along x
  glm::vec3 sunDir{0.25f, 0.35f, 1.0f};       // towards the sun
  float ambient = 0.3f;                       // floor light without sun
  glm::vec3 waterColor{0.03f, 0.17f, 0.24f};  // linear RGB, what deep water tends to
  float viewDistance = 0.5f;                  // tank widths of water that absorb ~63%
  float tileRepeat = 4.0f;                    // floor tiles across the tank
  bool caustics = true;
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
  void setCommon(gl::Program& p, const ripples::Ripples& model) const;
  void renderCaustics(const ripples::Ripples& model);

  gl::ShaderLibrary& m_shaders;
  RipplesView3DParams m_params;
  OrbitCamera m_camera;
  gl::Texture2D m_floor, m_caustics;
  gl::Framebuffer m_causticsFbo;
  gl::VertexArray m_vao = gl::VertexArray::create();
};

}  // namespace tidepool
