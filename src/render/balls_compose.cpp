#include "render/balls_compose.h"

#include "render/balls/bindings.glsl"

namespace tidepool {

namespace {

// Clips the segment a-b (clip space) to the half space f >= 0; false when nothing is left.
template <typename Plane>
bool clipTo(glm::vec4& a, glm::vec4& b, Plane f) {
  const float fa = f(a), fb = f(b);
  if (fa < 0.0f && fb < 0.0f) return false;
  if (fa < 0.0f) a = glm::mix(a, b, fa / (fa - fb));
  if (fb < 0.0f) b = glm::mix(b, a, fb / (fb - fa));
  return true;
}

}  // namespace

std::vector<glm::vec4> boxEdgesInWindow(glm::vec3 lo, glm::vec3 hi, const glm::mat4& clipFromBox, glm::ivec2 size) {
  // Corner k has x from bit 0, y from bit 1, z from bit 2; edges join corners one bit apart.
  std::vector<glm::vec4> out;
  for (int k = 0; k < 8; ++k)
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (k & bit) continue;
      const auto corner = [&](int c) {
        return clipFromBox * glm::vec4(glm::mix(lo, hi, glm::vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1)), 1.0f);
      };
      glm::vec4 a = corner(k), b = corner(k | bit);
      if (!clipTo(a, b, [](glm::vec4 p) { return p.w + p.z; }) || !clipTo(a, b, [](glm::vec4 p) { return p.w - p.z; }))
        continue;
      for (const glm::vec4& p : {a, b}) {
        const glm::vec3 ndc = glm::vec3(p) / p.w;
        out.emplace_back((0.5f * ndc.x + 0.5f) * float(size.x), (0.5f * ndc.y + 0.5f) * float(size.y),
                         0.5f * ndc.z + 0.5f, 1.0f);
      }
    }
  return out;
}

void BallsCompose::draw(const gl::Texture2D* surface, const BallsGBuffer& gbuffer, const BallsViewParams& look,
                        const BallsCamera& camera, float radius, const ComposeScene& scene, RenderTarget& target) {
  gl::Program& program = m_shaders.program({"render/balls/compose.comp"});
  program.use();
  if (surface) {
    surface->bind(BALLS_VIEW_GBUFFER);
    gbuffer.foam().bind(BALLS_VIEW_FOAM);
    gbuffer.depth().bind(BALLS_VIEW_DEPTH);
  }
  if (scene.drawn) target.depth().bind(BALLS_VIEW_SCENE_DEPTH);
  target.color().bindImage(BALLS_VIEW_COMPOSE_TARGET, GL_READ_WRITE, GL_RGBA8);
  const std::vector<glm::vec4> lines =
      scene.box ? boxEdgesInWindow(scene.boxMin, scene.boxMax, camera.proj * camera.view * scene.boxModel,
                                   {camera.width, camera.height})
                : std::vector<glm::vec4>{};
  if (!lines.empty()) glUniform4fv(program.uniform("uLines"), GLsizei(lines.size()), &lines[0].x);
  program.set("uLineCount", int(lines.size() / 2));
  program.set("uLineColor", glm::vec3(0.7f, 0.72f, 0.75f));
  program.set("uSize", glm::ivec2(camera.width, camera.height));
  program.set("uBalls", surface ? 1 : 0);
  program.set("uScene", scene.drawn ? 1 : 0);
  program.set("uSceneMin", scene.rect.min);
  program.set("uSceneMax", scene.rect.max);
  program.set("uInvView", glm::inverse(camera.view));
  program.set("uInvFocal", glm::vec2(1.0f / camera.proj[0][0], 1.0f / camera.proj[1][1]));
  program.set("uOrtho", camera.isOrthographic() ? 1 : 0);
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
  program.dispatch({unsigned(camera.width + 15) / 16, unsigned(camera.height + 15) / 16, 1u});
  // Readers of the image: read-backs, the window's blit, texture fetches; the next frame's
  // raster clear and draws.
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace tidepool
