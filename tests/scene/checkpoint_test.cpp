// Checkpoints of running stages: 200 frames straight equal 100 frames, a save to a file, a load
// into a freshly created stage and 100 more frames, bit for bit, for every model (with the state
// each one keeps besides its buffers in play: a tap, Verlet's accelerations, moving obstacles and
// walls, bodies, rain's random generator, scheduled drops, life's rules and fp16 storage, the swarm's
// image colours, the water stage's switched model); and what a restore refuses.
#include "scene/checkpoint.h"

#include <gtest/gtest.h>

#include <cstring>

#include "scene/param_json.h"
#include "sim/ripples/ripples.h"
#include "support/error_of.h"
#include "support/gl_test.h"
#include "support/null_visitor.h"

using namespace tidepool;
using test::errorOf;

namespace {

class Checkpoints : public test::GlTest {};

constexpr double kFrame = 1.0 / 30;

Scene sceneOf(const std::string& json) {
  Scene s = parseScene(io::parseJson(json, "c.json"), "c.json");
  s.file = "c.json";  // as loadScene sets it
  return s;
}

// `n` frames as the app runs them: a step, then (with a target) a render, which may set what the
// next step reads (the swarm's aspect).
void frames(Stage& stage, int n, RenderTarget* target = nullptr) {
  gl::GpuProfiler profiler;
  for (int i = 0; i < n; ++i) {
    profiler.beginFrame();
    stage.step(profiler);
    if (target) stage.render(*target, profiler);
    profiler.endFrame();
    ASSERT_FALSE(stage.divergence().has_value()) << stage.divergence()->message;
  }
}

// Everything a checkpoint holds, the divergence watch's phase and last good copy included.
std::map<std::string, std::vector<std::uint8_t>> stateOf(Stage& stage, const Scene& scene) {
  const io::Checkpoint c = captureCheckpoint(stage, scene);
  std::map<std::string, std::vector<std::uint8_t>> out;
  for (const io::CheckpointEntry& e : c.entries) out[e.name] = e.bytes;
  const auto* t = reinterpret_cast<const std::uint8_t*>(&c.time);
  out["time"] = std::vector<std::uint8_t>(t, t + sizeof c.time);
  out["params"] = std::vector<std::uint8_t>(c.params.begin(), c.params.end());
  return out;
}

std::size_t bufferBytes(const std::map<std::string, std::vector<std::uint8_t>>& state) {
  std::size_t n = 0;
  for (const auto& [name, bytes] : state)
    if (name.rfind("model.", 0) == 0) n += bytes.size();
  return n;
}

// The names of the entries in which two states differ (and of those only one has).
std::vector<std::string> differences(const std::map<std::string, std::vector<std::uint8_t>>& a,
                                     const std::map<std::string, std::vector<std::uint8_t>>& b) {
  std::vector<std::string> out;
  for (const auto& [name, bytes] : a)
    if (!b.count(name) || b.at(name) != bytes) out.push_back(name);
  for (const auto& [name, bytes] : b)
    if (!a.count(name)) out.push_back(name);
  return out;
}

// 200 frames straight against 100 + save + load into a new stage + 100; `atFrame` runs before
// each frame's step (e.g. a key); `render`: each frame renders after its step into an image of
// another aspect than the default.
void expectExactRestore(gl::ShaderLibrary& shaders, const std::string& json,
                        const std::function<void(Stage&, int)>& atFrame = {}, bool render = false) {
  const Scene scene = sceneOf(json);
  test::TempDir dir;
  RenderTarget target(48, 24);
  const auto run = [&](Stage& stage, int from, int to) {
    for (int i = from; i < to; ++i) {
      if (atFrame) atFrame(stage, i);
      frames(stage, 1, render ? &target : nullptr);
    }
  };
  auto straight = createStage(scene, shaders);
  run(*straight, 0, 100);
  const auto middle = stateOf(*straight, scene);
  run(*straight, 100, 200);
  const auto expected = stateOf(*straight, scene);
  straight.reset();

  {
    auto first = createStage(scene, shaders);
    run(*first, 0, 100);
    saveCheckpoint(*first, scene, dir / "run.ckpt");
  }
  auto resumed = createStage(scene, shaders);
  loadCheckpoint(*resumed, scene, dir / "run.ckpt");
  EXPECT_EQ(differences(stateOf(*resumed, scene), middle), std::vector<std::string>{})
      << "the restored state differs from the straight run's at frame 100 in these entries";
  run(*resumed, 100, 200);
  const auto actual = stateOf(*resumed, scene);

  ASSERT_GT(bufferBytes(expected), 0u);
  EXPECT_NE(middle.at("time"), expected.at("time"));
  EXPECT_EQ(differences(actual, expected), std::vector<std::string>{})
      << "the resumed run differs from the straight one at frame 200 in these entries";
  std::size_t moved = 0;
  for (const auto& [name, bytes] : expected) moved += name.rfind("model.", 0) == 0 && middle.at(name) != bytes;
  EXPECT_GT(moved, 0u) << "nothing moved in the last 100 frames: the comparison would prove nothing";
}

const char* kBalls = R"({"model": "balls", "params": {
  "particles": {"radius": 0.02, "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": [0.2, 0.2, 0.16]},
  "engine": {"integrator": "verlet", "substeps": 3, "dt": 0.0008},
  "walls": {"piston_axis": 1, "piston_travel": 0.2, "piston_period": 2},
  "tap": {"enabled": true, "position": [0.3, 0.1, 0.3], "direction": [0, 0, -1], "speed": 1, "radius": 0.04, "max": 200},
  "obstacles": [{"shape": "sphere", "centre": [0.3, 0.1, 0.1], "size": [0.06, 0.06, 0.06], "spin": 2,
                 "spin_axis": [0, 0, 1], "path": {"kind": "oscillate", "amplitude": [0.04, 0, 0], "period": 1}}]}})";

