// "method": "auto" in real runs (llvmpipe, small): the setting picked from the shipped data meets
// the scene's bound when run on the study's reference problem, both at the picked step and at the
// step the scene actually takes (whole substeps per frame), and it is cheaper than the most
// accurate measured setting: in the data's cost column and in a cost proxy counted from the run
// (state bytes, cell updates or steps per simulated second), never in wall-clock time.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/balls_stage.h"
#include "scene/scene.h"
#include "sim/balls/measure/balls_measure.h"
#include "sim/ripples/measure/ripples_measure.h"
#include "sim/swarm/measure/swarm_measure.h"
#include "sim/swarm/swarm.h"
#include "support/gl_test.h"
#include "sweep/balls_settle_study.h"

using namespace tidepool;

namespace {

class ResolveAutoRealRun : public test::GlTest {};

template <std::size_t N>
int indexOf(const std::array<const char*, N>& names, const std::string& name) {
  for (std::size_t i = 0; i < N; ++i)
    if (name == names[i]) return int(i);
  ADD_FAILURE() << name << " is not a known name";
  return 0;
}

}  // namespace

TEST_F(ResolveAutoRealRun, SwarmPickMeetsItsEnergyDriftAndMovesLessStateThanTheMostAccurate) {
  const std::filesystem::path file = findAssetDir() / "scenes" / "swarm-auto.json";
  const Scene scene = loadScene(file);
  ASSERT_TRUE(scene.autoChoice);
  const double bound = scene.accuracy["energyDrift"];
  const sim::SwarmParams& picked = scene.params.model<sim::SwarmParams>();
  ASSERT_GT(picked.maxDt, 0.0f);
  // At the picked step (a row of the study: a whole number of steps per orbit) ...
  const int stepsPerOrbit = int(std::lround(sim::orbitPeriod() / picked.maxDt));
  EXPECT_LE(sim::orbitEnergyError(shaders(), picked.integrator, picked.storage, stepsPerOrbit), bound);
  // ... and at the step the scene takes in its frame.
  const double sceneDt = sim::swarmFrameSeconds(picked) / sim::swarmSubsteps(picked);
  EXPECT_LE(sceneDt, picked.maxDt * (1 + 1e-6));
  const int sceneSteps = int(std::ceil(sim::orbitPeriod() / sceneDt));
  EXPECT_LE(sim::orbitEnergyError(shaders(), picked.integrator, picked.storage, sceneSteps), bound);

  // Cost: the step is bound by memory traffic (shaders/swarm/swarm_step.comp reads and writes
  // each particle once), so state bytes per simulated second rank the settings.
  const sim::SwarmParams& best = scene.autoChoice->mostAccurateParams.model<sim::SwarmParams>();
  auto bytesPerSimSecond = [](const sim::SwarmParams& p, double dt) {
    return 2.0 * double(sim::swarmBytesPerParticle(p.storage)) / dt;
  };
  EXPECT_LT(scene.autoChoice->costMsPerSimS, scene.autoChoice->mostAccurateCost);
  EXPECT_LT(bytesPerSimSecond(picked, picked.maxDt), bytesPerSimSecond(best, best.maxDt));
  const double bestSceneDt = sim::swarmFrameSeconds(best) / sim::swarmSubsteps(best);
  EXPECT_LE(bytesPerSimSecond(picked, sceneDt), bytesPerSimSecond(best, bestSceneDt));
}

