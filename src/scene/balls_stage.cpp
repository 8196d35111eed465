#include "scene/balls_stage.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "io/obj.h"
#include "render/balls_view.h"

namespace tidepool {
namespace {

constexpr int kStatsInterval = 30;  // frames between statistics read-backs

using ViewSettings = BallsViewSettings;

void visitAll(ParamVisitor& v, balls::Params& model, ViewSettings& view) {
  balls::visit(v, model);
  if (v.beginGroup({"view", "View", "how the balls are drawn"})) {
    visit(v, view);
    v.endGroup();
  }
}

class BallsStage final : public ModelStage<balls::Balls> {
 public:
  BallsStage(gl::ShaderLibrary& shaders, const balls::Params& model, const ViewSettings& view)
      : ModelStage(shaders, model), m_view(shaders), m_settings(view) {}

  void visitParams(ParamVisitor& v) override { visitAll(v, m_model.params(), m_settings); }
  void reset() override {
    ModelStage::reset();
    m_frames = 0;
  }
  void step(double frameSeconds, gl::GpuProfiler& profiler) override {
    ModelStage::step(frameSeconds, profiler);
    if (m_frames++ % kStatsInterval == 0) m_stats = m_model.stats();
  }
  void render(RenderTarget& target, gl::GpuProfiler& profiler) override {
    m_view.params() = m_settings.look;
    m_view.camera().params() = m_settings.camera;
    m_view.render(m_model, target, profiler);
  }
  void input(const Input& in) override {
    m_view.camera().params() = m_settings.camera;
    m_view.camera().handle(in);
    m_settings.camera = m_view.camera().params();
  }
  // An OBJ dropped on the window becomes one more obstacle (the last one is replaced when there
  // are already kMaxObstacles): a solid fill when it is closed, else a shell, in the middle of the
  // domain. The next step builds it, or refuses it (obstacleError()).
  bool dropFile(const std::string& path) override {
    if (std::filesystem::path(path).extension() != ".obj") return false;
    balls::Params& p = m_model.params();
    balls::ObstacleParams o;
    o.shape = balls::Shape::Mesh;
    o.mesh = path;
    o.centre = 0.5f * (p.domainMin + p.domainMax);
    o.size = glm::vec3(0.2f * glm::length(p.domainMax - p.domainMin) / std::sqrt(3.0f));
    try {
      o.shell = !io::checkClosed(io::readObj(path)).closed();
    } catch (const Error&) {  // the build says what is wrong with it
    }
    if (p.obstacles.size() >= balls::kMaxObstacles) p.obstacles.pop_back();
    p.obstacles.push_back(o);
    return true;
  }
  std::pair<std::string, double> liveMetric() const override {
    return {"max overlap (% of r)", m_frames > 0 ? 100.0 * m_stats.maxOverlap : NAN};
  }
  std::string status() const override {
    char buf[160];
    std::snprintf(buf, sizeof buf, "; KE %.4g, PE %.4g; overlap max %.1f%% mean %.2f%% of r", m_stats.kinetic,
                  m_stats.potential, 100.0 * m_stats.maxOverlap, 100.0 * m_stats.meanOverlap);
    return m_model.status() + buf;
  }

 private:
  BallsView m_view;
  ViewSettings m_settings;
  balls::Stats m_stats;
  long m_frames = 0;
};

}  // namespace

void visit(ParamVisitor& v, BallsViewSettings& s) {
  visit(v, s.look);
  if (v.beginGroup({"camera", "Camera", "left drag rotates, right drag pans, wheel zooms"})) {
    visit(v, s.camera);
    v.endGroup();
  }
}

void visit(ParamVisitor& v, BallsSceneParams& p) { visitAll(v, p.model, p.view); }

const BallsSceneParams& ballsScene(const Scene& scene) {
  if (scene.model != "balls") throw Error(scene.file.string() + ": not a balls scene (model " + scene.model + ")");
  return scene.params.as<BallsSceneParams>();
}

balls::Params ballsParams(const Scene& scene) { return ballsScene(scene).model; }

namespace {

SceneParams parseBallsParams(const io::Json& params, const std::string& where) {
  return readSceneParams<BallsSceneParams>(params, where);
}

std::unique_ptr<Stage> createBallsStage(const SceneParams& params, const std::string& where,
                                        gl::ShaderLibrary& shaders) {
  const BallsSceneParams& p = params.as<BallsSceneParams>();
  try {
    return std::make_unique<BallsStage>(shaders, p.model, p.view);
  } catch (const Error& e) {  // e.g. a missing or open obstacle mesh: say which scene asked for it
    throw Error(where + ": " + e.what());
  }
}

}  // namespace

ModelEntry ballsModel() {
  return {"balls", "water as equal balls colliding: grid neighbours, three contact laws, three integrators",
          parseBallsParams, createBallsStage};
}

}  // namespace tidepool
