// The balls view draws a mesh obstacle as its triangles, where its fixed particles are (one
// transform, spin included); other obstacles as the surface of their balls; a hidden obstacle
// leaves no pixel.
#include <gtest/gtest.h>

#include "render/balls_view.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;

namespace {

class BallsViewObstacleTest : public test::GlTest {};

// Pixels that are not the background colour.
std::vector<bool> covered(BallsView& view, const Balls& model, RenderTarget& target) {
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

std::size_t count(const std::vector<bool>& v) { return std::size_t(std::count(v.begin(), v.end(), true)); }

std::size_t onlyIn(const std::vector<bool>& a, const std::vector<bool>& b) {  // pixels of a not in b
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] && !b[i];
  return n;
}

}  // namespace

TEST_F(BallsViewObstacleTest, MeshObstacleIsDrawnWhereItsParticlesAreAndTurnsWithThem) {
  Params p;
  p.fill = Fill::None;
  p.radius = 0.01f;
  p.obstacle = Shape::Mesh;
  p.obstacleMesh = "blob";  // no symmetry about the spin axis
  p.obstacleCentre = glm::vec3(0.5f, 0.5f, 0.4f);
  p.obstacleSize = glm::vec3(0.3f);
  p.obstacleSpin = 4.0f;
  p.dt = 1e-3f;
  Balls model(shaders(), p);
  BallsView view(shaders());
  view.params().showBox = false;
  RenderTarget target(128, 128);

  const std::vector<bool> before = covered(view, model, target);
  ASSERT_GT(count(before), 800u);
  for (int i = 0; i < 400; ++i) model.stepOnce();  // 1.6 rad
  const std::vector<bool> mesh = covered(view, model, target);
  EXPECT_GT(onlyIn(mesh, before) + onlyIn(before, mesh), count(mesh) / 10) << "the mesh turned";
  view.params().obstacleBalls = true;
  const std::vector<bool> both = covered(view, model, target);
  // The particles lie inside the mesh or stick out by less than r: a thin rim at most.
  EXPECT_LT(onlyIn(both, mesh), count(mesh) / 12) << "particles and mesh drawn with one transform";
  view.params().showObstacle = false;
  EXPECT_EQ(count(covered(view, model, target)), 0u);

  model.params().obstacle = Shape::Box;  // analytic shapes: the surface built from their balls
  model.stepOnce();
  EXPECT_EQ(model.obstacleMesh(), nullptr);
  view.params().showObstacle = true;
  view.params().obstacleBalls = false;
  EXPECT_GT(count(covered(view, model, target)), 800u);
}