const char* kFluid = R"({"model": "fluid", "params": {
  "particles": {"spacing": 0.03, "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": [0.2, 0.2, 0.2]},
  "engine": {"substeps": 2, "dt": 0.002},
  "tap": {"enabled": true, "position": [0.3, 0.1, 0.3], "direction": [0, 0, -1], "speed": 1, "radius": 0.04, "max": 150},
  "obstacles": [{"shape": "sphere", "centre": [0.3, 0.1, 0.1], "size": [0.08, 0.08, 0.08],
                 "path": {"kind": "oscillate", "amplitude": [0.04, 0, 0], "period": 1}}]}})";

// Two bodies dropped into the water: one falls onto the other's corner.
const char* kFluidBodies = R"({"model": "fluid", "params": {
  "particles": {"spacing": 0.03, "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": [0.4, 0.2, 0.12]},
  "engine": {"substeps": 2, "dt": 0.002},
  "obstacles": [{"shape": "box", "centre": [0.2, 0.1, 0.2], "size": [0.06, 0.06, 0.03], "dynamic": true, "density": 400},
                {"shape": "box", "centre": [0.24, 0.1, 0.3], "size": [0.04, 0.04, 0.04], "dynamic": true,
                 "density": 900, "orientation": [0, 20, 10]}]}})";

// The same bodies on balls, with velocity Verlet (its stored accelerations and the bodies' states
// both restored).
const char* kBallsBodies = R"({"model": "balls", "params": {
  "particles": {"radius": 0.015, "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": [0.4, 0.2, 0.12]},
  "engine": {"integrator": "verlet", "substeps": 4, "dt": 0.0008},
  "obstacles": [{"shape": "box", "centre": [0.2, 0.1, 0.2], "size": [0.06, 0.06, 0.03], "dynamic": true, "density": 400},
                {"shape": "box", "centre": [0.24, 0.1, 0.3], "size": [0.04, 0.04, 0.04], "dynamic": true,
                 "density": 900, "orientation": [0, 20, 10]}]}})";

}  // namespace

