#include "scene/water_runs.h"

#include <cmath>
#include <cstdio>

#include "scene/param_json.h"
#include "sim/balls/balls.h"
#include "sim/fluid/fluid.h"

namespace tidepool {

balls::Params asBalls(const fluid::Params& f, balls::Params own) {
  static_cast<water::Setup&>(own) = water::switched(f, fluid::Params::kPacking, own, balls::Params::kPacking);
  return own;
}

fluid::Params asFluid(const balls::Params& b, fluid::Params own) {
  static_cast<water::Setup&>(own) =
      water::switched(balls::resolved(b), balls::Params::kPacking, own, fluid::Params::kPacking);
  return own;
}

namespace {

// What differs between the models' runs, as overloads: their statistics' line and metric, their
// export, and how a frame's steps are counted.
std::string statsLine(const balls::Stats& s) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "; KE %.4g, PE %.4g; overlap max %.1f%% mean %.2f%% of r", s.kinetic, s.potential,
                100.0 * s.maxOverlap, 100.0 * s.meanOverlap);
  return buf;
}
std::string statsLine(const fluid::Stats& s) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "; KE %.4g J, PE %.4g J; density error mean %.2f%% max %.1f%%", s.kinetic, s.potential,
                100.0 * s.compressionMean, 100.0 * s.compressionMax);
  return buf;
}
std::pair<std::string, double> metric(const balls::Stats& s) { return {"max overlap (% of r)", 100.0 * s.maxOverlap}; }
std::pair<std::string, double> metric(const fluid::Stats& s) {
  return {"density error (%)", 100.0 * s.compressionMean};
}
ExportSource exportOf(const balls::Balls& b) { return waterSource(b); }
ExportSource exportOf(const fluid::Fluid& f) { return fluidSource(f); }
// Balls do not count their steps: a frame is params().substeps of them.
std::uint64_t frameSteps(const balls::Balls& b, std::uint64_t) { return std::uint64_t(b.params().substeps); }
std::uint64_t frameSteps(const fluid::Fluid& f, std::uint64_t before) {
  return f.stepCount() - std::min(before, f.stepCount());
}

template <class M>
class Run final : public WaterRun {
 public:
  using Params = std::remove_cvref_t<decltype(std::declval<M&>().params())>;
  using Stats = decltype(std::declval<M&>().stats());

  Run(const Params& params, const char* statsEntry) : m_params(params), m_statsEntry(statsEntry) {}

  water::Setup& setup() override { return params(); }
  void visitParams(ParamVisitor& v) override { visit(v, params()); }
  water::Setup runningSetup() override { return asRun(params()); }
  water::Packing packing() const override { return Params::kPacking; }
  void refine(double factor) override {
    Params p = params();
    refineParams(p, factor);
    params() = p;
  }
  void save() override { m_saved = params(); }
  void restore() override { params() = m_saved; }
  void start(gl::ShaderLibrary& shaders, const std::vector<glm::vec4>* pos,
             const std::vector<glm::vec4>* vel) override {
    auto next = std::make_unique<M>(shaders, params());
    if (pos) next->upload(*pos, *vel);
    m_model = std::move(next);
  }
  void stop() override {
    if (m_model) m_params = m_model->params();
    m_model.reset();
  }
  sim::Model* model() override { return m_model.get(); }
  const sim::Model* model() const override { return m_model.get(); }
  water::ParticleWater* water() override { return m_model.get(); }
  std::uint64_t frameSteps(std::uint64_t before) const override { return tidepool::frameSteps(*m_model, before); }
  std::optional<ExportSource> exportSource() override { return exportOf(*m_model); }
  void refreshStats() override { m_stats = m_model->stats(); }
  void visitStats(sim::StateVisitor& v) override { v.value(m_statsEntry, m_stats); }
  std::string statsLine() const override { return tidepool::statsLine(m_stats); }
  std::pair<std::string, double> liveMetric() const override { return metric(m_stats); }
  water::Bodies* bodies() override { return m_model ? &m_model->bodies() : nullptr; }

 private:
  Params& params() { return m_model ? m_model->params() : m_params; }
  static void refineParams(balls::Params& p, double factor) { balls::refine(p, factor); }
  static void refineParams(fluid::Params& p, double factor) { water::refine(p, factor); }

  static water::Setup asRun(const balls::Params& p) { return balls::resolved(p); }
  static water::Setup asRun(const fluid::Params& p) { return p; }

  Params m_params, m_saved;  // idle: as the model left them when it stopped
  std::unique_ptr<M> m_model;
  Stats m_stats;
  const char* m_statsEntry;
};

}  // namespace

std::array<std::unique_ptr<WaterRun>, 2> waterRuns(const balls::Params& balls, const fluid::Params& fluid) {
  return {std::make_unique<Run<balls::Balls>>(balls, "stage.balls_stats"),
          std::make_unique<Run<fluid::Fluid>>(fluid, "stage.fluid_stats")};
}

}  // namespace tidepool
