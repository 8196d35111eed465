// Renderer of the balls model, "balls" mode: sphere impostors read straight from the model's
// position SSBO (true per-pixel sphere depth), the obstacle in grey — a mesh obstacle as its
// flat-shaded triangles, the others as their fixed particles — and the domain box (walls where
// they are now). The screen-space water mode builds on this (issue 6).
#pragma once

#include "gl/framebuffer.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "render/orbit_camera.h"
#include "render/target.h"
#include "scene/param.h"
#include "sim/balls/balls.h"

namespace tidepool {

struct BallsViewParams {
  glm::vec3 waterColor{0.18f, 0.45f, 0.91f};  // linear RGB (water-webgpu's ball colour)
  glm::vec3 obstacleColor{0.55f, 0.55f, 0.58f};
  glm::vec3 background{0.09f, 0.10f, 0.12f};
  bool showBox = true;
  bool showObstacle = true;
  bool obstacleBalls = false;  // a mesh obstacle's fixed particles too (they lie up to r outside the mesh)
};
void visit(ParamVisitor& v, BallsViewParams& p);

class BallsView {
 public:
  explicit BallsView(gl::ShaderLibrary& shaders);
  BallsViewParams& params() { return m_params; }
  OrbitCamera& camera() { return m_camera; }
  void render(const balls::Balls& model, RenderTarget& target, gl::GpuProfiler& profiler);

 private:
  glm::mat4 domainModel(const balls::Balls& model) const;  // simulation -> world
  void uploadMesh(const balls::Balls& model);              // the obstacle's mesh, when it was rebuilt
  gl::ShaderLibrary& m_shaders;
  BallsViewParams m_params;
  OrbitCamera m_camera;
  gl::VertexArray m_vao = gl::VertexArray::create();
  gl::Buffer m_meshVertices;  // vec4 per triangle corner, obstacle frame
  GLsizei m_meshCorners = 0;
  const io::TriangleMesh* m_meshSource = nullptr;  // the model's obstacleMesh() and obstacleVersion() uploaded
  unsigned m_meshVersion = ~0u;
};

}  // namespace tidepool
