// The deferred balls renderer against analytic values, with either raster (compute kernels or
// fragments): one ray-traced sphere has the exact front depth and silhouette; thickness adds up
// along the eye ray and stops at opaque meshes; the nearer of overlapping spheres wins each pixel.
// The water blur smooths flat regions but not across depth steps.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "render/balls_view.h"
#include "sim/water/water_init.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

using BallsViewTest = test::GlTest;
class BallsRasterTest : public test::GlTest, public ::testing::WithParamInterface<BallsRaster> {};

constexpr int kSize = 65;  // odd: the centre pixel's centre is on the optical axis
constexpr float kFov = glm::radians(60.0f), kNear = 0.5f, kFar = 10.0f;

BallsCamera axisCamera() { return BallsCamera::perspective(glm::mat4(1.0f), kFov, kSize, kSize, kNear, kFar); }

// Eye at the origin looking down -z: balls at (0, 0, -distance).
gl::Buffer ballsAt(const std::vector<float>& distances) {
  std::vector<glm::vec4> pos;
  for (float d : distances) pos.emplace_back(0.0f, 0.0f, -d, 1.0f);
  return gl::Buffer(std::span<const glm::vec4>(pos));
}

std::vector<glm::vec4> pixels(const gl::Texture2D& t) {
  std::vector<glm::vec4> out(std::size_t(t.width()) * t.height());
  t.download(GL_RGBA, GL_FLOAT, out.data());
  return out;
}

float linearDepth(float window) {  // glm::perspective, window depth 0..1 -> view distance (m)
  const float ndc = 2.0f * window - 1.0f;
  return 2.0f * kNear * kFar / (kFar + kNear - ndc * (kFar - kNear));
}

struct Frame {
  BallsView view;
  RenderTarget target{kSize, kSize};
  gl::GpuProfiler profiler;
  explicit Frame(gl::ShaderLibrary& shaders, BallsRaster raster, BallsMode mode = BallsMode::Water) : view(shaders) {
    view.params().raster = raster;
    view.params().mode = mode;
    view.params().showBox = false;
  }
  void render(const gl::Buffer& water, std::size_t n, float r, const gl::Buffer* obstacle = nullptr,
              std::size_t obstacleCount = 0, float obstacleRadius = 0) {
    BallsScene scene;
    scene.water = {&water, nullptr, n, r, glm::mat4(1.0f)};
    if (obstacle) scene.obstacle = {obstacle, nullptr, obstacleCount, obstacleRadius, glm::mat4(1.0f)};
    view.render(scene, axisCamera(), target, profiler);
  }
  glm::vec4 centre() const { return pixels(view.gbuffer().surface())[std::size_t(kSize / 2) * kSize + kSize / 2]; }
};

}  // namespace

TEST_P(BallsRasterTest, OneSphereHasTheAnalyticFrontDepthAndSilhouette) {
  const float d = 2.0f, r = 0.5f;
  const gl::Buffer ball = ballsAt({d});
  Frame f(shaders(), GetParam(), BallsMode::Balls);
  f.render(ball, 1, r);
  const std::vector<float> depth = f.view.gbuffer().readDepth();
  const std::size_t centre = std::size_t(kSize / 2) * kSize + kSize / 2;
  EXPECT_NEAR(linearDepth(depth[centre]), d - r, 1e-3f) << "front point of the sphere, linearised";
  EXPECT_NEAR(f.centre().a, d - r, 2e-4f) << "G-buffer view depth (32-bit float)";
  // Silhouette: the tangent cone's half-angle a (sin a = r/d) projects to tan(a) * focal px.
  const float focalPx = 0.5f * kSize / std::tan(0.5f * kFov);
  const float expected = r / std::sqrt(d * d - r * r) * focalPx;
  int covered = 0;
  for (float z : depth) covered += z < 1.0f;
  EXPECT_NEAR(std::sqrt(covered / float(M_PI)), expected, 1.0f) << "silhouette radius, px";
  int row = 0;
  for (int x = 0; x < kSize; ++x) row += depth[std::size_t(kSize / 2) * kSize + x] < 1.0f;
  EXPECT_NEAR(0.5f * row, expected, 1.0f) << "half the centre row's covered width, px";
}

