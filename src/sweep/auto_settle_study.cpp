// PROVISIONAL (see auto_settle_study.h): max overlap and energy drift of a settling column
// against cost, per contact law and integrator, until the balls-settle study replaces it.
#include "sweep/auto_settle_study.h"

#include <cmath>

#include "bench/bench.h"
#include "sim/balls/balls.h"
#include "sweep/sweep.h"

namespace tidepool::sweep {
namespace {

constexpr double kContactTime = 0.002;  // s: stiff enough that the column's own weight overlaps it by ~1% of r

balls::Params column(balls::Contact contact, balls::Integrator integrator, double dt) {
  balls::Params p;
  p.radius = 0.01f;
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(0.1f, 0.1f, 0.6f);
  p.fill = balls::Fill::Block;
  p.fillMin = glm::vec3(0.0f);
  p.fillMax = glm::vec3(0.1f, 0.1f, 0.3f);
  p.contact = contact;
  p.integrator = integrator;
  p.dt = float(dt);
  p.substeps = 1;
  p.contactTime = float(kContactTime);
  p.restitution = 0.5f;
  return p;
}

// GPU ms of one step of a 65k-ball lattice (4k when quick), as balls-restitution measures it.
double msPerStep(gl::ShaderLibrary& shaders, int n, balls::Contact contact, balls::Integrator integrator) {
  balls::Params p;
  p.fill = balls::Fill::Lattice;
  p.latticeCount = n;
  p.latticeScaling = false;
  p.radius = 0.5f / std::cbrt(float(n)) * 0.98f;
  p.contact = contact;
  p.integrator = integrator;
  p.dt = 1e-4f;
  balls::Balls model(shaders, p);
  const bench::Common timing{"auto", "", 5, 2};
  constexpr int kSteps = 5;
  return bench::gpuMedianMs(timing,
                            [&] {
                              for (int i = 0; i < kSteps; ++i) model.stepOnce();
                            }) /
         kSteps;
}

Result settle(Env& env) {
  Result r;
  r.model = "balls";
  r.metrics = {"steps_per_contact", "max_overlap", "energy_drift"};
  r.chart.title = "balls-settle-provisional: max overlap of a settling column against cost (t_c = 2 ms, e = 0.5)";
  r.chart.xLabel = "GPU ms per simulated second (65k-ball lattice)";
  r.chart.yLabel = "max overlap / r";
  const std::vector<double> dts =
      env.quick ? std::vector<double>{1e-4, 2e-4} : std::vector<double>{2e-5, 4e-5, 8e-5, 1.6e-4, 3.2e-4};
  for (balls::Contact contact : {balls::Contact::SpringDashpot, balls::Contact::Penalty})
    for (balls::Integrator integrator : {balls::Integrator::SymplecticEuler, balls::Integrator::VelocityVerlet}) {
      const double stepMs = msPerStep(env.shaders, env.quick ? 4096 : 65536, contact, integrator);
      for (double dt : dts) {
        const Settle s = measureSettle(env.shaders, contact, integrator, dt, env.quick ? 0.1 : 0.5);
        Row row;
        row.method = std::string(balls::kContactNames[int(contact)]) + "/" + balls::kIntegratorNames[int(integrator)];
        row.dt = dt;
        row.resolution = "450-ball column";
        row.costMsPerSimS = stepMs / dt;
        row.stable = s.stable;
        // t_c/dt only where it sets the accuracy (the spring-dashpot law); penalty steps are absolute.
        row.metrics = {contact == balls::Contact::SpringDashpot ? kContactTime / dt : NAN, s.maxOverlap, s.energyDrift};
        row.x = row.costMsPerSimS;
        row.y = s.maxOverlap;
        r.rows.push_back(row);
      }
    }
  markPareto(r.rows);
  return r;
}

}  // namespace

Settle measureSettle(gl::ShaderLibrary& shaders, balls::Contact contact, balls::Integrator integrator, double dt,
                     double seconds) {
  balls::Balls b(shaders, column(contact, integrator, dt));
  const balls::Stats start = b.stats();
  const double e0 = start.kinetic + start.potential;
  const int steps = int(std::lround(seconds / dt));
  const int sampleEvery = std::max(1, int(std::lround(0.005 / dt)));
  Settle s;
  double mid = NAN;
  for (int i = 1; i <= steps; ++i) {
    b.stepOnce();
    if (i % sampleEvery && i != steps) continue;
    const balls::Stats st = b.stats();
    if (st.nonFinite > 0 || st.outside > 0 || !(st.maxOverlap < 1.0)) {
      s.stable = false;
      s.maxOverlap = std::isfinite(st.maxOverlap) ? std::max(s.maxOverlap, st.maxOverlap) : INFINITY;
      s.energyDrift = INFINITY;
      return s;
    }
    s.maxOverlap = std::max(s.maxOverlap, st.maxOverlap);
    if (2 * i < steps) continue;
    const double e = st.kinetic + st.potential;
    if (std::isnan(mid)) mid = e;
    s.energyDrift = std::max(s.energyDrift, std::abs(e - mid) / e0);
  }
  return s;
}

Study ballsSettleProvisionalStudy() {
  return {"balls-settle-provisional",
          "PROVISIONAL until balls-settle lands: settling-column max overlap and energy drift vs cost", settle};
}

}  // namespace tidepool::sweep
