// `tidepool check-resume`: a resumed run equals the uninterrupted one, every state buffer and
// value bit for bit, for a scene of every model; and the check fails, naming the entry, when a
// step reads state a checkpoint does not hold (a ripples step made to read the buffer it writes).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/gl_test.h"
#include "support/run_process.h"

using namespace tidepool;
using test::runTidepool;

namespace {

// Small scenes of every model, each with the state it keeps besides its main buffers in play.
const std::pair<const char*, const char*> kScenes[] = {
    {"balls", R"({"model": "balls", "params": {
       "particles": {"radius": 0.02, "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": [0.2, 0.2, 0.16]},
       "engine": {"substeps": 3, "dt": 0.0008},
       "tap": {"enabled": true, "position": [0.3, 0.1, 0.3], "direction": [0, 0, -1], "speed": 1, "radius": 0.04, "max": 100},
       "obstacles": [{"shape": "sphere", "centre": [0.3, 0.1, 0.1], "size": [0.06, 0.06, 0.06],
                      "path": {"kind": "oscillate", "amplitude": [0.04, 0, 0], "period": 1}}]}})"},
    {"fluid", R"({"model": "fluid", "params": {
       "particles": {"spacing": 0.03, "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": [0.2, 0.2, 0.2]},
       "engine": {"substeps": 2, "dt": 0.002}}})"},
    {"life", R"({"model": "life", "params": {"species": 3, "particle_count": 256, "width": 200, "height": 120}})"},
    {"swarm", R"({"model": "swarm", "params": {"particles": 512, "preset": "orbit"}})"},
    {"ripples", R"({"model": "ripples", "params": {"width": 48, "height": 32, "touch": {"rain": 15}}})"},
    {"blank", R"({"model": "blank"})"},
};

}  // namespace

TEST(CheckResume, EveryModelResumesExactly) {
  test::TempDir dir;
  for (const auto& [model, json] : kScenes) {
    SCOPED_TRACE(model);
    dir.write(std::string(model) + ".json", json);
    const auto r = runTidepool(
        {"check-resume", (dir / (std::string(model) + ".json")).string(), "--frames", "6", "--size", "48x32"});
    EXPECT_FALSE(r.signaled);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("resume is exact: 6 frames resumed from a checkpoint after 6 equal 12 straight"),
              std::string::npos)
        << r.out;
  }
}

TEST(CheckResume, AStepThatReadsUnsavedStateFailsNamingTheEntry) {
  test::TempDir dir;
  std::filesystem::copy(std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "shaders", dir / "shaders",
                        std::filesystem::copy_options::recursive);
  std::ifstream in(dir / "shaders/ripples/step.comp");
  std::stringstream text;
  text << in.rdbuf();
  std::string step = text.str();
  const std::string writeOnly = "writeonly buffer StateOut", write = "stateOut[cellIndex(p)] = vec2(";
  ASSERT_NE(step.find(writeOnly), std::string::npos);
  ASSERT_NE(step.find(write), std::string::npos);
  // The step now mixes in the state of two steps ago: the other ping-pong buffer, never saved.
  step.replace(step.find(writeOnly), writeOnly.size(), "buffer StateOut");
  step.replace(step.find(write), write.size(), "stateOut[cellIndex(p)] = 0.01 * stateOut[cellIndex(p)] + vec2(");
  dir.write("shaders/ripples/step.comp", step);
  dir.write("r.json", kScenes[4].second);
  const auto r = runTidepool({"check-resume", (dir / "r.json").string(), "--frames", "6", "--size", "48x32"},
                             {"TIDEPOOL_SHADER_DIR=" + (dir / "shaders").string()});
  EXPECT_FALSE(r.signaled);
  EXPECT_EQ(r.exitCode, 1) << r.out;
  EXPECT_NE(r.err.find("resume is not exact"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'model.state'"), std::string::npos) << r.err;
}
