// "model": "auto" for water: balls or fluid, and the fluid's iterations and step, picked from rows
// of the water studies. The rows here are fixtures (tests/data/water-auto/README.md says which
// row decides each pick), read through the real code path: TIDEPOOL_ASSET_DIR points at them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "base/error.h"
#include "scene/balls_stage.h"
#include "scene/fluid_stage.h"
#include "scene/scene.h"
#include "support/accuracy_data.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"
#include "support/run_process.h"
#include "support/scene_error.h"

using namespace tidepool;
using test::sceneError;

namespace {

const std::filesystem::path kFixture = std::filesystem::path(TIDEPOOL_TEST_DATA) / "water-auto";

// A small tank in a water auto scene's params form (a fluid scene's, SI units): a 5 ms frame of
// 5 steps of 1 ms, particles 2 cm apart, a block of 5 x 5 x 5 of them.
std::string waterScene(const std::string& accuracy, const std::string& engine = R"("dt": 0.001, "substeps": 5)",
                       const std::string& more = "") {
  return R"({"model": "auto", "accuracy": )" + accuracy + R"(, "params": {
      "particles": {"spacing": 0.02, "domain_max": [0.2, 0.1, 0.2], "fill": "block",
                    "fill_min": [0, 0, 0], "fill_max": [0.1, 0.1, 0.1]},
      "engine": {)" +
         engine + "}" + more + "}}";
}

Scene load(const std::string& json) { return parseScene(io::parseJson(json, "s.json"), "s.json"); }

// The frame a water auto scene states: its params read as a fluid scene's (dt x substeps, s).
double statedFrame(const std::string& json) {
  const io::Json params = io::parseJson(json, "s.json").at("params");
  const fluid::Params p = readSceneParams<FluidSceneParams>(params, "s.json").as<FluidSceneParams>().model;
  return double(p.dt) * p.substeps;
}

// The frame the scene runs: the picked model's dt x substeps (s).
double frameOf(const Scene& s) {
  if (s.model == "fluid") return double(fluidScene(s).model.dt) * fluidScene(s).model.substeps;
  return double(ballsScene(s).model.dt) * ballsScene(s).model.substeps;
}

class ResolveAutoWater : public ::testing::Test {
 protected:
  test::ScopedAssetDir m_assets{kFixture};
};

class ResolveAutoWaterRun : public test::GlTest {
 protected:
  test::ScopedAssetDir m_assets{kFixture};
};

}  // namespace

// Balls compress: their best row (0.8%) times the margin 2 is above 1%. The fluid with 4
// iterations at dt 2 ms has 0.4%; a row at another spacing (1 iteration, cheaper, 0.01%) is not
// this scene's.
TEST_F(ResolveAutoWater, PicksFluidWhenOnlyTheFluidMeetsATightDensityBound) {
  const Scene s = load(waterScene(R"({"densityError": 0.01})"));
  ASSERT_TRUE(s.autoChoice);
  EXPECT_EQ(s.model, "fluid");
  EXPECT_EQ(s.method, MethodMode::Auto);
  EXPECT_EQ(s.autoChoice->model, "fluid");
  const fluid::Params& p = fluidScene(s).model;
  EXPECT_EQ(p.iterations, 4);
  EXPECT_EQ(p.substeps, 3);  // 5 ms in steps of at most 2 ms
  EXPECT_NEAR(p.dt, 0.005 / 3, 1e-9);
  EXPECT_EQ(p.spacing(), 0.02f);  // the scene's own keys stay
  EXPECT_EQ(p.domainMax, glm::vec3(0.2f, 0.1f, 0.2f));
  EXPECT_EQ(s.autoChoice->headline(), "auto: fluid, 4 iterations, dt 1.67 ms (density error 0.4% <= 1%)");
  EXPECT_EQ(
      s.autoChoice->summary().rfind("auto: picked fluid, 4 iterations, dt 1.67 ms (density error 0.4% for "
                                    "density error <= 1%, cost 50 ms per simulated s; most accurate, fluid, 8 "
                                    "iterations, dt 1 ms, costs 180; data: fluid-density on fixture, not measured)",
                                    0),
      0u)
      << s.autoChoice->summary();
  EXPECT_EQ(s.autoChoice->summary().find('\n'), std::string::npos);
  EXPECT_EQ(s.autoChoice->mostAccurateParams.as<FluidSceneParams>().model.iterations, 8);
}

