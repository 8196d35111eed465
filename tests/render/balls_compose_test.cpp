// The balls renderer's compose on fixed spheres (no simulation, so the pictures are the same
// every run): a pool of balls with foam, a sphere mesh sticking out of it and the domain box,
// against reference images, and meshes in front of and behind the water composited the right
// way round. The references were taken from the full-screen fragment compose before the compose
// moved to compute: balls mode with the mesh and the box, water mode with the mesh, and without
// it (nothing for the raster to draw). Water mode with the box is a reference of the compute
// compose: the fragment path drew the box's lines into the scene's depth, so the water behind a
// line pixel lost its thickness there and the blur spread that into a paler band beside each
// line; the compute compose draws the lines without a depth buffer and the band is gone.
//
// Regenerate the reference images (after a deliberate change to the look), then look at them:
//   TIDEPOOL_UPDATE_GOLDEN=1 build/tests/tidepool_tests --gtest_filter='*BallsGolden*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "io/png.h"
#include "render/balls_view.h"
#include "sim/water/water_init.h"
#include "support/gl_test.h"
#include "support/image_diff.h"

using namespace tidepool;

namespace {

constexpr int kWidth = 192, kHeight = 128;
// Per pixel, the largest channel difference (of 255). Away from the box's one-pixel lines the
// images may differ by rounding only; the lines are allowed to step by a pixel here and there.
constexpr int kRounding = 2;               // channel levels
constexpr double kMaxOffFraction = 0.001;  // pixels differing by more than kRounding
constexpr double kMaxMean = 0.15;          // mean over all pixels and channels, levels

struct Difference : test::PixelDifference {
  bool within() const { return mean <= kMaxMean && offFraction <= kMaxOffFraction; }
};

Difference compare(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  return {test::pixelDifference(a, b, kRounding)};
}

std::ostream& operator<<(std::ostream& os, const Difference& d) {
  return os << "mean " << d.mean << " (limit " << kMaxMean << "), pixels off by more than " << kRounding << ": "
            << 100.0 * d.offFraction << "% (limit " << 100.0 * kMaxOffFraction << "%)";
}

// A sphere obstacle's mesh (its balls' surface), radius about `size`.
std::vector<MeshVertex> sphereMesh(float size) {
  water::ObstacleParams o;
  o.shape = water::Shape::Sphere;
  o.size = glm::vec3(size);
  return ballUnionMesh(water::Obstacle(o, 0.02f).particles(), 0.02f);
}

// A pool: three jittered layers of balls r = 2 cm in the unit box's lower part, foamy in one
// corner; a sphere mesh half under the water; the box's wireframe; seen from above and aside.
class Pool {
 public:
  Pool() {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> jitter(-0.006f, 0.006f);
    for (int z = 0; z < 3; ++z)
      for (int y = 0; y < 22; ++y)
        for (int x = 0; x < 22; ++x) {
          const glm::vec3 p = glm::vec3(0.08f + 0.04f * x, 0.08f + 0.04f * y, 0.03f + 0.035f * z) +
                              glm::vec3(jitter(rng), jitter(rng), jitter(rng));
          m_pos.emplace_back(p, 1.0f);
          m_vel.emplace_back(0.0f, 0.0f, 0.0f, x + y < 10 ? 0.9f : 0.0f);
        }
    m_positions = gl::Buffer(std::span<const glm::vec4>(m_pos));
    m_velocities = gl::Buffer(std::span<const glm::vec4>(m_vel));
    m_sphere = sphereMesh(0.2f);
    m_mesh = gl::Buffer(std::span<const MeshVertex>(m_sphere));
  }
  BallsScene scene(bool mesh) const {
    BallsScene s;
    s.water = {&m_positions, &m_velocities, m_pos.size(), 0.02f, glm::mat4(1.0f)};
    if (mesh)
      s.obstacleMeshes = {{&m_mesh, m_sphere.size(), glm::translate(glm::mat4(1.0f), glm::vec3(0.6f, 0.45f, 0.1f))}};
    s.boxMin = glm::vec3(0.0f);
    s.boxMax = glm::vec3(1.0f, 1.0f, 0.6f);
    return s;
  }
  static BallsCamera camera() {
    const glm::mat4 view =
        glm::lookAt(glm::vec3(1.25f, -0.65f, 0.9f), glm::vec3(0.5f, 0.5f, 0.15f), glm::vec3(0, 0, 1));
    return BallsCamera::perspective(view, glm::radians(45.0f), kWidth, kHeight, 0.5f, 5.0f);
  }

