#include "scene/water_stage.h"

#include <cmath>
#include <filesystem>

#include "io/obj.h"
#include "render/balls_view.h"
#include "scene/param_json.h"
#include "sim/water/probes.h"

namespace tidepool {
namespace {

constexpr int kStatsInterval = 30;  // frames between statistics read-backs

class WaterStage final : public Stage {
 public:
  WaterStage(gl::ShaderLibrary& shaders, WaterModel active, const balls::Params& balls, const fluid::Params& fluid,
             const BallsViewSettings& view)
      : m_shaders(shaders),
        m_runs(waterRuns(balls, fluid)),
        m_view(view),
        m_active(active),
        m_choice(active),
        m_renderer(shaders),
        m_probes(shaders) {
    run().start(shaders, nullptr, nullptr);
    m_resolution = liveResolution();
  }

  void visitParams(ParamVisitor& v) override {
    v.choice({"water_model", "Water model", "balls (DEM contacts) or fluid (PBF): switching keeps the particles"},
             m_choice, kWaterModelNames);
    run().visitParams(v);
    visitViewGroup(v, m_view);
  }
  void reset() override {
    model()->reset();
    m_frames = 0;
    m_resolution = liveResolution();  // as set (a checkpoint's parameters are refined already)
  }
  void step(gl::GpuProfiler& profiler) override {
    if (liveResolution() != m_resolution) refineLive();
    if (m_choice != m_active) switchModel();
    const std::uint64_t before = model()->stepCount();
    model()->step(profiler);
    m_steps += run().frameSteps(before);
    if (m_frames++ % kStatsInterval == 0) run().refreshStats();
  }
  StageIndicators indicators() override {
    StageIndicators s;
    s.steps = m_steps;
    s.particles = water().count();
    if (const grid::UniformGrid* g = water().neighbourGrid()) {
      s.gridCells = g->dims();
      s.cellSize = g->params().cellSize;
    }
    s.view = m_renderer.camera().view();
    return s;
  }
  void render(RenderTarget& target, gl::GpuProfiler& profiler) override {
    m_renderer.params() = m_view.look;
    m_renderer.camera().params() = m_view.camera;
    m_renderer.render(water(), target, profiler);
  }
  void input(const Input& in) override {
    m_renderer.camera().params() = m_view.camera;
    if (!grabBody(in)) m_renderer.camera().handle(in);
    m_view.camera = m_renderer.camera().params();
  }
  // A left drag that starts on a dynamic body pulls the point picked toward the mouse, at the
  // depth along the ray where it was picked (water::Bodies::grab); elsewhere it turns the camera.
  bool grabBody(const Input& in) {
    const bool pressed = in.left && !m_leftHeld;
    m_leftHeld = in.left;
    water::Bodies* bodies = run().bodies();
    if (!in.left || !bodies) {
      if (bodies) bodies->grab(std::nullopt);
      m_grab.reset();
      return false;
    }
    const OrbitCamera& camera = m_renderer.camera();
    const glm::dvec3 origin(camera.rayOrigin(in.cursor, in.viewport));
    const glm::dvec3 direction(camera.rayDirection(in.cursor, in.viewport));
    if (pressed)
      if (const auto hit = bodies->pick(water().obstacles(), origin, direction))
        m_grab = Grab{hit->first, bodies->anchorAt(hit->first, origin + hit->second * direction), hit->second};
    if (!m_grab || !bodies->dynamic(m_grab->obstacle)) return false;
    bodies->grab(water::Bodies::Grab{m_grab->obstacle, m_grab->anchor, origin + m_grab->depth * direction});
    return true;
  }
  void key(int c) override {
    if (c == 'M') m_choice = m_choice == WaterModel::Balls ? WaterModel::Fluid : WaterModel::Balls;
  }
  // An OBJ dropped on the window becomes one more obstacle (the last one is replaced when there
  // are already kMaxObstacles): a solid fill when it is closed, else a shell, in the middle of the
  // domain. The mesh is read whole first: a bad file changes nothing (the returned line says why).
  std::string dropFile(const std::string& path) override {
    if (std::filesystem::path(path).extension() != ".obj") return "water takes OBJ meshes (.obj files): " + path;
    bool closed = false;
    try {
      closed = io::checkClosed(io::readObj(path)).closed();
    } catch (const Error& e) {
      return std::string("not added: ") + e.what();
    }
    water::Setup& p = run().setup();
    water::ObstacleParams o;
    o.shape = water::Shape::Mesh;
    o.mesh = path;
    o.centre = 0.5f * (p.domainMin + p.domainMax);
    o.size = glm::vec3(0.2f * glm::length(p.domainMax - p.domainMin) / std::sqrt(3.0f));
    o.shell = !closed;
    if (p.obstacles.size() >= water::kMaxObstacles) p.obstacles.pop_back();
    p.obstacles.push_back(o);
    return "";
  }
  std::string running() const override { return kWaterModelNames[index(m_active)]; }
  double simTime() const override { return m_runs[index(m_active)]->model()->time(); }
  double frameSeconds() const override { return m_runs[index(m_active)]->model()->frameSeconds(); }
  std::pair<std::string, double> liveMetric() const override {
    if (m_frames == 0) return {"density error (%)", NAN};
    return m_runs[index(m_active)]->liveMetric();
  }
  ProbeReadings probes() override {
    const std::vector<water::ProbeParams>& listed = water().water().probes;
    if (listed.empty()) return {};
    ProbeReadings r;
    r.columns = water::probeColumns(listed);
    try {
      r.values = m_probes.measure(*run().water(), &r.error);  // what this model cannot measure: NaN, and why
    } catch (const Error& e) {  // a probe the setup cannot measure (edited to a missing obstacle)
      r.error = e.what();
      r.values.assign(r.columns.size(), NAN);
    }
    return r;
  }
  std::string status() const override {
    const WaterRun& r = *m_runs[index(m_active)];
    std::string refused = m_switchError.empty() ? "" : "not switched: " + m_switchError + "\n";
    if (!m_resolutionError.empty()) refused += "resolution not changed: " + m_resolutionError + "\n";
    return refused + r.model()->status() + r.statsLine();
  }
  std::optional<DivergenceReport> divergence() const override { return m_runs[index(m_active)]->model()->divergence(); }
  std::optional<std::uint64_t> recover() override { return model()->recover(); }
  void flushChecks() override { model()->flushChecks(); }
  sim::Model* model() override { return run().model(); }
  std::optional<ExportSource> exportSource() override { return run().exportSource(); }
  io::TriangleMesh exportObstacles() override { return obstacleSurface(water().obstacles(), water().radius()); }
  std::optional<SurfaceInput> surfaceInput() override {
    const water::ParticleWater& w = water();
    return SurfaceInput{&w.positions(),      w.count(),
                        w.radius(),          water::volumePerParticle(w.radius(), w.packing()),
                        w.water().domainMin, w.water().domainMax};
  }

