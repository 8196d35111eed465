#include "scene/blank.h"

namespace tidepool {
namespace {

class BlankStage final : public Stage {
 public:
  explicit BlankStage(const BlankParams& p) : m_params(p) {}
  void visitParams(ParamVisitor& v) override { visit(v, m_params); }
  void reset() override { m_time = 0; }
  void step(gl::GpuProfiler&) override { m_time += frameSeconds(); }
  double frameSeconds() const override { return m_params.frameSeconds; }
  void render(RenderTarget& target, gl::GpuProfiler& profiler) override {
    auto scope = profiler.scope("blank.clear");
    target.bind();
    glClearColor(m_params.color.r, m_params.color.g, m_params.color.b, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  double simTime() const override { return m_time; }
  std::string status() const override { return "no model: blank scene"; }
  void visitState(sim::StateVisitor& v) override {
    std::uint64_t steps = 0;
    v.clock(m_time, steps);
  }

 private:
  BlankParams m_params;
  double m_time = 0;
};

}  // namespace

void visit(ParamVisitor& v, BlankParams& p) {
  v.color({"color", "Colour", "clear colour, linear RGB"}, p.color);
  v.realDouble({"frame_seconds", "Frame seconds", "s its clock advances per frame"}, p.frameSeconds, 1e-4f, 1.0f);
}

namespace {

SceneParams parseBlankParams(const io::Json& params, const std::string& where) {
  return readSceneParams<BlankParams>(params, where);
}

std::unique_ptr<Stage> createBlankStage(const SceneParams& params, const std::string&, gl::ShaderLibrary&) {
  return std::make_unique<BlankStage>(params.as<BlankParams>());
}

}  // namespace

ModelEntry blankModel() {
  return {"blank", "no simulation: clears to a colour (the shell before any model)", parseBlankParams,
          createBlankStage};
}

}  // namespace tidepool
