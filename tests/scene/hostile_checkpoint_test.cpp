// Checkpoints whose framing and checksum are valid but whose values are not (anyone can recompute
// a CRC-32): each model refuses, in one line naming the entry or the state, NaN and infinite
// numbers, out-of-range values, counts and capacities the parameters and buffers do not back, a
// state that fails its health check or crowds a grid cell, and parameters it cannot run.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>

#include "scene/checkpoint.h"
#include "support/checkpoint_edit.h"
#include "support/error_of.h"
#include "support/gl_test.h"

using namespace tidepool;
using test::errorOf;
using test::setElement;
using test::setValue;

namespace {

class HostileCheckpoints : public test::GlTest {
 public:
  // A checkpoint of `json` after `n` frames (each check judged at once, so the watch keeps a good copy).
  void capture(const std::string& json, int n = 10) {
    m_scene = parseScene(io::parseJson(json, "c.json"), "c.json");
    auto stage = createStage(m_scene, shaders());
    gl::GpuProfiler profiler;
    for (int i = 0; i < n; ++i) {
      profiler.beginFrame();
      stage->step(profiler);
      stage->flushChecks();
      profiler.endFrame();
    }
    m_good = captureCheckpoint(*stage, m_scene);
  }
  // What restoring the checkpoint, edited, into a fresh stage says ("" if it loads).
  std::string refusal(const std::function<void(io::Checkpoint&)>& edit) {
    io::Checkpoint c = m_good;
    edit(c);
    auto fresh = createStage(m_scene, shaders());
    return errorOf([&] { restoreCheckpoint(*fresh, m_scene, c, "run.ckpt"); });
  }
  std::size_t count() const {
    std::uint64_t n = 0;
    std::memcpy(&n, m_good.find("model.count")->bytes.data(), sizeof n);
    return std::size_t(n);
  }

  Scene m_scene;
  io::Checkpoint m_good;
};

const char* kBalls = R"({"model": "balls", "params": {
  "particles": {"radius": 0.02, "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": [0.2, 0.2, 0.16]}}})";
const char* kFluid = R"({"model": "fluid", "params": {
  "particles": {"spacing": 0.03, "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": [0.2, 0.2, 0.2]}}})";

#define EXPECT_STARTS(text, prefix) EXPECT_EQ((text).rfind(prefix, 0), 0u) << (text)
#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

// What balls and fluid refuse alike; `many` is how the health check words their particles.
void expectWaterRefusals(HostileCheckpoints& t, const std::string& model, const std::string& many) {
  ASSERT_EQ(t.refusal([](io::Checkpoint&) {}), "") << "the checkpoint as saved loads";
  const std::size_t n = t.count();
  ASSERT_GT(n, 64u);
  EXPECT_STARTS(t.refusal([](io::Checkpoint& c) { setValue(c, "model.capacity", std::uint64_t(33554432)); }),
                "run.ckpt: entry 'model.capacity' = 33554432 is more than the parameters' fill and tap (");
  EXPECT_EQ(t.refusal([](io::Checkpoint& c) { setValue(c, "model.tap_next_layer", double(INFINITY)); }),
            "run.ckpt: entry 'model.tap_next_layer' = inf is not a finite number");
  EXPECT_EQ(t.refusal([](io::Checkpoint& c) { setElement(c, "model.positions", 3, glm::vec4(NAN, 0, 0, 1)); }),
            "run.ckpt: " + model + " state: 1 " + many + " are NaN or infinite");
  EXPECT_EQ(t.refusal([](io::Checkpoint& c) { setElement(c, "model.velocities", 5, glm::vec4(0, INFINITY, 0, 0)); }),
            "run.ckpt: " + model + " state: 1 " + many + " are NaN or infinite");
  EXPECT_EQ(t.refusal([](io::Checkpoint& c) { setElement(c, "model.positions", 0, glm::vec4(5, 5, 5, 1)); }),
            "run.ckpt: " + model + " state: 1 " + many + " left the domain");
  // Every particle at one point: a step would compare each with all the others.
  const std::string crowded = t.refusal([n](io::Checkpoint& c) {
    for (std::size_t i = 0; i < n; ++i) setElement(c, "model.positions", i, glm::vec4(0.1f, 0.1f, 0.1f, 1.0f));
  });
  EXPECT_STARTS(crowded, "run.ckpt: " + std::to_string(n) + " particles in one cube of edge 2r = ");
  EXPECT_HAS(crowded, ", at most 64 (water at rest packs 1.41)");
}

}  // namespace