TEST_F(Checkpoints, FluidWithBodiesRestoresExactly) { expectExactRestore(shaders(), kFluidBodies); }

TEST_F(Checkpoints, BallsWithBodiesRestoreExactly) { expectExactRestore(shaders(), kBallsBodies); }

TEST_F(Checkpoints, BallsRestoreExactly) { expectExactRestore(shaders(), kBalls); }

TEST_F(Checkpoints, FluidRestoresExactly) { expectExactRestore(shaders(), kFluid); }

TEST_F(Checkpoints, WaterSwitchedToTheOtherModelRestoresExactly) {
  // A balls scene switched to fluid at frame 40 (M): the checkpoint at 100 runs fluid.
  expectExactRestore(shaders(), kBalls, [](Stage& stage, int frame) {
    if (frame == 40) stage.key('M');
  });
}

TEST_F(Checkpoints, LifeRestoresExactly) {
  expectExactRestore(shaders(), R"({"model": "life", "params": {"species": 4, "particle_count": 2000,
    "width": 200, "height": 120, "seed": 7, "model": {"max_dt": 0.02}}})");
}

TEST_F(Checkpoints, LifeWithVerletAndFp16StorageOnATorusRestoresExactly) {
  expectExactRestore(shaders(), R"({"model": "life", "params": {"species": 3, "particle_count": 1500,
    "width": 160, "height": 160, "seed": 11, "looping_borders": true,
    "model": {"integrator": "verlet", "storage": "fp16", "max_dt": 0.02}}})");
}

TEST_F(Checkpoints, SwarmRestoresExactly) {
  expectExactRestore(shaders(), R"({"model": "swarm", "params": {"particles": 20000, "integrator": "rk4",
    "preset": "sines", "substeps": 2, "view": {"color_mode": "image", "image": "colors"}}})",
                     {}, true);
}

TEST_F(Checkpoints, RipplesWithRainDropsAndASphereRestoreExactly) {
  expectExactRestore(shaders(), R"({"model": "ripples", "params": {"width": 64, "height": 48,
    "touch": {"rain": 20}, "sphere": {"enabled": true},
    "drops": [{"time": 1.0, "x": 0.3, "y": 0.4}, {"time": 4.5, "x": 0.7, "y": 0.6}]}})");
}

TEST_F(Checkpoints, BlankKeepsItsClock) {
  const Scene scene = sceneOf(R"({"model": "blank"})");
  test::TempDir dir;
  auto stage = createStage(scene, shaders());
  frames(*stage, 7);
  saveCheckpoint(*stage, scene, dir / "b.ckpt");
  auto fresh = createStage(scene, shaders());
  loadCheckpoint(*fresh, scene, dir / "b.ckpt");
  EXPECT_EQ(fresh->simTime(), stage->simTime());
}

// Parameters edited while running are part of the checkpoint and override the scene file's.
TEST_F(Checkpoints, LiveEditsOfTheParametersSurviveARestore) {
  struct SetFriction : test::NullVisitor {
    void real(const ParamInfo& info, float& value, float, float) override {
      if (std::string(info.key) == "friction") value = 2.5f;
    }
  };
  const Scene scene = sceneOf(R"({"model": "swarm", "params": {"particles": 3000, "friction": 0.5}})");
  test::TempDir dir;
  auto stage = createStage(scene, shaders());
  frames(*stage, 3);
  SetFriction edit;
  stage->visitParams(edit);
  frames(*stage, 3);
  saveCheckpoint(*stage, scene, dir / "s.ckpt");
  auto fresh = createStage(scene, shaders());
  loadCheckpoint(*fresh, scene, dir / "s.ckpt");
  const io::Json params = writeParams([&](ParamVisitor& v) { fresh->visitParams(v); });
  EXPECT_EQ(params.at("friction").get<float>(), 2.5f);
}

