#include "render/balls_compose.h"

#include "render/balls_bindings.glsl"

namespace tidepool {

void BallsCompose::draw(const gl::Texture2D& surface, const BallsGBuffer& gbuffer, const BallsViewParams& look,
                        const BallsCamera& camera, float radius, RenderTarget& target) {
  target.bind();
  m_vao.bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  // Water: out = colour + transmit * scene (per channel, the second fragment output).
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_SRC1_COLOR);
  gl::Program& program = m_shaders.program({"render/fullscreen.vert", "render/balls_compose.frag"});
  program.use();
  surface.bind(BALLS_VIEW_GBUFFER);
  gbuffer.foam().bind(BALLS_VIEW_FOAM);
  gbuffer.depth().bind(BALLS_VIEW_DEPTH);
  program.set("uInvView", glm::inverse(camera.view));
  program.set("uInvFocal", glm::vec2(1.0f / camera.proj[0][0], 1.0f / camera.proj[1][1]));
  program.set("uViewport", glm::vec2(float(camera.width), float(camera.height)));
  program.set("uDepthRange", glm::vec2(camera.near, camera.far));
  program.set("uMode", int(look.mode));
  program.set("uDebug", int(look.debug));
  program.set("uWaterColor", look.waterColor);
  program.set("uAbsorption", look.absorption);
  program.set("uBackground", look.background);
  program.set("uF0", look.fresnelF0);
  program.set("uSpecular", look.specular);
  program.set("uFoamOn", look.foam ? 1 : 0);
  program.set("uThicknessScale", 40.0f * radius);  // ~20 balls deep shows white
  program.set("uDepthStep", look.depthThreshold * radius);
  program.set("uLightView", camera.towardsLight(look.lightDirection));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Mesa rejects draws into several colour buffers while a dual-source factor is set, even with
  // blending off: leave the default factors behind.
  glBlendFunc(GL_ONE, GL_ZERO);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
}

}  // namespace tidepool
