#include "sweep/water_run.h"

#include <cmath>
#include <limits>

#include "sim/balls/balls.h"
#include "sim/balls/measure/balls_measure.h"
#include "sim/fluid/fluid.h"
#include "sim/water/water_init.h"

namespace tidepool::sweep {

namespace {

// Martin & Moyce (1952), "An experimental study of the collapse of liquid columns on a rigid
// horizontal plane", Phil. Trans. R. Soc. A 244, fig. 3, n² = 2 (a column 2a high), a = 2.25 in:
// the front Z = z/a against T = t·sqrt(2g/a), as digitised in pypr/pysph
// pysph/examples/db_exp_data.py (mm_data_2); the points to T = 5.1.
constexpr double kMartinMoyce[][2] = {{0.832, 1.217}, {1.219, 1.474}, {1.997, 2.292}, {2.547, 2.995},
                                      {3.345, 4.134}, {4.034, 4.944}, {4.418, 5.881}, {5.091, 6.980}};

}  // namespace

double rmsFromMartinMoyce(const std::vector<double>& front, double every, double a, double g, int& points) {
  double sum = 0;
  points = 0;
  for (const auto& [T, Z] : kMartinMoyce) {
    const double at = T / std::sqrt(2.0 * g / a) / every;  // in samples; sample j − 1 is at j·every
    const std::size_t i = std::size_t(at);
    if (i >= front.size()) break;
    const double before = i == 0 ? 1.0 : front[i - 1], after = front[i];
    const double z = before + (after - before) * (at - double(i));
    sum += (z - Z) * (z - Z);
    ++points;
  }
  return points > 0 ? std::sqrt(sum / points) : std::numeric_limits<double>::quiet_NaN();
}

WaterRun::WaterRun(gl::ShaderLibrary& shaders, const balls::Params& params) : m_probe(shaders) {
  balls::Params p = params;
  p.substeps = 1;
  m_profiler.setEnabled(false);
  m_balls = std::make_unique<balls::Balls>(shaders, p);
  m_water = balls::resolved(m_balls->params());
  m_dt = double(p.dt);
  m_radius = m_balls->radius();
  m_width = balls::columnScales(m_water).width;
}

WaterRun::WaterRun(gl::ShaderLibrary& shaders, const fluid::Params& params) : m_probe(shaders) {
  fluid::Params p = params;
  p.substeps = 1;
  m_profiler.setEnabled(false);
  m_fluid = std::make_unique<fluid::Fluid>(shaders, p);
  m_water = m_fluid->water();
  m_dt = double(p.dt);
  m_radius = m_fluid->radius();
  m_width = balls::columnScales(m_water).width;
}

WaterRun::~WaterRun() = default;

std::size_t WaterRun::count() const { return m_balls ? m_balls->count() : m_fluid->count(); }

double WaterRun::speedBound() const { return m_balls ? m_balls->speedBound() : m_fluid->speedBound(); }

sim::Model& WaterRun::model() {
  return m_balls ? static_cast<sim::Model&>(*m_balls) : static_cast<sim::Model&>(*m_fluid);
}

void WaterRun::stepFrame(bool watched) {
  if (m_stopped) return;  // the watch reported: the state is no longer judged good
  if (watched) {
    model().step(m_profiler);  // substeps = 1: one step, then the watch
    m_stopped = model().divergence().has_value();
  } else if (m_balls) {
    m_balls->stepOnce();
  } else {
    m_fluid->stepOnce();
  }
  ++m_steps;
}

void WaterRun::advanceTo(double t, bool watched) {
  const long target = std::lround(t / m_dt);
  if (target <= m_steps) return;
  m_ms += timedSteps(target - m_steps, [&] { stepFrame(watched); });
}

std::optional<std::string> WaterRun::divergence() {
  model().flushChecks();
  if (const auto report = model().divergence()) {
    m_stopped = true;
    return report->message;
  }
  return std::nullopt;
}

WaterSample WaterRun::sample(bool density) {
  fluid::Stats s;  // the fluid's own statistics, or the balls' with the probe's density
  if (m_balls) {
    const balls::Stats b = m_balls->stats();
    if (density)  // the balls' configuration read with the fluid's kernel: h = 2 × the spacing 2r, HCP V0
      s = m_probe.measure(*m_balls, {.spacing = 2.0f * m_balls->radius()}, m_balls->gravity(), m_balls->time());
    s.maxSpeed = b.maxSpeed;
    s.nonFinite = b.nonFinite;
    s.outside = b.outside;
    s.front = b.front;
  } else {
    s = m_fluid->stats();
  }
  WaterSample out;
  out.time = time();
  out.compressionMean = s.compressionMean;
  out.compressionMax = s.compressionMax;
  out.front = (s.front - double(m_water.domainMin.x) + m_radius) / m_width;  // as validate --probe front
  out.maxSpeed = s.maxSpeed;
  out.healthy = s.nonFinite == 0 && s.outside == 0 && s.maxSpeed <= speedBound();
  return out;
}

}  // namespace tidepool::sweep
