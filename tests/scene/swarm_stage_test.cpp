// The swarm stage: UI-style parameter edits re-allocate or are refused with a one-line status,
// dropped images recolour, the mouse adds an attractor.
#include <gtest/gtest.h>

#include <optional>

#include "io/png.h"
#include "scene/scene.h"
#include "sim/swarm/swarm_params.h"
#include "support/gl_test.h"
#include "support/null_visitor.h"

using namespace tidepool;

namespace {

class SwarmStages : public test::GlTest {};

// Sets one integer parameter the way the ImGui editor does: through visitParams.
class SetInteger final : public test::NullVisitor {
 public:
  SetInteger(const char* key, int value) : m_key(key), m_value(value) {}
  void integer(const ParamInfo& info, int& value, int, int) override {
    if (m_key == info.key) value = m_value;
  }

 private:
  std::string m_key;
  int m_value;
};

// Sets (when `value` is given) and reads one text parameter through visitParams.
class TextParam final : public test::NullVisitor {
 public:
  explicit TextParam(const char* key, std::optional<std::string> value = std::nullopt) : m_key(key), m_value(value) {}
  void text(const ParamInfo& info, std::string& value) override {
    if (m_key != info.key) return;
    if (m_value) value = *m_value;
    seen = value;
  }
  std::string seen;

 private:
  std::string m_key;
  std::optional<std::string> m_value;
};

std::unique_ptr<Stage> smallSwarm(gl::ShaderLibrary& shaders, const std::string& extra = "") {
  const std::string scene = "{\"model\": \"swarm\", \"params\": {\"particles\": 5000" + extra + "}}";
  return createStage(parseScene(io::parseJson(scene, "test"), "test"), shaders);
}

}  // namespace

TEST_F(SwarmStages, CountChangesReallocateAndTooLargeOnesAreRefusedKeepingTheParticles) {
  auto stage = smallSwarm(shaders());
  gl::GpuProfiler profiler;
  RenderTarget target(32, 16);
  SetInteger more("particles", 7000);
  stage->visitParams(more);
  stage->step(profiler);
  EXPECT_EQ(stage->status().rfind("7000 particles", 0), 0u) << stage->status();

  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  if (maxBlock / 16 >= sim::kMaxSwarmParticles) GTEST_SKIP() << "this GPU fits the largest count the UI offers";
  SetInteger tooMany("particles", sim::kMaxSwarmParticles);
  stage->visitParams(tooMany);
  stage->step(profiler);
  stage->render(target, profiler);
  const std::string status = stage->status();
  EXPECT_EQ(status.rfind("7000 particles", 0), 0u) << status;
  EXPECT_NE(status.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), std::string::npos) << status;
}

TEST_F(SwarmStages, DroppedImageRecoloursAndABadOneIsReported) {
  test::TempDir dir;
  io::writePng(dir / "red.png", io::Image{2, 2, std::vector<std::uint8_t>(16, 255)});
  auto stage = smallSwarm(shaders(), ", \"view\": {\"color_mode\": \"image\", \"image\": \"colors\"}");
  gl::GpuProfiler profiler;
  RenderTarget target(32, 16);
  stage->render(target, profiler);
  EXPECT_EQ(stage->status().find('\n'), std::string::npos) << "the preset image loads: " << stage->status();
  stage->step(profiler);
  EXPECT_EQ(stage->dropFile((dir / "red.png").string()), "");
  stage->render(target, profiler);
  EXPECT_EQ(stage->simTime(), 0.0) << "a new image restarts from the start positions it colours";
  EXPECT_EQ(stage->status().find('\n'), std::string::npos) << stage->status();
  EXPECT_NE(stage->dropFile((dir / "missing.png").string()).find("missing.png"), std::string::npos);
  stage->render(target, profiler);
  EXPECT_NE(stage->status().find("missing.png"), std::string::npos) << stage->status();
}

TEST_F(SwarmStages, AnImageEditThatCannotLoadKeepsTheOldImageAndSaysWhy) {
  auto stage = smallSwarm(shaders(), ", \"view\": {\"color_mode\": \"image\", \"image\": \"colors\"}");
  gl::GpuProfiler profiler;
  RenderTarget target(32, 16);
  stage->render(target, profiler);
  for (int i = 0; i < 3; ++i) stage->step(profiler);
  const double time = stage->simTime();
  ASSERT_GT(time, 0.0);
  TextParam edit("image", "/nonexistent/a\nb.png");
  stage->visitParams(edit);
  stage->render(target, profiler);
  stage->render(target, profiler);
  const std::string status = stage->status();
  EXPECT_NE(status.find("\nnot loaded: params.view.image = '/nonexistent/a\\x0ab.png': file not found: "
                        "'/nonexistent/a\\x0ab.png'"),
            std::string::npos)
      << status;
  EXPECT_EQ(status.find('\n'), status.rfind('\n')) << "the refusal is one line: " << status;
  TextParam read("image");
  stage->visitParams(read);
  EXPECT_EQ(read.seen, "colors") << "the old image stays";
  EXPECT_EQ(stage->simTime(), time) << "nothing restarted the swarm";
}

TEST_F(SwarmStages, LeftButtonAddsTheMouseAttractor) {
  auto stage = smallSwarm(shaders(), ", \"preset\": \"none\", \"gravity\": 0, \"mouse_strength\": 9");
  gl::GpuProfiler profiler;
  RenderTarget target(64, 32);
  stage->render(target, profiler);  // sets the aspect
  Input in;
  in.viewport = {64, 32};
  in.cursor = {48, 8};  // NDC (0.5, 0.5)
  in.left = true;
  stage->input(in);
  for (int i = 0; i < 30; ++i) stage->step(profiler);
  stage->render(target, profiler);
  // Particles gather at the cursor: its pixel neighbourhood is far brighter than average.
  const std::vector<std::uint8_t> px = target.readRgba8();
  double total = 0, near = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) {
      const double v =
          px[std::size_t(y * 64 + x) * 4] + px[std::size_t(y * 64 + x) * 4 + 1] + px[std::size_t(y * 64 + x) * 4 + 2];
      total += v;
      if (std::abs(x - 48) <= 3 && std::abs(y - 8) <= 3) near += v;
    }
  EXPECT_GT(near / 49.0, 3.0 * total / (64.0 * 32.0));
}
