// Accuracy and stability of the wave rule against theory (shared/ACCURACY-REFERENCES.md,
// "Heightfield / shallow-water wave grid"):
//   phase speed  c̃/c = 2·asin(C·S)/(C·kΔx), S² = sin²(k_xΔx/2) + sin²(k_yΔx/2)
//   stability    C = c·Δt/Δx ≤ 1/√2 in 2D; the seed rule's limit (derived below) found the same way.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "sim/ripples/measure/ripples_measure.h"
#include "sim/ripples/ripples.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::ripples;

namespace {

using RipplesTest = test::GlTest;

constexpr double kPi = std::numbers::pi;

// True when random noise stays bounded (below 100x its start) for `steps` steps of dt.
bool staysBounded(gl::ShaderLibrary& shaders, const Params& p, double dt, int steps) {
  return std::isfinite(noiseGrowth(shaders, p, dt, steps));
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

}  // namespace

TEST_F(RipplesTest, PhaseSpeedFollowsTheDiscreteDispersionRelationAlongTheAxis) {
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

TEST_F(RipplesTest, PhaseSpeedAlongTheDiagonalLagsLess) {
  const int n = 16;  // one period across a 16x16 torus in x and in y: 11.3 cells per wavelength
  const double k = 2 * kPi / n;
  const double measured = measuredPhaseRatio(shaders(), n, n, k, k, 0.5);
  const double predicted = predictedPhaseRatio(k, k, 0.5);
  EXPECT_NEAR(measured / predicted, 1.0, 0.01) << "measured " << measured << ", predicted " << predicted;
  EXPECT_GT(measured, predictedPhaseRatio(std::hypot(k, k), 0.0, 0.5)) << "an axis wave of the same length lags more";
}

TEST_F(RipplesTest, GaussianRingFrontTravelsAtTheNumericalPhaseSpeed) {
  // A Gaussian bump of width sigma = 4 cells: its spectrum peaks near 2*pi*sigma = 25 cells per
  // wavelength (>= 10). The ring crest is timed between two radii well after it has separated.
  const int n = 256;
  const double sigma = 4.0, courantNumber = 0.5;
  Params p = periodicWaveGrid(n, n);
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

TEST_F(RipplesTest, WaveRuleStabilityLimitIsOneOverSqrtTwo) {
  const Params p = periodicWaveGrid(32, 32);
  const double limit = 1.0 / std::sqrt(2.0);
  auto stableAt = [&](double c) { return staysBounded(shaders(), p, c * p.cellSize / p.waveSpeed, 10000); };
  EXPECT_TRUE(stableAt(0.99 * limit)) << "just below the limit the energy must stay bounded";
  EXPECT_FALSE(stableAt(1.05 * limit)) << "5% above the limit the solution must grow";
  const double measured = bisectLimit(0.5, 1.0, 0.005, stableAt);
  RecordProperty("measured_courant_limit", std::to_string(measured));
  std::printf("wave rule: measured Courant limit %.4f, theory %.4f\n", measured, limit);
  EXPECT_NEAR(measured / limit, 1.0, 0.02);
}

TEST_F(RipplesTest, SeedRuleStabilityLimitMatchesItsDerivation) {
  // Seed rule, checkerboard mode (mean4 − h = −2h): v' = f·(v − dt·(k + 2c)·h), h' = h + dt·v'.
  // The one-step matrix has trace 1 + f − f·dt²·ω² and determinant f (ω² = k + 2c), so it is
  // stable while dt²·ω² < 2(1 + f)/f. With the seed's k = 0.7, c = 20, f = 0.995: dt < 0.3139,
  // i.e. with dt = 10 x frame time the seed blows up below about 32 frames per second.
  Params p = periodicWaveGrid(32, 32);
  p.rule = Rule::Seed;
  p.seedTimeScale = 1.0f;
  const double omega2 = p.seedElasticity + 2.0 * p.seedPropagation;
  const double theory = std::sqrt(2.0 * (1.0 + p.seedFriction) / (p.seedFriction * omega2));
  auto stableAt = [&](double dt) { return staysBounded(shaders(), p, dt, 4000); };
  const double measured = bisectLimit(0.1, 1.0, 0.005, stableAt);
  std::printf("seed rule: measured dt limit %.4f (seed time units), theory %.4f; frame rate floor %.1f fps\n", measured,
              theory, 10.0 / measured);  // the seed runs with dt = 10 x frame time
  EXPECT_NEAR(measured / theory, 1.0, 0.02);
}
