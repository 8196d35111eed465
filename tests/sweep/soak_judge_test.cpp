// The soak's verdict (sweep/soak.h) on made-up samples: each check passes a run that holds and
// names the step where one that does not fails.
#include <gtest/gtest.h>

#include <cmath>

#include "sweep/soak.h"

using namespace tidepool::sweep;

namespace {

// 21 samples of 1000 steps each: 100 MiB, 500 particles all sound, energy 2 (10 at step 0).
std::vector<SoakSample> steadyRun() {
  std::vector<SoakSample> out;
  for (long k = 0; k <= 20; ++k) out.push_back({k * 1000, k * 0.1, k * 1.0, 100.0, 500, 500, k == 0 ? 10.0 : 2.0});
  return out;
}

bool mentions(const std::vector<std::string>& failures, const std::string& text) {
  for (const std::string& f : failures)
    if (f.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(SoakJudge, SteadyRunHolds) { EXPECT_TRUE(judgeSoak(steadyRun(), {}).empty()); }

TEST(SoakJudge, MemoryMayGrowDuringWarmUpOnly) {
  std::vector<SoakSample> run = steadyRun();
  run[0].rssMiB = 40;  // shaders, driver caches: before the end of warm-up (step 2000)
  run[1].rssMiB = 80;
  EXPECT_TRUE(judgeSoak(run, {}).empty());
  // A slow leak afterwards: 0.5 MiB per sample, 9 MiB from step 2000 to 20000.
  for (std::size_t k = 2; k < run.size(); ++k) run[k].rssMiB = 100.0 + 0.5 * double(k - 2);
  const auto failures = judgeSoak(run, {});
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_TRUE(mentions(failures, "RSS grew by 9.0 MiB from step 2000 to 20000")) << failures[0];
  EXPECT_TRUE(judgeSoak(run, {.rssGrowthMiB = 10}).empty());
}

TEST(SoakJudge, LostOrNanParticlesFail) {
  std::vector<SoakSample> run = steadyRun();
  run[7].held = 499;  // one NaN or outside the walls
  EXPECT_TRUE(mentions(judgeSoak(run, {}), "count did not hold at step 7000: 499 of 500"));
  run = steadyRun();
  run[12].count = run[12].held = 498;  // two gone altogether
  EXPECT_TRUE(mentions(judgeSoak(run, {}), "at step 12000: 498 of 498 sound (finite, inside), 500 at the start"));
}

TEST(SoakJudge, EnergyBoundedByTheWarmUpsLargest) {
  std::vector<SoakSample> run = steadyRun();
  run[15].energy = 99;  // below 10 x 10
  EXPECT_TRUE(judgeSoak(run, {}).empty());
  run[15].energy = 101;
  EXPECT_TRUE(mentions(judgeSoak(run, {}), "energy 101 at step 15000, beyond 100"));
  run[15].energy = NAN;
  EXPECT_TRUE(mentions(judgeSoak(run, {}), "energy nan at step 15000"));
  run = steadyRun();
  for (SoakSample& s : run) s.energy = 0;  // nothing moves: no bound
  EXPECT_TRUE(mentions(judgeSoak(run, {}), "energy stayed 0 through the warm-up"));
}

TEST(SoakJudge, OneSampleIsNotARun) { EXPECT_TRUE(mentions(judgeSoak({steadyRun()[0]}, {}), "fewer than two")); }