// A loose bound: balls at dt 1 ms (2%, x 2 = 4% <= 5%) cost 10, less than any fluid row; the
// cheaper balls row at 2 ms is unstable and never picked.
TEST_F(ResolveAutoWater, PicksTheCheaperBallsWhenALooseBoundLetsThemQualify) {
  const Scene s = load(waterScene(R"({"densityError": 0.05})"));
  ASSERT_TRUE(s.autoChoice);
  EXPECT_EQ(s.model, "balls");
  EXPECT_EQ(s.autoChoice->model, "balls");
  const balls::Params& b = ballsScene(s).model;
  EXPECT_FLOAT_EQ(b.radius, 0.01f * std::pow(2.0f, 1.0f / 6.0f));  // the same water volume (asBalls)
  EXPECT_EQ(b.fillMax, glm::vec3(0.1f, 0.1f, 0.1f));
  EXPECT_EQ(b.contact, balls::Contact::SpringDashpot);
  EXPECT_EQ(b.integrator, balls::Integrator::SymplecticEuler);
  EXPECT_EQ(b.substeps, 5);
  EXPECT_NEAR(b.dt, 0.001, 1e-9);
  EXPECT_EQ(s.autoChoice->costMsPerSimS, 10);
  EXPECT_EQ(s.autoChoice->headline(),
            "auto: balls, spring-dashpot, symplectic-euler, dt 1 ms (density error 2% <= 5%)");
  // The most accurate is a fluid row: its params are the fluid's.
  EXPECT_EQ(s.autoChoice->mostAccurateParams.as<FluidSceneParams>().model.iterations, 8);
}

// Among the fluid rows that meet the bound, the cheapest: the fewest iterations, then the
// largest step (a row counts with the worst error of its family at its step or smaller).
TEST_F(ResolveAutoWater, PicksTheFewestIterationsAndTheLargestStepThatMeetTheBound) {
  struct Case {
    double bound;
    int iterations;
    double rowDt;
  };
  for (const Case& c : {Case{0.01, 4, 0.002}, Case{0.0025, 8, 0.002}, Case{0.0015, 8, 0.001}}) {
    SCOPED_TRACE(c.bound);
    const Scene s = load(waterScene(R"({"densityError": )" + std::to_string(c.bound) + "}"));
    ASSERT_TRUE(s.autoChoice);
    ASSERT_EQ(s.model, "fluid");
    const fluid::Params& p = fluidScene(s).model;
    EXPECT_EQ(p.iterations, c.iterations);
    EXPECT_EQ(p.substeps, int(std::ceil(0.005 / c.rowDt - 1e-9)));  // the largest step the row allows
  }
}

// The pick divides the scene's frame (its dt x substeps, as stated or the fluid's defaults) into
// more, shorter steps of the same total, for balls and fluid alike.
TEST_F(ResolveAutoWater, TheFrameKeepsItsSimulatedTime) {
  for (const std::string engine :
       {R"("dt": 0.001, "substeps": 5)", R"("dt": 0.0005, "substeps": 7)", R"("dt": 0.004, "substeps": 1)", ""}) {
    SCOPED_TRACE(engine);
    for (const auto& [bound, model, rowDt] : {std::tuple{"0.01", "fluid", 0.002}, std::tuple{"0.05", "balls", 0.001}}) {
      const std::string json = waterScene(std::string(R"({"densityError": )") + bound + "}", engine);
      const Scene s = load(json);
      ASSERT_EQ(s.model, model);
      const double stated = statedFrame(json);
      EXPECT_NEAR(frameOf(s), stated, 1e-6 * stated);
      const double dt = s.model == "fluid" ? fluidScene(s).model.dt : ballsScene(s).model.dt;
      const int substeps = s.model == "fluid" ? fluidScene(s).model.substeps : ballsScene(s).model.substeps;
      EXPECT_LE(dt, rowDt * (1 + 1e-6));
      if (substeps > 1) EXPECT_GT(stated / (substeps - 1), rowDt);  // the fewest substeps that do
    }
  }
}

