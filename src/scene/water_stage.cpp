#include "scene/water_stage.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "io/obj.h"
#include "render/balls_view.h"
#include "scene/param_json.h"
#include "sim/balls/balls.h"
#include "sim/balls/balls_init.h"
#include "sim/fluid/fluid.h"

namespace tidepool {
namespace {
const float kHcpOverCubic = std::pow(2.0f, 1.0f / 6.0f);  // 2r / d at equal particles per volume
}  // namespace

balls::Params asBalls(const fluid::Params& f, balls::Params own) {
  const balls::Params w = fluid::resolvedWater(f);
  own.radius = 0.5f * f.spacing * kHcpOverCubic;
  own.domainMin = w.domainMin;
  own.domainMax = w.domainMax;
  own.fill = w.fill;
  own.fillMin = w.fillMin;
  own.fillMax = w.fillMax;
  own.slabHeight = w.slabHeight;
  own.randomCount = w.randomCount;
  own.jitter = w.jitter;
  own.maxParticles = w.maxParticles;
  own.resolution = w.resolution;
  own.pistonAxis = w.pistonAxis;
  own.pistonTravel = w.pistonTravel;
  own.pistonPeriod = w.pistonPeriod;
  own.rotation = w.rotation;
  own.rotationRate = w.rotationRate;
  own.contraction = w.contraction;
  own.gravity = w.gravity;
  own.obstacles = w.obstacles;
  own.tap = w.tap;
  own.tapPosition = w.tapPosition;
  own.tapDirection = w.tapDirection;
  own.tapSpeed = w.tapSpeed;
  own.tapRadius = w.tapRadius;
  own.tapMax = w.tapMax;
  return own;
}

fluid::Params asFluid(const balls::Params& b, fluid::Params own) {
  const balls::Params kept = own.water;  // the fluid keeps its own time step and damping
  own.water = balls::resolved(b);
  own.water.dt = kept.dt;
  own.water.substeps = kept.substeps;
  own.water.damping = kept.damping;
  own.spacing = 2.0f * own.water.radius / kHcpOverCubic;
  return own;
}

namespace {

// Balls and fluid parameters for a scene of either model; `active` says which one it runs.
struct WaterSetup {
  WaterModel active = WaterModel::Balls;
  balls::Params balls;
  fluid::Params fluid;
  BallsViewSettings view;
};

constexpr int kStatsInterval = 30;  // frames between statistics read-backs

class WaterStage final : public Stage {
 public:
  WaterStage(gl::ShaderLibrary& shaders, const WaterSetup& setup)
      : m_shaders(shaders), m_setup(setup), m_choice(setup.active), m_view(shaders) {
    start(nullptr);
    m_resolution = liveResolution();
  }