TEST_P(BallsRasterTest, CoincidentSpheresAddTheirThickness) {
  const float r = 0.3f;
  const gl::Buffer one = ballsAt({2.0f}), three = ballsAt({2.0f, 2.0f, 2.0f});
  Frame f(shaders(), GetParam());
  f.render(one, 1, r);
  const float single = f.centre().b;
  EXPECT_NEAR(single, 2.0f * r, 2e-3f) << "the chord through the centre is the diameter";
  f.render(three, 3, r);
  EXPECT_NEAR(f.centre().b, 3.0f * single, 6e-3f);
}

TEST_P(BallsRasterTest, ASphereBehindAnOpaqueObstacleBallAddsNoThickness) {
  const float r = 0.3f;
  const gl::Buffer water = ballsAt({3.0f, 1.2f}), wall = ballsAt({2.0f});
  Frame f(shaders(), GetParam());
  f.render(water, 1, r, &wall, 1, 0.5f);  // only the ball behind the obstacle
  EXPECT_EQ(f.centre().b, 0.0f);
  f.render(water, 2, r, &wall, 1, 0.5f);  // plus one in front of it: only that one counts
  EXPECT_NEAR(f.centre().b, 2.0f * r, 2e-3f);
}

TEST_P(BallsRasterTest, ASphereBehindAnOpaqueMeshAddsNoThickness) {
  // The obstacle as a mesh: a sphere obstacle of balls r = 0.04 whose surface has radius 0.4,
  // centred 2 m away, behind one water ball and in front of another.
  const float r = 0.3f;
  water::ObstacleParams o;
  o.shape = water::Shape::Sphere;
  o.size = glm::vec3(0.36f);
  const std::vector<MeshVertex> sphere = ballUnionMesh(water::Obstacle(o, 0.04f).particles(), 0.04f);
  ASSERT_FALSE(sphere.empty());
  const gl::Buffer mesh{std::span<const MeshVertex>(sphere)}, water = ballsAt({3.0f, 1.2f});
  Frame f(shaders(), GetParam());
  BallsScene scene;
  scene.obstacleMeshes = {{&mesh, sphere.size(), glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -2.0f))}};
  scene.water = {&water, nullptr, 1, r, glm::mat4(1.0f)};  // only the ball behind the mesh
  f.view.render(scene, axisCamera(), f.target, f.profiler);
  EXPECT_EQ(f.centre().b, 0.0f);
  std::vector<float> depth(std::size_t(kSize) * kSize);
  f.target.depth().download(GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  EXPECT_NEAR(linearDepth(depth[std::size_t(kSize / 2) * kSize + kSize / 2]), 1.6f, 0.02f)
      << "the mesh's front is the scene's depth";
  scene.water.count = 2;  // plus one in front of it: only that one counts
  f.view.render(scene, axisCamera(), f.target, f.profiler);
  EXPECT_NEAR(f.centre().b, 2.0f * r, 2e-3f);
}

