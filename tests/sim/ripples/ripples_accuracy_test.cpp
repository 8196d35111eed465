// Accuracy and stability of the wave rule against theory (shared/ACCURACY-REFERENCES.md §3):
//   phase speed  c̃/c = 2·asin(C·S)/(C·kΔx), S² = sin²(k_xΔx/2) + sin²(k_yΔx/2)
//   stability    C = c·Δt/Δx ≤ 1/√2 in 2D; the seed rule's limit (derived below) found the same way.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "sim/ripples/ripples.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::ripples;

namespace {

class RipplesAccuracy : public test::GlTest {};

constexpr double kPi = std::numbers::pi;

Params periodicGrid(int width, int height) {
  Params p;
  p.rule = Rule::Wave;
  p.boundary = Boundary::Periodic;
  p.width = width;
  p.height = height;
  p.velDamping = 0;
  p.posDamping = 0;
  p.autoSubsteps = false;
  p.substeps = 1;
  return p;
}

// Measured phase speed ratio c̃/c of the standing wave cos(kx·x + ky·y) (k in radians per cell).
// The leapfrog recurrence a[n+1] + a[n-1] = 2·cos(θ)·a[n] holds exactly for the mode's amplitude
// a[n]; θ = ω̃·Δt is fitted by least squares over several periods.
double measuredPhaseRatio(gl::ShaderLibrary& shaders, int width, int height, double kx, double ky, double courant) {
  Params p = periodicGrid(width, height);
  Ripples r(shaders, p);
  std::vector<float> hv(std::size_t(width) * height * 2, 0.0f);
  std::vector<double> mode(std::size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      mode[std::size_t(y) * width + x] = std::cos(kx * x + ky * y);
      hv[2 * (std::size_t(y) * width + x)] = float(0.01 * mode[std::size_t(y) * width + x]);
    }
  r.upload(hv);
  const double dt = courant * p.cellSize / p.waveSpeed;
  const double kdx = std::hypot(kx, ky);
  const double period = 2 * kPi / (courant * kdx);  // steps, roughly
  const int steps = int(4 * period) + 8;
  std::vector<double> a;
  for (int n = 0; n <= steps; ++n) {
    const std::vector<float> s = r.download();
    double dot = 0;
    for (std::size_t i = 0; i < mode.size(); ++i) dot += s[2 * i] * mode[i];
    a.push_back(dot);
    r.stepOnce(dt);
  }
  double num = 0, den = 0;
  for (std::size_t n = 1; n + 1 < a.size(); ++n) {
    num += a[n] * (a[n + 1] + a[n - 1]);
    den += 2 * a[n] * a[n];
  }
  const double theta = std::acos(std::clamp(num / den, -1.0, 1.0));
  return theta / (courant * kdx);
}

double predictedPhaseRatio(double kx, double ky, double courant) {
  const double s = std::sqrt(std::pow(std::sin(kx / 2), 2) + std::pow(std::sin(ky / 2), 2));
  return 2 * std::asin(courant * s) / (courant * std::hypot(kx, ky));
}

// True when random noise stays bounded (max |h| < 100x the start) for `steps` steps at this dt.
bool staysBounded(gl::ShaderLibrary& shaders, const Params& p, double dt, int steps) {
  Ripples r(shaders, p);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1e-3f, 1e-3f);
  std::vector<float> hv(std::size_t(p.width) * p.height * 2, 0.0f);
  for (std::size_t i = 0; i < hv.size(); i += 2) hv[i] = u(rng);
  r.upload(hv);
  for (int done = 0; done < steps;) {
    for (int i = 0; i < 500 && done < steps; ++i, ++done) r.stepOnce(dt);
    const std::vector<float> hv = r.download();
    for (std::size_t i = 0; i < hv.size(); i += 2)
      if (!(std::abs(hv[i]) < 0.1f)) return false;  // heights; also catches NaN and inf
  }
  return true;
}

// Largest stable value of f(x) = staysBounded at x, by bisection to a relative width `tolerance`.
template <class Stable>
double bisect(double stable, double unstable, double tolerance, Stable isStable) {
  while ((unstable - stable) / stable > tolerance) {
    const double mid = 0.5 * (stable + unstable);
    (isStable(mid) ? stable : unstable) = mid;
  }
  return 0.5 * (stable + unstable);
}

}  // namespace

TEST_F(RipplesAccuracy, PhaseSpeedFollowsTheDiscreteDispersionRelationAlongTheAxis) {
  for (int cellsPerWavelength : {10, 16, 32}) {
    const double k = 2 * kPi / cellsPerWavelength;
    const double measured = measuredPhaseRatio(shaders(), 2 * cellsPerWavelength, 16, k, 0.0, 0.5);
    const double predicted = predictedPhaseRatio(k, 0.0, 0.5);
    SCOPED_TRACE("cells per wavelength " + std::to_string(cellsPerWavelength));
    EXPECT_NEAR(measured / predicted, 1.0, 0.01) << "measured " << measured << ", predicted " << predicted;
    if (cellsPerWavelength == 10) {
      EXPECT_NEAR(predicted, 0.9876, 1e-4);  // the reference table
      EXPECT_LT(measured, 0.993) << "the numerical lag behind c must be visible";
    }
  }
}

