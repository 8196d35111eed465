// Scenes that grow with the GPU: particles.resolution refines a water scene's spacing
// keeping its physical setup; the window edits it live; --fit-gpu measures the finest that fits.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "app/fit_gpu.h"
#include "scene/balls_stage.h"
#include "scene/fluid_stage.h"
#include "scene/scene.h"
#include "sim/water/water_init.h"
#include "support/gl_test.h"
#include "support/null_visitor.h"

using namespace tidepool;

namespace {

io::Json atResolution(double r) { return io::Json{{"particles", {{"resolution", r}}}}; }

const balls::Params& ballsOf(const Scene& s) { return s.params.model<balls::Params>(); }

// A small dam break of ~1300 balls (substeps 2): quick on llvmpipe at resolution 1 to 2.
io::Json smallDam() {
  return io::parseJson(R"({"model": "balls", "params": {
      "particles": {"radius": 0.01, "domain_max": [0.4, 0.1, 0.3], "fill": "block", "fill_max": [0.1, 0.1, 0.2]},
      "engine": {"dt": 0.0005, "substeps": 2, "contact_time": 0.005}},
      "clip": {"width": 64, "height": 36}})",
                       "dam.json");
}

long countOf(const Stage& stage) {
  std::smatch m;
  const std::string status = stage.status();
  return std::regex_search(status, m, std::regex(R"((\d+) (balls|particles))")) ? std::stol(m[1]) : -1;
}

// Sets particles.resolution as the panel would.
struct SetResolution : test::NullVisitor {
  float value = 1;
  void real(const ParamInfo& info, float& v, float, float) override {
    if (std::string(info.key) == "resolution") v = value;
  }
};

// Reads the time step as the panel shows it.
struct ReadDt : test::NullVisitor {
  float dt = 0;
  void real(const ParamInfo& info, float& v, float, float) override {
    if (std::string(info.key) == "dt") dt = v;
  }
};

class Resolution : public test::GlTest {};

