// What a frame is: a stage steps the simulated time its model's parameters state
// (Stage::frameSeconds), whatever the clip's fps, which is only the video's playback rate.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "sim/ripples/ripples_params.h"
#include "sim/swarm/swarm_params.h"
#include "support/accuracy_data.h"
#include "support/gl_test.h"
#include "support/scene_error.h"

using namespace tidepool;
using test::sceneError;

namespace {

class FrameTime : public test::GlTest {};

std::unique_ptr<Stage> stageOf(const std::string& model, const std::string& params, int fps,
                               gl::ShaderLibrary& shaders) {
  const std::string json =
      R"({"model": ")" + model + R"(", "params": )" + params + R"(, "clip": {"fps": )" + std::to_string(fps) + "}}";
  return createStage(parseScene(io::parseJson(json, "f.json"), "f.json"), shaders);
}

std::vector<std::vector<std::uint8_t>> stateOf(Stage& stage) {
  std::vector<std::vector<std::uint8_t>> state;
  if (sim::Model* model = stage.model())
    for (const sim::StateBuffer& b : model->stateBuffers()) state.push_back(b.buffer->read<std::uint8_t>(b.bytes));
  return state;
}

// Steps the same scene at clip fps 24 and 120: both advance kFrames x `frameSeconds` and end in
// the same state, byte for byte.
void expectFrames(const std::string& model, const std::string& params, double frameSeconds,
                  gl::ShaderLibrary& shaders) {
  SCOPED_TRACE(model);
  constexpr int kFrames = 6;
  auto slow = stageOf(model, params, 24, shaders), fast = stageOf(model, params, 120, shaders);
  EXPECT_EQ(slow->frameSeconds(), frameSeconds);
  EXPECT_EQ(fast->frameSeconds(), frameSeconds);
  const std::vector<std::vector<std::uint8_t>> start = stateOf(*slow);
  gl::GpuProfiler profiler;
  for (int i = 0; i < kFrames; ++i) {
    slow->step(profiler);
    fast->step(profiler);
  }
  EXPECT_NEAR(slow->simTime(), kFrames * frameSeconds, 1e-12);
  EXPECT_EQ(fast->simTime(), slow->simTime());
  const std::vector<std::vector<std::uint8_t>> end = stateOf(*slow);
  EXPECT_EQ(stateOf(*fast), end) << "the clip's fps changed what a frame simulates";
  if (!start.empty()) EXPECT_NE(end, start) << "the frames must move something for the comparison to mean much";
}

}  // namespace

TEST_F(FrameTime, AFrameIsTheModelsOwnTimeWhateverTheClipFps) {
  // swarm: speed x frame_seconds (the gravity moves every particle)
  expectFrames("swarm", R"({"particles": 4096, "frame_seconds": 0.0625, "speed": 0.5})", 0.03125, shaders());
  // ripples: frame_seconds (the rain's drops, per simulated second, spread)
  expectFrames("ripples", R"({"width": 32, "height": 32, "frame_seconds": 0.03125, "touch": {"rain": 100}})", 0.03125,
               shaders());
  // life: one step of max_dt
  expectFrames("life",
               R"({"species": 2, "particle_count": 512, "width": 64, "height": 48, "model": {"max_dt": 0.0625}})",
               0.0625, shaders());
  expectFrames("blank", R"({"frame_seconds": 0.25})", 0.25, shaders());
}

// The shipped swarm and ripples scenes (all at clip fps 30) keep the frame they had when the
// clip's fps set it: the default frame_seconds is 1/30 s.
TEST(FrameTimeScenes, ShippedScenesKeepTheirSimulatedTimePerFrame) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(findAssetDir() / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    if (!test::missingAccuracyData(entry.path()).empty()) continue;  // water-auto without its rows: no swarm
    const Scene scene = loadScene(entry.path());
    const double clipFrame = 1.0 / scene.clip.fps;
    if (scene.params.holds<sim::SwarmParams>()) {
      const sim::SwarmParams& p = scene.params.model<sim::SwarmParams>();
      EXPECT_NEAR(sim::swarmFrameSeconds(p), p.speed * clipFrame, 1e-12);
      ++checked;
    } else if (scene.params.holds<ripples::Params>()) {
      EXPECT_NEAR(scene.params.model<ripples::Params>().frameSeconds, clipFrame, 1e-12);
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);
}

TEST(FrameTimeScenes, AnOutOfRangeFrameIsOneLineNamingTheKey) {
  EXPECT_EQ(sceneError(R"({"model": "swarm", "params": {"frame_seconds": 0}})"),
            "s.json: params.frame_seconds = 0 is out of range [0.0001, 1]");
  EXPECT_EQ(sceneError(R"({"model": "ripples", "params": {"frame_seconds": 2}})"),
            "s.json: params.frame_seconds = 2 is out of range [0.0001, 1]");
  EXPECT_EQ(sceneError(R"({"model": "blank", "params": {"frame_seconds": -1}})"),
            "s.json: params.frame_seconds = -1 is out of range [0.0001, 1]");
  EXPECT_EQ(sceneError(R"({"model": "swarm", "params": {"frame_seconds": 0.02}})"), "");
}
