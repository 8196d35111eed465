// Hostile input: a bad file dropped on the window changes nothing. Each stage that
// takes files reads the whole file before it changes anything; a refusal is one line naming the
// file and the problem, and every parameter the UI shows is as it was.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "io/png.h"
#include "scene/param_json.h"
#include "scene/scene.h"
#include "sim/life/life_rules.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class BadDrop : public test::GlTest {};

std::unique_ptr<Stage> stageOf(const std::string& scene, gl::ShaderLibrary& shaders) {
  return createStage(parseScene(io::parseJson(scene, "drop.json"), "drop.json"), shaders);
}

// Everything the UI shows and edits (the life panel's "error" line, which says why a drop was
// refused, left out).
io::Json shown(Stage& stage) {
  io::Json params = writeParams([&](ParamVisitor& v) { stage.visitParams(v); });
  if (params.contains("rules")) params["rules"].erase("error");
  return params;
}

void expectRefused(const std::string& refusal, const std::string& file, const std::string& problem) {
  EXPECT_EQ(refusal.find('\n'), std::string::npos) << refusal;
  EXPECT_NE(refusal.find(file), std::string::npos) << refusal;
  EXPECT_NE(refusal.find(problem), std::string::npos) << refusal;
}

}  // namespace

TEST_F(BadDrop, LifeKeepsItsRulesAndParams) {
  test::TempDir dir;
  dir.write("truncated.json", life::rulesToJson(life::generateRules({.species = 2, .seed = 5})).dump().substr(0, 90));
  dir.write("deep.json", std::string(200, '[') + std::string(200, ']'));
  dir.write("wrong.json", R"({"particleCount": 0, "simulationSize": [64, 64], "species": []})");
  auto stage = stageOf(R"({"model": "life", "params": {"species": 3, "particle_count": 1024, "width": 256,
                           "height": 144, "seed": 4}})",
                       shaders());
  gl::GpuProfiler profiler;
  stage->step(profiler);
  const std::string code = stage->shareText();
  const io::Json params = shown(*stage);
  const double time = stage->simTime();
  expectRefused(stage->dropFile((dir / "truncated.json").string()), "truncated.json:1:", "malformed JSON");
  expectRefused(stage->dropFile((dir / "deep.json").string()), "deep.json:1:", "nested deeper than 64 levels");
  expectRefused(stage->dropFile((dir / "wrong.json").string()), "wrong.json.particleCount = 0", "[1, 16777216]");
  expectRefused(stage->dropFile("/dev/zero"), "/dev/zero", "not a regular file");
  EXPECT_EQ(stage->shareText(), code);
  EXPECT_EQ(shown(*stage), params);
  EXPECT_EQ(stage->simTime(), time) << "not respawned";
  stage->step(profiler);
  EXPECT_EQ(stage->shareText(), code);
}

TEST_F(BadDrop, SwarmKeepsItsImageAndParticles) {
  test::TempDir dir;
  dir.write("text.png", "not a png at all");
  io::writePng(dir / "good.png", io::Image{2, 2, std::vector<std::uint8_t>(16, 200)});
  std::ifstream good(dir / "good.png", std::ios::binary);
  const std::string truncated(std::istreambuf_iterator<char>(good), {});
  dir.write("truncated.png", truncated.substr(0, truncated.size() / 2));
  auto stage = stageOf(R"({"model": "swarm", "params": {"particles": 4000}})", shaders());
  gl::GpuProfiler profiler;
  RenderTarget target(32, 16);
  stage->step(profiler);
  stage->render(target, profiler);
  const io::Json params = shown(*stage);
  const double time = stage->simTime();
  expectRefused(stage->dropFile((dir / "text.png").string()), "text.png: not a PNG image", "");
  expectRefused(stage->dropFile((dir / "truncated.png").string()), "truncated.png: cannot decode", "");
  expectRefused(stage->dropFile((dir / "missing.png").string()), "missing.png", "not found");
  stage->step(profiler);
  stage->render(target, profiler);
  EXPECT_EQ(shown(*stage), params) << "the view's colour mode and image are unchanged";
  EXPECT_GT(stage->simTime(), time) << "not restarted, as a new image would";
  EXPECT_EQ(stage->dropFile((dir / "good.png").string()), "");
  stage->render(target, profiler);
  EXPECT_EQ(stage->simTime(), 0.0) << "a good image restarts from the start positions it colours";
  EXPECT_EQ(shown(*stage)["view"]["image"], (dir / "good.png").string());
}

TEST_F(BadDrop, WaterKeepsItsObstacles) {
  test::TempDir dir;
  dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  dir.write("empty.obj", "# nothing\n");
  dir.write("closed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  auto stage = stageOf(R"({"model": "balls", "params": {"particles": {"radius": 0.02, "domain_max": [0.4, 0.3, 0.4],
                           "fill": "block", "fill_max": [0.1, 0.1, 0.1]},
                           "obstacles": [{"shape": "sphere", "centre": [0.3, 0.1, 0.3], "size": [0.05, 0.05, 0.05]}]}})",
                       shaders());
  gl::GpuProfiler profiler;
  stage->step(profiler);
  const io::Json params = shown(*stage);
  ASSERT_EQ(params["obstacles"].size(), 1u) << params.dump();
  expectRefused(stage->dropFile((dir / "bad.obj").string()), "bad.obj:4: vertex index 7 out of range", "");
  expectRefused(stage->dropFile((dir / "empty.obj").string()), "empty.obj: no triangles", "");
  expectRefused(stage->dropFile((dir / "cube.png").string()), "cube.png", "OBJ meshes");
  stage->step(profiler);
  EXPECT_EQ(shown(*stage), params);
  EXPECT_EQ(stage->status().find("not changed"), std::string::npos) << stage->status();
  EXPECT_EQ(stage->dropFile((dir / "closed.obj").string()), "");
  stage->step(profiler);
  EXPECT_EQ(shown(*stage)["obstacles"].size(), 2u);
}