  void visitParams(ParamVisitor& v) override {
    v.choice({"water_model", "Water model", "balls (DEM contacts) or fluid (PBF): switching keeps the particles"},
             m_choice, kWaterModelNames);
    if (m_balls)
      balls::visit(v, m_balls->params());
    else
      fluid::visit(v, m_fluid->params());
    visitViewGroup(v, m_setup.view);
  }
  void reset() override {
    model()->reset();
    m_frames = 0;
    m_resolution = liveResolution();  // as set (a checkpoint's parameters are refined already)
  }
  void step(double frameSeconds, gl::GpuProfiler& profiler) override {
    if (liveResolution() != m_resolution) refineLive();
    if (m_choice != active()) switchModel();
    const std::uint64_t before = model()->stepCount();
    model()->step(frameSeconds, profiler);
    // Balls do not count their steps: a frame is params().substeps of them.
    const std::uint64_t after = model()->stepCount();
    m_steps += m_balls ? std::uint64_t(m_balls->params().substeps) : after - std::min(before, after);
    if (m_frames++ % kStatsInterval == 0) refreshStats();
  }
  StageIndicators indicators() override {
    StageIndicators s;
    s.steps = m_steps;
    s.particles = water().count();
    const grid::UniformGrid* g = m_balls ? m_balls->neighbourGrid() : m_fluid->neighbourGrid();
    if (g) {
      s.gridCells = g->dims();
      s.cellSize = g->params().cellSize;
    }
    s.view = m_view.camera().view();
    return s;
  }
  void render(RenderTarget& target, gl::GpuProfiler& profiler) override {
    m_view.params() = m_setup.view.look;
    m_view.camera().params() = m_setup.view.camera;
    m_view.render(water(), target, profiler);
  }
  void input(const Input& in) override {
    m_view.camera().params() = m_setup.view.camera;
    m_view.camera().handle(in);
    m_setup.view.camera = m_view.camera().params();
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
    balls::Params& p = m_balls ? m_balls->params() : m_fluid->params().water;
    balls::ObstacleParams o;
    o.shape = balls::Shape::Mesh;
    o.mesh = path;
    o.centre = 0.5f * (p.domainMin + p.domainMax);
    o.size = glm::vec3(0.2f * glm::length(p.domainMax - p.domainMin) / std::sqrt(3.0f));
    o.shell = !closed;
    if (p.obstacles.size() >= balls::kMaxObstacles) p.obstacles.pop_back();
    p.obstacles.push_back(o);
    return "";
  }
  double simTime() const override { return model().time(); }
  std::pair<std::string, double> liveMetric() const override {
    if (m_frames == 0) return {"density error (%)", NAN};
    if (m_balls) return {"max overlap (% of r)", 100.0 * m_ballsStats.maxOverlap};
    return {"density error (%)", 100.0 * m_fluidStats.compressionMean};
  }
  std::string status() const override {
    char buf[200];
    if (m_balls)
      std::snprintf(buf, sizeof buf, "; KE %.4g, PE %.4g; overlap max %.1f%% mean %.2f%% of r", m_ballsStats.kinetic,
                    m_ballsStats.potential, 100.0 * m_ballsStats.maxOverlap, 100.0 * m_ballsStats.meanOverlap);
    else
      std::snprintf(buf, sizeof buf, "; KE %.4g J, PE %.4g J; density error mean %.2f%% max %.1f%%",
                    m_fluidStats.kinetic, m_fluidStats.potential, 100.0 * m_fluidStats.compressionMean,
                    100.0 * m_fluidStats.compressionMax);
    std::string refused = m_switchError.empty() ? "" : "not switched: " + m_switchError + "\n";
    if (!m_resolutionError.empty()) refused += "resolution not changed: " + m_resolutionError + "\n";
    return refused + model().status() + buf;
  }
  std::optional<DivergenceReport> divergence() const override { return model().divergence(); }
  bool recover() override { return model()->recover(); }
  void flushChecks() override { model()->flushChecks(); }
  sim::Model* model() override { return m_balls ? static_cast<sim::Model*>(m_balls.get()) : m_fluid.get(); }
  std::optional<ExportSource> exportSource() override {
    return m_balls ? waterSource(*m_balls) : fluidSource(*m_fluid);
  }
  io::TriangleMesh exportObstacles() override { return obstacleSurface(water().obstacles(), water().radius()); }
  std::optional<SurfaceInput> surfaceInput() override {
    const sim::ParticleWater& w = water();
    // Water at rest: balls pack hexagonally (√2 per (2r)³), the fluid's lattice is cubic (one per d³ = (2r)³).
    const float cube = std::pow(2.0f * w.radius(), 3.0f);
    const float volume = m_balls ? cube / std::sqrt(2.0f) : cube;
    return SurfaceInput{&w.positions(), w.count(), w.radius(), volume, w.water().domainMin, w.water().domainMax};
  }

  // Checkpoints: which model runs comes before the parameters (they are that model's keys).
  void visitSetupState(sim::StateVisitor& v) override {
    WaterModel running = active();
    v.choice("stage.water_model", running, kWaterModelNames.size());
    if (v.loading() && running != active()) {
      m_choice = running;
      start(nullptr);
    }
  }
  // The model's state, the statistics' frame phase and values, and the other model's parameters
  // (what a later switch keeps of them).
  void visitState(sim::StateVisitor& v) override {
    model()->visitState(v);
    v.value("stage.frames", m_frames);
    v.value("stage.balls_stats", m_ballsStats);
    v.value("stage.fluid_stats", m_fluidStats);
    const ParamVisit other = [this](ParamVisitor& p) {
      if (m_balls)
        fluid::visit(p, m_setup.fluid);
      else
        balls::visit(p, m_setup.balls);
    };
    std::string json = writeParams(other).dump();
    v.text("stage.other_model_params", json, std::size_t(1) << 20);
    if (!v.loading()) return;
    try {
      readParams(io::parseJson(json, "stage.other_model_params"), other, "stage.other_model_params");
    } catch (const Error& e) {
      v.fail(e.what());
    }
  }

