// The swarm renderer: image colouring at start positions, points where the state says, and the
// high-quality mode that keeps counting past 255 particles per pixel.
#include <gtest/gtest.h>

#include <random>

#include "render/swarm_renderer.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::sim;

namespace {

class SwarmRendering : public test::GlTest {};
class SwarmPointPaths : public test::GlTest, public ::testing::WithParamInterface<bool> {};  // computePoints

// NDC of the centre of pixel (px, py) of a w x h image, py counted from the top row.
glm::vec2 pixelCentre(int px, int py, int w, int h) {
  return {-1.0f + 2.0f * (float(px) + 0.5f) / float(w), 1.0f - 2.0f * (float(py) + 0.5f) / float(h)};
}

}  // namespace

TEST_F(SwarmRendering, ParticleStartingAtAPixelCentreGetsThatPixelsColour) {
  io::Image image{5, 3, {}};
  for (int i = 0; i < 15; ++i)  // every pixel different, neighbours far apart
    image.rgba.insert(image.rgba.end(),
                      {std::uint8_t(i * 17), std::uint8_t(255 - i * 13), std::uint8_t((i * 97) % 256), 255});
  std::vector<SwarmParticle> start;
  for (int py = 0; py < 3; ++py)
    for (int px = 0; px < 5; ++px) start.push_back({pixelCentre(px, py, 5, 3), {0.0f, 0.0f}});
  for (Storage storage : {Storage::Fp32, Storage::Fp16}) {
    SCOPED_TRACE(kStorageNames[int(storage)]);
    SwarmParams params;
    params.storage = storage;
    params.particles = 15;
    Swarm swarm(shaders(), params);
    swarm.upload(start);
    SwarmRenderer renderer(shaders());
    renderer.colorFromImage(swarm, image);
    ASSERT_TRUE(renderer.hasColors(swarm));
    const std::vector<std::uint32_t> colors = renderer.colors().read<std::uint32_t>(15);
    for (int i = 0; i < 15; ++i)
      for (int c = 0; c < 4; ++c)  // fp16 positions are off-centre by < 1e-3 texel: at most 1 step
        EXPECT_NEAR(int((colors[i] >> (8 * c)) & 0xFF), int(image.rgba[std::size_t(i * 4 + c)]), 1)
            << "pixel " << i % 5 << "," << i / 5 << " channel " << c;
  }
}

TEST_P(SwarmPointPaths, PointsLandOnTheirPixelsTopRowFirst) {
  for (Storage storage : {Storage::Fp32, Storage::Fp16}) {  // fp16: the state read as 4 x GL_HALF_FLOAT
    SCOPED_TRACE(kStorageNames[int(storage)]);
    SwarmParams params;
    params.particles = 2;
    params.storage = storage;
    Swarm swarm(shaders(), params);
    swarm.upload(
        std::vector<SwarmParticle>{{pixelCentre(3, 1, 32, 16), {0, 0}}, {pixelCentre(20, 12, 32, 16), {0, 0}}});
    SwarmRenderer renderer(shaders());
    RenderTarget target(32, 16);
    gl::GpuProfiler profiler;
    SwarmViewParams view;
    view.blend = false;
    view.showAttractors = false;
    view.computePoints = GetParam();
    renderer.render(swarm, view, {1.0f, 0.5f, 0.0f}, {}, target, profiler);
    const std::vector<std::uint8_t> px = target.readRgba8();
    int lit = 0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 32; ++x) {
        const std::uint8_t* p = &px[std::size_t(y * 32 + x) * 4];
        if (p[0] == 0) continue;
        ++lit;
        EXPECT_TRUE((x == 3 && y == 1) || (x == 20 && y == 12)) << "lit at " << x << "," << y;
        EXPECT_EQ(p[0], 255);
        EXPECT_NEAR(p[1], 128, 1);
      }
    EXPECT_EQ(lit, 2);

    view.pointSize = 5;  // round sprite: 5 px across, corners cut
    renderer.render(swarm, view, {1.0f, 1.0f, 1.0f}, {}, target, profiler);
    const std::vector<std::uint8_t> sprite = target.readRgba8();
    auto at = [&](int x, int y) { return sprite[std::size_t(y * 32 + x) * 4]; };
    EXPECT_EQ(at(20, 12), 255);
    EXPECT_EQ(at(22, 12), 255);
    EXPECT_EQ(at(20, 14), 255);
    EXPECT_EQ(at(22, 14), 0) << "sprites are round";
  }
}

