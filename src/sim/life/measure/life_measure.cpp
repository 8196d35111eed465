#include "sim/life/measure/life_measure.h"

#include <cmath>
#include <numbers>

#include "sim/life/life.h"
#include "sim/measure/bisect.h"

namespace tidepool::life {

PairOscillator pairOscillator(double friction) {
  constexpr double kOmega = 50, kRadius = 2, kCollisionRadius = 1, kEquilibrium = 0.5;
  // k = ω²/2 = c/Rc − s/R and k·d* = c − s give s and c.
  const double k = 0.5 * kOmega * kOmega;
  const double s = k * (kCollisionRadius - kEquilibrium) / (1 - kCollisionRadius / kRadius);
  const double c = k * kCollisionRadius + s * kCollisionRadius / kRadius;
  PairOscillator pair;
  pair.omega = kOmega;
  pair.equilibrium = kEquilibrium;
  pair.amplitude = 0.02 * kEquilibrium;
  Species species;
  species.forces = {Force{float(s), float(c), float(kRadius), float(kCollisionRadius)}};
  pair.rules.species = {species};
  pair.rules.particleCount = 2;
  pair.rules.size = glm::vec2(16.0f);
  pair.rules.friction = float(friction);
  pair.rules.centralForce = 0;
  pair.rules.loopingBorders = false;
  return pair;
}

double pairGrowth(gl::ShaderLibrary& shaders, const PairOscillator& pair, Integrator integrator, double omegaDt,
                  int periods) {
  Params params;
  params.integrator = integrator;
  Life life(shaders, pair.rules, params);
  const float half = float(0.5 * (pair.equilibrium + pair.amplitude));
  life.upload({glm::vec4(-half, 0.0f, 0.0f, 0.0f), glm::vec4(half, 0.0f, 0.0f, 0.0f)},
              {glm::vec4(0.0f), glm::vec4(0.0f)});
  const float dt = float(omegaDt / pair.omega);
  const int steps = int(std::ceil(periods * 2.0 * std::numbers::pi / omegaDt));
  double worst = 0;
  for (int n = 0; n < steps; ++n) {
    life.stepOnce(dt);
    const std::vector<glm::vec4> p = life.downloadPositions();  // in cell order: either way round
    const double d = glm::length(glm::dvec2(p[0]) - glm::dvec2(p[1]));
    const double growth = std::abs(d - pair.equilibrium) / pair.amplitude;
    if (!std::isfinite(growth) || growth > kPairGrowthBound) return INFINITY;
    worst = std::max(worst, growth);
  }
  return worst;
}

double pairStableLimit(gl::ShaderLibrary& shaders, const PairOscillator& pair, Integrator integrator,
                       double tolerance) {
  auto stable = [&](double omegaDt) {
    return pairGrowth(shaders, pair, integrator, omegaDt, kPairPeriods) < kPairGrowthBound;
  };
  return largestStable(1.0, 4.0, tolerance, stable);
}

double eulerStableLimit(double frictionOverOmega) {
  // g(h) = h² − 2(exp(a·h) + 1) is ≤ 0 at h = 2. Scan up for its first root; there is none once
  // h²·exp(−a·h), falling beyond h = 2/a, is below 2 (< 2·(1 + f)).
  const double a = frictionOverOmega;
  const auto g = [a](double h) { return h * h - 2.0 * (std::exp(a * h) + 1.0); };
  if (a <= 0) return 2.0;
  double lo = 2.0, hi = 2.0;
  for (; g(hi) <= 0; lo = hi, hi += 0.01)
    if (hi > 2.0 / a && hi * hi * std::exp(-a * hi) < 2.0) return INFINITY;
  return bisectLimit(lo, hi, 1e-12, [&](double h) { return g(h) <= 0; });
}

}  // namespace tidepool::life