TEST_F(Checkpoints, AnotherModelsCheckpointIsRefusedNamingBoth) {
  const Scene balls = sceneOf(kBalls), fluid = sceneOf(kFluid);
  test::TempDir dir;
  auto stage = createStage(balls, shaders());
  frames(*stage, 2);
  saveCheckpoint(*stage, balls, dir / "run.ckpt");
  auto other = createStage(fluid, shaders());
  EXPECT_EQ(errorOf([&] { loadCheckpoint(*other, fluid, dir / "run.ckpt"); }),
            (dir / "run.ckpt").string() + " is a balls checkpoint (of c.json), the scene runs fluid");
}

// Entries that do not fit the state at the checkpoint's parameters: a buffer of another size, a
// count above the capacity, a missing or a foreign entry, parameters out of range.
TEST_F(Checkpoints, EntriesThatDoNotFitTheSceneAreRefusedNamingThem) {
  const Scene scene = sceneOf(kBalls);
  auto stage = createStage(scene, shaders());
  frames(*stage, 2);
  const io::Checkpoint good = captureCheckpoint(*stage, scene);
  const auto refusal = [&](const std::function<void(io::Checkpoint&)>& edit) {
    io::Checkpoint c = good;
    edit(c);
    auto fresh = createStage(scene, shaders());
    return errorOf([&] { restoreCheckpoint(*fresh, scene, c, "run.ckpt"); });
  };
  const auto entry = [](io::Checkpoint& c, const std::string& name) -> io::CheckpointEntry& {
    for (io::CheckpointEntry& e : c.entries)
      if (e.name == name) return e;
    throw Error("no " + name);
  };
  std::size_t positions = entry(const_cast<io::Checkpoint&>(good), "model.positions").bytes.size();
  EXPECT_EQ(refusal([&](io::Checkpoint& c) { entry(c, "model.positions").bytes.resize(positions - 16); }),
            "run.ckpt: buffer 'model.positions' holds " + std::to_string(positions - 16) +
                " bytes, the scene's state at these parameters has " + std::to_string(positions));
  const std::string count = refusal([&](io::Checkpoint& c) { entry(c, "model.count").bytes.assign(8, 0xFF); });
  EXPECT_NE(count.find("run.ckpt: entry 'model.count' = 18446744073709551615 is more than these parameters allow"),
            std::string::npos)
      << count;
  EXPECT_EQ(refusal([&](io::Checkpoint& c) { entry(c, "model.tap_next_layer").bytes.resize(4); }),
            "run.ckpt: entry 'model.tap_next_layer' holds 4 bytes, this build's has 8");
  EXPECT_EQ(refusal([&](io::Checkpoint& c) {
              std::erase_if(c.entries, [](auto& e) { return e.name == "model.acc_valid"; });
            }),
            "run.ckpt: no entry 'model.acc_valid' (a checkpoint of another model or build)");
  EXPECT_EQ(refusal([&](io::Checkpoint& c) {
              c.entries.push_back({io::EntryKind::Value, "model.extra", {1}});
            }),
            "run.ckpt: entry 'model.extra' is not part of this scene's state");
  EXPECT_EQ(refusal([&](io::Checkpoint& c) { entry(c, "model.acc_valid").bytes = {7}; }),
            "run.ckpt: entry 'model.acc_valid' = 7 is not a flag (0 or 1)");
  const std::string params = refusal([&](io::Checkpoint& c) {
    io::Json p = io::parseJson(c.params, "p");
    p["engine"]["dt"] = 0;
    c.params = p.dump();
  });
  EXPECT_EQ(params.rfind("run.ckpt: params.engine.dt = 0 is out of range", 0), 0u) << params;
  const std::string tooMany = refusal([&](io::Checkpoint& c) {  // the model itself refuses these parameters
    io::Json p = io::parseJson(c.params, "p");
    p["particles"]["max_particles"] = 10;
    c.params = p.dump();
  });
  EXPECT_EQ(tooMany.rfind("run.ckpt: balls: ", 0), 0u) << tooMany;
  EXPECT_NE(tooMany.find("but at most 10 fit (max_particles = 10)"), std::string::npos) << tooMany;
  EXPECT_NE(refusal([&](io::Checkpoint& c) { c.params = "{"; }).find("run.ckpt: params:1:2: malformed JSON"),
            std::string::npos);
}