 private:
  WaterModel active() const { return m_balls ? WaterModel::Balls : WaterModel::Fluid; }
  const sim::Model& model() const { return m_balls ? static_cast<const sim::Model&>(*m_balls) : *m_fluid; }
  const sim::ParticleWater& water() const {
    return m_balls ? static_cast<const sim::ParticleWater&>(*m_balls) : *m_fluid;
  }

  // Builds the chosen model; with `from`, it takes over those particles.
  void start(const sim::ParticleWater* from) {
    std::vector<glm::vec4> pos, vel;
    if (from) {
      pos = from->positions().read<glm::vec4>(from->count());
      vel = from->velocities().read<glm::vec4>(from->count());
    }
    if (m_choice == WaterModel::Balls) {
      auto next = std::make_unique<balls::Balls>(m_shaders, m_setup.balls);
      if (from) next->upload(pos, vel);
      m_fluid.reset();
      m_balls = std::move(next);
    } else {
      auto next = std::make_unique<fluid::Fluid>(m_shaders, m_setup.fluid);
      if (from) next->upload(pos, vel);
      m_balls.reset();
      m_fluid = std::move(next);
    }
    m_frames = 0;
  }

  void switchModel() {
    if (m_balls) {
      m_setup.balls = m_balls->params();
      m_setup.fluid = asFluid(m_setup.balls, m_setup.fluid);
    } else {
      m_setup.fluid = m_fluid->params();
      m_setup.balls = asBalls(m_setup.fluid, m_setup.balls);
    }
    try {
      start(&water());
    } catch (const Error& e) {  // e.g. too many particles for the other model: stay as we are
      m_choice = active();
      m_switchError = e.what();
    }
  }

  float liveResolution() const { return m_balls ? m_balls->params().resolution : m_fluid->params().water.resolution; }

  // particles.resolution edited in the panel: both models' parameters (the live ones with the
  // user's other edits) refined by the ratio, and the model built again with its new particles. A
  // refinement past a limit (substeps, counts, the GPU's memory) is refused by name and undone.
  void refineLive() {
    const double factor = double(liveResolution()) / m_resolution;
    const WaterSetup before = m_setup;
    if (m_balls)
      m_balls->params().resolution = m_resolution;
    else
      m_fluid->params().water.resolution = m_resolution;
    try {
      m_setup.balls = m_balls ? m_balls->params() : m_setup.balls;
      m_setup.fluid = m_fluid ? m_fluid->params() : m_setup.fluid;
      balls::refine(m_setup.balls, factor);
      fluid::refine(m_setup.fluid, factor);
      start(nullptr);
      m_resolutionError.clear();
    } catch (const Error& e) {
      m_setup = before;
      m_resolutionError = e.what();  // start() builds before it replaces: the old model runs on
    }
    m_resolution = liveResolution();
  }

  void refreshStats() {
    if (m_balls)
      m_ballsStats = m_balls->stats();
    else
      m_fluidStats = m_fluid->stats();
  }

  gl::ShaderLibrary& m_shaders;
  WaterSetup m_setup;
  WaterModel m_choice;
  std::unique_ptr<balls::Balls> m_balls;
  std::unique_ptr<fluid::Fluid> m_fluid;
  BallsView m_view;
  balls::Stats m_ballsStats;
  fluid::Stats m_fluidStats;
  std::string m_switchError;
  std::string m_resolutionError;  // why the last resolution edit was refused
  float m_resolution = 1;         // the refinement the running model's parameters have
  long m_frames = 0;
  std::uint64_t m_steps = 0;  // steps of either model since the start (the indicators' counter)
};

std::unique_ptr<Stage> build(gl::ShaderLibrary& shaders, const WaterSetup& setup, const std::string& where) {
  try {
    return std::make_unique<WaterStage>(shaders, setup);
  } catch (const Error& e) {  // e.g. a missing or open obstacle mesh: say which scene asked for it
    throw Error(where + ": " + e.what());
  }
}

}  // namespace

std::unique_ptr<Stage> createWaterStage(gl::ShaderLibrary& shaders, const balls::Params& balls,
                                        const BallsViewSettings& view, const std::string& where) {
  return build(shaders, {WaterModel::Balls, balls, asFluid(balls, fluid::Params{}), view}, where);
}

std::unique_ptr<Stage> createWaterStage(gl::ShaderLibrary& shaders, const fluid::Params& fluid,
                                        const BallsViewSettings& view, const std::string& where) {
  return build(shaders, {WaterModel::Fluid, asBalls(fluid, balls::Params{}), fluid, view}, where);
}

}  // namespace tidepool
