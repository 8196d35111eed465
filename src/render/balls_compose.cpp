#include "render/balls_compose.h"

#include <algorithm>
#include <array>

#include "gl/kernel.h"
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

constexpr std::size_t kMaxLinePoints = 24;  // uLines[24]: a box's 12 edges

struct ComposeUniforms {  // see render/balls/compose.comp
  glm::ivec2 size{0};
  GLint balls = 0, scene = 0;
  glm::ivec2 sceneMin{0}, sceneMax{0};
  std::array<glm::vec4, kMaxLinePoints> lines{};
  GLint lineCount = 0;
  glm::vec3 lineColor{0.7f, 0.72f, 0.75f};
  glm::mat4 invView{1.0f};
  glm::vec2 invFocal{1.0f};
  GLint ortho = 0;
  glm::vec2 depthRange{0.0f};
  GLint mode = 0, debug = 0;
  glm::vec3 waterColor{0.0f};
  float absorption = 0.0f;
  glm::vec3 background{0.0f};
  float f0 = 0.0f, specular = 0.0f;
  GLint foamOn = 0;
  float thicknessScale = 0.0f;
  glm::vec3 lightView{0.0f};
  float depthStep = 0.0f;
  float ior = 1.0f, scattering = 1.0f, spray = 0.0f, radius = 0.0f;
  GLint environment = 0;
  glm::vec3 skyColor{0.0f}, sunWorld{0.0f, 0.0f, 1.0f};
  glm::mat4 boxFromWorld{1.0f};
  glm::vec3 floorMin{0.0f}, floorMax{1.0f};
  float tileSize = 1.0f, pixelSpread = 0.0f, glass = 0.0f;
  GLint caustics = 0, causticsLight = BALLS_VIEW_CAUSTICS;                               // on, texture unit
  GLint gbuffer = BALLS_VIEW_GBUFFER, foam = BALLS_VIEW_FOAM, depth = BALLS_VIEW_DEPTH;  // texture units
  GLint sceneDepth = BALLS_VIEW_SCENE_DEPTH, target = BALLS_VIEW_COMPOSE_TARGET;         // texture, image unit
  static constexpr auto fields() {
    using U = ComposeUniforms;
    return std::tuple{gl::field("uSize", &U::size),
                      gl::field("uBalls", &U::balls),
                      gl::field("uScene", &U::scene),
                      gl::field("uSceneMin", &U::sceneMin),
                      gl::field("uSceneMax", &U::sceneMax),
                      gl::field("uLines", &U::lines),
                      gl::field("uLineCount", &U::lineCount),
                      gl::field("uLineColor", &U::lineColor),
                      gl::field("uInvView", &U::invView),
                      gl::field("uInvFocal", &U::invFocal),
                      gl::field("uOrtho", &U::ortho),
                      gl::field("uDepthRange", &U::depthRange),
                      gl::field("uMode", &U::mode),
                      gl::field("uDebug", &U::debug),
                      gl::field("uWaterColor", &U::waterColor),
                      gl::field("uAbsorption", &U::absorption),
                      gl::field("uBackground", &U::background),
                      gl::field("uF0", &U::f0),
                      gl::field("uSpecular", &U::specular),
                      gl::field("uFoamOn", &U::foamOn),
                      gl::field("uThicknessScale", &U::thicknessScale),
                      gl::field("uLightView", &U::lightView),
                      gl::field("uDepthStep", &U::depthStep),
                      gl::field("uIor", &U::ior),
                      gl::field("uScattering", &U::scattering),
                      gl::field("uSpray", &U::spray),
                      gl::field("uRadius", &U::radius),
                      gl::field("uEnvironment", &U::environment),
                      gl::field("uSkyColor", &U::skyColor),
                      gl::field("uSunWorld", &U::sunWorld),
                      gl::field("uBoxFromWorld", &U::boxFromWorld),
                      gl::field("uFloorMin", &U::floorMin),
                      gl::field("uFloorMax", &U::floorMax),
                      gl::field("uTileSize", &U::tileSize),
                      gl::field("uPixelSpread", &U::pixelSpread),
                      gl::field("uGlass", &U::glass),
                      gl::field("uCaustics", &U::caustics),
                      gl::field("uCausticsLight", &U::causticsLight),
                      gl::field("uGBuffer", &U::gbuffer),
                      gl::field("uFoam", &U::foam),
                      gl::field("uDepth", &U::depth),
                      gl::field("uSceneDepth", &U::sceneDepth),
                      gl::field("uTarget", &U::target)};
  }
};

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
  const gl::Kernel<ComposeUniforms> compose(m_shaders, "render/balls/compose.comp", {});
  if (surface) {
    surface->bind(BALLS_VIEW_GBUFFER);
    gbuffer.foam().bind(BALLS_VIEW_FOAM);
    gbuffer.depth().bind(BALLS_VIEW_DEPTH);
  }
  if (scene.drawn) target.depth().bind(BALLS_VIEW_SCENE_DEPTH);
  if (scene.caustics) scene.caustics->bind(BALLS_VIEW_CAUSTICS);
  target.color().bindImage(BALLS_VIEW_COMPOSE_TARGET, GL_READ_WRITE, GL_RGBA8);
  const std::vector<glm::vec4> lines =
      scene.box ? boxEdgesInWindow(scene.boxMin, scene.boxMax, camera.proj * camera.view * scene.boxModel,
                                   {camera.width, camera.height})
                : std::vector<glm::vec4>{};
  ComposeUniforms u{.size = {camera.width, camera.height},
                    .balls = surface ? 1 : 0,
                    .scene = scene.drawn ? 1 : 0,
                    .sceneMin = scene.rect.min,
                    .sceneMax = scene.rect.max,
                    .lineCount = int(std::min(lines.size(), kMaxLinePoints) / 2),
                    .invView = glm::inverse(camera.view),
                    .invFocal = glm::vec2(1.0f / camera.proj[0][0], 1.0f / camera.proj[1][1]),
                    .ortho = camera.isOrthographic() ? 1 : 0,
                    .depthRange = glm::vec2(camera.near, camera.far),
                    .mode = int(look.mode),
                    .debug = int(look.debug),
                    .waterColor = look.waterColor,
                    .absorption = look.absorption,
                    .background = look.background,
                    .f0 = look.fresnelF0,
                    .specular = look.specular,
                    .foamOn = look.foam ? 1 : 0,
                    .thicknessScale = 40.0f * radius,  // ~20 balls deep shows white
                    .lightView = camera.towardsLight(look.lightDirection),
                    .depthStep = look.depthThreshold * radius,
                    .ior = look.refractionIndex,
                    .scattering = look.scattering,
                    .spray = look.spray,
                    .radius = radius,
                    .environment = look.environment ? 1 : 0,
                    .skyColor = look.skyColor,
                    .sunWorld = look.sunWorld(),
                    .boxFromWorld = glm::inverse(scene.boxModel),
                    .floorMin = scene.boxMin,
                    .floorMax = scene.boxMax,
                    .tileSize = std::min(scene.boxMax.x - scene.boxMin.x, scene.boxMax.y - scene.boxMin.y) /
                                std::max(look.floorTiles, 1.0f),
                    // Both projections: rad (perspective) or m (orthographic) per pixel at the centre.
                    .pixelSpread = 2.0f / (camera.proj[1][1] * float(camera.height)),
                    .glass = look.glass,
                    .caustics = scene.caustics ? 1 : 0};
  std::copy_n(lines.begin(), std::min(lines.size(), kMaxLinePoints), u.lines.begin());
  compose.dispatch({unsigned(camera.width + 15) / 16, unsigned(camera.height + 15) / 16, 1u}, u);
  // Readers of the image: read-backs, the window's blit, texture fetches; the next frame's
  // raster clear and draws.
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace tidepool
