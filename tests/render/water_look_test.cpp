// The water mode's looks (render/balls_view_params.h, shaders/render/balls/compose.comp):
//   - the optics (shaders/render/balls/water_optics.glsl) against the textbook formulas in double:
//     Beer–Lambert transmittance, Schlick's Fresnel, Snell's refraction;
//   - a synthetic slab of known thickness over the floor (the environment), composed as the
//     renderer does, transmits the floor as Beer–Lambert says and reflects the sky by Fresnel;
//   - the presets set their fields and keys after them override them.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/kernel.h"
#include "render/balls_compose.h"
#include "render/balls_gbuffer.h"
#include "render/balls_view.h"
#include "render/obstacle_mesh.h"
#include "scene/balls_stage.h"
#include "scene/scene.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class WaterLookTest : public test::GlTest {};

// Evaluates the three formulas for case i of the inputs (vec4 each: colour + absorption,
// thickness + F0 + cos θ + index, the incident ray's angle to the normal).
const char* kOptics = R"(#version 430 core
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Out { vec4 outputs[]; };
uniform uint uCount;
#include "render/balls/water_optics.glsl"
void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  const vec4 a = inputs[2u * i], b = inputs[2u * i + 1u];
  // The incident ray at angle b.w to the normal (0, 0, 1), coming down in the xz plane.
  const vec3 incident = vec3(sin(b.w), 0.0, -cos(b.w));
  outputs[2u * i] = vec4(transmittance(a.rgb, a.a, b.x), schlick(b.y, b.z));
  outputs[2u * i + 1u] = vec4(refracted(incident, vec3(0.0, 0.0, 1.0), b.z + 1.0), 0.0);
}
)";

struct OpticsUniforms {
  GLuint count = 0;
  static constexpr auto fields() { return std::tuple{gl::field("uCount", &OpticsUniforms::count)}; }
};

// The clear look with only the surface's optics left: no scattering, highlight or foam, the sun
// at the horizon (the floor lit evenly), `tiles` across the box.
BallsViewParams opticsOnly(float tiles) {
  BallsViewParams look;
  applyLook(look, WaterLook::Clear);
  look.mode = BallsMode::Water;
  look.scattering = 0.0f;
  look.specular = 0.0f;
  look.foam = false;
  look.floorTiles = tiles;
  look.lightDirection = {1.0f, 0.0f, 0.0f};
  return look;
}

// A G-buffer of size x size whose foam and depth are those of one big ball in front of the
// camera at `centre` everywhere: the compose then shades whatever surface texture it is given.
void coverWithABall(BallsGBuffer& gbuffer, int size, const BallsCamera& camera, glm::vec3 centre) {
  gbuffer.resize(size, size);
  const glm::vec4 ball(centre, 1.0f);
  const gl::Buffer balls(sizeof ball, &ball);
  gl::GpuProfiler profiler;
  gbuffer.draw({.positions = &balls, .count = 1, .radius = 0.4f}, camera, {}, true, BallsRaster::Compute, profiler);
}

}  // namespace

