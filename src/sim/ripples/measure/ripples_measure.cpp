#include "sim/ripples/measure/ripples_measure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "sim/ripples/ripples.h"

namespace tidepool::ripples {

Params periodicWaveGrid(int width, int height) {
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

double predictedPhaseRatio(double kx, double ky, double courant) {
  const double s = std::sqrt(std::pow(std::sin(kx / 2), 2) + std::pow(std::sin(ky / 2), 2));
  return 2 * std::asin(std::min(courant * s, 1.0)) / (courant * std::hypot(kx, ky));
}

double measuredPhaseRatio(gl::ShaderLibrary& shaders, int width, int height, double kx, double ky, double courant,
                          double periods) {
  const Params p = periodicWaveGrid(width, height);
  Ripples r(shaders, p);
  std::vector<float> hv(std::size_t(width) * height * 2, 0.0f);
  std::vector<double> mode(std::size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * width + x;
      mode[i] = std::cos(kx * x + ky * y);
      hv[2 * i] = float(0.01 * mode[i]);
    }
  r.upload(hv);
  const double dt = courant * p.cellSize / p.waveSpeed;
  const double period = 2 * std::numbers::pi / (courant * std::hypot(kx, ky));  // steps, roughly
  const int steps = int(periods * period) + 8;
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
  return std::acos(std::clamp(num / den, -1.0, 1.0)) / (courant * std::hypot(kx, ky));
}

double noiseGrowth(gl::ShaderLibrary& shaders, const Params& p, double dt, int steps, double giveUp) {
  Ripples r(shaders, p);
  std::mt19937 rng(3);
  constexpr float kStart = 1e-3f;
  std::uniform_real_distribution<float> u(-kStart, kStart);
  std::vector<float> hv(std::size_t(p.width) * p.height * 2, 0.0f);
  for (std::size_t i = 0; i < hv.size(); i += 2) hv[i] = u(rng);
  r.upload(hv);
  double growth = 0;
  for (int done = 0; done < steps;) {
    for (int i = 0; i < 500 && done < steps; ++i, ++done) r.stepOnce(dt);
    const std::vector<float> state = r.download();
    double maxH = 0;
    for (std::size_t i = 0; i < state.size(); i += 2) {
      if (!std::isfinite(state[i])) return std::numeric_limits<double>::infinity();
      maxH = std::max(maxH, double(std::abs(state[i])));
    }
    growth = maxH / kStart;
    if (growth > giveUp) return std::numeric_limits<double>::infinity();
  }
  return growth;
}

}  // namespace tidepool::ripples