  // Checkpoints: which model runs comes before the parameters (they are that model's keys).
  void visitSetupState(sim::StateVisitor& v) override {
    WaterModel running = m_active;
    v.choice("stage.water_model", running, kWaterModelNames.size());
    if (v.loading() && running != m_active) {
      m_choice = running;
      start(running, nullptr);
    }
  }
  // The model's state, the statistics' frame phase and values, and the other model's parameters
  // (what a later switch keeps of them).
  void visitState(sim::StateVisitor& v) override {
    model()->visitState(v);
    v.value("stage.frames", m_frames);
    for (auto& r : m_runs) r->visitStats(v);
    WaterRun& other = *m_runs[1 - index(m_active)];
    const ParamVisit visitOther = [&other](ParamVisitor& p) { other.visitParams(p); };
    std::string json = writeParams(visitOther).dump();
    v.text("stage.other_model_params", json, std::size_t(1) << 20);
    if (!v.loading()) return;
    try {
      readParams(io::parseJson(json, "stage.other_model_params"), visitOther, "stage.other_model_params");
    } catch (const Error& e) {
      v.fail(e.what());
    }
  }

 private:
  struct Grab {  // the body the left button holds
    std::size_t obstacle = 0;
    glm::dvec3 anchor{0.0};
    double depth = 0;  // along the mouse's ray, m
  };
  std::optional<Grab> m_grab;
  bool m_leftHeld = false;
  static std::size_t index(WaterModel m) { return std::size_t(m); }
  WaterRun& run() { return *m_runs[index(m_active)]; }
  const water::ParticleWater& water() { return *run().water(); }
  float liveResolution() { return run().setup().resolution; }