 private:
  std::vector<glm::vec4> m_pos, m_vel;
  std::vector<MeshVertex> m_sphere;
  gl::Buffer m_positions, m_velocities, m_mesh;
};

struct Reference {
  const char* name;  // tests/data/golden/compose-<name>.png
  BallsMode mode;
  bool mesh, box;
  BallsRaster raster = BallsRaster::Compute;
};

class BallsGoldenCompose : public test::GlTest, public ::testing::WithParamInterface<Reference> {
 protected:
  static std::vector<std::uint8_t> render(const Reference& r) {
    const Pool pool;
    BallsView view(shaders());
    applyLook(view.params(), WaterLook::Seed);  // the references are the seed's look
    view.params().mode = r.mode;
    view.params().raster = r.raster;
    view.params().showBox = r.box;
    RenderTarget target(kWidth, kHeight);
    gl::GpuProfiler profiler;
    view.render(pool.scene(r.mesh), Pool::camera(), target, profiler);
    return target.readRgba8();
  }
};

std::filesystem::path referencePath(const Reference& r) {
  return std::filesystem::path(TIDEPOOL_TEST_DATA) / "golden" / (std::string("compose-") + r.name + ".png");
}

}  // namespace

TEST_P(BallsGoldenCompose, MatchesTheFragmentComposeReference) {
  const Reference r = GetParam();
  const std::vector<std::uint8_t> image = render(r);
  const char* update = std::getenv("TIDEPOOL_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    if (r.raster != BallsRaster::Compute) GTEST_SKIP() << "the compute raster writes it";
    io::writePng(referencePath(r), {kWidth, kHeight, image});
    GTEST_SKIP() << "wrote " << referencePath(r);
  }
  const io::Image expected = io::readPng(referencePath(r));
  ASSERT_EQ(expected.width, kWidth) << referencePath(r) << ": regenerate it (see the top of this file)";
  ASSERT_EQ(expected.height, kHeight) << referencePath(r) << ": regenerate it (see the top of this file)";
  const Difference d = compare(image, expected.rgba);
  EXPECT_TRUE(d.within()) << referencePath(r) << ": " << d;
  RecordProperty("difference", (std::ostringstream() << d).str());
}

