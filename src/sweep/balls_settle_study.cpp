// balls-settle: a block of water six balls deep (r = 1 cm) is released at rest on the floor under
// g = 9.81 m/s² and left to settle for 0.25 s with a strong velocity damping (60/s, so that even
// the softest setting comes to rest). The balls start in a simple cubic stack that fits the box
// exactly, every ball touching its neighbours and the walls: rigid balls would not move at all,
// so whatever the block does is the method's error. Its contacts give way by the overlap their
// stiffness needs to carry the water above, and energy the integrator injects keeps it moving.
// Both depend on dt, because both contact laws tie their stiffness to the time step:
//   penalty         Δv = 0.96·share·δ per step (the seed's), a stiffness of 0.48/dt per unit mass:
//                   the static overlap grows as dt (δ ≈ L·g·dt/0.48 under L layers)
//   spring-dashpot  with t_c = 20·dt (a fixed number of steps per contact, e = 0.5), a stiffness
//                   of (π² + ln²e)/t_c² per unit effective mass: the overlap grows as dt²
// The block is the same at every size; --quick makes it 7 × 7 balls across (294 balls), the
// default run 200 × 200 (240k balls) so that the cost is a GPU-sized one.
#include <cmath>
#include <cstdio>
#include <limits>

#include "sim/balls/balls.h"
#include "sweep/balls_settle_study.h"
#include "sweep/sweep.h"

