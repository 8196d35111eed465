// The life model end to end: `--rules` takes a share code or a rules file (the web app's
// format) on render; bad rules stop the run with one line naming the field; the window draws
// the life panel (its widgets within ImGui's limits); the benchmark prints its tables.
#include <gtest/gtest.h>

#include "io/json.h"
#include "io/png.h"
#include "sim/life/life_rules.h"
#include "support/gl_test.h"
#include "support/run_process.h"

using namespace tidepool;
using test::runTidepool;

namespace {
life::Rules small() {
  return life::generateRules({.species = 3, .particleCount = 1024, .size = {256, 144}, .seed = 6});
}
}  // namespace

TEST(LifeCli, RenderTakesAShareCodeOrARulesFile) {
  test::TempDir dir;
  const std::string code = life::encodeShareCode(small());
  auto r = runTidepool({"render", "life", "--rules", code, "--frames", "2", "--size", "64x36", "--out",
                        (dir / "a").string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "a/frame_00001.png"));
  dir.write("mine.json", life::rulesToJson(small()).dump(2));
  r = runTidepool({"render", "life", "--rules", (dir / "mine.json").string(), "--frames", "1", "--size", "64x36",
                   "--out", (dir / "b").string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
}

TEST(LifeCli, BadRulesAreAOneLineErrorNamingTheField) {
  test::TempDir dir;
  io::Json j = life::rulesToJson(small());
  j["species"][1]["forces"][0]["collisionRadius"] = 1000;
  dir.write("bad.json", j.dump());
  auto r = runTidepool({"render", "life", "--rules", (dir / "bad.json").string(), "--frames", "1", "--size", "32x18",
                        "--out", (dir / "o").string(), "--quiet"});
  EXPECT_EQ(r.exitCode, 1);
  ASSERT_EQ(r.errLines().size(), 1u) << r.err;
  EXPECT_NE(r.err.find("params.rules: " + (dir / "bad.json").string() + ": species[1].forces[0].collisionRadius"),
            std::string::npos)
      << r.err;
  r = runTidepool({"render", "life", "--rules", "no-such-preset", "--frames", "1", "--out", (dir / "o").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("neither a rules file, a preset in assets/rules nor a share code"), std::string::npos) << r.err;
  r = runTidepool({"render", "ripples", "--rules", "x", "--frames", "1", "--out", (dir / "o").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("rules"), std::string::npos) << r.err;
}

TEST(LifeCli, BenchPrintsPassesPairsAndCrossover) {
  auto r = runTidepool(
      {"bench", "life", "--n", "1024", "--brute", "256,512", "--settle", "1", "--repeats", "1", "--warmup", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("pairs/s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("crossover"), std::string::npos) << r.out;
}

TEST(LifeCli, WindowDrawsTheSceneAndItsPanelUnderXvfb) {
  test::TempDir dir;
  dir.write("life.json", R"({"model": "life", "params": {"species": 4, "particle_count": 2048, "width": 256,
                                                            "height": 144, "seed": 3}})");
  const std::string shot = (dir / "shot.png").string();
  auto r = test::runProcess({"xvfb-run", "-a", "-s", "-screen 0 800x600x24", TIDEPOOL_EXE, "run",
                             (dir / "life.json").string(), "--backend", "window", "--size", "640x480", "--frames", "3",
                             "--screenshot", shot});
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_FALSE(r.signaled);
  const io::Image img = io::readPng(shot);
  int lit = 0;  // particles and glow right of the panel
  for (int y = 0; y < 480; ++y)
    for (int x = 560; x < 640; ++x) lit += img.rgba[(std::size_t(y) * 640 + x) * 4 + 1] > 40;
  EXPECT_GT(lit, 500);
}
