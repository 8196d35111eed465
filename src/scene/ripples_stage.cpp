#include "scene/ripples_stage.h"

#include "render/ripples_view.h"
#include "scene/param_json.h"

namespace tidepool {
namespace {

// Programmatic drops for scenes: at `time` seconds, a bump at (x, y) in grid units.
struct Drop {
  float time = 0, x = 0.5f, y = 0.5f, radius = 0.05f, depth = -0.05f;
};

class RipplesStage final : public Stage {
 public:
  RipplesStage(gl::ShaderLibrary& shaders, const ripples::Params& model, const RipplesViewParams& view,
               std::vector<Drop> drops)
      : m_model(shaders, model), m_view(shaders), m_drops(std::move(drops)) {
    m_view.params() = view;
    reset();
  }

  void visitParams(ParamVisitor& v) override {
    ripples::visit(v, m_model.params());
    if (v.beginGroup({"view", "View", "2D refraction view"})) {
      visit(v, m_view.params());
      v.endGroup();
    }
  }
  void reset() override {
    m_model.reset();
    m_nextDrop = 0;
  }
  void step(double frameSeconds, gl::GpuProfiler& profiler) override {
    for (; m_nextDrop < m_drops.size() && m_drops[m_nextDrop].time <= m_model.time(); ++m_nextDrop) {
      const Drop& d = m_drops[m_nextDrop];
      m_model.touch(d.x, d.y, d.radius, d.depth);
    }
    m_model.step(frameSeconds, profiler);
  }
  void render(RenderTarget& target, gl::GpuProfiler& profiler) override { m_view.render(m_model, target, profiler); }
  void input(const Input& in) override {
    if (!in.left) {
      m_pressed = false;
      return;
    }
    const ripples::Params& p = m_model.params();
    const glm::vec2 uv = m_view.gridUv(in.cursor, in.viewport, {p.width, p.height});
    m_model.touch(uv.x, uv.y, p.touchRadius, m_pressed ? 0.1f * p.touchDepth : p.touchDepth);
    m_pressed = true;
  }
  double simTime() const override { return m_model.time(); }
  std::string status() const override { return m_model.status(); }

 private:
  ripples::Ripples m_model;
  RipplesView m_view;
  std::vector<Drop> m_drops;
  std::size_t m_nextDrop = 0;
  bool m_pressed = false;
};

}  // namespace

std::unique_ptr<Stage> createRipplesStage(const io::Json& params, const std::string& where,
                                          gl::ShaderLibrary& shaders) {
  ripples::Params model;
  RipplesViewParams view;
  std::vector<Drop> drops;
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
      drops.push_back(d);
    }
    std::sort(drops.begin(), drops.end(), [](const Drop& a, const Drop& b) { return a.time < b.time; });
    rest.erase("drops");
  }
  if (params.is_null()) rest = nullptr;
  readParams(
      rest,
      [&](ParamVisitor& v) {
        ripples::visit(v, model);
        if (v.beginGroup({"view", "View", ""})) {
          visit(v, view);
          v.endGroup();
        }
      },
      where);
  return std::make_unique<RipplesStage>(shaders, model, view, std::move(drops));
}

}  // namespace tidepool
