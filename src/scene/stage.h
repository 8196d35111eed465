// A running scene: one model (which owns its buffers and compute passes) and the renderer that
// reads it. The window app, the headless renderer, the benchmarks and the tests drive stages
// the same way: step() advances one frame of simulated time, render() draws it. How much time a
// frame is the model says from its parameters (frameSeconds()); the scene's clip fps is only the
// rate a video plays at.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/input.h"
#include "base/param.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"
#include "io/json.h"
#include "io/obj.h"
#include "render/export_source.h"
#include "render/surface_mesher.h"
#include "render/target.h"
#include "scene/scene_params.h"
#include "sim/divergence.h"
#include "sim/model.h"
#include "sim/model_state.h"

namespace tidepool {

// What the window's indicators show of a stage besides the frame rate (app/indicators.h).
struct StageIndicators {
  std::uint64_t steps = 0;        // simulation steps taken, a running count (a reset may restart it)
  std::size_t particles = 0;      // particles (or cells)
  bool countsCells = false;       // `particles` counts grid cells (ripples)
  glm::uvec3 gridCells{0u};       // the neighbour grid's cells per axis (0: no grid to show)
  float cellSize = 0.0f;          // its cell edge, world units
  std::optional<glm::mat4> view;  // 3D views: the camera's view matrix (the axes gizmo)
};

// One value per column (water::probeColumns); `error` says why some or all of them are NaN (a
// probe the running model cannot measure).
struct ProbeReadings {
  std::vector<std::string> columns;
  std::vector<double> values;
  std::string error;
};

class Stage {
 public:
  virtual ~Stage() = default;
  virtual void visitParams(ParamVisitor& v) = 0;     // the model's and the view's Params
  virtual void reset() = 0;                          // back to the initial state (same parameters)
  virtual void restart() { reset(); }                // the window's R: as reset, but life draws new random particles
  virtual void step(gl::GpuProfiler& profiler) = 0;  // one frame: frameSeconds() of simulated time
  virtual double frameSeconds() const = 0;           // simulated s of one frame, from the parameters
  virtual void render(RenderTarget& target, gl::GpuProfiler& profiler) = 0;
  virtual void input(const Input&) {}
  virtual void key(int /*asciiUpperCase*/) {}  // a letter key the app does not use (e.g. 'C', 'N')
  // A file dropped on the window: "" when the model took it, else the one line the UI shows, why
  // not (a kind of file this model does not read, or one it refused: then nothing has changed).
  // A stage reads the whole file before it changes anything.
  virtual std::string dropFile(const std::string& path) { return "this model takes no files: " + path; }
  virtual double simTime() const = 0;                   // simulated seconds since reset
  virtual std::string status() const { return ""; }     // one line for the UI (counts, warnings)
  virtual std::string shareText() const { return ""; }  // the UI offers to copy it (e.g. a rules share code)
  virtual StageIndicators indicators() { return {}; }   // steps, count, grid, camera (the window's overlay)
  // What runs now, for the window title and the panel: water "balls" or "fluid" (M switches), life
  // its preset or "seed N" (N makes new rules); "": the scene's model, which never changes.
  virtual std::string running() const { return ""; }

  // Failing loudly: a model that watches itself reports a blow-up here (non-blocking, a frame or
  // two late), can go back to its last good state with half the time step (recover() says how
  // many frames back it lies), and settles the check still in flight at the end of a headless run.
  virtual std::optional<DivergenceReport> divergence() const { return std::nullopt; }
  // The model's current error metric for the live plot (name with units, value); NaN: none yet.
  virtual std::pair<std::string, double> liveMetric() const { return {"", NAN}; }
  // The scene's own probes (sim/water/probes.h), measured now, for the live plots: none for a
  // stage without them.
  virtual ProbeReadings probes() { return {}; }
  virtual std::optional<std::uint64_t> recover() { return std::nullopt; }
  virtual void flushChecks() {}

  // Checkpoints (scene/checkpoint.h): the state beyond the parameters. A save visits
  // visitSetupState and visitState with a saver; a restore visits visitSetupState (what must be in
  // place before the parameters are read back: the water stage's running model), reads the
  // parameters through visitParams, calls reset() and then visits visitState with a loader.
  virtual void visitSetupState(sim::StateVisitor&) {}
  virtual void visitState(sim::StateVisitor& v) = 0;  // the model's state and the stage's own
  virtual sim::Model* model() { return nullptr; }     // the model it steps (blank: none), for soak runs to read

  // Export (render/particle_exporter.h): what to copy of the particles (or the ripples' heightfield)
  // as they are now; nullopt for a model with neither (blank). The obstacles as one mesh, as placed
  // now (water scenes; empty for none).
  virtual std::optional<ExportSource> exportSource() { return std::nullopt; }
  virtual io::TriangleMesh exportObstacles() { return {}; }
  // What the water-surface mesher reads (render/surface_mesher.h); nullopt for a model without
  // water (life, swarm, ripples, blank).
  virtual std::optional<SurfaceInput> surfaceInput() { return std::nullopt; }
};

// A stage whose model is a sim::Model (every model but blank): stepping, the clock, the status
// line and the divergence watch go to the model; the stage adds its view, input and extras by
// overriding (and calling ModelStage::step etc. for the model's part).
template <class M>
class ModelStage : public Stage {
  static_assert(std::is_base_of_v<sim::Model, M>, "a ModelStage drives a sim::Model");

 public:
  void reset() override { m_model.reset(); }
  void step(gl::GpuProfiler& profiler) override { m_model.step(profiler); }
  double frameSeconds() const override { return m_model.frameSeconds(); }
  double simTime() const override { return m_model.time(); }
  std::string status() const override { return m_model.status(); }
  std::optional<DivergenceReport> divergence() const override { return m_model.divergence(); }
  std::optional<std::uint64_t> recover() override { return m_model.recover(); }
  void flushChecks() override { m_model.flushChecks(); }
  void visitState(sim::StateVisitor& v) override { m_model.visitState(v); }
  sim::Model* model() override { return &m_model; }
  StageIndicators indicators() override {
    StageIndicators s;
    s.steps = m_model.stepCount();
    s.particles = m_model.count();
    return s;
  }

 protected:
  template <class... Args>
  explicit ModelStage(Args&&... args) : m_model(std::forward<Args>(args)...) {}

  M m_model;
};

// A scene key (dotted, e.g. "particles" or "model.storage", with everything under it) whose value
// shapes the state rather than steering it: a checkpoint fixes it, so a resumed run refuses it.
struct StateKey {
  const char* key;
  const char* what;  // what it sets, for the refusal: "the particles' count, size, domain and initial water"
};

struct ModelEntry {
  const char* name;
  const char* summary;
  // Reads the scene's "params" object into the model's typed parameters, validated (errors name
  // the key after `where`, e.g. "scenes/dam.json: params.engine.dt = 0 is out of range ...").
  std::function<SceneParams(const io::Json& params, const std::string& where)> parse;
  // Builds the stage from them; `where` prefixes what only the build finds (a missing mesh file).
  std::function<std::unique_ptr<Stage>(const SceneParams& params, const std::string& where, gl::ShaderLibrary&)> create;
  // The keys a checkpoint fixes (scene/checkpoint.h); every other key is live, as the window's
  // panel edits it mid-run, and a resumed run takes it on top of the checkpoint's parameters.
  std::vector<StateKey> stateKeys = {};
};

const std::vector<ModelEntry>& models();  // every model a scene may name

}  // namespace tidepool
