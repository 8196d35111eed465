// The window's checkpoint logic without a window: F6 saves now, the autosave period (simulated
// seconds, 0: off, edited in the panel) saves at its multiples, and a failed save is a message
// for the panel, never an exception.
#include "app/window_checkpoints.h"

#include <gtest/gtest.h>

#include "support/gl_test.h"

using namespace tidepool;

namespace {
class WindowCheckpointLogic : public test::GlTest {};
}  // namespace

TEST_F(WindowCheckpointLogic, SavesOnRequestAndAtEveryAutosavePeriod) {
  test::TempDir dir;
  // blank: its clock advances frame_seconds a frame (a swarm's runs at its speed)
  const Scene scene =
      parseScene(io::parseJson(R"({"model": "blank", "params": {"frame_seconds": 0.0166666667}})", "w.json"), "w.json");
  auto stage = createStage(scene, shaders());
  WindowCheckpoints checkpoints(scene, dir / "w.ckpt", 0.25, stage->simTime());
  gl::GpuProfiler profiler;
  std::vector<std::string> messages;
  std::uint64_t frames = 0;
  const auto frame = [&](bool f6) {
    stage->step(profiler);
    if (auto saved = checkpoints.afterFrame(*stage, ++frames, f6)) {
      EXPECT_FALSE(saved->error) << saved->message;
      messages.push_back(saved->message);
    }
  };
  for (int i = 0; i < 60; ++i) frame(false);  // 1 s: autosaves at 0.25, 0.5, 0.75, 1.0
  ASSERT_EQ(messages.size(), 4u);
  EXPECT_EQ(messages[0].rfind("autosaved " + (dir / "w.ckpt").string() + " at t = 0.250 s", 0), 0u) << messages[0];
  EXPECT_EQ(io::readCheckpointFile(dir / "w.ckpt").time, stage->simTime());

  checkpoints.autosaveEvery() = 0;  // the panel turns it off; F6 still saves
  for (int i = 0; i < 30; ++i) frame(false);
  EXPECT_EQ(messages.size(), 4u);
  frame(true);
  ASSERT_EQ(messages.size(), 5u);
  EXPECT_EQ(messages[4].rfind("saved ", 0), 0u) << messages[4];
  EXPECT_EQ(io::readCheckpointFile(dir / "w.ckpt").time, stage->simTime());

  checkpoints.autosaveEvery() = 1.0f;  // a new period counts from multiples of itself
  for (int i = 0; i < 60; ++i) frame(false);
  EXPECT_EQ(messages.size(), 6u);
}

TEST_F(WindowCheckpointLogic, AFailedSaveIsAPanelMessageAndTheDefaultFileIsNamedAfterTheScene) {
  test::TempDir dir;
  Scene scene = parseScene(io::parseJson(R"({"model": "blank"})", "w.json"), "w.json");
  scene.file = "scenes/pool.json";  // as loadScene sets it
  auto stage = createStage(scene, shaders());
  EXPECT_EQ(WindowCheckpoints(scene, "", 0, 0).file(), "pool.ckpt");
  WindowCheckpoints checkpoints(scene, dir / "missing-folder/x.ckpt", 0, 0);
  const auto saved = checkpoints.afterFrame(*stage, 0, true);
  ASSERT_TRUE(saved.has_value());
  EXPECT_TRUE(saved->error);
  EXPECT_NE(saved->message.find("cannot write checkpoint"), std::string::npos) << saved->message;
}
