// The 3D views' projections: the orbit camera's perspective and orthographic matrices
// against hand-computed values, its rays (parallel when orthographic), BallsCamera's depth range
// read back from either matrix; and an orthographic balls picture in which two equal balls at
// different depths have the same size, with either raster.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "render/balls_view.h"
#include "render/orbit_camera.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

// Target at the origin, 2 m away, 60° vertical field, bounding sphere of radius 0.5 at the target:
// near and far 2 -+ 1.5 x 0.5 = 1.25 and 2.75.
OrbitCamera camera(Projection projection) {
  OrbitCamera c;
  c.params() = {.target = glm::vec3(0.0f),
                .distance = 2.0f,
                .yaw = 0.3f,
                .pitch = 0.4f,
                .fovDegrees = 60.0f,
                .projection = projection};
  c.fit(glm::vec3(0.0f), 0.5f);
  return c;
}

void expectMatrix(const glm::mat4& got, const glm::mat4& want) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(got[c][r], want[c][r], 1e-5f) << "column " << c << ", row " << r;
}

}  // namespace

TEST(OrbitCamera, PerspectiveMatrixIsTheHandComputedOne) {
  // aspect 2: P00 = 1 / (2 tan 30°), P11 = 1 / tan 30°, P22 = -(f + n) / (f - n) = -4 / 1.5,
  // P32 = -2fn / (f - n) = -6.875 / 1.5, P23 = -1.
  const float t = std::tan(glm::radians(30.0f));
  glm::mat4 want(0.0f);
  want[0][0] = 1.0f / (2.0f * t);
  want[1][1] = 1.0f / t;
  want[2][2] = -4.0f / 1.5f;
  want[3][2] = -6.875f / 1.5f;
  want[2][3] = -1.0f;
  expectMatrix(camera(Projection::Perspective).projection(2.0f), want);
}

TEST(OrbitCamera, OrthographicMatrixIsTheHandComputedOne) {
  // Half height distance x tan 30° = 1.1547 (as wide as the perspective view at the target),
  // half width twice that: P00 = 1 / 2.3094, P11 = 1 / 1.1547, P22 = -2 / (f - n),
  // P32 = -(f + n) / (f - n), P33 = 1.
  const float h = 2.0f * std::tan(glm::radians(30.0f));
  glm::mat4 want(0.0f);
  want[0][0] = 1.0f / (2.0f * h);
  want[1][1] = 1.0f / h;
  want[2][2] = -2.0f / 1.5f;
  want[3][2] = -4.0f / 1.5f;
  want[3][3] = 1.0f;
  const glm::mat4 proj = camera(Projection::Orthographic).projection(2.0f);
  expectMatrix(proj, want);
  const BallsCamera balls = BallsCamera::of(glm::mat4(1.0f), proj, 200, 100);
  EXPECT_TRUE(balls.isOrthographic());
  EXPECT_NEAR(balls.near, 1.25f, 1e-5f);
  EXPECT_NEAR(balls.far, 2.75f, 1e-5f);
  const BallsCamera persp =
      BallsCamera::of(glm::mat4(1.0f), camera(Projection::Perspective).projection(2.0f), 200, 100);
  EXPECT_FALSE(persp.isOrthographic());
  EXPECT_NEAR(persp.near, 1.25f, 1e-5f);
  EXPECT_NEAR(persp.far, 2.75f, 1e-5f);
}

TEST(OrbitCamera, OrthographicRaysAreParallelAndStartOnTheEyesPlane) {
  const OrbitCamera c = camera(Projection::Orthographic);
  const glm::ivec2 viewport(200, 100);
  const glm::vec3 forward = glm::normalize(-c.eye());
  const glm::mat4 v = c.view();
  const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
  const float h = 2.0f * std::tan(glm::radians(30.0f));
  for (const glm::vec2 pixel : {glm::vec2(100, 50), glm::vec2(0, 0), glm::vec2(200, 100), glm::vec2(30, 80)}) {
    const glm::vec3 dir = c.rayDirection(pixel, viewport), origin = c.rayOrigin(pixel, viewport);
    EXPECT_NEAR(glm::distance(dir, forward), 0.0f, 1e-5f);
    // Pixel (0, 0) is the top left: x from -2h to 2h, y from h down to -h.
    const glm::vec3 want = c.eye() + (pixel.x / 50.0f - 2.0f) * h * right + (1.0f - pixel.y / 50.0f) * h * up;
    EXPECT_NEAR(glm::distance(origin, want), 0.0f, 1e-4f) << pixel.x << "," << pixel.y;
  }
  const OrbitCamera p = camera(Projection::Perspective);
  EXPECT_EQ(p.rayOrigin({0, 0}, viewport), p.eye());
  EXPECT_GT(glm::distance(p.rayDirection({0, 0}, viewport), forward), 0.1f);
}

