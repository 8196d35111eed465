// Where the integrators of the swarm and of particle life fail, on their harmonic setups
// (sim/swarm/swarm_measure.h: the core of a softened attractor; sim/life/life_measure.h: two
// particles bound by the collision force): the amplitude's growth over 50 periods against ω·dt,
// one curve per method, blow-ups drawn at the growth bound. Each method's largest stable ω·dt
// (bisection) and its theoretical limit are printed and written into its rows: the lines of the
// stability table in docs/ACCURACY.md.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "sim/life/life_measure.h"
#include "sim/swarm/swarm_measure.h"
#include "sweep/sweep.h"

namespace tidepool::sweep {
namespace {

std::vector<double> omegaDts(bool quick) {
  std::vector<double> out;
  for (double h = quick ? 0.5 : 0.25; h < 4.01; h += quick ? 1.0 : 0.25) out.push_back(h);
  return out;
}

// One curve: the growth at each ω·dt of `grid`, and the method's bisected limit beside its theory.
void addCurve(Result& r, const std::string& method, double theory, double limit, double omega,
              const std::vector<double>& grid, double bound, const std::function<double(double)>& growth) {
  std::printf("%s: largest stable omega dt = %.4f (theory %.4f)\n", method.c_str(), limit, theory);
  for (double h : grid) {
    const double g = growth(h);
    Row row;
    row.method = method;
    row.dt = h / omega;
    char resolution[32];
    std::snprintf(resolution, sizeof resolution, "omega dt = %.2f", h);
    row.resolution = resolution;
    row.stable = std::isfinite(g) && g < bound;
    row.metrics = {h, row.stable ? g : INFINITY, limit, theory};
    row.x = h;
    row.y = row.stable ? g : bound;
    r.rows.push_back(row);
  }
}

Result chartFrame(const std::string& model, const std::string& title, double marker, const std::string& label) {
  Result r;
  r.model = model;
  r.metrics = {"omega_dt", "growth", "measured_limit", "theory_limit"};
  r.chart.title = title;
  r.chart.xLabel = "{/Symbol w} dt";
  r.chart.yLabel = "largest amplitude / start over 50 periods (blow-ups at the bound)";
  r.chart.logX = false;
  r.chart.pareto = false;
  r.chart.markerX = marker;
  r.chart.markerLabel = label;
  return r;
}

Result swarmStability(Env& env) {
  Result r = chartFrame("swarm", "swarm-stability: amplitude growth in a softened attractor's core against omega dt",
                        2.0, "2");
  const double tolerance = env.quick ? 0.05 : 0.01;
  const double sqrt8 = 2.0 * std::numbers::sqrt2;
  for (sim::Integrator integrator : {sim::Integrator::ExplicitEuler, sim::Integrator::SymplecticEuler,
                                     sim::Integrator::Verlet, sim::Integrator::Rk4}) {
    const double theory = integrator == sim::Integrator::ExplicitEuler ? 0.0
                          : integrator == sim::Integrator::Rk4         ? sqrt8
                                                                       : 2.0;
    addCurve(r, sim::kIntegratorNames[int(integrator)], theory,
             sim::oscillatorStableLimit(env.shaders, integrator, tolerance), sim::oscillatorOmega(),
             omegaDts(env.quick), sim::kOscillatorGrowthBound,
             [&](double h) { return sim::oscillatorGrowth(env.shaders, integrator, h, sim::kOscillatorPeriods); });
  }
  return r;
}

Result lifeStability(Env& env) {
  const life::PairOscillator damped = life::pairOscillator(10.0), undamped = life::pairOscillator(0.0);
  const double a = double(damped.rules.friction) / damped.omega;
  char label[32];
  std::snprintf(label, sizeof label, "%.3f", life::eulerStableLimit(a));
  Result r = chartFrame("life", "life-stability: a bound pair's oscillation growth against omega dt",
                        life::eulerStableLimit(a), label);
  const double tolerance = env.quick ? 0.05 : 0.01;
  struct Curve {
    const life::PairOscillator& pair;
    life::Integrator integrator;
    std::string method;
    double theory;
  };
  for (const Curve& c : {Curve{damped, life::Integrator::Euler, "euler, friction 10/s", life::eulerStableLimit(a)},
                         Curve{damped, life::Integrator::Verlet, "verlet, friction 10/s", 2.0},
                         Curve{undamped, life::Integrator::Euler, "euler, no friction", 2.0}})
    addCurve(r, c.method, c.theory, life::pairStableLimit(env.shaders, c.pair, c.integrator, tolerance), c.pair.omega,
             omegaDts(env.quick), life::kPairGrowthBound,
             [&](double h) { return life::pairGrowth(env.shaders, c.pair, c.integrator, h, life::kPairPeriods); });
  return r;
}

}  // namespace

Study swarmStabilityStudy() {
  return {"swarm-stability", "amplitude growth vs omega dt in an attractor's core; limits beside theory",
          swarmStability};
}
Study lifeStabilityStudy() {
  return {"life-stability", "a bound pair's growth vs omega dt, with friction; limits beside theory", lifeStability};
}

}  // namespace tidepool::sweep
