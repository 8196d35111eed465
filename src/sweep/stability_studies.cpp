// Where the integrators of the swarm, of particle life and of the balls' contact laws fail, on
// their harmonic setups (sim/swarm/measure/swarm_measure.h: the core of a softened attractor;
// sim/life/measure/life_measure.h: two particles bound by the collision force;
// sim/balls/measure/contact_stability.h: a ball resting on a fixed particle): the amplitude's growth
// against ω·dt, one curve per method, blow-ups drawn at the growth bound. Each method's largest
// stable ω·dt (bisection) and its theoretical limit are printed and written into its rows: the
// lines of the stability table in docs/ACCURACY.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "sim/balls/measure/contact_stability.h"
#include "sim/life/measure/life_measure.h"
#include "sim/swarm/measure/swarm_measure.h"
#include "sweep/sweep.h"

namespace tidepool::sweep {
namespace {

std::vector<double> omegaDts(bool quick) {
  std::vector<double> out;
  for (double h = quick ? 0.5 : 0.25; h < 4.01; h += quick ? 1.0 : 0.25) out.push_back(h);
  return out;
}

// A point of a curve: stable or not, and the amplitude charted.
struct Point {
  bool stable = false;
  double y = 0;
};
// Stable while the growth g stays finite and below `bound`; g is charted.
Point boundedGrowth(double g, double bound) { return {std::isfinite(g) && g < bound, g}; }

// One curve: a point at each ω·dt of `grid` (time step dtOf(ω·dt)), blow-ups charted at `bound`,
// and the method's bisected limit beside its theory.
void addCurve(Result& r, const std::string& method, double theory, double limit,
              const std::function<double(double)>& dtOf, const std::vector<double>& grid, double bound,
              const std::function<Point(double)>& point) {
  std::printf("%s: largest stable omega dt = %.4f (theory %.4f)\n", method.c_str(), limit, theory);
  for (double h : grid) {
    const Point p = point(h);
    Row row;
    row.method = method;
    row.dt = dtOf(h);
    char resolution[32];
    std::snprintf(resolution, sizeof resolution, "omega dt = %.2f", h);
    row.resolution = resolution;
    row.stable = p.stable;
    row.metrics = {h, row.stable ? p.y : INFINITY, limit, theory};
    row.x = h;
    row.y = row.stable ? std::min(p.y, bound) : bound;
    announce(row);
    r.rows.push_back(row);
  }
}

Result chartFrame(const std::string& model, const std::string& title, double marker, const std::string& label) {
  return emptyResult(model, {"omega_dt", "growth", "measured_limit", "theory_limit"},
                     {.title = title,
                      .xLabel = "{/Symbol w} dt",
                      .yLabel = "largest amplitude / start over 50 periods (blow-ups at the bound)",
                      .logX = false,
                      .pareto = false,
                      .markerX = marker,
                      .markerLabel = label});
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
    addCurve(
        r, sim::kIntegratorNames[int(integrator)], theory,
        sim::oscillatorStableLimit(env.shaders, integrator, tolerance),
        [](double h) { return h / sim::oscillatorOmega(); }, omegaDts(env.quick), sim::kOscillatorGrowthBound,
        [&](double h) {
          return boundedGrowth(sim::oscillatorGrowth(env.shaders, integrator, h, sim::kOscillatorPeriods),
                               sim::kOscillatorGrowthBound);
        });
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
    addCurve(
        r, c.method, c.theory, life::pairStableLimit(env.shaders, c.pair, c.integrator, tolerance),
        [&](double h) { return h / c.pair.omega; }, omegaDts(env.quick), life::kPairGrowthBound,
        [&](double h) {
          return boundedGrowth(life::pairGrowth(env.shaders, c.pair, c.integrator, h, life::kPairPeriods),
                               life::kPairGrowthBound);
        });
  return r;
}

Result ballsStability(Env& env) {
  Result r = chartFrame("balls", "balls-stability: a resting contact's growth against omega dt, per law and integrator",
                        2.0, "2");
  r.chart.logX = true;
  r.metrics[1] = "largest_over_push";
  const int steps = env.quick ? 1000 : 2000;
  r.chart.yLabel = "largest amplitude / push over " + std::to_string(steps) + " steps (blow-ups at 100)";
  std::vector<double> grid;  // geometric from 0.05 to 4: the damped explicit Euler limit is 0.14
  for (double h = 0.05; h < 4.01; h *= env.quick ? 2.0 : std::pow(2.0, 0.25)) grid.push_back(h);
  const double tolerance = env.quick ? 0.1 : 0.01;
  using balls::Contact;
  using balls::Integrator;
  struct Curve {
    Contact law;
    Integrator integrator;
    bool quick;  // also in a quick run
  };
  for (const Curve& c : {Curve{Contact::Penalty, Integrator::ExplicitEuler, false},
                         Curve{Contact::Penalty, Integrator::SymplecticEuler, true},
                         Curve{Contact::Penalty, Integrator::VelocityVerlet, false},
                         Curve{Contact::CudaSample, Integrator::ExplicitEuler, true},
                         Curve{Contact::CudaSample, Integrator::SymplecticEuler, true},
                         Curve{Contact::CudaSample, Integrator::VelocityVerlet, false},
                         Curve{Contact::SpringDashpot, Integrator::SymplecticEuler, false}}) {
    if (env.quick && !c.quick) continue;
    addCurve(
        r, std::string(balls::kContactNames[int(c.law)]) + ", " + balls::kIntegratorNames[int(c.integrator)],
        balls::restingTheoryLimit(c.law, c.integrator),
        balls::restingStableLimit(env.shaders, c.law, c.integrator, tolerance, steps),
        [&](double h) { return balls::restingStep(c.law, h); }, grid, balls::kRestingBlowUp,
        [&](double h) {
          const balls::RestingRun run = balls::restingRun(env.shaders, c.law, c.integrator, h, steps);
          return Point{run.growth < balls::kRestingGrowthBound, run.largest};
        });
  }
  // Their other limit, in dt itself: a loaded contact's overlap past r (sim/balls/measure/contact_stability.h).
  for (Contact law : {Contact::Penalty, Contact::CudaSample})
    std::printf("%s: overlap past r from dt = %.4g ms (theory %.4g ms)\n", balls::kContactNames[int(law)],
                1e3 * balls::overlapStepLimit(env.shaders, law, tolerance), 1e3 * balls::overlapStepTheory(law));
  return r;
}

}  // namespace

Study ballsStabilityStudy() {
  return {"balls-stability",
          "a resting contact's growth vs omega dt per contact law and integrator; limits beside theory",
          ballsStability};
}
Study swarmStabilityStudy() {
  return {"swarm-stability", "amplitude growth vs omega dt in an attractor's core; limits beside theory",
          swarmStability};
}
Study lifeStabilityStudy() {
  return {"life-stability", "a bound pair's growth vs omega dt, with friction; limits beside theory", lifeStability};
}

}  // namespace tidepool::sweep
