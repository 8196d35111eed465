// Pixel-by-pixel difference of two RGBA8 images of the same size (alpha ignored), for tests that
// compare two renderers or a render with a reference.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace tidepool::test {

struct PixelDifference {
  double mean = 0;         // mean |a − b| over all pixels' RGB channels, in levels of 255
  double offFraction = 0;  // fraction of pixels whose largest channel difference exceeds the threshold
  int maxAbs = 0;          // the largest channel difference, in levels
};

inline PixelDifference pixelDifference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                                       int threshold) {
  PixelDifference d;
  std::size_t off = 0;
  for (std::size_t i = 0; i < a.size(); i += 4) {
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int e = std::abs(int(a[i + c]) - int(b[i + c]));
      d.mean += e;
      worst = std::max(worst, e);
    }
    off += worst > threshold;
    d.maxAbs = std::max(d.maxAbs, worst);
  }
  d.mean /= 3.0 * double(a.size() / 4);
  d.offFraction = double(off) / double(a.size() / 4);
  return d;
}

}  // namespace tidepool::test
