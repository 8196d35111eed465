// The water stage runs balls or fluid and switches between them keeping the particle set (the
// window's "Water model" choice, or the M key).
#include <gtest/gtest.h>

#include <regex>

#include "scene/scene.h"
#include "scene/stage.h"
#include "support/gl_test.h"
#include "support/null_visitor.h"

using namespace tidepool;

namespace {

class WaterStage : public test::GlTest {};

// The first number of the status line: the particle count ("5000 balls + ...", "5000 particles + ...").
long countOf(const Stage& stage) {
  std::smatch m;
  const std::string status = stage.status();
  return std::regex_search(status, m, std::regex(R"((\d+) (balls|particles))")) ? std::stol(m[1]) : -1;
}

bool isFluid(const Stage& stage) { return stage.status().find("particles") != std::string::npos; }

// Sets the "water_model" choice as the UI would.
struct ChooseModel : test::NullVisitor {
  int index = 0;
  void choiceIndex(const ParamInfo& info, int& value, std::span<const char* const>) override {
    if (std::string(info.key) == "water_model") value = index;
  }
};

std::unique_ptr<Stage> small(gl::ShaderLibrary& shaders, const char* model) {
  const std::string params = std::string(model) == "balls"
                                 ? R"({"particles": {"radius": 0.02, "domain_max": [0.4, 0.2, 0.4], "fill": "block",
                                       "fill_max": [0.2, 0.2, 0.2]}})"
                                 : R"({"particles": {"spacing": 0.04, "domain_max": [0.4, 0.2, 0.4], "fill": "block",
                                       "fill_max": [0.2, 0.2, 0.2]}})";
  Scene s = parseScene(
      io::parseJson(std::string(R"({"model": ")") + model + R"(", "params": )" + params + "}", "w.json"), "w.json");
  return createStage(s, shaders);
}

}  // namespace

TEST_F(WaterStage, SwitchingBetweenBallsAndFluidKeepsTheParticles) {
  for (const char* start : {"balls", "fluid"}) {
    SCOPED_TRACE(start);
    std::unique_ptr<Stage> stage = small(shaders(), start);
    gl::GpuProfiler profiler;
    for (int i = 0; i < 3; ++i) stage->step(profiler);
    const long before = countOf(*stage);
    ASSERT_GT(before, 0);
    const bool wasFluid = isFluid(*stage);
    EXPECT_EQ(wasFluid, std::string(start) == "fluid");
    EXPECT_EQ(stage->running(), start);                  // as the window's title says it
    stage->key('M');                                     // the next step switches
    for (int i = 0; i < 10; ++i) stage->step(profiler);  // and the other model runs on with them
    EXPECT_NE(isFluid(*stage), wasFluid) << stage->status();
    EXPECT_EQ(stage->running(), wasFluid ? "balls" : "fluid");
    EXPECT_EQ(countOf(*stage), before) << stage->status();
    ChooseModel back;  // and back through the UI's choice
    back.index = wasFluid ? 1 : 0;
    stage->visitParams(back);
    stage->step(profiler);
    EXPECT_EQ(isFluid(*stage), wasFluid) << stage->status();
    EXPECT_EQ(countOf(*stage), before);
    EXPECT_FALSE(stage->divergence().has_value());
  }
}