TEST_P(BallsRasterTest, TheNearerOfOverlappingSpheresWinsEachPixel) {
  // Two balls side by side, the right one nearer and overlapping the left one's disc: in the
  // overlap the right one's depth and normal win, whichever is drawn first.
  const float r = 0.4f;
  const float dl = 3.0f, dr = 2.5f;  // view distances of the centres
  const float xl = -0.25f, xr = 0.2f;
  for (bool nearFirst : {false, true}) {
    SCOPED_TRACE(nearFirst ? "near ball first" : "far ball first");
    std::vector<glm::vec4> pos = {{xl, 0.0f, -dl, 1.0f}, {xr, 0.0f, -dr, 1.0f}};
    if (nearFirst) std::swap(pos[0], pos[1]);
    const gl::Buffer balls{std::span<const glm::vec4>(pos)};
    Frame f(shaders(), GetParam(), BallsMode::Balls);
    f.render(balls, 2, r);
    const std::vector<glm::vec4> g = pixels(f.view.gbuffer().surface());
    // Per pixel, the CPU reference: the smaller front depth of the two rays' hits.
    const float focal = 1.0f / std::tan(0.5f * kFov);
    int overlap = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const glm::dvec3 dir((2.0 * (x + 0.5) / kSize - 1.0) / focal, (2.0 * (y + 0.5) / kSize - 1.0) / focal, -1.0);
        double best = 0;
        int hits = 0;
        for (const glm::vec4& c : pos) {
          const glm::dvec3 centre(c);
          const double a = glm::dot(dir, dir), along = glm::dot(dir, centre) / a;
          const glm::dvec3 off = along * dir - centre;
          const double h2 = double(r) * r - glm::dot(off, off);
          if (h2 < 0) continue;
          const double t = along - std::sqrt(h2 / a);
          best = hits++ == 0 ? t : std::min(best, t);
        }
        const glm::vec4 p = g[std::size_t(y) * kSize + x];
        if (hits == 0) continue;  // silhouette pixels may differ by rounding: only hit pixels checked
        overlap += hits == 2;
        EXPECT_NEAR(p.a, best, 2e-3) << "pixel " << x << "," << y;
      }
    EXPECT_GT(overlap, 50) << "the discs overlap on screen";
  }
}

namespace {

// Renders the balls (with foam) with both rasters and compares their G-buffers pixel by pixel;
// returns the pixels covered by both and those whose coverage or front ball differs (rounding at
// silhouettes, or two balls meeting at one depth).
std::pair<int, int> compareRasters(gl::ShaderLibrary& shaders, const std::vector<glm::vec4>& pos,
                                   const std::vector<glm::vec4>& vel, float radius) {
  const gl::Buffer positions{std::span<const glm::vec4>(pos)}, velocities{std::span<const glm::vec4>(vel)};
  std::vector<glm::vec4> surface[2], foam[2];
  std::vector<float> depth[2];
  for (BallsRaster raster : {BallsRaster::Compute, BallsRaster::Fragment}) {
    Frame f(shaders, raster);
    BallsScene scene;
    scene.water = {&positions, &velocities, pos.size(), radius, glm::mat4(1.0f)};
    f.view.render(scene, axisCamera(), f.target, f.profiler);
    const int i = int(raster);
    surface[i] = pixels(f.view.gbuffer().surface());
    foam[i].resize(surface[i].size());
    f.view.gbuffer().foam().download(GL_RGBA, GL_FLOAT, foam[i].data());
    depth[i] = f.view.gbuffer().readDepth();
  }
  int covered = 0, differ = 0;
  for (std::size_t p = 0; p < surface[0].size(); ++p) {
    const glm::vec4 c = surface[0][p], g = surface[1][p];
    if ((c.a > 0) != (g.a > 0)) {
      ++differ;
      continue;
    }
    if (c.a == 0) continue;
    ++covered;
    EXPECT_NEAR(c.a, g.a, 1e-3f) << "view depth, pixel " << p;
    EXPECT_NEAR(c.b, g.b, 1e-3f * g.b + 2e-4f) << "thickness (m), pixel " << p;
    EXPECT_NEAR(depth[0][p], depth[1][p], 1e-4f) << "window depth, pixel " << p;
    if (glm::distance(glm::vec2(c), glm::vec2(g)) > 0.02f) {  // another front ball
      ++differ;
      continue;
    }
    EXPECT_NEAR(foam[0][p].r, foam[1][p].r, 1e-3f) << "foam of the same ball, pixel " << p;
  }
  return {covered, differ};
}

}  // namespace