// A bound no row meets names the bound, the best row and its error, and the file of the rows.
TEST_F(ResolveAutoWater, ABoundNobodyMeetsIsOneLineNamingTheBoundTheBestAndTheFile) {
  const std::string e = sceneError(waterScene(R"({"densityError": 0.001})"));
  EXPECT_EQ(e,
            "s.json: scene.accuracy.densityError 0.001 cannot be met by any measured setting; best is fluid, 8 "
            "iterations, dt 1 ms with 0.0006 (needs <= 0.0005, the bound over the safety factor 2); rows: " +
                (kFixture / "accuracy" / "fluid-density.csv").string());
}

TEST_F(ResolveAutoWater, MistakesAreOneLineErrorsNamingTheKey) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"model": "auto"})",
       "s.json: scene.model = 'auto' needs scene.accuracy, the error the water accepts (densityError, frontError)"},
      {waterScene(R"({"densityErr": 0.01})"),
       "s.json: scene.accuracy.densityErr: unknown key (known for \"model\": \"auto\": densityError, frontError)"},
      {waterScene(R"({"maxOverlap": 0.1})"),
       "s.json: scene.accuracy.maxOverlap is a balls metric of \"method\": \"auto\"; a \"model\": \"auto\" scene "
       "states densityError, frontError"},
      {waterScene(R"({"densityError": 0})"), "s.json: scene.accuracy.densityError = 0 is out of range (0, 1]"},
      {waterScene(R"({"densityError": "1%"})"), "s.json: scene.accuracy.densityError: expected a number, got \"1%\""},
      {waterScene("0.01"), "s.json: scene.accuracy: expected an object {...}, got number"},
      {waterScene(R"({"densityError": 0.01, "frontError": 0.05})"),
       "s.json: scene.accuracy: frontError (water-front) and densityError (fluid-density) are measured by different "
       "studies; state bounds of one study"},
      {R"({"model": "auto", "method": "params", "accuracy": {"densityError": 0.01}})",
       "s.json: scene.method = 'params' contradicts scene.model = 'auto', which picks the method too (remove method)"},
      {waterScene(R"({"densityError": 0.01})", R"("dt": 0.001)", R"(, "solver": {"iterations": 2})"),
       "s.json: params.solver.iterations is picked by \"model\": \"auto\"; remove it (or the auto model)"},
      {waterScene(R"({"densityError": 0.01})", R"("contact": "penalty")"),
       "s.json: params.engine.contact: unknown key"},
      {R"({"model": "auto", "accuracy": {"densityError": 0.01}, "params": {"particles": {"spacing": 0.03}}})",
       "s.json: scene.accuracy: no row of fluid-density was measured at this scene's spacing 0.03 m (measured: 0.01, "
       "0.02 m)"},
      {R"({"model": "balls", "method": "auto", "accuracy": {"densityError": 0.01}})",
       "s.json: scene.accuracy.densityError is a water metric, for \"model\": \"auto\" (balls or fluid as it "
       "needs); a balls scene states maxOverlap, energyDrift, restitutionError"},
      {R"({"model": "fluid", "method": "auto", "accuracy": {"densityError": 0.01}})",
       "s.json: scene.method = 'auto': no measured data for model 'fluid' alone; \"model\": \"auto\" picks balls or "
       "fluid and its step for water (densityError, frontError)"},
  };
  for (const auto& [json, message] : cases) {
    SCOPED_TRACE(json);
    const std::string got = sceneError(json);
    EXPECT_EQ(got.rfind(message, 0), 0u) << got;
    EXPECT_EQ(got.find('\n'), std::string::npos) << got;
  }
}

TEST_F(ResolveAutoWater, MissingDataIsOneLineNamingTheFile) {
  test::TempDir empty;
  test::ScopedAssetDir assets(empty.path());
  EXPECT_EQ(sceneError(waterScene(R"({"densityError": 0.01})")),
            "s.json: scene.accuracy.densityError: accuracy data '" + (empty / "accuracy/fluid-density.csv").string() +
                "' is missing: run `tidepool sweep fluid-density --ship` (on the GPU machine) to measure and ship it");
  const std::string front = sceneError(waterScene(R"({"frontError": 0.05})"));
  EXPECT_EQ(front.rfind("s.json: scene.accuracy.frontError: accuracy data '", 0), 0u) << front;
  EXPECT_NE(front.find("water-front.csv' is missing"), std::string::npos) << front;
}