TEST_F(WaterLookTest, TheOpticsAreBeerLambertSchlickAndSnell) {
  test::TempDir dir;
  dir.write("optics.comp", kOptics);
  std::filesystem::create_directories(dir / "render/balls");
  std::filesystem::copy_file(shaderDir() / "render/balls/water_optics.glsl", dir / "render/balls/water_optics.glsl");
  gl::ShaderLibrary lib(dir.path());
  const gl::Kernel<OpticsUniforms> kernel(lib, "optics.comp", {0, 1});
  struct Case {
    glm::vec3 colour;
    float absorption, thickness, f0, cosine, angle;
  };
  std::vector<Case> cases;
  for (float thickness : {0.0f, 0.01f, 0.3f, 1.5f})
    for (float angle : {0.0f, 0.3f, 0.8f, 1.4f})
      cases.push_back({{0.62f, 0.86f, 0.92f}, 4.0f, thickness, 0.02f, std::cos(angle), angle});
  cases.push_back({{0.1f, 0.45f, 0.5f}, 12.0f, 0.2f, 0.5f, 0.0f, 1.5f});
  std::vector<glm::vec4> in;
  for (const Case& c : cases) {
    in.emplace_back(c.colour, c.absorption);
    in.emplace_back(c.thickness, c.f0, c.cosine, c.angle);
  }
  const gl::Buffer input(in.size() * sizeof(glm::vec4), in.data());
  gl::Buffer output(in.size() * sizeof(glm::vec4));
  input.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  output.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  kernel.dispatchThreads(cases.size(), {GLuint(cases.size())});
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<glm::vec4> out = output.read<glm::vec4>(in.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    SCOPED_TRACE(i);
    for (int k = 0; k < 3; ++k) {  // T = exp(−σ d), σ = −absorption ln(colour)
      const double sigma = -double(c.absorption) * std::log(double(c.colour[k]));
      EXPECT_NEAR(out[2 * i][k], std::exp(-sigma * c.thickness), 2e-6);
    }
    EXPECT_NEAR(out[2 * i].w, c.f0 + (1.0 - c.f0) * std::pow(1.0 - c.cosine, 5.0), 2e-6);
    // Snell: sin θt = sin θi / n, the refracted ray going on down in the plane of incidence.
    const double n = double(c.cosine) + 1.0, sinT = std::sin(double(c.angle)) / n;
    const glm::vec3 r(out[2 * i + 1]);
    EXPECT_NEAR(glm::length(r), 1.0, 2e-6);
    EXPECT_NEAR(r.x, sinT, 2e-6);
    EXPECT_NEAR(r.y, 0.0, 2e-6);
    EXPECT_NEAR(r.z, -std::sqrt(1.0 - sinT * sinT), 2e-6);
  }
}

// A slab of water of thickness d filling the left half of the picture, facing an orthographic
// camera that looks straight down at the floor (one tile in view, the sun at the horizon so the
// sky straight up is the sky colour alone); no scattering, highlight or foam. Where the slab is,
// the picture is F0 times the sky plus (1 − F0) T(d) times the floor seen in the right half.
TEST_F(WaterLookTest, ASlabOfKnownThicknessTransmitsTheFloorByBeerLambert) {
  constexpr int kSize = 32;
  BallsViewParams look = opticsOnly(1.0f);
  look.background = look.skyColor;
  const float height = 2.0f;  // the eye above the floor, m
  const BallsCamera camera = BallsCamera::orthographic(
      glm::lookAt(glm::vec3(0.5f, 0.5f, height), glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)), 0.05f,
      kSize, kSize, 0.1f, 10.0f);
  BallsGBuffer gbuffer(shaders());
  coverWithABall(gbuffer, kSize, camera, {0.5f, 0.5f, 1.5f});
  BallsCompose compose(shaders());
  const ComposeScene scene{.boxMin = glm::vec3(0.0f), .boxMax = glm::vec3(1.0f)};
  for (float d : {0.0f, 0.05f, 0.2f, 0.6f}) {
    SCOPED_TRACE(d);
    std::vector<glm::vec4> surface(kSize * kSize, glm::vec4(0.0f));
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize / 2; ++x) surface[std::size_t(y * kSize + x)] = glm::vec4(0.0f, 0.0f, d, 1.0f);
    gl::Texture2D slab(kSize, kSize, GL_RGBA32F);
    slab.upload(GL_RGBA, GL_FLOAT, surface.data());
    RenderTarget target(kSize, kSize);
    compose.draw(&slab, gbuffer, look, camera, 0.01f, scene, target);
    const std::vector<std::uint8_t> rgba = target.readRgba8();
    const auto at = [&](int x, int y) {
      const std::uint8_t* p = &rgba[std::size_t((y * kSize + x) * 4)];
      return glm::vec3(p[0], p[1], p[2]) / 255.0f;
    };
    const glm::vec3 floor = at(3 * kSize / 4, kSize / 2);
    for (int k = 0; k < 3; ++k) {
      const double t = std::pow(double(look.waterColor[k]), double(look.absorption * d));
      const double want = look.fresnelF0 * look.skyColor[k] + (1.0 - look.fresnelF0) * t * floor[k];
      for (glm::ivec2 px : {glm::ivec2(4, 4), glm::ivec2(kSize / 4, kSize / 2), glm::ivec2(kSize / 2 - 3, kSize - 5)})
        EXPECT_NEAR(at(px.x, px.y)[k], want, 1.5 / 255.0) << "channel " << k << " at " << px.x << ", " << px.y;
    }
  }
}