TEST_F(BallsViewTest, ComputeAndFragmentRastersAgree) {
  std::vector<glm::vec4> pos, vel;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 400; ++i) {
    pos.emplace_back(0.8f * u(rng), 0.8f * u(rng), -2.5f + 0.8f * u(rng), 1.0f);
    vel.emplace_back(0.0f, 0.0f, 0.0f, 0.5f + 0.5f * u(rng));
  }
  // Two balls near the eye, over SMALL_PIXELS px of box each: one work group draws each.
  pos.emplace_back(0.05f, 0.0f, -0.6f, 1.0f);
  pos.emplace_back(-0.1f, 0.1f, -0.8f, 1.0f);
  vel.resize(pos.size(), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  const auto [covered, differ] = compareRasters(shaders(), pos, vel, 0.08f);
  EXPECT_GT(covered, kSize * kSize / 4);
  EXPECT_LT(differ, covered / 50) << "pixels whose coverage or front ball differ";
}

TEST_F(BallsViewTest, ComputeRasterDrawsMoreBigBallsThanItsListHolds) {
  // BallsSplat::kMaxBig + 1000 balls of 10 px radius or more on screen: the list overflows and the
  // balls past it are drawn by their own threads in both kernels.
  std::vector<glm::vec4> pos, vel;
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (unsigned i = 0; i < BallsSplat::kMaxBig + 1000; ++i) {
    pos.emplace_back(0.3f * u(rng), 0.3f * u(rng), -1.4f + 0.3f * u(rng), 1.0f);
    vel.emplace_back(0.0f, 0.0f, 0.0f, 0.5f + 0.5f * u(rng));
  }
  const auto [covered, differ] = compareRasters(shaders(), pos, vel, 0.25f);
  EXPECT_GT(covered, kSize * kSize / 5);
  EXPECT_LT(differ, covered / 20) << "pixels whose coverage or front ball differ";
}

INSTANTIATE_TEST_SUITE_P(Rasters, BallsRasterTest, ::testing::Values(BallsRaster::Compute, BallsRaster::Fragment),
                         [](const auto& info) { return std::string(kBallsRasterNames[int(info.param)]); });

TEST_F(BallsViewTest, DebugViewsShowTheBlurredOrTheUnblurredGBuffer) {
  // The depth view is (view depth - near) / (far - near) as grey: in water mode it shows the
  // blurred surface, or with debug_unblurred the G-buffer the blur read.
  std::vector<glm::vec4> pos;
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 300; ++i) pos.emplace_back(0.6f * u(rng), 0.6f * u(rng), -2.5f + 0.5f * u(rng), 1.0f);
  const gl::Buffer balls{std::span<const glm::vec4>(pos)};
  Frame f(shaders(), BallsRaster::Compute);
  f.view.params().debug = BallsDebug::Depth;
  for (bool unblurred : {false, true}) {
    SCOPED_TRACE(unblurred ? "unblurred" : "blurred");
    f.view.params().debugUnblurred = unblurred;
    f.render(balls, pos.size(), 0.1f);
    const std::vector<std::uint8_t> rgba = f.target.readRgba8();  // top row first
    const std::vector<glm::vec4> raw = pixels(f.view.gbuffer().surface()), blurred = pixels(f.view.composedSurface());
    int matched = 0, differ = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const std::size_t i = std::size_t(y) * kSize + x;
        if (raw[i].a <= 0.0f) continue;
        const float grey = rgba[(std::size_t(kSize - 1 - y) * kSize + x) * 4] / 255.0f;
        const auto shade = [](float depth) { return (depth - kNear) / (kFar - kNear); };
        const float want = shade(unblurred ? raw[i].a : blurred[i].a),
                    other = shade(unblurred ? blurred[i].a : raw[i].a);
        EXPECT_NEAR(grey, want, 1.0f / 255.0f) << x << "," << y;
        matched += std::abs(grey - want) < 1.0f / 255.0f;
        differ += std::abs(other - want) > 2.0f / 255.0f;
      }
    EXPECT_GT(matched, 100);
    EXPECT_GT(differ, 10) << "the blur moved the depth where the two views can tell";
  }
}