namespace {

class OrthographicBallsTest : public test::GlTest, public ::testing::WithParamInterface<BallsRaster> {};

// Pixel columns a ball covers on the G-buffer's row through its centre (the eye looks down -z).
int widthOnRow(const std::vector<glm::vec4>& surface, int size, int row, int fromX, int toX) {
  int n = 0;
  for (int x = fromX; x < toX; ++x) n += surface[std::size_t(row) * size + x].a > 0.0f;
  return n;
}

}  // namespace

TEST_P(OrthographicBallsTest, EqualBallsAtDifferentDepthsHaveTheSameSize) {
  // Balls of r = 0.25 at x = -0.5 (1.5 m deep) and x = +0.5 (4 m deep), 2 m of picture over 101 px:
  // both 0.5 m = 25.25 px wide in the orthographic view; the perspective one shrinks the far one.
  constexpr int kSize = 101;
  const std::vector<glm::vec4> pos = {{-0.5f, 0.0f, -1.5f, 1.0f}, {0.5f, 0.0f, -4.0f, 1.0f}};
  const gl::Buffer balls{std::span<const glm::vec4>(pos)};
  BallsScene scene;
  scene.water = {&balls, nullptr, 2, 0.25f, glm::mat4(1.0f)};
  BallsView view(shaders());
  view.params().raster = GetParam();
  view.params().mode = BallsMode::Balls;
  view.params().showBox = false;
  RenderTarget target(kSize, kSize);
  gl::GpuProfiler profiler;
  profiler.setEnabled(false);
  view.render(scene, BallsCamera::orthographic(glm::mat4(1.0f), 1.0f, kSize, kSize, -1.0f, 6.0f), target, profiler);
  std::vector<glm::vec4> surface(std::size_t(kSize) * kSize);
  view.gbuffer().surface().download(GL_RGBA, GL_FLOAT, surface.data());
  const int nearWidth = widthOnRow(surface, kSize, kSize / 2, 0, kSize / 2);
  const int farWidth = widthOnRow(surface, kSize, kSize / 2, kSize / 2 + 1, kSize);
  EXPECT_NEAR(nearWidth, 25, 1);
  EXPECT_EQ(nearWidth, farWidth);
  // Front depths: 1.5 - r and 4 - r at the centres' pixels (x = 25 and 75), normals +z.
  const glm::vec4 a = surface[std::size_t(kSize / 2) * kSize + 25], b = surface[std::size_t(kSize / 2) * kSize + 75];
  EXPECT_NEAR(a.a, 1.25f, 1e-3f);
  EXPECT_NEAR(b.a, 3.75f, 1e-3f);
  EXPECT_NEAR(glm::length(glm::vec2(a)), 0.0f, 0.03f);

  view.render(scene, BallsCamera::perspective(glm::mat4(1.0f), glm::radians(60.0f), kSize, kSize, 0.5f, 6.0f), target,
              profiler);
  view.gbuffer().surface().download(GL_RGBA, GL_FLOAT, surface.data());
  EXPECT_GT(widthOnRow(surface, kSize, kSize / 2, 0, kSize / 2),
            2 * widthOnRow(surface, kSize, kSize / 2, kSize / 2 + 1, kSize))
      << "perspective: the nearer ball looks larger";
}

INSTANTIATE_TEST_SUITE_P(Rasters, OrthographicBallsTest, ::testing::Values(BallsRaster::Compute, BallsRaster::Fragment),
                         [](const auto& info) { return std::string(kBallsRasterNames[int(info.param)]); });