TEST_F(WaterLookTest, PresetsSetTheirFieldsAndKeysAfterThemOverrideThem) {
  const BallsViewParams defaults;
  BallsViewParams clear = defaults;
  applyLook(clear, WaterLook::Seed);
  applyLook(clear, WaterLook::Clear);
  EXPECT_EQ(defaults.look, WaterLook::Clear) << "the default look";
  EXPECT_EQ(clear.environment, defaults.environment);
  EXPECT_EQ(clear.waterColor, defaults.waterColor);
  EXPECT_EQ(clear.absorption, defaults.absorption);
  EXPECT_EQ(clear.background, defaults.background);
  EXPECT_EQ(clear.caustics, defaults.caustics);
  BallsViewParams seed;
  applyLook(seed, WaterLook::Seed);
  EXPECT_FALSE(seed.environment);
  EXPECT_EQ(seed.caustics, 0.0f);
  EXPECT_EQ(seed.waterColor, glm::vec3(0.18f, 0.45f, 0.91f)) << "water-webgpu's blue";
  EXPECT_EQ(seed.refractionIndex, 1.0f) << "the seed's water does not bend";

  const Scene ocean = loadScene(resolveScenePath("dam-break"), {{"view", {{"look", "ocean"}, {"absorption", 3.0}}}});
  BallsViewParams expected;
  applyLook(expected, WaterLook::Ocean);
  const BallsViewParams& got = ocean.params.as<BallsSceneParams>().view.look;
  EXPECT_EQ(got.look, WaterLook::Ocean);
  EXPECT_TRUE(got.environment);
  EXPECT_EQ(got.waterColor, expected.waterColor);
  EXPECT_EQ(got.refractionIndex, 1.33f);
  EXPECT_EQ(got.absorption, 3.0f) << "a key given with the look overrides the look's";
}