// `run` throws one line of Error containing `expected`.
template <class F>
void expectError(F run, const std::string& expected) {
  try {
    run();
    ADD_FAILURE() << "no error; expected one with: " << expected;
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(expected), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace

TEST(ResolutionRefine, KeepsTheSetupAndTheFrameAndScalesWhatDependsOnTheSpacing) {
  const Scene base = loadScene(resolveScenePath("dam-break"));
  const Scene fine = loadScene(resolveScenePath("dam-break"), atResolution(4));
  const balls::Params &a = ballsOf(base), &b = ballsOf(fine);
  EXPECT_FLOAT_EQ(a.resolution, 1.0f);
  EXPECT_FLOAT_EQ(b.resolution, 4.0f);
  EXPECT_FLOAT_EQ(b.radius, a.radius / 4);
  EXPECT_FLOAT_EQ(b.contactTime, a.contactTime / 4);
  EXPECT_EQ(b.substeps, a.substeps * 4);
  EXPECT_NEAR(double(b.dt) * b.substeps, double(a.dt) * a.substeps, 1e-9);  // the same simulated time per frame
  EXPECT_EQ(b.domainMin, a.domainMin);
  EXPECT_EQ(b.domainMax, a.domainMax);
  EXPECT_EQ(b.fillMin, a.fillMin);
  EXPECT_EQ(b.fillMax, a.fillMax);
  EXPECT_EQ(b.randomCount, a.randomCount * 64);
  EXPECT_EQ(b.tapMax, a.tapMax * 64);
  // The water's volume is the same: 64 times the balls of a 64th of the volume each.
  EXPECT_NEAR(water::estimatedWater(b) / water::estimatedWater(a), 64.0, 64.0 * 0.05);
}

TEST(ResolutionRefine, RefiningAndCoarseningComeBack) {
  balls::Params p = ballsOf(loadScene(resolveScenePath("dam-break")));
  const balls::Params start = p;
  balls::refine(p, 3.0);
  balls::refine(p, 1.0 / 3.0);
  EXPECT_FLOAT_EQ(p.radius, start.radius);
  EXPECT_EQ(p.substeps, start.substeps);
  EXPECT_NEAR(p.dt, start.dt, 1e-9);
  EXPECT_NEAR(p.resolution, 1.0f, 1e-6);
  EXPECT_EQ(p.randomCount, start.randomCount);
}

TEST(ResolutionRefine, FluidScenesRefineTheirSpacing) {
  const Scene base = loadScene(resolveScenePath("dam-break-fluid"));
  const Scene fine = loadScene(resolveScenePath("dam-break-fluid"), atResolution(2));
  const fluid::Params &a = base.params.model<fluid::Params>(), &b = fine.params.model<fluid::Params>();
  EXPECT_FLOAT_EQ(b.spacing(), a.spacing() / 2);
  EXPECT_EQ(b.substeps, a.substeps * 2);
  EXPECT_NEAR(double(b.dt) * b.substeps, double(a.dt) * a.substeps, 1e-9);
  EXPECT_FLOAT_EQ(b.resolution, 2.0f);
}

TEST(ResolutionRefine, PastALimitIsRefusedByName) {
  expectError([] { loadScene(resolveScenePath("dam-break"), atResolution(60)); },
              "substeps per frame (engine.substeps allows 1000)");
  io::Json random = io::Json{{"particles", {{"fill", "random"}, {"random_count", 1 << 24}, {"resolution", 8}}}};
  expectError([&] { loadScene(resolveScenePath("dam-break"), random); }, "at most 2^30");
  expectError([] { loadScene(resolveScenePath("life"), atResolution(2)); }, "params.particles: unknown key");
}

TEST_F(Resolution, TheModelBuildsTheRefinedWater) {
  const Scene base = parseScene(smallDam(), "dam.json");
  io::Json twice = smallDam();
  twice["params"]["particles"]["resolution"] = 2;
  const Scene fine = parseScene(twice, "dam.json");
  const long n1 = countOf(*createStage(base, shaders())), n2 = countOf(*createStage(fine, shaders()));
  ASSERT_GT(n1, 100);
  // 8 times, but for the lattice's layers at the edges of so small a block (255 -> 2448): R² or R⁴ fail.
  EXPECT_NEAR(double(n2) / double(n1), 8.0, 8.0 * 0.25) << n1 << " -> " << n2;
}

TEST_F(Resolution, AnEditInThePanelRefinesTheLiveParametersAndRebuilds) {
  auto stage = createStage(parseScene(smallDam(), "dam.json"), shaders());
  gl::GpuProfiler profiler;
  stage->step(profiler);
  const long before = countOf(*stage);
  ReadDt dt;
  stage->visitParams(dt);
  SetResolution edit;
  edit.value = 2;
  stage->visitParams(edit);
  stage->step(profiler);  // the step applies it
  ReadDt after;
  stage->visitParams(after);
  EXPECT_FLOAT_EQ(after.dt, dt.dt / 2);
  EXPECT_NEAR(double(countOf(*stage)) / double(before), 8.0, 8.0 * 0.25) << stage->status();
  EXPECT_LT(stage->simTime(), 2.0 / 60);  // the new particles start at t = 0: one frame since
  edit.value = 64;                        // 512 substeps is fine, 2^18 times the balls is not for this test's device
  stage->visitParams(edit);
  stage->step(profiler);
  const std::string status = stage->status();
  if (status.find("resolution not changed") != std::string::npos) {  // refused by name, the old run kept
    ReadDt kept;
    stage->visitParams(kept);
    EXPECT_FLOAT_EQ(kept.dt, dt.dt / 2);
    EXPECT_NE(status.find("balls"), std::string::npos) << status;
  }
}

TEST_F(Resolution, FitGpuPicksTheFinestMeasuredToFit) {
  const test::TempDir dir;
  const auto file = dir / "dam.json";
  io::writeJsonFile(file, smallDam());
  FitOptions o;
  o.width = 64;
  o.height = 36;
  o.frames = 2;
  o.maxResolution = 2.5;
  o.budgetMs = 1e6;  // everything fits: the search climbs to the cap
  FitResult fit = fitResolution(file, io::Json(), shaders(), o);
  ASSERT_FALSE(fit.trials.empty());
  EXPECT_DOUBLE_EQ(fit.resolution, 2.5) << fit.table();
  for (const FitTrial& t : fit.trials) {
    EXPECT_TRUE(t.refused.empty()) << t.refused;
    EXPECT_GT(t.frameMs, 0.0);
    EXPECT_EQ(t.fits, t.frameMs <= o.budgetMs);
  }
  // The particle counts grow as R³.
  const FitTrial &first = fit.trials.front(), &last = fit.trials.back();
  EXPECT_NEAR(double(last.particles) / double(first.particles), std::pow(last.resolution / first.resolution, 3.0),
              0.2 * std::pow(last.resolution / first.resolution, 3.0));
  io::Json picked = withFittedResolution(fit, io::Json(), o.budgetMs);
  EXPECT_DOUBLE_EQ(picked["particles"]["resolution"].get<double>(), 2.5);

  o.budgetMs = 1e-3;  // nothing fits: one line, with the coarsest tried and the budget
  fit = fitResolution(file, io::Json(), shaders(), o);
  EXPECT_EQ(fit.resolution, 0.0);
  for (const FitTrial& t : fit.trials) EXPECT_FALSE(t.fits);
  expectError([&] { withFittedResolution(fit, io::Json(), o.budgetMs); }, "over the budget");
}

TEST_F(Resolution, FitGpuMeasuresOnlyWater) {
  expectError([&] { fitResolution(resolveScenePath("life"), io::Json(), shaders(), FitOptions{}); }, "water");
}
