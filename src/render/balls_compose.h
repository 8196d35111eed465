// The full-screen compose pass of the balls renderer: shades the G-buffer into the scene target
// (balls: diffuse + ambient; water: Fresnel, sky, specular, Beer–Lambert absorption, foam, and
// the scene behind showing through by dual-source blending) and writes the balls' depth so they
// and the meshes occlude each other. Also draws the debug views of the G-buffer.
#pragma once

#include "gl/framebuffer.h"
#include "gl/shader_library.h"
#include "render/balls_gbuffer.h"
#include "render/target.h"

namespace tidepool {

class BallsCompose {
 public:
  explicit BallsCompose(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}
  // surface: the G-buffer's surface texture, blurred or not; radius: the balls' (m).
  void draw(const gl::Texture2D& surface, const BallsGBuffer& gbuffer, const BallsViewParams& look,
            const BallsCamera& camera, float radius, RenderTarget& target);

 private:
  gl::ShaderLibrary& m_shaders;
  gl::VertexArray m_vao = gl::VertexArray::create();
};

}  // namespace tidepool