// The floor seen through a tilted water surface moves as Snell's law says: a grout line of the
// floor (the joint between two tiles, straight down from an orthographic eye) lies where it is in
// the dry half of the picture, and where the refracted rays land on it under the slab in the other.
TEST_F(WaterLookTest, TheFloorThroughATiltedSurfaceIsWhereTheRefractedRaysLand) {
  constexpr int kSize = 64;
  constexpr double kTilt = 0.35, kHeight = 0.2, kEye = 2.0;  // rad; the surface's height over the floor at x = 1
  const BallsViewParams look = opticsOnly(4.0f);             // tiles of 0.5 m in a 2 m box: a joint at x = 1
  const double half = 0.08;                                  // the view's half width, m
  const BallsCamera camera = BallsCamera::orthographic(
      glm::lookAt(glm::vec3(1.0f, 0.25f, float(kEye)), glm::vec3(1.0f, 0.25f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)),
      float(half), kSize, kSize, 0.1f, 10.0f);
  BallsGBuffer gbuffer(shaders());
  coverWithABall(gbuffer, kSize, camera, {1.0f, 0.25f, 1.5f});
  const auto worldX = [&](int column) { return 1.0 + (2.0 * (column + 0.5) / kSize - 1.0) * half; };
  const auto surfaceZ = [&](double x) { return kHeight + (x - 1.0) * std::tan(kTilt); };
  // Water in the lower half of the rows: the view depth of a plane rising towards +x.
  std::vector<glm::vec4> surface(kSize * kSize, glm::vec4(0.0f));
  for (int y = 0; y < kSize / 2; ++y)
    for (int x = 0; x < kSize; ++x)
      surface[std::size_t(y * kSize + x)] = glm::vec4(0.0f, 0.0f, 0.05f, float(kEye - surfaceZ(worldX(x))));
  gl::Texture2D slab(kSize, kSize, GL_RGBA32F);
  slab.upload(GL_RGBA, GL_FLOAT, surface.data());
  RenderTarget target(kSize, kSize);
  BallsCompose compose(shaders());
  compose.draw(&slab, gbuffer, look, camera, 0.01f, {.boxMin = glm::vec3(0.0f), .boxMax = glm::vec3(2.0f)}, target);
  const std::vector<std::uint8_t> rgba = target.readRgba8();  // top row first
  // The mean column of the dark joint in a row (darker than halfway between its extremes).
  const auto jointColumn = [&](int row) {
    std::vector<double> luma(kSize);
    for (int x = 0; x < kSize; ++x) {
      const std::uint8_t* p = &rgba[std::size_t(((kSize - 1 - row) * kSize + x) * 4)];
      luma[std::size_t(x)] = double(p[0]) + p[1] + p[2];
    }
    const double mid =
        0.5 * (*std::min_element(luma.begin(), luma.end()) + *std::max_element(luma.begin(), luma.end()));
    double sum = 0, count = 0;
    for (int x = 0; x < kSize; ++x)
      if (luma[std::size_t(x)] < mid) sum += x, ++count;
    return count > 0 ? sum / count : -1.0;
  };
  // Where each column's ray lands: refracted at the plane (normal (−tan, 0, 1)), down to the floor.
  const glm::dvec3 n = glm::normalize(glm::dvec3(-std::tan(kTilt), 0.0, 1.0));
  const glm::dvec3 r = glm::refract(glm::dvec3(0.0, 0.0, -1.0), n, 1.0 / double(look.refractionIndex));
  double sum = 0, count = 0;
  for (int x = 0; x < kSize; ++x) {
    const double land = worldX(x) + surfaceZ(worldX(x)) * r.x / -r.z;
    const double f = land / 0.5 - std::floor(land / 0.5);
    if (std::min(f, 1.0 - f) < 0.03) sum += x, ++count;  // environment.glsl's kGroutWidth
  }
  ASSERT_GT(count, 0.0);
  const double dry = jointColumn(3 * kSize / 4), wet = jointColumn(kSize / 4), want = sum / count;
  EXPECT_NEAR(dry, (kSize - 1) / 2.0, 1.0) << "the joint at x = 1, straight down";
  EXPECT_GT(std::abs(want - dry), 5.0) << "the set-up bends the rays by a few pixels";
  EXPECT_NEAR(wet, want, 1.0) << "dry " << dry;
  std::printf("joint: dry %.2f, wet %.2f, Snell %.2f (columns)\n", dry, wet, want);
}

// The tank's side walls are glass: through one, the floor inside the tank is mixed with the sky
// it reflects by Schlick's Fresnel at the wall (F0 = glass). An orthographic eye outside the box
// looks steeply down, 75° from the wall's normal, through the wall x = 0; the reflected ray points
// down, where the sky is the background, and the sun straight up adds no glow to it.
TEST_F(WaterLookTest, TheTanksGlassWallsReflectTheSkyByFresnel) {
  constexpr int kSize = 16;
  BallsViewParams look;
  applyLook(look, WaterLook::Clear);
  look.lightDirection = {0.0f, 0.0f, 1.0f};
  const double angle = 75.0 * std::acos(-1.0) / 180.0;
  const glm::vec3 eye(-0.1f, 0.5f, 1.0f), target = eye + glm::vec3(std::cos(angle), 0.0, -std::sin(angle));
  const BallsCamera camera = BallsCamera::orthographic(glm::lookAt(eye, target, glm::vec3(0.0f, 0.0f, 1.0f)), 0.02f,
                                                       kSize, kSize, 0.1f, 10.0f);
  BallsGBuffer gbuffer(shaders());
  gbuffer.resize(kSize, kSize);
  BallsCompose compose(shaders());
  const ComposeScene scene{.boxMin = glm::vec3(0.0f), .boxMax = glm::vec3(1.0f)};
  const auto centre = [&](float glass) {
    look.glass = glass;
    RenderTarget target(kSize, kSize);
    compose.draw(nullptr, gbuffer, look, camera, 0.01f, scene, target);
    const std::vector<std::uint8_t> rgba = target.readRgba8();
    const std::uint8_t* p = &rgba[std::size_t((kSize / 2 * kSize + kSize / 2) * 4)];
    return glm::dvec3(p[0], p[1], p[2]) / 255.0;
  };
  const glm::dvec3 floor = centre(0.0f), glazed = centre(0.5f);
  const double cosine = std::cos(angle);
  const double fresnel = 0.5 + 0.5 * std::pow(1.0 - cosine, 5.0);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(glazed[k], floor[k] + fresnel * (look.background[k] - floor[k]), 1.5 / 255.0) << "channel " << k;
  EXPECT_GT(glm::length(glazed - floor), 0.05) << "the glass shows";
}

