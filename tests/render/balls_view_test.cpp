// The deferred balls renderer against analytic values: one ray-traced sphere has the exact front
// depth and silhouette; thickness adds up along the eye ray and stops at opaque meshes; the
// water blur smooths flat regions but not across depth steps.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "render/balls_view.h"
#include "sim/balls/balls_init.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class BallsViewTest : public test::GlTest {};

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
  explicit Frame(gl::ShaderLibrary& shaders, BallsMode mode = BallsMode::Water) : view(shaders) {
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

TEST_F(BallsViewTest, OneSphereHasTheAnalyticFrontDepthAndSilhouette) {
  const float d = 2.0f, r = 0.5f;
  const gl::Buffer ball = ballsAt({d});
  Frame f(shaders(), BallsMode::Balls);
  f.render(ball, 1, r);
  std::vector<float> depth(std::size_t(kSize) * kSize);
  f.view.gbuffer().depth().download(GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
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

TEST_F(BallsViewTest, CoincidentSpheresAddTheirThickness) {
  const float r = 0.3f;
  const gl::Buffer one = ballsAt({2.0f}), three = ballsAt({2.0f, 2.0f, 2.0f});
  Frame f(shaders());
  f.render(one, 1, r);
  const float single = f.centre().b;
  EXPECT_NEAR(single, 2.0f * r, 2e-3f) << "the chord through the centre is the diameter";
  f.render(three, 3, r);
  EXPECT_NEAR(f.centre().b, 3.0f * single, 6e-3f);
}

TEST_F(BallsViewTest, ASphereBehindAnOpaqueObstacleBallAddsNoThickness) {
  const float r = 0.3f;
  const gl::Buffer water = ballsAt({3.0f, 1.2f}), wall = ballsAt({2.0f});
  Frame f(shaders());
  f.render(water, 1, r, &wall, 1, 0.5f);  // only the ball behind the obstacle
  EXPECT_EQ(f.centre().b, 0.0f);
  f.render(water, 2, r, &wall, 1, 0.5f);  // plus one in front of it: only that one counts
  EXPECT_NEAR(f.centre().b, 2.0f * r, 2e-3f);
}

TEST_F(BallsViewTest, ASphereBehindAnOpaqueMeshAddsNoThickness) {
  // The obstacle as a mesh: a sphere obstacle of balls r = 0.04 whose surface has radius 0.4,
  // centred 2 m away, behind one water ball and in front of another.
  const float r = 0.3f;
  balls::ObstacleParams o;
  o.shape = balls::Shape::Sphere;
  o.size = glm::vec3(0.36f);
  const std::vector<MeshVertex> sphere = ballUnionMesh(balls::Obstacle(o, 0.04f).particles(), 0.04f);
  ASSERT_FALSE(sphere.empty());
  const gl::Buffer mesh{std::span<const MeshVertex>(sphere)}, water = ballsAt({3.0f, 1.2f});
  Frame f(shaders());
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
