// The balls view's debug views: the grid cells overlay compacts exactly the non-empty
// cells of the grid (its indirect command counts them, its list names them, in index order), on a
// grid of its own and on a balls model's; the screen-space normals view shows the view-space
// normal where the world normals view shows the same normal in world axes.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "render/balls_view.h"
#include "sim/balls/balls.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

using BallsViewTest = test::GlTest;

// Non-empty cells of a count array, in index order (the CPU reference of the compaction).
std::vector<std::uint32_t> nonEmpty(const std::vector<std::uint32_t>& counts) {
  std::vector<std::uint32_t> out;
  for (std::size_t c = 0; c < counts.size(); ++c)
    if (counts[c] > 0) out.push_back(std::uint32_t(c));
  return out;
}

}  // namespace

TEST_F(BallsViewTest, GridCellsCompactionListsExactlyTheNonEmptyCells) {
  // Clustered points in grids of 64 to 27000 cells (several scan blocks), and an empty grid.
  std::mt19937 rng(5);
  for (const float cellSize : {0.25f, 0.1f, 1.0f / 30.0f}) {
    for (const std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(700)}) {
      SCOPED_TRACE(testing::Message() << "cell " << cellSize << ", " << n << " points");
      std::normal_distribution<float> cluster(0.5f, 0.12f);
      std::vector<glm::vec4> pos;
      for (std::size_t i = 0; i < n; ++i) pos.emplace_back(cluster(rng), cluster(rng), cluster(rng), 1.0f);
      const gl::Buffer buffer(std::max<std::size_t>(pos.size(), 1) * sizeof(glm::vec4), pos.data());
      grid::UniformGrid grid(shaders(), {.cellSize = cellSize});
      grid.build(buffer, n);
      BallsGridCells cells(shaders());
      cells.compact(grid);
      const std::vector<std::uint32_t> want = nonEmpty(grid::reference::histogram(grid.shape(), pos));
      EXPECT_EQ(cells.drawnCells(), want.size());
      EXPECT_EQ(cells.cellIds(), want);
      const std::vector<std::uint32_t> header = cells.list().read<std::uint32_t>(4);
      EXPECT_EQ(header[0], 24u) << "a cube's 12 edges as GL_LINES";
      EXPECT_EQ(header[2], 0u);
      EXPECT_EQ(header[3], 0u);
    }
  }
}

TEST_F(BallsViewTest, GridCellsOverlayDrawsTheModelsNonEmptyCells) {
  balls::Params p;
  p.radius = 0.02f;
  p.fillMax = {0.3f, 0.4f, 0.3f};
  balls::Balls model(shaders(), p);
  gl::GpuProfiler profiler;
  profiler.setEnabled(false);
  model.step(profiler);
  ASSERT_NE(model.neighbourGrid(), nullptr);
  const grid::UniformGrid& grid = *model.neighbourGrid();
  BallsView view(shaders());
  RenderTarget target(96, 96);
  view.render(model, target, profiler);
  const std::vector<std::uint8_t> plain = target.readRgba8();
  for (const GridCellsMode mode : {GridCellsMode::Population, GridCellsMode::NonEmpty}) {
    view.params().gridCells = mode;
    view.render(model, target, profiler);
    const std::vector<std::uint32_t> want = nonEmpty(grid.cellCount().read<std::uint32_t>(grid.cells()));
    EXPECT_GT(want.size(), 10u);
    EXPECT_EQ(view.gridCells().drawnCells(), want.size());
    EXPECT_EQ(view.gridCells().cellIds(), want);
    const std::vector<std::uint8_t> drawn = target.readRgba8();
    std::size_t changed = 0;
    for (std::size_t i = 0; i < drawn.size(); i += 4) changed += drawn[i] != plain[i] || drawn[i + 2] != plain[i + 2];
    EXPECT_GT(changed, 200u) << "pixels of cell edges";
  }
}

TEST_F(BallsViewTest, ScreenNormalsFaceTheViewerWhereWorldNormalsFaceTheEye) {
  // One ball at the origin seen from an oblique eye: at the image centre the surface faces the
  // eye, so its view-space normal is +z (colour 0.5, 0.5, 1) and its world normal the unit vector
  // towards the eye.
  constexpr int kSize = 65;
  const glm::vec3 eye(1.6f, -1.2f, 0.9f);
  const BallsCamera camera = BallsCamera::perspective(glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 0, 1)),
                                                      glm::radians(40.0f), kSize, kSize, 0.5f, 5.0f);
  const std::vector<glm::vec4> pos = {{0.0f, 0.0f, 0.0f, 1.0f}};
  const gl::Buffer balls{std::span<const glm::vec4>(pos)};
  BallsScene scene;
  scene.water = {&balls, nullptr, 1, 0.4f, glm::mat4(1.0f)};
  BallsView view(shaders());
  view.params().mode = BallsMode::Balls;
  view.params().showBox = false;
  RenderTarget target(kSize, kSize);
  gl::GpuProfiler profiler;
  profiler.setEnabled(false);
  const auto centre = [&](BallsDebug debug) {
    view.params().debug = debug;
    view.render(scene, camera, target, profiler);
    const std::vector<std::uint8_t> rgba = target.readRgba8();
    const std::size_t i = (std::size_t(kSize / 2) * kSize + kSize / 2) * 4;
    return glm::vec3(rgba[i], rgba[i + 1], rgba[i + 2]) / 255.0f * 2.0f - 1.0f;
  };
  const glm::vec3 screen = centre(BallsDebug::ScreenNormals), world = centre(BallsDebug::Normals);
  EXPECT_NEAR(screen.x, 0.0f, 0.02f);
  EXPECT_NEAR(screen.y, 0.0f, 0.02f);
  EXPECT_NEAR(screen.z, 1.0f, 0.02f);
  const glm::vec3 towardsEye = glm::normalize(eye);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(world[k], towardsEye[k], 0.03f) << "axis " << k;
}