namespace tidepool::sweep {

double timedSteps(balls::Balls& model, long steps);  // balls_studies.cpp

namespace {

constexpr float kRadius = 0.01f, kGravity = 9.81f;
constexpr int kLayers = 6;
constexpr float kDamping = 60.0f;     // 1/s
constexpr double kSettleTime = 0.25;  // s
constexpr float kStepsPerContact = float(kSettleStepsPerContact);

struct Method {
  std::string name;
  balls::Contact contact;
  balls::Integrator integrator;
  std::vector<double> dts;
};

balls::Params settleBlock(int across, const Method& m, double dt) {
  balls::Params p;
  p.radius = kRadius;
  const float width = 2 * kRadius * float(across);
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(width, width, 6 * kRadius * kLayers);
  p.fill = water::Fill::None;
  p.contact = m.contact;
  p.integrator = m.integrator;
  p.dt = float(dt);
  p.substeps = 1;
  p.gravity = glm::vec3(0.0f, 0.0f, -kGravity);
  p.damping = kDamping;
  p.contactTime = float(kStepsPerContact * dt);
  p.restitution = 0.5f;
  return p;
}

// The simple cubic stack, touching the floor and the side walls.
std::vector<glm::vec4> cubicStack(int across) {
  std::vector<glm::vec4> out;
  for (int k = 0; k < kLayers; ++k)
    for (int j = 0; j < across; ++j)
      for (int i = 0; i < across; ++i) out.emplace_back(kRadius * glm::vec3(1 + 2 * i, 1 + 2 * j, 1 + 2 * k), 1.0f);
  return out;
}

// One settle: the public figures, and the study's other columns.
struct Outcome {
  Settle settle;
  double meanOverlap = 0, kineticPerBall = 0;
  std::size_t count = 0;
};

Outcome run(gl::ShaderLibrary& shaders, int across, const Method& m, double dt) {
  balls::Balls model(shaders, settleBlock(across, m, dt));
  const std::vector<glm::vec4> stack = cubicStack(across);
  model.upload(stack, std::vector<glm::vec4>(stack.size(), glm::vec4(0.0f)));
  const balls::Stats start = model.stats();  // at rest, touching: the rigid balls' settled state
  const long steps = std::lround(kSettleTime / dt);
  const double ms = timedSteps(model, steps);
  const balls::Stats end = model.stats();
  const double n = double(start.count), unit = n * kGravity * kRadius;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Outcome o;
  o.settle.energyDrift = (end.kinetic + end.potential - start.potential) / unit;
  o.settle.maxOverlap = end.nonFinite ? nan : end.maxOverlap;
  o.settle.stable = end.nonFinite == 0 && end.outside == 0 && end.count == start.count &&
                    std::isfinite(o.settle.energyDrift) && end.maxOverlap <= 1.0;
  o.settle.costMsPerSimS = ms / (double(steps) * dt);
  o.meanOverlap = end.nonFinite ? nan : end.meanOverlap;
  o.kineticPerBall = end.nonFinite ? nan : end.kinetic / unit;
  o.count = start.count;
  return o;
}

Row settle(gl::ShaderLibrary& shaders, int across, const Method& m, double dt) {
  const Outcome o = run(shaders, across, m, dt);
  Row row;
  row.method = m.name;
  row.dt = dt;
  row.resolution = "N = " + std::to_string(o.count) + ", " + std::to_string(kLayers) + " layers";
  row.costMsPerSimS = o.settle.costMsPerSimS;
  row.stable = o.settle.stable;
  row.metrics = {o.settle.maxOverlap, o.meanOverlap, o.settle.energyDrift, o.kineticPerBall,
                 m.contact == balls::Contact::SpringDashpot ? kStepsPerContact * dt : 0.0};
  row.x = row.costMsPerSimS;
  row.y = row.metrics[0];
  std::printf("  %-40s dt = %.3g s: max overlap %.3g r, energy drift %+.3g, %s\n", m.name.c_str(), dt, row.y,
              o.settle.energyDrift, row.stable ? "stable" : "UNSTABLE");
  std::fflush(stdout);
  return row;
}

Result settleStudy(Env& env) {
  Result r =
      emptyResult("balls", {"max_overlap_r", "mean_overlap_r", "energy_drift", "kinetic_per_ball", "contact_time"});
  const int across = env.quick ? 7 : 200;
  using C = balls::Contact;
  using I = balls::Integrator;
  const std::string spring = "spring-dashpot tc = 20 dt, ";
  std::vector<Method> methods;
  if (env.quick) {
    methods = {{"penalty, symplectic-euler", C::Penalty, I::SymplecticEuler, {4e-5, 2e-5}},
               {spring + "symplectic-euler", C::SpringDashpot, I::SymplecticEuler, {1e-3, 5e-4, 2.5e-4}},
               {spring + "verlet", C::SpringDashpot, I::VelocityVerlet, {5e-4, 2.5e-4}}};
  } else {
    const std::vector<double> springDts = {2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5, 3.125e-5};
    methods = {{"penalty, symplectic-euler", C::Penalty, I::SymplecticEuler, {8e-5, 4e-5, 2e-5, 1e-5, 5e-6}},
               {spring + "symplectic-euler", C::SpringDashpot, I::SymplecticEuler, springDts},
               {spring + "verlet", C::SpringDashpot, I::VelocityVerlet, springDts},
               {spring + "explicit-euler", C::SpringDashpot, I::ExplicitEuler, springDts}};
  }
  for (const Method& m : methods)
    for (double dt : m.dts) {
      r.rows.push_back(settle(env.shaders, across, m, dt));
      announce(r.rows.back());
    }
  r.chart.title = "balls-settle: overlap of a settled water block against cost, per contact law and integrator";
  r.chart.xLabel = "GPU ms per simulated second (" + r.rows.front().resolution + ", r = 1 cm, g = 9.81 m/s^2)";
  r.chart.yLabel = "max overlap / r after 0.25 s";
  return r;
}

}  // namespace

Settle measureSettle(gl::ShaderLibrary& shaders, balls::Contact contact, balls::Integrator integrator, double dt,
                     int across) {
  return run(shaders, across, {"", contact, integrator, {}}, dt).settle;
}

Study ballsSettleStudy() {
  return {"balls-settle", "max overlap and energy drift of a settled water block vs cost, per contact law",
          settleStudy};
}

}  // namespace tidepool::sweep