TEST_F(RipplesAccuracy, PhaseSpeedAlongTheDiagonalLagsLess) {
  const int n = 16;  // one period across a 16x16 torus in x and in y: 11.3 cells per wavelength
  const double k = 2 * kPi / n;
  const double measured = measuredPhaseRatio(shaders(), n, n, k, k, 0.5);
  const double predicted = predictedPhaseRatio(k, k, 0.5);
  EXPECT_NEAR(measured / predicted, 1.0, 0.01) << "measured " << measured << ", predicted " << predicted;
  EXPECT_GT(measured, predictedPhaseRatio(std::hypot(k, k), 0.0, 0.5)) << "an axis wave of the same length lags more";
}

// Radius (cells) of the outgoing ring's crest: radially averaged height, maximum beyond `minRadius`,
// refined by a parabola through the three bins around it.
double crestRadius(const std::vector<float>& hv, int n, double minRadius) {
  std::vector<double> sum(std::size_t(n), 0.0), count(std::size_t(n), 0.0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double r = std::hypot(x + 0.5 - 0.5 * n, y + 0.5 - 0.5 * n);
      const std::size_t bin = std::size_t(std::lround(r));
      if (bin >= sum.size()) continue;
      sum[bin] += hv[2 * (std::size_t(y) * n + x)];
      count[bin] += 1;
    }
  std::size_t best = std::size_t(minRadius);
  for (std::size_t b = best; b + 1 < sum.size(); ++b)
    if (count[b] > 0 && sum[b] / count[b] > sum[best] / count[best]) best = b;
  const double a = sum[best - 1] / count[best - 1], m = sum[best] / count[best], c = sum[best + 1] / count[best + 1];
  return double(best) + 0.5 * (a - c) / (a - 2 * m + c);
}

TEST_F(RipplesAccuracy, GaussianRingFrontTravelsAtTheNumericalPhaseSpeed) {
  // A Gaussian bump of width sigma = 4 cells: its spectrum peaks near 2*pi*sigma = 25 cells per
  // wavelength (>= 10). The ring crest is timed between two radii well after it has separated.
  const int n = 256;
  const double sigma = 4.0, courantNumber = 0.5;
  Params p = periodicGrid(n, n);
  Ripples r(shaders(), p);
  std::vector<float> hv(std::size_t(n) * n * 2, 0.0f);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double d2 = std::pow(x + 0.5 - 0.5 * n, 2) + std::pow(y + 0.5 - 0.5 * n, 2);
      hv[2 * (std::size_t(y) * n + x)] = float(0.01 * std::exp(-d2 / (2 * sigma * sigma)));
    }
  r.upload(hv);
  const double dt = courantNumber * p.cellSize / p.waveSpeed;
  const int steps1 = 80, steps2 = 200;  // crest near 40 and 100 cells
  for (int i = 0; i < steps1; ++i) r.stepOnce(dt);
  const double r1 = crestRadius(r.download(), n, 20);
  for (int i = steps1; i < steps2; ++i) r.stepOnce(dt);
  const double r2 = crestRadius(r.download(), n, 60);
  const double measured = (r2 - r1) / ((steps2 - steps1) * courantNumber);  // c̃/c
  const double k = 1.0 / sigma;  // dominant wavenumber of the Gaussian (rad/cell)
  const double predicted = predictedPhaseRatio(k, 0.0, courantNumber);
  std::printf("ring crest: r = %.2f -> %.2f cells, speed %.4f c, predicted phase speed %.4f c\n", r1, r2, measured,
              predicted);
  EXPECT_NEAR(measured / predicted, 1.0, 0.01);
}

TEST_F(RipplesAccuracy, WaveRuleStabilityLimitIsOneOverSqrtTwo) {
  const Params p = periodicGrid(32, 32);
  const double limit = 1.0 / std::sqrt(2.0);
  auto stableAt = [&](double c) { return staysBounded(shaders(), p, c * p.cellSize / p.waveSpeed, 10000); };
  EXPECT_TRUE(stableAt(0.99 * limit)) << "just below the limit the energy must stay bounded";
  EXPECT_FALSE(stableAt(1.05 * limit)) << "5% above the limit the solution must grow";
  const double measured = bisect(0.5, 1.0, 0.005, stableAt);
  RecordProperty("measured_courant_limit", std::to_string(measured));
  std::printf("wave rule: measured Courant limit %.4f, theory %.4f\n", measured, limit);
  EXPECT_NEAR(measured / limit, 1.0, 0.02);
}

TEST_F(RipplesAccuracy, SeedRuleStabilityLimitMatchesItsDerivation) {
  // Seed rule, checkerboard mode (mean4 − h = −2h): v' = f·(v − dt·(k + 2c)·h), h' = h + dt·v'.
  // The one-step matrix has trace 1 + f − f·dt²·ω² and determinant f (ω² = k + 2c), so it is
  // stable while dt²·ω² < 2(1 + f)/f. With the seed's k = 0.7, c = 20, f = 0.995: dt < 0.3139,
  // i.e. with dt = 10 x frame time the seed blows up below about 32 frames per second.
  Params p = periodicGrid(32, 32);
  p.rule = Rule::Seed;
  p.seedTimeScale = 1.0f;
  const double omega2 = p.seedElasticity + 2.0 * p.seedPropagation;
  const double theory = std::sqrt(2.0 * (1.0 + p.seedFriction) / (p.seedFriction * omega2));
  auto stableAt = [&](double dt) { return staysBounded(shaders(), p, dt, 4000); };
  const double measured = bisect(0.1, 1.0, 0.005, stableAt);
  std::printf("seed rule: measured dt limit %.4f (seed time units), theory %.4f; frame rate floor %.1f fps\n", measured,
              theory, 10.0 / measured);  // the seed runs with dt = 10 x frame time
  EXPECT_NEAR(measured / theory, 1.0, 0.02);
}
