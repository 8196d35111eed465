// The life scene: its share code is the running rules; N makes new (valid, reproducible) rules
// of the same shape; a bad "rules" key names the scene key; a dropped rules JSON replaces the
// rules, a bad one is refused in the panel and changes nothing.
#include <gtest/gtest.h>

#include "io/json.h"
#include "scene/scene.h"
#include "sim/life/life.h"
#include "sim/life/life_rules.h"
#include "support/gl_test.h"
#include "support/null_visitor.h"

using namespace tidepool;

namespace {
class LifeStage : public test::GlTest {};

// Reads one text parameter the way the ImGui editor shows it: through visitParams.
class ReadText final : public test::NullVisitor {
 public:
  explicit ReadText(const char* key) : m_key(key) {}
  void text(const ParamInfo& info, std::string& value) override {
    if (m_key == info.key) found = value;
  }
  std::string found;

 private:
  std::string m_key;
};

std::string shownText(Stage& stage, const char* key) {
  ReadText reader(key);
  stage.visitParams(reader);
  return reader.found;
}

io::Json smallScene() {
  return io::Json::parse(R"({"species": 3, "particle_count": 1024, "width": 256, "height": 144, "seed": 4})");
}

std::unique_ptr<Stage> lifeStage(const io::Json& params, gl::ShaderLibrary& shaders) {
  Scene scene = parseScene({{"model", "life"}, {"params", params}}, "s.json");
  scene.file = "s.json";
  return createStage(scene, shaders);
}
}  // namespace

TEST_F(LifeStage, ShareCodeFollowsTheRulesAndNMakesNewOnes) {
  auto stage = lifeStage(smallScene(), shaders());
  const life::Rules first = life::decodeShareCode(stage->shareText());
  EXPECT_TRUE(first == life::generateRules({.species = 3, .particleCount = 1024, .size = {256, 144}, .seed = 4}));
  gl::GpuProfiler profiler;
  stage->key('N');
  stage->step(profiler);
  const life::Rules next = life::decodeShareCode(stage->shareText());
  EXPECT_FALSE(next == first);
  EXPECT_EQ(next.speciesCount(), 3);
  EXPECT_EQ(next.particleCount, 1024);
  auto again = lifeStage(smallScene(), shaders());
  again->key('N');
  again->step(profiler);
  EXPECT_EQ(again->shareText(), stage->shareText()) << "N is reproducible too";
}

// What the window's title names: the preset, until N makes new rules from a new seed.
TEST_F(LifeStage, RunningNamesThePresetUntilNMakesNewRules) {
  io::Json p = smallScene();
  p["rules"] = "cells";
  auto stage = lifeStage(p, shaders());
  EXPECT_EQ(stage->running(), "cells");
  gl::GpuProfiler profiler;
  stage->step(profiler);
  EXPECT_EQ(stage->running(), "cells");
  stage->key('N');
  stage->step(profiler);
  EXPECT_EQ(stage->running().rfind("seed ", 0), 0u) << stage->running();
  EXPECT_EQ(lifeStage(smallScene(), shaders())->running(), "seed 4");
}

TEST_F(LifeStage, BadRulesKeyIsReportedWithTheSceneKey) {
  io::Json p = smallScene();
  p["rules"] = "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA";
  try {
    lifeStage(p, shaders());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: params.rules: share code:"), std::string::npos) << e.what();
  }
  p["rules"] = "cells";  // a preset name from assets/rules
  EXPECT_NO_THROW(lifeStage(p, shaders()));
}

TEST_F(LifeStage, DroppedRulesFileLoadsAndABadOneChangesNothing) {
  test::TempDir dir;
  const life::Rules dropped = life::generateRules({.species = 2, .particleCount = 512, .size = {128, 72}, .seed = 9});
  io::writeJsonFile((dir / "good.json").string(), life::rulesToJson(dropped));
  io::Json bad = life::rulesToJson(dropped);
  bad["species"][0]["forces"][1]["collisionRadius"] = 1e3;
  io::writeJsonFile((dir / "bad.json").string(), bad);

  auto stage = lifeStage(smallScene(), shaders());
  gl::GpuProfiler profiler;
  EXPECT_EQ(stage->dropFile((dir / "good.json").string()), "");
  stage->step(profiler);
  EXPECT_TRUE(life::decodeShareCode(stage->shareText()) == dropped);
  EXPECT_EQ(shownText(*stage, "error"), "");

  const std::string before = stage->shareText();
  const std::string refused = stage->dropFile((dir / "bad.json").string());  // refused with a reason
  EXPECT_NE(refused.find("bad.json: species[0].forces[1].collisionRadius"), std::string::npos) << refused;
  stage->step(profiler);
  EXPECT_EQ(stage->shareText(), before);
  const std::string error = shownText(*stage, "error");
  EXPECT_NE(error.find("not loaded: "), std::string::npos) << error;
  EXPECT_NE(error.find("species[0].forces[1].collisionRadius = 1000 is larger than radius"), std::string::npos)
      << error;
}

// R in the window (Stage::restart): the original's Restart, new random particles under the same
// rules; each restart draws others, and reset() still gives the seed's own start.
TEST_F(LifeStage, RestartKeepsTheRulesAndDrawsNewPositions) {
  auto stage = lifeStage(smallScene(), shaders());
  auto* life = dynamic_cast<life::Life*>(stage->model());
  ASSERT_NE(life, nullptr);
  const std::string rules = stage->shareText();
  const std::vector<glm::vec4> start = life->downloadPositions();
  gl::GpuProfiler profiler;
  stage->step(profiler);
  stage->restart();
  EXPECT_EQ(stage->shareText(), rules);
  EXPECT_EQ(stage->simTime(), 0.0);
  const std::vector<glm::vec4> first = life->downloadPositions();
  stage->restart();
  const std::vector<glm::vec4> second = life->downloadPositions();
  ASSERT_EQ(first.size(), start.size());
  ASSERT_EQ(second.size(), start.size());
  std::size_t movedFromStart = 0, movedAgain = 0;
  std::vector<int> perSpecies(3, 0), perSpeciesStart(3, 0);
  for (std::size_t i = 0; i < start.size(); ++i) {
    movedFromStart += glm::vec2(first[i]) != glm::vec2(start[i]);
    movedAgain += glm::vec2(second[i]) != glm::vec2(first[i]);
    EXPECT_LE(std::abs(first[i].x), 128.0f);  // inside the 256 x 144 box
    EXPECT_LE(std::abs(first[i].y), 72.0f);
    ++perSpecies[std::size_t(first[i].w)];
    ++perSpeciesStart[std::size_t(start[i].w)];
  }
  EXPECT_GT(movedFromStart, start.size() * 9 / 10) << "new random positions";
  EXPECT_GT(movedAgain, start.size() * 9 / 10) << "each restart draws others";
  for (int s = 0; s < 3; ++s) EXPECT_NEAR(perSpecies[s], perSpeciesStart[s], 120) << "the same spawn weights";
  stage->reset();
  EXPECT_EQ(life->downloadPositions(), start) << "reset: the seed's own start (checkpoints rely on it)";
}
