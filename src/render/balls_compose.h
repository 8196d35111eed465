// The compose pass of the balls renderer, a compute kernel (shaders/render/balls/compose.comp):
// shades the G-buffer over the scene in the target (balls: diffuse + ambient; water: Fresnel,
// sky, specular, Beer–Lambert absorption, foam, and the scene behind showing through), where the
// balls are nearer than the scene's depth; draws the domain box's lines into the scene on the
// way; also draws the debug views of the G-buffer. When the raster drew no obstacle this frame
// the scene is the background: the target is then written without being cleared or read.
#pragma once

#include <vector>

#include "gl/shader_library.h"
#include "render/balls_gbuffer.h"
#include "render/target.h"

namespace tidepool {

// What the compose draws over: the target's colour and depth from the raster, or nothing.
struct ComposeScene {
  bool drawn = false;  // the raster drew obstacles into the target this frame
  bool box = false;    // draw the domain box's edges
  glm::vec3 boxMin{0.0f}, boxMax{1.0f};
  glm::mat4 boxModel{1.0f};
  WindowRect rect;  // where the raster drew them (drawn): the scene is at the far plane elsewhere
  const gl::Texture2D* caustics = nullptr;  // the sunlight on the box's floor (WaterCaustics); null: 1
};

class BallsCompose {
 public:
  explicit BallsCompose(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}
  // surface: the G-buffer's surface texture, blurred or not, or null when there are no balls
  // (the G-buffer is then not read); radius: the balls' (m).
  void draw(const gl::Texture2D* surface, const BallsGBuffer& gbuffer, const BallsViewParams& look,
            const BallsCamera& camera, float radius, const ComposeScene& scene, RenderTarget& target);

 private:
  gl::ShaderLibrary& m_shaders;
};

// The box's 12 edges clipped to the near and far planes, in window coordinates (x, y in px,
// z the window depth in [0, 1], w = 1), two points per edge left; clipFromBox maps the box's
// frame to clip space.
std::vector<glm::vec4> boxEdgesInWindow(glm::vec3 lo, glm::vec3 hi, const glm::mat4& clipFromBox, glm::ivec2 size);

}  // namespace tidepool
