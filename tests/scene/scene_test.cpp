// Every shipped scene loads and builds its stage; bad scene content is reported by key.
#include <gtest/gtest.h>

#include "scene/scene.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {
class Scenes : public test::GlTest {};
}  // namespace

TEST_F(Scenes, EveryShippedSceneLoadsBuildsStepsAndRenders) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(findAssetDir() / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene scene = loadScene(entry.path());
    auto stage = createStage(scene, shaders());
    RenderTarget target(32, 16);
    gl::GpuProfiler profiler;
    stage->step(1.0 / scene.clip.fps, profiler);
    stage->render(target, profiler);
    EXPECT_GT(stage->simTime(), 0.0);
    stage->reset();
    EXPECT_EQ(stage->simTime(), 0.0);
    ++count;
  }
  EXPECT_GE(count, 2);
}

TEST(SceneFile, HeaderIsValidatedAndBareNamesResolve) {
  EXPECT_EQ(resolveScenePath("default").filename(), "default.json");
  EXPECT_THROW(resolveScenePath("no-such-scene"), Error);
  auto err = [](const std::string& text) {
    try {
      parseScene(io::parseJson(text, "s.json"), "s.json");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(err("{\"modle\": \"blank\"}").rfind("s.json: scene.modle: unknown key", 0), 0u);
  EXPECT_EQ(err("{\"clip\": {\"frames\": 0}}"), "s.json: scene.clip.frames = 0 is out of range [1, 1000000]");
  EXPECT_EQ(err("[]"), "s.json: a scene must be a JSON object {...}");
  Scene s = parseScene(io::parseJson("{\"model\": \"blank\", \"params\": {\"color\": [1,0,0]}}", "s"), "s");
  EXPECT_EQ(s.params["color"][0], 1);
}

TEST_F(Scenes, UnknownModelAndBadParamsAreReported) {
  Scene s = parseScene(io::parseJson("{\"model\": \"fluidd\"}", "s.json"), "s.json");
  s.file = "s.json";
  try {
    createStage(s, shaders());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("s.json: scene.model = 'fluidd' is not a model (known: blank", 0), 0u)
        << e.what();
  }
  s.model = "blank";
  s.params = io::parseJson("{\"colour\": [1,0,0]}", "s.json");
  EXPECT_THROW(createStage(s, shaders()), Error);
}
