// The quarter-space table of sph_kernels.h. Out of line, and built by a plain function rather than
// a lambda: GCC tries to constant-evaluate a static's initializer when it could be constexpr (a
// lambda is implicitly), and gives up only after some 30 s of the 17 × 17 × 400 × 400 loop, in
// every file that called edgeDensity(). The table is computed at run time either way.
#include "sim/fluid/sph_kernels.h"

namespace tidepool::fluid {

namespace {

EdgeTable computeEdgeTable() {  // not constexpr on purpose (above)
  EdgeTable t{};
  constexpr int n = 400;
  for (int j = 0; j < kEdgeTableSize; ++j)
    for (int i = 0; i < kEdgeTableSize; ++i) {
      const double a = i / 16.0, b = j / 16.0;
      double sum = 0;
      const double dx = (1.0 - a) / n;
      for (int u = 0; u < n; ++u) {
        const double x = a + (u + 0.5) * dx, top = 1.0 - x * x - b * b;
        if (top <= 0) continue;
        const double ymax = std::sqrt(1.0 - x * x), dy = (ymax - b) / n;
        for (int v = 0; v < n; ++v) {
          const double y = b + (v + 0.5) * dy, q = 1.0 - x * x - y * y;
          if (q > 0) sum += std::pow(q, 3.5) * dx * dy;
        }
      }
      t[std::size_t(i + kEdgeTableSize * j)] = float(9.0 / (2.0 * std::numbers::pi) * sum);
    }
  return t;
}

}  // namespace

const EdgeTable& edgeTable() {
  static const EdgeTable table = computeEdgeTable();
  return table;
}

}  // namespace tidepool::fluid
