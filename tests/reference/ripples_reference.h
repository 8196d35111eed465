// CPU reference of one ripples step in double precision: plain loops over the grid, the same
// formulas as shaders/ripples/step.comp. It is the oracle the GPU result is compared against.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/ripples/ripples_params.h"

namespace tidepool::ripples::reference {

struct State {
  int width = 0, height = 0;
  std::vector<double> h, v;  // row-major, width * height
};

inline State fromInterleaved(int width, int height, const std::vector<float>& hv) {
  State s{width, height, std::vector<double>(std::size_t(width) * height),
          std::vector<double>(std::size_t(width) * height)};
  for (std::size_t i = 0; i < s.h.size(); ++i) {
    s.h[i] = hv[2 * i];
    s.v[i] = hv[2 * i + 1];
  }
  return s;
}

inline void step(State& s, const Params& p, double dt) {
  const int w = s.width, hgt = s.height;
  auto at = [&](int x, int y) {
    if (p.boundary == Boundary::Periodic) {
      x = (x + w) % w;
      y = (y + hgt) % hgt;
    } else {
      x = std::clamp(x, 0, w - 1);
      y = std::clamp(y, 0, hgt - 1);
    }
    return s.h[std::size_t(y) * w + x];
  };
  std::vector<double> h2(s.h.size()), v2(s.v.size());
  for (int y = 0; y < hgt; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      const double h = s.h[i];
      const double sum4 = at(x - 1, y) + at(x + 1, y) + at(x, y - 1) + at(x, y + 1);
      double v = s.v[i], hs = h, stepDt = dt;
      if (p.rule == Rule::Seed) {
        stepDt = p.seedTimeScale * dt;
        v += stepDt * (-p.seedElasticity * h + p.seedPropagation * (0.25 * sum4 - h));
        v *= p.seedFriction;
      } else {
        v += double(p.waveSpeed) * p.waveSpeed * dt / (double(p.cellSize) * p.cellSize) * (sum4 - 4.0 * h);
        v *= std::max(0.0, 1.0 - p.velDamping * dt);
        hs = h + (0.25 * sum4 - h) * std::min(p.posDamping * dt, 1.0);
      }
      if (p.boundary == Boundary::Absorbing) {
        const int edge = std::min(std::min(x, y), std::min(w - 1 - x, hgt - 1 - y));
        const double depth = std::max(0.0, 1.0 - double(edge) / p.spongeCells);
        v *= 1.0 + (std::exp(-p.spongeDamping * dt) - 1.0) * depth * depth;
      }
      v2[i] = v;
      h2[i] = hs + stepDt * v;
    }
  s.h.swap(h2);
  s.v.swap(v2);
}

}  // namespace tidepool::ripples::reference
