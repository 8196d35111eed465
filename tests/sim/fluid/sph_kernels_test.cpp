// Properties of the PBF smoothing kernels (src/sim/fluid/sph_kernels.h): normalisation, the
// gradient against the kernel it differentiates, compact support, and the density a cubic
// lattice of spacing d and mass ρ0·d³ reads back, which tells how large h must be against the
// spacing for a resting fluid to read its rest density.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/fluid/sph_kernels.h"

using namespace tidepool::fluid;

namespace {

// ∫ W dV over the ball of radius h, by the midpoint rule in r: 4π ∫ W(r) r² dr.
template <class Kernel>
double volumeIntegral(Kernel w, double h) {
  const int n = 20000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) * h / n;
    sum += w(r) * r * r;
  }
  return 4.0 * std::numbers::pi * sum * h / n;
}

// Σ_j W(x_i − x_j) · d³ at a site of an infinite simple cubic lattice of spacing d: the density
// over ρ0 that a fluid at rest on that lattice reads.
double latticeDensity(double h, double d) {
  const int n = int(std::ceil(h / d));
  double sum = 0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) sum += poly6(d * d * double(i * i + j * j + k * k), h);
  return sum * d * d * d;
}

}  // namespace

TEST(SphKernels, Poly6AndSpikyIntegrateToOne) {
  for (double h : {0.01, 0.1, 1.0}) {
    EXPECT_NEAR(volumeIntegral([h](double r) { return poly6(r * r, h); }, h), 1.0, 1e-6) << "h = " << h;
    EXPECT_NEAR(volumeIntegral([h](double r) { return spiky(r, h); }, h), 1.0, 1e-6) << "h = " << h;
  }
}

TEST(SphKernels, SpikyGradientIsTheDerivativeOfSpikyAlongR) {
  const double h = 0.1, e = 1e-7;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  for (double r : {0.001, 0.02, 0.05, 0.09, 0.0999}) {
    const glm::dvec3 g = spikyGradient(r * dir, h);
    const double dwdr = (spiky(r + e, h) - spiky(r - e, h)) / (2 * e);
    EXPECT_NEAR(glm::dot(g, dir), dwdr, 1e-6 * std::abs(dwdr)) << "r = " << r;
    EXPECT_NEAR(glm::length(glm::cross(g, dir)), 0.0, 1e-9 * glm::length(g)) << "r = " << r;  // along r
  }
}

TEST(SphKernels, SupportEndsAtHWithNoJump) {
  const double h = 0.1;
  EXPECT_EQ(poly6(h * h, h), 0.0);
  EXPECT_EQ(spiky(h, h), 0.0);
  EXPECT_EQ(glm::length(spikyGradient(glm::dvec3(h, 0, 0), h)), 0.0);
  EXPECT_EQ(glm::length(spikyGradient(glm::dvec3(0.0), h)), 0.0);  // no direction at r = 0
  const double justInside = h * (1 - 1e-6);
  EXPECT_LT(poly6(justInside * justInside, h), 1e-12 * poly6(0.0, h));
  EXPECT_LT(spiky(justInside, h), 1e-12 * spiky(0.0, h));
  EXPECT_GT(poly6(0.0, h), poly6(0.25 * h * h, h));  // decreasing
  EXPECT_GT(spiky(0.0, h), spiky(0.5 * h, h));
}

TEST(SphKernels, FloatAgreesWithDouble) {
  const float h = 0.1f;
  for (float r : {0.0f, 0.013f, 0.05f, 0.0875f}) {
    EXPECT_NEAR(poly6(r * r, h), poly6(double(r) * double(r), double(h)), 1e-5 * poly6(0.0, double(h)));
    const glm::vec3 g = spikyGradient(glm::vec3(r, 0.0f, 0.0f), h);
    const glm::dvec3 gd = spikyGradient(glm::dvec3(r, 0.0, 0.0), double(h));
    EXPECT_NEAR(g.x, gd.x, 1e-5 * std::abs(spikyGradient(glm::dvec3(1e-9, 0, 0), double(h)).x));
  }
}

// A resting lattice reads its rest density once h spans enough neighbours: at h = 1.5 d the
// estimate is 5% low, from h = 2 d within 1% (1.0098), from h = 2.5 d within 0.5%.
TEST(SphKernels, RestingLatticeReadsItsRestDensityOnceHSpansTwoSpacings) {
  const double d = 0.02;
  EXPECT_NEAR(latticeDensity(1.5 * d, d), 0.9494, 1e-3);
  EXPECT_NEAR(latticeDensity(2.0 * d, d), 1.0, 0.01);
  for (double ratio : {2.5, 3.0, 4.0}) EXPECT_NEAR(latticeDensity(ratio * d, d), 1.0, 0.005) << "h/d = " << ratio;
}