  // Builds model `which` from its parameters; with `from`, it takes over those particles. Throws
  // Error and then keeps the running model.
  void start(WaterModel which, const water::ParticleWater* from) {
    std::vector<glm::vec4> pos, vel;
    if (from) {
      pos = from->positions().read<glm::vec4>(from->count());
      vel = from->velocities().read<glm::vec4>(from->count());
    }
    m_runs[index(which)]->start(m_shaders, from ? &pos : nullptr, from ? &vel : nullptr);
    if (which != m_active) m_runs[index(m_active)]->stop();
    m_active = which;
    m_frames = 0;
  }

  // The chosen model takes over the particles, with the running one's water setup.
  void switchModel() {
    WaterRun& to = *m_runs[index(m_choice)];
    to.setup() = water::switched(run().runningSetup(), run().packing(), to.setup(), to.packing());
    try {
      start(m_choice, &water());
    } catch (const Error& e) {  // e.g. too many particles for the other model: stay as we are
      m_choice = m_active;
      m_switchError = e.what();
    }
  }

  // particles.resolution edited in the panel: both models' parameters (the live ones with the
  // user's other edits) refined by the ratio, and the model built again with its new particles. A
  // refinement past a limit (substeps, counts, the GPU's memory) is refused by name and undone.
  void refineLive() {
    const double factor = double(liveResolution()) / m_resolution;
    run().setup().resolution = m_resolution;
    for (auto& r : m_runs) r->save();
    try {
      for (auto& r : m_runs) r->refine(factor);
      start(m_active, nullptr);
      m_resolutionError.clear();
    } catch (const Error& e) {
      for (auto& r : m_runs) r->restore();
      m_resolutionError = e.what();  // start() builds before it replaces: the old model runs on
    }
    m_resolution = liveResolution();
  }

  gl::ShaderLibrary& m_shaders;
  std::array<std::unique_ptr<WaterRun>, 2> m_runs;  // indexed by WaterModel
  BallsViewSettings m_view;
  WaterModel m_active, m_choice;
  BallsView m_renderer;
  water::Probes m_probes;
  std::string m_switchError;
  std::string m_resolutionError;  // why the last resolution edit was refused
  float m_resolution = 1;         // the refinement the running model's parameters have
  long m_frames = 0;
  std::uint64_t m_steps = 0;  // steps of either model since the start (the indicators' counter)
};

std::unique_ptr<Stage> build(gl::ShaderLibrary& shaders, WaterModel active, const balls::Params& balls,
                             const fluid::Params& fluid, const BallsViewSettings& view, const std::string& where) {
  try {
    return std::make_unique<WaterStage>(shaders, active, balls, fluid, view);
  } catch (const Error& e) {  // e.g. a missing or open obstacle mesh: say which scene asked for it
    throw Error(where + ": " + e.what());
  }
}

}  // namespace

std::unique_ptr<Stage> createWaterStage(gl::ShaderLibrary& shaders, const balls::Params& balls,
                                        const BallsViewSettings& view, const std::string& where) {
  return build(shaders, WaterModel::Balls, balls, asFluid(balls, fluid::Params{}), view, where);
}

std::unique_ptr<Stage> createWaterStage(gl::ShaderLibrary& shaders, const fluid::Params& fluid,
                                        const BallsViewSettings& view, const std::string& where) {
  return build(shaders, WaterModel::Fluid, asBalls(fluid, balls::Params{}), fluid, view, where);
}

}  // namespace tidepool