TEST_F(Checkpoints, ADivergedStateIsNotSaved) {
  const Scene scene = sceneOf(R"({"model": "ripples", "params": {"width": 16, "height": 16}})");
  ripples::Ripples model(shaders(), scene.params.model<ripples::Params>());
  std::vector<float> state(16 * 16 * 2, 0.0f);
  state[40] = std::nanf("");
  model.upload(state);
  io::Checkpoint c;
  sim::StateSaver saver(c);
  EXPECT_EQ(errorOf([&] { model.visitState(saver); }),
            "checkpoint not saved: ripples state: 1 cells are NaN or infinite");
}

// The watch's last good copy travels with the checkpoint: a resumed run that fails its very first
// check recovers to the good state the saving run had judged, bit for bit.
TEST_F(Checkpoints, TheLastGoodStateIsSavedSoThatAResumedRunCanRecover) {
  const Scene scene = sceneOf(R"({"model": "ripples", "params": {"width": 16, "height": 16}})");
  ripples::Params p = scene.params.model<ripples::Params>();
  p.frameSeconds = 1.0 / 60;
  p.autoSubsteps = false;  // one step per frame at C = 0.5, then (after the load) at C = 5
  p.substeps = 1;
  p.waveSpeed = float(0.5 * p.cellSize / p.frameSeconds);
  ripples::Ripples model(shaders(), p);
  std::vector<float> state(16 * 16 * 2, 0.0f);
  for (std::size_t i = 0; i < state.size(); i += 2) state[i] = 1e-3f * float(i % 7) - 3e-3f;
  model.upload(state);
  gl::GpuProfiler profiler;
  for (int i = 0; i < 20; ++i) {
    model.step(profiler);
    model.flushChecks();  // each check is judged before the next starts: good copies are kept
  }
  io::Checkpoint saved;
  sim::StateSaver saver(saved);
  model.visitState(saver);
  const io::CheckpointEntry* flag = saved.find("watch.has_good");
  ASSERT_TRUE(flag && flag->bytes == std::vector<std::uint8_t>{1}) << "20 judged frames keep a good copy";
  const io::CheckpointEntry* goodState = saved.find("watch.good.state");
  const io::CheckpointEntry* goodTime = saved.find("watch.good.time");
  ASSERT_TRUE(goodState && goodTime);
  double tGood = 0;
  std::memcpy(&tGood, goodTime->bytes.data(), sizeof tGood);
  ASSERT_GT(tGood, 0.0);
  ASSERT_LE(tGood, model.time());

  ripples::Ripples resumed(shaders(), p);
  sim::StateLoader loader(saved, "run.ckpt");
  resumed.visitState(loader);
  loader.finish();
  // Saved again at once, the copy is the same, entry for entry.
  io::Checkpoint again;
  sim::StateSaver saver2(again);
  resumed.visitState(saver2);
  for (const char* name : {"watch.has_good", "watch.good.time", "watch.good.count", "watch.good.state"})
    EXPECT_EQ(again.find(name)->bytes, saved.find(name)->bytes) << name;

  // Far past the Courant limit it blows up before its first check after the load: with the saved
  // copy, recovery goes back to it (without, there would be nothing to go back to).
  resumed.params().waveSpeed *= 10;
  for (int i = 0; i < 60 && !resumed.divergence(); ++i) {
    resumed.step(profiler);
    resumed.flushChecks();
  }
  ASSERT_TRUE(resumed.divergence().has_value()) << "C far above 1/sqrt(2) must blow up";
  const double failedTime = resumed.time();
  const std::optional<std::uint64_t> back = resumed.recover();
  ASSERT_TRUE(back) << "the good copy came with the checkpoint";
  EXPECT_EQ(resumed.time(), tGood);
  // Frames counted since the good copy, before the save and after the load alike.
  EXPECT_EQ(double(*back), std::round((failedTime - tGood) / p.frameSeconds));
  const std::vector<float> restored = resumed.download();
  ASSERT_EQ(restored.size() * sizeof(float), goodState->bytes.size());
  EXPECT_EQ(std::memcmp(restored.data(), goodState->bytes.data(), goodState->bytes.size()), 0);
}