TEST_P(SwarmPointPaths, HighQualityKeepsCountingPast255ParticlesPerPixel) {
  // 300 particles on one pixel, 600 on another; opacity 0.002: brightness 1 - exp(-0.002 n).
  std::vector<SwarmParticle> pile(900, SwarmParticle{pixelCentre(4, 4, 16, 8), {0, 0}});
  for (std::size_t i = 300; i < 900; ++i) pile[i].pos = pixelCentre(10, 4, 16, 8);
  SwarmParams params;
  params.particles = 900;
  Swarm swarm(shaders(), params);
  swarm.upload(pile);
  SwarmRenderer renderer(shaders());
  RenderTarget target(16, 8);
  gl::GpuProfiler profiler;
  SwarmViewParams view;
  view.highQuality = true;
  view.opacity = 0.002f;
  view.showAttractors = false;
  view.computePoints = GetParam();
  renderer.render(swarm, view, {1.0f, 1.0f, 1.0f}, {}, target, profiler);
  const std::vector<std::uint8_t> px = target.readRgba8();
  const int a = px[std::size_t(4 * 16 + 4) * 4], b = px[std::size_t(4 * 16 + 10) * 4];
  EXPECT_NEAR(a, 255.0 * (1.0 - std::exp(-0.6)), 1.5);
  EXPECT_NEAR(b, 255.0 * (1.0 - std::exp(-1.2)), 1.5);
  EXPECT_EQ(px[std::size_t(0) * 4], 0);
}

INSTANTIATE_TEST_SUITE_P(RasterAndCompute, SwarmPointPaths, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "compute" : "raster"); });

// The compute splat must look like GL_POINTS in every colour mode and look: the raster path
// rounds each blend to 8 bits, the splat rounds colours to 1/255 once, hence a few steps apart.
// Particles sit on pixel centres: a point within 1/256 px of a pixel edge may land on either
// side in the rasterizer's fixed-point snapping, and that is not what is compared here.
TEST_F(SwarmRendering, ComputeSplatMatchesRasterPoints) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> px(0, 63), py(0, 31);
  std::normal_distribution<float> vel(0.0f, 1.0f);
  std::vector<SwarmParticle> particles(6000);
  for (auto& p : particles) p = {pixelCentre(px(rng), py(rng), 64, 32), {vel(rng), vel(rng)}};
  SwarmParams params;
  params.particles = int(particles.size());
  Swarm swarm(shaders(), params);
  swarm.upload(particles);
  SwarmRenderer renderer(shaders());
  io::Image image{2, 2, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255}};
  renderer.colorFromImage(swarm, image);
  RenderTarget target(64, 32);
  gl::GpuProfiler profiler;
  for (SwarmColorMode mode : {SwarmColorMode::Single, SwarmColorMode::Image, SwarmColorMode::Velocity})
    for (int look = 0; look < 3; ++look) {  // additive, high quality, opaque
      SCOPED_TRACE(std::string(kSwarmColorModeNames[int(mode)]) + " look " + std::to_string(look));
      SwarmViewParams view;
      view.colorMode = mode;
      view.opacity = 0.2f;
      view.highQuality = look == 1;
      view.blend = look != 2;
      view.showAttractors = false;
      std::vector<std::uint8_t> images[2];
      for (int path = 0; path < 2; ++path) {
        view.computePoints = path == 1;
        renderer.render(swarm, view, {0.3f, 0.6f, 0.9f}, {}, target, profiler);
        images[path] = target.readRgba8();
      }
      int worst = 0, lit = 0;
      for (std::size_t i = 0; i < images[0].size(); ++i) {
        if (look == 2 && mode != SwarmColorMode::Single) continue;  // opaque: last particle vs mean colour
        const int d = std::abs(int(images[0][i]) - int(images[1][i]));
        worst = std::max(worst, d);
        lit += i % 4 == 3 && (images[1][i - 1] > 0 || images[1][i - 2] > 0 || images[1][i - 3] > 0);
      }
      EXPECT_LE(worst, look == 0 ? 6 : 2);
      if (look != 2 || mode == SwarmColorMode::Single) EXPECT_GT(lit, 500);
    }
}