TEST_F(BallsViewTest, BlurSmoothsFlatRegionsAndKeepsDepthSteps) {
  // Left half at 1 m (R around 0.3), right half at 2 m (R around 0.7), both with noise.
  const int w = 96, h = 32, step = 48;
  std::vector<glm::vec4> in(std::size_t(w) * h);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> noise(-0.1f, 0.1f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool left = x < step;
      in[std::size_t(y) * w + x] = {(left ? 0.3f : 0.7f) + noise(rng), 0.0f, (left ? 0.2f : 0.6f) + noise(rng),
                                    left ? 1.0f : 2.0f};
    }
  gl::Texture2D source(w, h, GL_RGBA32F);
  source.upload(GL_RGBA, GL_FLOAT, in.data());
  WaterBlur blur(shaders());
  blur.run(source, 8.0f, 0.5f);  // 8 px kernel at 1 m, 4 px at 2 m; steps over 0.5 m kept
  const std::vector<glm::vec4> out = pixels(blur.result());
  auto variance = [&](const std::vector<glm::vec4>& img) {
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int y = 8; y < h - 8; ++y)
      for (int x = 10; x < step - 10; ++x) {
        const double v = img[std::size_t(y) * w + x].r;
        sum += v, sum2 += v * v, ++n;
      }
    return sum2 / n - (sum / n) * (sum / n);
  };
  EXPECT_LT(variance(out), 0.2 * variance(in)) << "a flat region is smoothed";
  for (int y = 0; y < h; ++y) {
    const glm::vec4 a = out[std::size_t(y) * w + step - 1], b = out[std::size_t(y) * w + step];
    EXPECT_NEAR(a.a, 1.0f, 1e-5f) << "each layer keeps its depth";
    EXPECT_NEAR(b.a, 2.0f, 1e-5f);
    EXPECT_NEAR(a.r, 0.3f, 0.1f) << "row " << y << ": the near layer keeps its value at the step";
    EXPECT_NEAR(b.r, 0.7f, 0.1f) << "row " << y << ": the far layer keeps its value at the step";
    EXPECT_NEAR(a.b, 0.2f, 0.1f);
    EXPECT_NEAR(b.b, 0.6f, 0.1f);
  }
}

TEST_F(BallsViewTest, BlurSmoothsAlongBothAxes) {
  // Stripes across x (values change from column to column) and across y, on one flat layer: each
  // pass must take them out, or the water shows streaks along the other pass's axis.
  const int w = 64, h = 64;
  for (int axis = 0; axis < 2; ++axis) {
    SCOPED_TRACE(axis == 0 ? "stripes across x" : "stripes across y");
    std::vector<glm::vec4> in(std::size_t(w) * h);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> noise(-0.1f, 0.1f);
    std::vector<float> stripe(w);
    for (float& s : stripe) s = noise(rng);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const float s = stripe[axis == 0 ? x : y];
        in[std::size_t(y) * w + x] = {0.5f + s, 0.5f + s, 0.3f + s, 1.0f + 0.1f * s};
      }
    gl::Texture2D source(w, h, GL_RGBA32F);
    source.upload(GL_RGBA, GL_FLOAT, in.data());
    WaterBlur blur(shaders());
    blur.run(source, 8.0f, 0.5f);
    const std::vector<glm::vec4> out = pixels(blur.result());
    double before = 0, after = 0, depthBefore = 0, depthAfter = 0;
    for (int y = 16; y < h - 16; ++y)
      for (int x = 16; x < w - 16; ++x) {
        const std::size_t i = std::size_t(y) * w + x;
        before += std::pow(in[i].r - 0.5, 2), after += std::pow(out[i].r - 0.5, 2);
        depthBefore += std::pow(in[i].a - 1.0, 2), depthAfter += std::pow(out[i].a - 1.0, 2);
      }
    EXPECT_LT(after, 0.2 * before) << "normal x";
    EXPECT_LT(depthAfter, 0.2 * depthBefore) << "depth";
  }
}