TEST_F(Checkpoints, AGoodCopyLargerThanTheStateIsRefused) {
  const Scene scene = sceneOf(R"({"model": "ripples", "params": {"width": 16, "height": 16}})");
  const ripples::Params p = scene.params.model<ripples::Params>();
  ripples::Ripples model(shaders(), p);
  gl::GpuProfiler profiler;
  for (int i = 0; i < 20; ++i) {
    model.step(profiler);
    model.flushChecks();
  }
  io::Checkpoint saved;
  sim::StateSaver saver(saved);
  model.visitState(saver);
  ASSERT_NE(saved.find("watch.good.state.bytes"), nullptr);
  for (io::CheckpointEntry& e : saved.entries)
    if (e.name == "watch.good.state.bytes") {
      const std::uint64_t huge = std::uint64_t(1) << 40;
      std::memcpy(e.bytes.data(), &huge, sizeof huge);
    }
  ripples::Ripples resumed(shaders(), p);
  sim::StateLoader loader(saved, "run.ckpt");
  const std::string error = errorOf([&] { resumed.visitState(loader); });
  EXPECT_EQ(error.rfind("run.ckpt: entry 'watch.good.state.bytes' = 1099511627776 is more than", 0), 0u) << error;
}

TEST(CheckpointSchedule, SavesAtEveryMultipleOfThePeriodCountedFromZero) {
  CheckpointSchedule s(0.5, 0.0);
  std::vector<double> saved;
  double t = 0;
  for (int i = 0; i < 60; ++i) {  // 2 s of frames of 1/30 s: t drifts off the exact multiples
    t += kFrame;
    if (s.due(t)) saved.push_back(t);
  }
  ASSERT_EQ(saved.size(), 4u);
  for (std::size_t k = 0; k < saved.size(); ++k) EXPECT_NEAR(saved[k], 0.5 * double(k + 1), 1e-9);
  CheckpointSchedule resumed(0.5, 1.2);  // a run resumed at t = 1.2 s keeps the cadence
  EXPECT_DOUBLE_EQ(resumed.next(), 1.5);
  EXPECT_FALSE(resumed.due(1.4));
  EXPECT_TRUE(resumed.due(1.7));  // one save for a frame that passed a multiple
  EXPECT_DOUBLE_EQ(resumed.next(), 2.0);
  CheckpointSchedule off(0.0, 0.0);
  EXPECT_FALSE(off.due(1e9));
}

TEST(CheckpointSchedule, DefaultPathsLieBesideTheOutput) {
  EXPECT_EQ(defaultCheckpointPath("out/dam", "", "scenes/dam.json"), "out/dam.ckpt");
  EXPECT_EQ(defaultCheckpointPath("out/dam/", "", "scenes/dam.json"), "out/dam.ckpt");
  EXPECT_EQ(defaultCheckpointPath("", "clips/a.mp4", "scenes/dam.json"), "clips/a.ckpt");
  EXPECT_EQ(defaultCheckpointPath("", "", "scenes/dam.json"), "dam.ckpt");
}