TEST_F(HostileCheckpoints, BallsRefuseWhatTheirParametersAndHealthDoNotAllow) {
  capture(kBalls);
  expectWaterRefusals(*this, "balls", "balls");
}

TEST_F(HostileCheckpoints, FluidRefusesWhatItsParametersAndHealthDoNotAllow) {
  capture(kFluid);
  expectWaterRefusals(*this, "fluid", "fluid particles");
}

TEST_F(HostileCheckpoints, RipplesRefuseRainDebtNaNCellsAndAGoodCopyOfAnotherCount) {
  capture(R"({"model": "ripples", "params": {"width": 16, "height": 16, "touch": {"rain": 15}}})", 20);
  ASSERT_EQ(refusal([](io::Checkpoint&) {}), "");
  EXPECT_EQ(refusal([](io::Checkpoint& c) { setValue(c, "model.rain_debt", double(INFINITY)); }),
            "run.ckpt: entry 'model.rain_debt' = inf is not a finite number");
  EXPECT_EQ(refusal([](io::Checkpoint& c) { setValue(c, "model.rain_debt", 1e9); }),
            "run.ckpt: entry 'model.rain_debt' = 1000000000.000000 is not in [0, 1)");
  EXPECT_EQ(refusal([](io::Checkpoint& c) { setElement(c, "model.state", 7, NAN); }),
            "run.ckpt: ripples state: 1 cells are NaN or infinite");
  ASSERT_NE(m_good.find("watch.good.count"), nullptr) << "20 judged frames keep a good copy";
  EXPECT_STARTS(refusal([](io::Checkpoint& c) { setValue(c, "watch.good.count", std::uint64_t(1000000)); }),
                "run.ckpt: entry 'watch.good.count' = 1000000 ");
  EXPECT_EQ(refusal([](io::Checkpoint& c) { setValue(c, "watch.good.count", std::uint64_t(16 * 16 * 2)); }),
            "run.ckpt: entry 'watch.good.count' = 512 does not match 'watch.good.state' of 2048 bytes");
  EXPECT_STARTS(refusal([](io::Checkpoint& c) { setValue(c, "watch.good.time", 1e6); }),
                "run.ckpt: entry 'watch.good.time' = 1000000.000000 is after the state's time ");
  EXPECT_HAS(refusal([](io::Checkpoint& c) { setValue(c, "watch.report_time", double(NAN)); }),
             "run.ckpt: entry 'watch.report_time' = ");
}

TEST_F(HostileCheckpoints, SwarmRefusesACountItCannotHoldAndNaNs) {
  capture(R"({"model": "swarm", "params": {"particles": 4096}})");
  ASSERT_EQ(refusal([](io::Checkpoint&) {}), "");
  // Parameters asking for more than the device holds: refused, not run with the scene's count.
  const std::string tooMany = refusal([](io::Checkpoint& c) {
    io::Json p = io::parseJson(c.params, "p");
    p["particles"] = 64 << 20;
    c.params = p.dump();
  });
  EXPECT_STARTS(tooMany, "run.ckpt: ");
  EXPECT_HAS(refusal([](io::Checkpoint& c) { setValue(c, "model.aspect", double(NAN)); }), "entry 'model.aspect' = ");
  EXPECT_EQ(refusal([](io::Checkpoint& c) { setValue(c, "model.aspect", -1.0); }),
            "run.ckpt: entry 'model.aspect' = -1.000000 is not a width/height ratio");
  EXPECT_EQ(refusal([](io::Checkpoint& c) { setValue(c, "model.mouse", glm::dvec2(INFINITY, 0)); }),
            "run.ckpt: entry 'model.mouse' = inf is not a finite number");
  EXPECT_STARTS(refusal([](io::Checkpoint& c) { setElement(c, "model.state", 0, NAN); }), "run.ckpt: swarm state: ");
}

TEST_F(HostileCheckpoints, LifeRefusesNaNsInItsStateAndBrush) {
  capture(R"({"model": "life", "params": {"species": 3, "particle_count": 1000}})");
  ASSERT_EQ(refusal([](io::Checkpoint&) {}), "");
  EXPECT_EQ(refusal([](io::Checkpoint& c) { setValue(c, "model.push_radius", float(INFINITY)); }),
            "run.ckpt: entry 'model.push_radius' = inf is not a finite number");
  EXPECT_STARTS(refusal([](io::Checkpoint& c) { setElement(c, "model.positions", 0, NAN); }), "run.ckpt: life state: ");
}