TEST_F(BallsViewTest, BlurFollowsASlopeAndKeepsItFlatUpToASilhouette) {
  // A plane seen at a grazing angle: depth rises 4 mm per texel along x (6 cm across a 16-px
  // kernel, far above the 1 cm threshold) with 1 mm of noise, and ends at x = 48 (empty beyond).
  const int w = 64, h = 16, edge = 48;
  const auto plane = [](int x) { return 1.0f + 0.004f * float(x); };
  std::vector<glm::vec4> in(std::size_t(w) * h, glm::vec4(0.0f));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> noise(-0.001f, 0.001f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < edge; ++x) in[std::size_t(y) * w + x] = {0.0f, 0.0f, 0.1f, plane(x) + noise(rng)};
  gl::Texture2D source(w, h, GL_RGBA32F);
  source.upload(GL_RGBA, GL_FLOAT, in.data());
  WaterBlur blur(shaders());
  blur.run(source, 16.0f, 0.01f, 2);
  const std::vector<glm::vec4> out = pixels(blur.result());
  double before = 0, after = 0, worstNearEdge = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 4; x < edge - 4; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      before += std::pow(in[i].a - plane(x), 2), after += std::pow(out[i].a - plane(x), 2);
    }
    for (int x = edge - 4; x < edge; ++x)
      worstNearEdge = std::max(worstNearEdge, double(std::abs(out[std::size_t(y) * w + x].a - plane(x))));
    EXPECT_EQ(out[std::size_t(y) * w + edge].a, 0.0f) << "empty stays empty";
  }
  EXPECT_LT(after, 0.2 * before) << "the sloping surface is smoothed";
  EXPECT_LT(worstNearEdge, 0.0012) << "m: at the silhouette the surface stays on the plane (noise 1 mm)";
}

TEST_F(BallsViewTest, BlurSmoothsTheBallsUpToTheWatersTopEdge) {
  // The water's top edge seen from the side: balls of radius 6 px on a square 8-px lattice, the
  // top row's centres at y = 36, each a bump of 4 mm on a plane 1 m away (its rim behind its
  // front). Kernels cut short where a row crosses the scalloped edge left the top row's bumps
  // standing, a picket fence of normals; the line fit over what each side has must not.
  const int w = 96, h = 48, top = 36;
  const float radius = 6.0f, bump = 0.004f;
  std::vector<glm::vec4> in(std::size_t(w) * h, glm::vec4(0.0f));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int cy = 4; cy <= top; cy += 8)
        for (int cx = 4; cx < w; cx += 8) {
          const float d = std::hypot(float(x - cx), float(y - cy)) / radius;
          if (d > 1.0f) continue;
          const float depth = 1.0f + bump * (1.0f - std::sqrt(1.0f - d * d));
          glm::vec4& p = in[std::size_t(y) * w + x];
          if (p.a == 0.0f || depth < p.a) p = {0.0f, 0.0f, 0.1f, depth};
        }
  gl::Texture2D source(w, h, GL_RGBA32F);
  source.upload(GL_RGBA, GL_FLOAT, in.data());
  WaterBlur blur(shaders());
  blur.run(source, 12.0f, 0.05f, 2);  // 12 px kernels, well above the bumps' 4 mm steps
  const std::vector<glm::vec4> out = pixels(blur.result());
  // Squared depth differences between neighbours along x in the band of the top row of balls.
  const auto roughness = [&](const std::vector<glm::vec4>& img) {
    double sum = 0;
    for (int y = top - 6; y < h; ++y)
      for (int x = 8; x < w - 9; ++x) {
        const glm::vec4 a = img[std::size_t(y) * w + x], b = img[std::size_t(y) * w + x + 1];
        if (a.a > 0.0f && b.a > 0.0f) sum += std::pow(double(b.a - a.a), 2);
      }
    return sum;
  };
  for (std::size_t i = 0; i < in.size(); ++i) ASSERT_EQ(out[i].a > 0.0f, in[i].a > 0.0f) << "coverage is kept";
  EXPECT_LT(roughness(out), 0.05 * roughness(in)) << "the top row's bumps are smoothed away";
}