// Spray: a lone ball (a droplet) is drawn white as foam; a ball in a sheet of water one ball
// thick is not, though the water along the ray is no thicker there (its neighbours on screen
// tell). The eye looks down the view's −z at a sheet of 6 × 6 balls and, beside it, one alone.
TEST_F(WaterLookTest, ALoneBallIsSprayAndASheetIsWater) {
  constexpr int kWidth = 160, kHeight = 90;
  constexpr float kRadius = 0.01f;
  std::vector<glm::vec4> positions;
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 6; ++x)
      positions.emplace_back(-0.15f + 0.02f * float(x), -0.05f + 0.02f * float(y), -1.0f, 1.0f);
  const glm::vec3 lone(0.15f, 0.0f, -1.0f), sheet(-0.09f, 0.01f, -1.0f);  // view space (the view is the identity)
  positions.emplace_back(lone, 1.0f);
  const gl::Buffer buffer(positions.size() * sizeof(glm::vec4), positions.data());
  BallsScene scene;
  scene.water = {&buffer, nullptr, positions.size(), kRadius, glm::mat4(1.0f)};
  scene.boxMin = glm::vec3(-2.0f, -2.0f, -3.0f);
  scene.boxMax = glm::vec3(2.0f, 2.0f, 2.0f);
  const BallsCamera camera =
      BallsCamera::perspective(glm::mat4(1.0f), glm::radians(30.0f), kWidth, kHeight, 0.5f, 10.0f);
  const auto colours = [&](float spray) {
    BallsView view(shaders());
    applyLook(view.params(), WaterLook::Ocean);
    view.params().mode = BallsMode::Water;
    view.params().showBox = false;
    view.params().spray = spray;
    RenderTarget target(kWidth, kHeight);
    gl::GpuProfiler profiler;
    view.render(scene, camera, target, profiler);
    const std::vector<std::uint8_t> rgba = target.readRgba8();  // top row first
    const auto at = [&](glm::vec3 p) {
      const glm::vec4 clip = camera.proj * glm::vec4(p, 1.0f);
      const glm::ivec2 px = glm::ivec2((0.5f * glm::vec2(clip) / clip.w + 0.5f) * glm::vec2(kWidth, kHeight));
      const std::uint8_t* c = &rgba[std::size_t(((kHeight - 1 - px.y) * kWidth + px.x) * 4)];
      return glm::vec3(c[0], c[1], c[2]) / 255.0f;
    };
    return std::pair{at(lone), at(sheet)};
  };
  const auto [loneWater, sheetWater] = colours(0.0f);
  const auto [loneSpray, sheetSpray] = colours(1.0f);
  EXPECT_EQ(sheetSpray, sheetWater) << "the sheet stays water";
  EXPECT_GT(loneSpray.r, loneWater.r + 0.2f) << "the lone ball turns white";
  EXPECT_GT(std::min({loneSpray.r, loneSpray.g, loneSpray.b}), 0.55f);
  EXPECT_LT(std::max({loneSpray.r, loneSpray.g, loneSpray.b}) - std::min({loneSpray.r, loneSpray.g, loneSpray.b}),
            0.15f)
      << "white, not the water's colour";
}

