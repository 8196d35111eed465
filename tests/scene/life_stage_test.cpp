// The life scene: its share code is the running rules; N makes new (valid, reproducible) rules
// of the same shape; a bad "rules" key names the scene key.
#include <gtest/gtest.h>

#include "scene/life_stage.h"
#include "sim/life/life_rules.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {
class LifeStageTest : public test::GlTest {};

io::Json smallScene() {
  return io::Json::parse(R"({"species": 3, "particle_count": 1024, "width": 256, "height": 144, "seed": 4})");
}
}  // namespace

TEST_F(LifeStageTest, ShareCodeFollowsTheRulesAndNMakesNewOnes) {
  auto stage = createLifeStage(smallScene(), "s.json: params", shaders());
  const life::Rules first = life::decodeShareCode(stage->shareText());
  EXPECT_TRUE(first == life::generateRules({.species = 3, .particleCount = 1024, .size = {256, 144}, .seed = 4}));
  gl::GpuProfiler profiler;
  stage->key('N');
  stage->step(0.025, profiler);
  const life::Rules next = life::decodeShareCode(stage->shareText());
  EXPECT_FALSE(next == first);
  EXPECT_EQ(next.speciesCount(), 3);
  EXPECT_EQ(next.particleCount, 1024);
  auto again = createLifeStage(smallScene(), "s.json: params", shaders());
  again->key('N');
  again->step(0.025, profiler);
  EXPECT_EQ(again->shareText(), stage->shareText()) << "N is reproducible too";
}

TEST_F(LifeStageTest, BadRulesKeyIsReportedWithTheSceneKey) {
  io::Json p = smallScene();
  p["rules"] = "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA";
  try {
    createLifeStage(p, "s.json: params", shaders());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: params.rules: share code:"), std::string::npos) << e.what();
  }
  p["rules"] = "cells";  // a preset name from assets/rules
  EXPECT_NO_THROW(createLifeStage(p, "s.json: params", shaders()));
}
