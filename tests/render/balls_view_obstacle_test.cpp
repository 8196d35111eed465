// The balls view draws a mesh obstacle as its triangles, where its fixed particles are (one
// transform, spin included); other obstacles as the surface of their balls; a hidden obstacle
// leaves no pixel; several obstacles each follow their own pose, meshed once, not every frame.
#include <gtest/gtest.h>

#include "render/balls_view.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;
using namespace tidepool::water;

namespace {

using BallsViewTest = test::GlTest;

// A model of the obstacles alone (no water, balls of 1 cm, 1 ms steps) and its view without the
// domain box (only the obstacles cover pixels), 128x128 pixels.
struct Drawn {
  Drawn(gl::ShaderLibrary& shaders, const std::vector<ObstacleParams>& obstacles)
      : model(shaders, params(obstacles)), view(shaders) {
    applyLook(view.params(), WaterLook::Seed);  // a flat background, which covered() tells apart
    view.params().showBox = false;
  }

  static Params params(const std::vector<ObstacleParams>& obstacles) {
    Params p;
    p.fill = Fill::None;
    p.radius = 0.01f;
    p.dt = 1e-3f;
    p.obstacles = obstacles;
    return p;
  }

  // Pixels that are not the background colour.
  std::vector<bool> covered() {
    gl::GpuProfiler profiler;
    profiler.setEnabled(false);
    view.render(model, target, profiler);
    const std::vector<std::uint8_t> rgba = target.readRgba8();
    const glm::vec3 bg = view.params().background * 255.0f;
    std::vector<bool> out(rgba.size() / 4);
    for (std::size_t i = 0; i < out.size(); ++i)
      for (int c = 0; c < 3; ++c) out[i] = out[i] || std::abs(float(rgba[4 * i + c]) - bg[c]) > 3.0f;
    return out;
  }

  Balls model;
  BallsView view;
  RenderTarget target{128, 128};
};

std::size_t count(const std::vector<bool>& v) { return std::size_t(std::count(v.begin(), v.end(), true)); }

std::size_t onlyIn(const std::vector<bool>& a, const std::vector<bool>& b) {  // pixels of a not in b
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] && !b[i];
  return n;
}

}  // namespace

TEST_F(BallsViewTest, MeshObstacleIsDrawnWhereItsParticlesAreAndTurnsWithThem) {
  ObstacleParams blob;
  blob.shape = Shape::Mesh;
  blob.mesh = "blob";  // no symmetry about the spin axis
  blob.centre = glm::vec3(0.5f, 0.5f, 0.4f);
  blob.size = glm::vec3(0.3f);
  blob.spin = 4.0f;
  Drawn s(shaders(), {blob});

  const std::vector<bool> before = s.covered();
  ASSERT_GT(count(before), 800u);
  for (int i = 0; i < 400; ++i) s.model.stepOnce();  // 1.6 rad
  const std::vector<bool> mesh = s.covered();
  EXPECT_GT(onlyIn(mesh, before) + onlyIn(before, mesh), count(mesh) / 10) << "the mesh turned";
  s.view.params().obstacleBalls = true;
  const std::vector<bool> both = s.covered();
  // The particles lie inside the mesh or stick out by less than r: a thin rim at most.
  EXPECT_LT(onlyIn(both, mesh), count(mesh) / 12) << "particles and mesh drawn with one transform";
  s.view.params().showObstacle = false;
  EXPECT_EQ(count(s.covered()), 0u);

  s.model.params().obstacles[0].shape = Shape::Box;  // analytic shapes: the surface built from their balls
  s.model.stepOnce();
  EXPECT_EQ(s.model.obstacles().body(0).mesh, nullptr);
  s.view.params().showObstacle = true;
  s.view.params().obstacleBalls = false;
  EXPECT_GT(count(s.covered()), 800u);
}

TEST_F(BallsViewTest, EachObstacleFollowsItsOwnPoseAndIsMeshedOnce) {
  ObstacleParams helix;  // turning about its vertical axis
  helix.shape = Shape::Helix;
  helix.centre = glm::vec3(0.3f, 0.5f, 0.2f);
  helix.size = glm::vec3(0.15f, 0.15f, 0.3f);
  helix.spin = 3.0f;
  ObstacleParams box;  // tilted, going round a circle and tumbling about x
  box.shape = Shape::Box;
  box.centre = glm::vec3(0.7f, 0.5f, 0.5f);
  box.size = glm::vec3(0.1f, 0.05f, 0.03f);
  box.orientation = glm::vec3(0.0f, 30.0f, 0.0f);
  box.spin = 2.0f;
  box.spinAxis = glm::vec3(1.0f, 0.0f, 0.0f);
  box.path.kind = PathKind::Circle;
  box.path.amplitude = glm::vec3(0.1f, 0.1f, 0.1f);
  box.path.period = 1.0f;
  Drawn s(shaders(), {helix, box});

  const std::vector<bool> start = s.covered();
  ASSERT_GT(count(start), 800u);
  EXPECT_EQ(s.view.obstacleMeshes().size(), 2u);
  EXPECT_EQ(s.view.obstacleMeshes().builds(), 2u);
  for (int frame = 0; frame < 6; ++frame) {
    for (int i = 0; i < 60; ++i) s.model.stepOnce();
    const std::vector<bool> mesh = s.covered();
    s.view.params().obstacleBalls = true;
    const std::vector<bool> both = s.covered();
    s.view.params().obstacleBalls = false;
    SCOPED_TRACE(frame);
    EXPECT_LT(onlyIn(both, mesh), count(mesh) / 12) << "every obstacle's balls inside its own mesh";
    if (frame == 2) EXPECT_GT(onlyIn(mesh, start) + onlyIn(start, mesh), count(mesh) / 10) << "they moved";
  }
  EXPECT_EQ(s.view.obstacleMeshes().builds(), 2u) << "moving obstacles are not meshed again";
  s.model.params().obstacles.erase(s.model.params().obstacles.begin());  // the helix goes: nothing rebuilt
  s.model.stepOnce();
  s.covered();
  EXPECT_EQ(s.view.obstacleMeshes().size(), 1u);
  EXPECT_EQ(s.view.obstacleMeshes().builds(), 2u);
}