TEST_F(ResolveAutoRealRun, RipplesPickMeetsItsPhaseErrorAndUpdatesFewerCellsThanTheMostAccurate) {
  const std::filesystem::path file = findAssetDir() / "scenes" / "ripples-auto.json";
  const Scene scene = loadScene(file);
  ASSERT_TRUE(scene.autoChoice);
  const double bound = scene.accuracy["phaseError"], wavelength = scene.accuracy["wavelength"];
  const ripples::Params& picked = scene.params.model<ripples::Params>();
  const int cells = int(std::lround(wavelength / picked.cellSize));
  const double k = 2 * std::numbers::pi / cells;
  const double pickedCourant = picked.courantTarget * ripples::kCourantLimit2D;
  EXPECT_LE(std::abs(ripples::measuredPhaseRatio(shaders(), 2 * cells, 8, k, 0.0, pickedCourant, 3.0) - 1.0), bound);
  const int substeps = ripples::substepsFor(picked);
  const double sceneCourant = ripples::courant(picked, picked.frameSeconds / substeps);
  EXPECT_LE(sceneCourant, pickedCourant * (1 + 1e-6));
  EXPECT_LE(std::abs(ripples::measuredPhaseRatio(shaders(), 2 * cells, 8, k, 0.0, sceneCourant, 3.0) - 1.0), bound);

  const ripples::Params& best = scene.autoChoice->mostAccurateParams.model<ripples::Params>();
  auto cellUpdatesPerSimSecond = [&](const ripples::Params& p) {
    return double(p.width) * p.height * ripples::substepsFor(p) / p.frameSeconds;
  };
  EXPECT_LT(scene.autoChoice->costMsPerSimS, scene.autoChoice->mostAccurateCost);
  EXPECT_LT(cellUpdatesPerSimSecond(picked), cellUpdatesPerSimSecond(best));
}

TEST_F(ResolveAutoRealRun, BallsPickMeetsItsRestitutionErrorInFewerStepsThanTheMostAccurate) {
  const std::filesystem::path file = findAssetDir() / "scenes" / "balls-auto.json";
  const Scene scene = loadScene(file);
  ASSERT_TRUE(scene.autoChoice);
  const double bound = scene.accuracy["restitutionError"];
  const balls::Params picked = ballsParams(scene);
  EXPECT_EQ(picked.contact, balls::Contact::SpringDashpot);
  // measureBounce runs t_c = 10 ms; the scene's t_c/dt is what carries over.
  const balls::Bounce b =
      balls::measureBounce(shaders(), picked.integrator, picked.restitution, picked.contactTime / picked.dt);
  EXPECT_LE(std::abs(b.restitution / picked.restitution - 1.0), bound);

  const balls::Params& best = scene.autoChoice->mostAccurateParams.model<balls::Params>();
  EXPECT_NEAR(picked.dt * picked.substeps, best.dt * best.substeps, 1e-6);  // the frame's simulated time is kept
  EXPECT_LT(scene.autoChoice->costMsPerSimS, scene.autoChoice->mostAccurateCost);
  EXPECT_LT(1.0 / picked.dt, 1.0 / best.dt);  // steps per simulated second
}

// maxOverlap reads balls-settle.csv, measured on a block of r = 1 cm balls under g = 9.81 m/s²
// with t_c = 20 dt: the pick (integrator, dt and that t_c) runs there at the study's small size.
TEST_F(ResolveAutoRealRun, BallsOverlapPickMeetsItsBoundOnTheSettlingColumn) {
  const Scene scene = parseScene(io::parseJson(R"({"model": "balls", "method": "auto",
      "accuracy": {"maxOverlap": 0.1}, "params": {"engine": {"dt": 0.0005, "substeps": 8}}})",
                                               "s.json"),
                                 "s.json");
  ASSERT_TRUE(scene.autoChoice);
  const balls::Params picked = ballsParams(scene);
  EXPECT_NEAR(picked.contactTime, sweep::kSettleStepsPerContact * picked.dt, 1e-9);  // the study's stiffness
  const sweep::Settle s = sweep::measureSettle(shaders(), picked.contact, picked.integrator, picked.dt);
  EXPECT_TRUE(s.stable);
  EXPECT_LE(s.maxOverlap, 0.1);
  EXPECT_LT(scene.autoChoice->costMsPerSimS, scene.autoChoice->mostAccurateCost);
}