INSTANTIATE_TEST_SUITE_P(Pool, BallsGoldenCompose,
                         ::testing::Values(Reference{"balls", BallsMode::Balls, true, true},
                                           Reference{"water", BallsMode::Water, true, false},
                                           Reference{"water-nomesh", BallsMode::Water, false, false},
                                           Reference{"water-box", BallsMode::Water, true, true},
                                           Reference{"balls", BallsMode::Balls, true, true, BallsRaster::Fragment},
                                           Reference{"water", BallsMode::Water, true, false, BallsRaster::Fragment}),
                         [](const auto& info) {
                           std::string name =
                               std::string(info.param.name) + "_" + kBallsRasterNames[int(info.param.raster)];
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// The metric tells the references apart: it is not loose enough to pass another picture.
TEST_F(BallsGoldenCompose, TheMetricCatchesAnotherPicture) {
  const auto balls = render({"balls", BallsMode::Balls, true, true});
  const Difference modes = compare(balls, render({"water", BallsMode::Water, true, true}));
  EXPECT_FALSE(modes.within()) << "balls mode against water mode: " << modes;
  const Difference mesh = compare(balls, render({"balls", BallsMode::Balls, false, true}));
  EXPECT_FALSE(mesh.within()) << "with and without the obstacle: " << mesh;
}

namespace {

class BallsComposeTest : public test::GlTest {};

constexpr int kSize = 65;
// Eye at the origin looking down -z. Water: one sheet of balls r = 5 cm at 2 m, 0.6 m wide.
// Obstacles: a sphere mesh (radius ~0.1 m) in front of the sheet on the left, one behind it on
// the right.
struct Layout {
  std::vector<glm::vec4> sheet;
  std::vector<MeshVertex> sphere = sphereMesh(0.1f);
  std::pair<glm::vec3, glm::vec3> bounds = meshBounds(sphere);  // the scene pass covers their rectangle only
  Layout() {
    for (int y = -5; y <= 5; ++y)
      for (int x = -5; x <= 5; ++x) sheet.emplace_back(0.06f * x, 0.06f * y, -2.0f, 1.0f);
  }
};

// `stale`: what the target's colour holds before the frame (a frame drawn before it), and its
// depth, 1 (far) when the colour is black, else 0.
std::vector<std::uint8_t> renderLayout(gl::ShaderLibrary& shaders, const Layout& l, BallsMode mode, bool water,
                                       bool front, bool back, glm::vec4 stale = glm::vec4(0.0f)) {
  const gl::Buffer balls{std::span<const glm::vec4>(l.sheet)}, mesh{std::span<const MeshVertex>(l.sphere)};
  BallsScene scene;
  scene.water = {&balls, nullptr, water ? l.sheet.size() : 0, 0.05f, glm::mat4(1.0f)};
  if (front)
    scene.obstacleMeshes.push_back(
        {&mesh, l.sphere.size(), glm::translate(glm::mat4(1.0f), {-0.15f, 0, -1.5f}), l.bounds.first, l.bounds.second});
  if (back)
    scene.obstacleMeshes.push_back(
        {&mesh, l.sphere.size(), glm::translate(glm::mat4(1.0f), {0.15f, 0, -2.5f}), l.bounds.first, l.bounds.second});
  BallsView view(shaders);
  applyLook(view.params(), WaterLook::Seed);  // water that tints what it covers, over a flat background
  view.params().mode = mode;
  view.params().showBox = false;
  view.params().blurRadius = 0.0f;  // a flat sheet: its balls' own normals
  RenderTarget target(kSize, kSize);
  target.bind();
  glClearColor(stale.r, stale.g, stale.b, stale.a);
  glClearDepth(stale == glm::vec4(0.0f) ? 1.0 : 0.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl::GpuProfiler profiler;
  view.render(scene, BallsCamera::perspective(glm::mat4(1.0f), glm::radians(30.0f), kSize, kSize, 0.5f, 10.0f), target,
              profiler);
  return target.readRgba8();
}

glm::ivec3 pixel(const std::vector<std::uint8_t>& rgba, glm::vec3 viewPoint) {  // the pixel showing a view point
  const float focal = 1.0f / std::tan(glm::radians(15.0f));
  const glm::vec2 ndc = glm::vec2(viewPoint) * focal / -viewPoint.z;
  const glm::ivec2 px = glm::ivec2((0.5f * ndc + 0.5f) * float(kSize));
  const std::uint8_t* p = &rgba[(std::size_t(kSize - 1 - px.y) * kSize + px.x) * 4];
  return {p[0], p[1], p[2]};
}

int largest(glm::ivec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

TEST_F(BallsComposeTest, MeshesInFrontOfTheWaterHideItAndMeshesBehindShowThroughWaterOnly) {
  const Layout l;
  const glm::vec3 front(-0.15f, 0.0f, -1.45f), back(0.15f, 0.0f, -2.45f);  // points on the meshes' near sides
  for (BallsMode mode : {BallsMode::Balls, BallsMode::Water}) {
    SCOPED_TRACE(kBallsModeNames[int(mode)]);
    const auto all = renderLayout(shaders(), l, mode, true, true, true);
    const auto meshes = renderLayout(shaders(), l, mode, false, true, true);
    const auto water = renderLayout(shaders(), l, mode, true, false, false);
    EXPECT_LE(largest(pixel(all, front) - pixel(meshes, front)), 1) << "the front mesh hides the water";
    EXPECT_GT(largest(pixel(water, front) - pixel(meshes, front)), 20) << "where the water alone looks otherwise";
    const int through = largest(pixel(all, back) - pixel(water, back));
    if (mode == BallsMode::Balls) {
      EXPECT_LE(through, 1) << "opaque balls hide the mesh behind them";
    } else {
      EXPECT_GT(through, 20) << "the mesh behind shows through the thin water";
      EXPECT_GT(largest(pixel(all, back) - pixel(meshes, back)), 20) << "tinted by it";
    }
  }
}

// The scene pass clears depth only, and only in the meshes' window rectangle; the compose must
// take the background wherever no mesh was drawn, whatever the target's colour and depth held.
TEST_F(BallsComposeTest, LastFramesColourAndDepthNeverShow) {
  const Layout l;
  for (BallsMode mode : {BallsMode::Balls, BallsMode::Water}) {
    SCOPED_TRACE(kBallsModeNames[int(mode)]);
    const auto fresh = renderLayout(shaders(), l, mode, true, true, true);
    const auto stale = renderLayout(shaders(), l, mode, true, true, true, glm::vec4(1.0f, 0.0f, 1.0f, 1.0f));
    EXPECT_EQ(fresh, stale);
  }
}

TEST(MeshesWindowRect, HoldsEveryMeshAndFallsBackToTheWindow) {
  const BallsCamera camera = BallsCamera::perspective(glm::mat4(1.0f), glm::radians(30.0f), 200, 100, 0.5f, 10.0f);
  const std::vector<MeshVertex> sphere = sphereMesh(0.1f);
  BallsScene scene;
  EXPECT_EQ(meshesWindowRect(scene, camera).max, glm::ivec2(0)) << "nothing to draw: an empty rectangle";
  MeshBatch mesh{nullptr, sphere.size(), glm::translate(glm::mat4(1.0f), {0.2f, -0.1f, -2.0f}), glm::vec3(-0.1f),
                 glm::vec3(0.1f)};
  scene.obstacleMeshes = {mesh};
  const WindowRect r = meshesWindowRect(scene, camera);
  for (const MeshVertex& v : sphere) {  // every vertex projects inside, a pixel in from the edge
    const glm::vec4 clip = camera.proj * mesh.model * v.position;
    const glm::vec2 px = (0.5f * glm::vec2(clip) / clip.w + 0.5f) * glm::vec2(200, 100);
    EXPECT_GE(px.x, float(r.min.x + 1));
    EXPECT_GE(px.y, float(r.min.y + 1));
    EXPECT_LE(px.x, float(r.max.x - 1));
    EXPECT_LE(px.y, float(r.max.y - 1));
  }
  EXPECT_LT((r.max.x - r.min.x) * (r.max.y - r.min.y), 200 * 100 / 8) << "a small mesh: a small rectangle";
  const auto whole = [&](const BallsScene& s) {
    const WindowRect w = meshesWindowRect(s, camera);
    return w.min == glm::ivec2(0) && w.max == glm::ivec2(200, 100);
  };
  BallsScene near = scene;
  near.obstacleMeshes[0].model = glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -0.55f});
  EXPECT_TRUE(whole(near)) << "a mesh through the near plane";
  BallsScene unknown = scene;
  unknown.obstacleMeshes[0].boundsMin = glm::vec3(1.0f);
  unknown.obstacleMeshes[0].boundsMax = glm::vec3(-1.0f);
  EXPECT_TRUE(whole(unknown)) << "unknown bounds";
  BallsScene withBalls = scene;
  withBalls.obstacle.count = 10;
  EXPECT_TRUE(whole(withBalls)) << "the obstacles' balls are drawn";
}

TEST(BoxEdges, ProjectToTheWindowAndClipToTheDepthRange) {
  const glm::ivec2 size(200, 100);
  const glm::mat4 proj = glm::perspective(glm::radians(50.0f), 2.0f, 0.5f, 5.0f);
  const glm::vec3 lo(-0.5f), hi(0.5f);
  // Wholly in view: 12 edges, each end the corner's projection.
  const glm::mat4 clip = proj * glm::lookAt(glm::vec3(1.5f, -2.0f, 1.0f), glm::vec3(0.0f), glm::vec3(0, 0, 1));
  const std::vector<glm::vec4> whole = boxEdgesInWindow(lo, hi, clip, size);
  ASSERT_EQ(whole.size(), 24u);
  for (std::size_t i = 0; i < whole.size(); ++i) {
    bool isCorner = false;
    for (int c = 0; c < 8; ++c) {
      const glm::vec4 p = clip * glm::vec4(glm::mix(lo, hi, glm::vec3(c & 1, (c >> 1) & 1, c >> 2)), 1.0f);
      const glm::vec3 ndc = glm::vec3(p) / p.w;
      const glm::vec3 window((0.5f * ndc.x + 0.5f) * 200.0f, (0.5f * ndc.y + 0.5f) * 100.0f, 0.5f * ndc.z + 0.5f);
      isCorner = isCorner || glm::all(glm::lessThan(glm::abs(glm::vec3(whole[i]) - window), glm::vec3(1e-3f)));
    }
    EXPECT_TRUE(isCorner) << "end " << i;
  }
  // The eye inside the box looking along +x: the four edges along x are cut at the near plane
  // (window depth 0) and the far ones at x = 0.5 kept; the edges of the face behind the eye go.
  const glm::mat4 inside = proj * glm::lookAt(glm::vec3(-0.2f, 0.0f, 0.0f), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1));
  const std::vector<glm::vec4> cut = boxEdgesInWindow(lo, hi, inside, size);
  EXPECT_EQ(cut.size(), 2u * 8u);
  int atNear = 0;
  for (const glm::vec4& p : cut) {
    EXPECT_GE(p.z, -1e-5f);
    EXPECT_LE(p.z, 1.0f + 1e-5f);
    atNear += std::abs(p.z) < 1e-4f;
  }
  EXPECT_EQ(atNear, 4);
}
