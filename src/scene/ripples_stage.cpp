#include "scene/ripples_stage.h"

#include "render/ripples_view.h"
#include "render/ripples_view3d.h"
#include "scene/param_json.h"

namespace tidepool {
namespace {

enum class ViewMode { TopDown, ThreeD };
constexpr std::array<const char*, 2> kViewModeNames = {"2d", "3d"};

// Everything about how the scene is shown, as one parameter group ("view" in scene files).
struct ViewSettings {
  ViewMode mode = ViewMode::TopDown;
  RipplesViewParams topDown;
  RipplesView3DParams threeD;
  OrbitCameraParams camera;
};

void visit(ParamVisitor& v, ViewSettings& s) {
  v.choice({"mode", "View", "2d: refraction from above; 3d: tank with caustics"}, s.mode, kViewModeNames);
  if (v.beginGroup({"top_down", "2D view", ""})) {
    visit(v, s.topDown);
    v.endGroup();
  }
  if (v.beginGroup({"three_d", "3D view", ""})) {
    visit(v, s.threeD);
    v.endGroup();
  }
  if (v.beginGroup({"camera", "Camera", "3D view: right drag rotates, middle drag pans, wheel zooms"})) {
    visit(v, s.camera);
    v.endGroup();
  }
}

// Programmatic drops for scenes: at `time` seconds, a bump at (x, y) in grid units.
struct Drop {
  float time = 0, x = 0.5f, y = 0.5f, radius = 0.05f, depth = -0.05f;
};

class RipplesStage final : public ModelStage<ripples::Ripples> {
 public:
  RipplesStage(gl::ShaderLibrary& shaders, const ripples::Params& model, const ViewSettings& view,
               std::vector<Drop> drops)
      : ModelStage(shaders, model), m_view2d(shaders), m_view3d(shaders), m_view(view), m_drops(std::move(drops)) {
    reset();
  }

  void visitParams(ParamVisitor& v) override {
    ripples::visit(v, m_model.params());
    if (v.beginGroup({"view", "View", "how the water is shown"})) {
      visit(v, m_view);
      v.endGroup();
    }
  }
  void reset() override {
    ModelStage::reset();
    m_nextDrop = 0;
  }
  void step(gl::GpuProfiler& profiler) override {
    for (; m_nextDrop < m_drops.size() && m_drops[m_nextDrop].time <= m_model.time(); ++m_nextDrop) {
      const Drop& d = m_drops[m_nextDrop];
      m_model.touch(d.x, d.y, d.radius, d.depth);
    }
    ModelStage::step(profiler);
  }
  void render(RenderTarget& target, gl::GpuProfiler& profiler) override {
    syncViews();
    if (m_view.mode == ViewMode::ThreeD)
      m_view3d.render(m_model, target, profiler);
    else
      m_view2d.render(m_model, target, profiler);
  }
  void input(const Input& in) override {
    syncViews();
    const ripples::Params& p = m_model.params();
    glm::vec2 uv;
    bool onWater = true;
    if (m_view.mode == ViewMode::ThreeD) {
      Input orbit = in;  // left button disturbs the water; right rotates, middle pans
      orbit.left = in.right;
      orbit.right = in.middle;
      m_view3d.camera().handle(orbit);
      m_view.camera = m_view3d.camera().params();
      onWater = m_view3d.pick(in.cursor, in.viewport, {p.width, p.height}, uv);
    } else {
      uv = m_view2d.gridUv(in.cursor, in.viewport, {p.width, p.height});
    }
    if (!in.left || !onWater) {
      m_pressed = in.left;
      return;
    }
    m_model.touch(uv.x, uv.y, p.touchRadius, m_pressed ? 0.1f * p.touchDepth : p.touchDepth);
    m_pressed = true;
  }
  StageIndicators indicators() override {
    StageIndicators s = ModelStage::indicators();
    s.countsCells = true;
    if (m_view.mode == ViewMode::ThreeD) {
      syncViews();
      s.view = m_view3d.camera().view();
    }
    return s;
  }
  std::pair<std::string, double> liveMetric() const override { return {"max |h| (m)", m_model.lastMaxHeight()}; }
  void visitState(sim::StateVisitor& v) override {
    ModelStage::visitState(v);
    v.count("stage.next_drop", m_nextDrop, m_drops.size());  // the scene's drops already made
  }
  std::optional<ExportSource> exportSource() override { return ripplesSource(m_model); }  // a heightfield

 private:
  // The UI edits m_view; the views take their copies before drawing.
  void syncViews() {
    m_view2d.params() = m_view.topDown;
    m_view3d.params() = m_view.threeD;
    m_view3d.camera().params() = m_view.camera;
  }

  RipplesView m_view2d;
  RipplesView3D m_view3d;
  ViewSettings m_view;
  std::vector<Drop> m_drops;
  std::size_t m_nextDrop = 0;
  bool m_pressed = false;
};

// A ripples scene's "params": the model's keys, "view" and "drops" (sorted by time).
struct RipplesSceneParams {
  ripples::Params model;
  ViewSettings view;
  std::vector<Drop> drops;
};

SceneParams parseRipplesParams(const io::Json& params, const std::string& where) {
  RipplesSceneParams p;
  io::Json rest = params.is_object() ? params : io::Json::object();
  // "drops": [{"time": 0.2, "x": 0.3, "y": 0.6, "radius": 0.04, "depth": -0.05}, ...]
  if (auto it = rest.find("drops"); it != rest.end()) {
    if (!it->is_array()) throw Error(where + ".drops: expected an array of drops");
    for (std::size_t i = 0; i < it->size(); ++i) {
      Drop d;
      readParams((*it)[i],
                 [&](ParamVisitor& v) {
                   v.real({"time", "Time", "s"}, d.time, 0.0f, 1e6f);
                   v.real({"x", "x", "grid widths"}, d.x, 0.0f, 1.0f);
                   v.real({"y", "y", "grid heights"}, d.y, 0.0f, 1.0f);
                   v.real({"radius", "Radius", "grid widths"}, d.radius, 0.001f, 0.5f);
                   v.real({"depth", "Depth", "m"}, d.depth, -1.0f, 1.0f);
                 },
                 where + ".drops[" + std::to_string(i) + "]");
      p.drops.push_back(d);
    }
    std::sort(p.drops.begin(), p.drops.end(), [](const Drop& a, const Drop& b) { return a.time < b.time; });
    rest.erase("drops");
  }
  if (params.is_null()) rest = nullptr;
  readParams(
      rest,
      [&](ParamVisitor& v) {
        ripples::visit(v, p.model);
        if (v.beginGroup({"view", "View", ""})) {
          visit(v, p.view);
          v.endGroup();
        }
      },
      where);
  return SceneParams(std::move(p));
}

std::unique_ptr<Stage> createRipplesStage(const SceneParams& params, const std::string&, gl::ShaderLibrary& shaders) {
  const RipplesSceneParams& p = params.as<RipplesSceneParams>();
  return std::make_unique<RipplesStage>(shaders, p.model, p.view, p.drops);
}

}  // namespace

ModelEntry ripplesModel() {
  return {"ripples",
          "heightfield water: wave equation or the seed's spring model, 2D refraction view",
          parseRipplesParams,
          createRipplesStage,
          {{"width", "the grid's size"}, {"height", "the grid's size"}, {"drops", "the drops timed from the start"}}};
}

}  // namespace tidepool
