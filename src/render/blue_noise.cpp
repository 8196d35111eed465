#include "render/blue_noise.h"

#include <algorithm>
#include <cmath>

namespace tidepool {
namespace {

// Gaussian energy of every pixel, kept up to date as points are set or cleared.
class Energy {
 public:
  explicit Energy(int size) : m_size(size), m_kernel(std::size_t(size) * size), m_energy(m_kernel.size(), 0.0) {
    constexpr double kSigma = 1.5;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const int dx = std::min(x, size - x), dy = std::min(y, size - y);  // toroidal distance
        m_kernel[std::size_t(y) * size + x] = std::exp(-(dx * dx + dy * dy) / (2 * kSigma * kSigma));
      }
  }
  void add(int p, double sign) {
    const int px = p % m_size, py = p / m_size;
    for (int y = 0; y < m_size; ++y) {
      const int ky = (y - py + m_size) % m_size;
      for (int x = 0; x < m_size; ++x)
        m_energy[std::size_t(y) * m_size + x] += sign * m_kernel[std::size_t(ky) * m_size + (x - px + m_size) % m_size];
    }
  }
  // Tightest cluster (highest energy among set pixels) or largest void (lowest among clear ones).
  int extreme(const std::vector<char>& set, bool cluster) const {
    int best = -1;
    for (int i = 0; i < int(set.size()); ++i) {
      if (bool(set[std::size_t(i)]) != cluster) continue;
      if (best < 0 || (cluster ? m_energy[std::size_t(i)] > m_energy[std::size_t(best)]
                               : m_energy[std::size_t(i)] < m_energy[std::size_t(best)]))
        best = i;
    }
    return best;
  }

 private:
  int m_size;
  std::vector<double> m_kernel, m_energy;
};

}  // namespace

std::vector<float> voidAndCluster(int size, std::uint32_t seed) {
  const int n = size * size;
  std::vector<char> pattern(std::size_t(n), 0);
  Energy energy(size);
  // Initial binary pattern: a tenth of the pixels at random (xorshift32), then relaxed by moving
  // the tightest cluster into the largest void until that changes nothing.
  std::uint32_t state = seed ? seed : 1u;
  const int ones = std::max(1, n / 10);
  for (int placed = 0; placed < ones;) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    const int p = int(state % std::uint32_t(n));
    if (pattern[std::size_t(p)]) continue;
    pattern[std::size_t(p)] = 1;
    energy.add(p, 1);
    ++placed;
  }
  for (int guard = 0; guard < 10 * n; ++guard) {
    const int cluster = energy.extreme(pattern, true);
    pattern[std::size_t(cluster)] = 0;
    energy.add(cluster, -1);
    const int gap = energy.extreme(pattern, false);
    pattern[std::size_t(gap)] = 1;
    energy.add(gap, 1);
    if (gap == cluster) break;
  }
  std::vector<int> rank(std::size_t(n), -1);
  // Phase 1: ranks below the initial count, removing tightest clusters from a copy.
  {
    std::vector<char> p = pattern;
    Energy e = energy;
    for (int r = ones - 1; r >= 0; --r) {
      const int c = e.extreme(p, true);
      p[std::size_t(c)] = 0;
      e.add(c, -1);
      rank[std::size_t(c)] = r;
    }
  }
  // Phases 2 and 3 (simplified into one): fill the largest void until every pixel has a rank.
  for (int r = ones; r < n; ++r) {
    const int v = energy.extreme(pattern, false);
    pattern[std::size_t(v)] = 1;
    energy.add(v, 1);
    rank[std::size_t(v)] = r;
  }
  std::vector<float> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out[std::size_t(i)] = (float(rank[std::size_t(i)]) + 0.5f) / float(n);
  return out;
}

gl::Texture2D makeBlueNoiseTexture() {
  constexpr int kSize = 64;
  static const std::vector<float> values = voidAndCluster(kSize);  // CPU work once per process
  gl::Texture2D t(kSize, kSize, GL_R32F);
  t.upload(GL_RED, GL_FLOAT, values.data());
  t.setFilter(GL_NEAREST, GL_NEAREST);
  return t;
}

}  // namespace tidepool