// frontError reads the dam-break front rows: balls at 0.5 ms (0.02) meet 5%; 3% needs the fluid.
TEST_F(ResolveAutoWater, FrontErrorPicksFromTheWaterFrontRows) {
  const Scene loose = load(waterScene(R"({"frontError": 0.05})"));
  ASSERT_TRUE(loose.autoChoice);
  EXPECT_EQ(loose.model, "balls");
  EXPECT_NEAR(ballsScene(loose).model.dt, 0.0005, 1e-9);
  EXPECT_EQ(loose.autoChoice->studies, "water-front");
  EXPECT_EQ(loose.autoChoice->meets, "front error 0.02 <= 0.05");
  const Scene tight = load(waterScene(R"({"frontError": 0.03})"));
  EXPECT_EQ(tight.model, "fluid");
  EXPECT_EQ(fluidScene(tight).model.iterations, 4);
}

// The shipped scene reads the dam break's params; with these rows it is the fluid. Without data
// it fails in one line naming the file, never a crash, from the command line too.
TEST_F(ResolveAutoWater, TheShippedSceneLoadsWithDataAndFailsInOneLineWithout) {
  const std::filesystem::path scene = std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "assets/scenes/water-auto.json";
  const Scene s = loadScene(scene);
  EXPECT_EQ(s.model, "fluid");
  EXPECT_EQ(s.accuracy, io::Json({{"densityError", 0.01}}));
  EXPECT_EQ(fluidScene(s).model.iterations, 4);
  EXPECT_NEAR(frameOf(s), 0.005, 1e-8);  // the dam break's frame: 5 steps of 1 ms

  test::TempDir empty;
  test::TempDir out;
  test::expectOneLineError({"render", scene.string(), "--frames", "1", "--out", out.path().string(), "--quiet"},
                           "water-auto.json: scene.accuracy.densityError: accuracy data '" +
                               (empty / "accuracy/fluid-density.csv").string() + "' is missing",
                           1, {"TIDEPOOL_ASSET_DIR=" + empty.path().string()});
}

// `tidepool render` says what was picked, as for "method": "auto": one log line at load.
TEST_F(ResolveAutoWater, TheCommandLineLogsThePick) {
  test::TempDir dir;
  dir.write("tank.json", waterScene(R"({"densityError": 0.01})"));
  const auto r = test::runTidepool({"render", (dir / "tank.json").string(), "--frames", "1", "--size", "32x18", "--out",
                                    (dir / "out").string(), "--quiet"},
                                   {"TIDEPOOL_ASSET_DIR=" + kFixture.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("auto: picked fluid, 4 iterations, dt 1.67 ms (density error 0.4% for density error <= 1%"),
            std::string::npos)
      << r.err;
}

// The picked parameters build and step the water stage (llvmpipe, 125 particles, three frames):
// the model the pick names runs, for the frame's simulated time, without diverging.
TEST_F(ResolveAutoWaterRun, PickedParametersBuildAndStepARealStage) {
  for (const auto& [bound, metric] :
       {std::pair{"0.01", "density error (%)"}, std::pair{"0.05", "max overlap (% of r)"}}) {
    SCOPED_TRACE(bound);
    const Scene s = load(waterScene(std::string(R"({"densityError": )") + bound + "}"));
    auto stage = createStage(s, shaders());
    gl::GpuProfiler profiler;
    for (int f = 0; f < 3; ++f) stage->step(profiler);
    stage->flushChecks();
    EXPECT_NEAR(stage->simTime(), 3 * frameOf(s), 1e-6);
    EXPECT_FALSE(stage->divergence()) << stage->divergence()->message;
    const auto [name, value] = stage->liveMetric();
    EXPECT_EQ(name, metric);  // the model that runs is the one picked
    EXPECT_TRUE(std::isfinite(value));
  }
}
