// Reproducible runs: the same scene stepped twice from a fresh model gives bit-identical
// state, for every model. llvmpipe runs compute on several threads (at least four here:
// LP_NUM_THREADS is raised before the suite makes its context, even over an inherited 1), so an
// order decided by thread timing (the grid's atomicAdd slots) may show up here; the grid's stable
// order within cells (grid/grid.h) removes it. Thread timing only sometimes scrambles that order:
// UniformGridTest.StableOrderDoesNotDependOnTheAtomicSlots scrambles it on purpose.
// The water scenes move an obstacle and run a tap, so those paths are covered too, and bodies.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "io/json.h"
#include "scene/scene.h"
#include "sim/balls/balls.h"
#include "sim/fluid/fluid.h"
#include "sim/life/life.h"
#include "sim/ripples/ripples.h"
#include "sim/swarm/swarm.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class Determinism : public test::GlTest {
 protected:
  static void SetUpTestSuite() {
    // Before llvmpipe starts its threads; a larger setting of the run's own is kept.
    const char* threads = std::getenv("LP_NUM_THREADS");
    if (!threads || std::atoi(threads) < 4) setenv("LP_NUM_THREADS", "4", 1);
    GlTest::SetUpTestSuite();
  }
};

using State = std::vector<std::vector<std::uint8_t>>;

// Steps `frames` frames of 1/60 s and reads every state buffer back, byte for byte.
State run(sim::Model& model, int frames) {
  gl::GpuProfiler profiler;
  for (int f = 0; f < frames; ++f) {
    profiler.beginFrame();
    model.step(profiler);
    profiler.endFrame();
  }
  State state;
  for (const sim::StateBuffer& b : model.stateBuffers()) state.push_back(b.buffer->read<std::uint8_t>(b.bytes));
  return state;
}

// Two fresh models of the same parameters, stepped alike (a few hundred steps each): equal to the
// last bit.
template <class M, class... Args>
void expectReproducible(int frames, Args&... args) {
  M first(args...);
  const State a = run(first, frames);
  M second(args...);
  const State b = run(second, frames);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k].size(), b[k].size()) << "buffer " << k;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a[k].size(); ++i) differing += a[k][i] != b[k][i];
    EXPECT_EQ(differing, 0u) << "buffer " << k << " (" << first.stateBuffers()[k].name << ") differs in " << differing
                             << " of " << a[k].size() << " bytes";
  }
}

Scene waterScene(const char* model, const char* particles) {
  const std::string json = std::string(R"({"model": ")") + model + R"(", "params": {"particles": )" + particles + R"(,
      "tap": {"enabled": true, "position": [0.15, 0.2, 0.4], "direction": [0, 0, -1], "speed": 1.0,
              "radius": 0.05, "max": 600},
      "obstacles": [{"shape": "sphere", "centre": [0.3, 0.2, 0.1], "size": [0.08, 0.08, 0.08],
                     "path": {"kind": "oscillate", "amplitude": [0.1, 0, 0], "period": 0.5}}]}})";
  return parseScene(io::parseJson(json, "determinism.json"), "determinism.json");
}

// Two boxes above the water of a 0.6 × 0.4 m tank, the second turned and denser, falling onto the first.
std::vector<water::ObstacleParams> droppedBoxes() {
  water::ObstacleParams box;
  box.shape = water::Shape::Box;
  box.size = glm::vec3(0.06f, 0.05f, 0.03f);
  box.dynamic = true;
  std::vector<water::ObstacleParams> boxes = {box, box};
  boxes[0].centre = glm::vec3(0.3f, 0.2f, 0.2f);
  boxes[1].centre = glm::vec3(0.34f, 0.22f, 0.3f);
  boxes[1].orientation = glm::vec3(0.0f, 25.0f, 0.0f);
  boxes[1].density = 1500.0f;
  return boxes;
}

}  // namespace

TEST_F(Determinism, Balls) {
  const Scene s = waterScene("balls", R"({"radius": 0.012, "domain_max": [0.6, 0.4, 0.5], "fill": "block",
                                     "fill_min": [0.3, 0, 0], "fill_max": [0.6, 0.4, 0.25]})");
  balls::Params p = s.params.model<balls::Params>();
  p.substeps = 8;
  ASSERT_TRUE(p.deterministic) << "the default";
  expectReproducible<balls::Balls>(30,  // 240 steps
                                   shaders(), p);
}

TEST_F(Determinism, Fluid) {
  const Scene s = waterScene("fluid", R"({"spacing": 0.02, "domain_max": [0.6, 0.4, 0.5], "fill": "block",
                                     "fill_min": [0.3, 0, 0], "fill_max": [0.6, 0.4, 0.2]})");
  fluid::Params p = s.params.model<fluid::Params>();
  p.substeps = 4;
  p.vorticity = 0.01f;  // every pass of the step, XSPH and vorticity included
  expectReproducible<fluid::Fluid>(60, shaders(), p);
}

// Bodies dropped into the water, onto each other and the walls: their loads are group sums added
// in a fixed order, their contacts solved in a fixed order.
TEST_F(Determinism, BallsWithBodies) {
  const Scene s = waterScene("balls", R"({"radius": 0.012, "domain_max": [0.6, 0.4, 0.5], "fill": "block",
                                     "fill_min": [0, 0, 0], "fill_max": [0.6, 0.4, 0.12]})");
  balls::Params p = s.params.model<balls::Params>();
  p.substeps = 8;
  p.obstacles = droppedBoxes();
  expectReproducible<balls::Balls>(30, shaders(), p);
}

TEST_F(Determinism, FluidWithBodies) {
  const Scene s = waterScene("fluid", R"({"spacing": 0.02, "domain_max": [0.6, 0.4, 0.5], "fill": "block",
                                     "fill_min": [0, 0, 0], "fill_max": [0.6, 0.4, 0.12]})");
  fluid::Params p = s.params.model<fluid::Params>();
  p.substeps = 4;
  p.obstacles = droppedBoxes();
  expectReproducible<fluid::Fluid>(60, shaders(), p);
}

TEST_F(Determinism, Life) {
  for (life::Storage storage : {life::Storage::Fp32, life::Storage::Fp16}) {
    SCOPED_TRACE(life::kStorageNames[std::size_t(storage)]);
    const life::Rules rules = life::generateRules({.species = 6, .particleCount = 4096, .size = {256, 192}, .seed = 7});
    life::Params p;
    p.storage = storage;
    expectReproducible<life::Life>(220, shaders(), rules, p);
  }
}

TEST_F(Determinism, Swarm) {
  sim::SwarmParams p;
  p.particles = 8192;
  p.substeps = 1;
  expectReproducible<sim::Swarm>(220, shaders(), p);
}

TEST_F(Determinism, Ripples) {
  ripples::Params p;
  p.width = p.height = 96;
  expectReproducible<ripples::Ripples>(60, shaders(), p);
}