// Obstacles are lit by the environment too: a face turned to the sky takes the sky's colour in its
// ambient share, colour · 0.2 · (sky − 1) from the white ambient without the environment; here a
// square facing the eye, with the box's up towards the eye as well.
TEST_F(WaterLookTest, ObstaclesFacingTheSkyTakeItsColourInTheirAmbientLight) {
  constexpr int kSize = 32;
  std::vector<MeshVertex> square;
  for (glm::vec2 c :
       {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
    square.push_back({glm::vec4(0.3f * c, 0.0f, 1.0f), glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)});
  const gl::Buffer vertices(square.size() * sizeof(MeshVertex), square.data());
  BallsScene scene;
  scene.obstacleMeshes = {{&vertices, square.size(), glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -2.0f))}};
  scene.boxMin = glm::vec3(-5.0f, -5.0f, -10.0f);
  scene.boxMax = glm::vec3(5.0f);
  const BallsCamera camera = BallsCamera::perspective(glm::mat4(1.0f), glm::radians(30.0f), kSize, kSize, 0.5f, 10.0f);
  const auto centre = [&](bool environment) {
    BallsView view(shaders());
    applyLook(view.params(), WaterLook::Clear);
    view.params().environment = environment;
    view.params().showBox = false;
    RenderTarget target(kSize, kSize);
    gl::GpuProfiler profiler;
    view.render(scene, camera, target, profiler);
    const std::vector<std::uint8_t> rgba = target.readRgba8();
    const std::uint8_t* p = &rgba[std::size_t((kSize / 2 * kSize + kSize / 2) * 4)];
    return glm::dvec3(p[0], p[1], p[2]) / 255.0;
  };
  const glm::dvec3 white = centre(false), sky = centre(true);
  BallsViewParams look;
  applyLook(look, WaterLook::Clear);
  const glm::dvec3 skyLight = glm::dvec3(look.skyColor) / double(look.skyColor.b);  // blue is its brightest
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(sky[k], white[k] + look.obstacleColor[k] * 0.2 * (skyLight[k] - 1.0), 1.5 / 255.0) << "channel " << k;
  EXPECT_LT(sky.r, white.r - 0.04) << "bluer in the sky's light";
}

TEST_F(WaterLookTest, TheFloorTakesTheSunlightTheCausticsSendIt) {
  // The floor seen from straight above, the sun overhead: 0.4 of ambient plus 0.6 of sun times
  // the caustics' light. A light of 0.5 on the box's left half and 1 on its right: the left half
  // shows 0.7 of the right's colour, and the floor outside the box its dry colour.
  constexpr int kSize = 32;
  BallsViewParams look = opticsOnly(1.0f);
  look.lightDirection = {0.0f, 0.0f, 1.0f};
  const BallsCamera camera = BallsCamera::orthographic(
      glm::lookAt(glm::vec3(0.5f, 0.5f, 2.0f), glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)), 0.75f, kSize,
      kSize, 0.1f, 10.0f);
  std::vector<float> texels(16 * 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) texels[std::size_t(y * 16 + x)] = x < 8 ? 0.5f : 1.0f;
  gl::Texture2D light(16, 16, GL_R16F);
  light.upload(GL_RED, GL_FLOAT, texels.data());
  BallsGBuffer gbuffer(shaders());
  BallsCompose compose(shaders());
  const auto render = [&](const gl::Texture2D* caustics) {
    RenderTarget target(kSize, kSize);
    const ComposeScene scene{.boxMin = glm::vec3(0.0f), .boxMax = glm::vec3(1.0f), .caustics = caustics};
    compose.draw(nullptr, gbuffer, look, camera, 0.01f, scene, target);
    return target.readRgba8();
  };
  const std::vector<std::uint8_t> lit = render(&light), dry = render(nullptr);
  const auto at = [&](const std::vector<std::uint8_t>& rgba, int x, int y) {
    const std::uint8_t* p = &rgba[std::size_t((y * kSize + x) * 4)];
    return glm::vec3(p[0], p[1], p[2]) / 255.0f;
  };
  // The box spans pixels 5.3 to 26.7 in x and y (0.75 m of half height over 16 px).
  for (int y : {10, 16, 21})
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(at(lit, 10, y)[k], 0.7 * at(dry, 10, y)[k], 1.5 / 255.0) << "left half, row " << y;
      EXPECT_NEAR(at(lit, 22, y)[k], at(dry, 22, y)[k], 1.0 / 255.0) << "right half";
      EXPECT_NEAR(at(lit, 2, y)[k], at(dry, 2, y)[k], 1.0 / 255.0) << "outside the box";
    }
}
