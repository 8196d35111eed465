// The PBF smoothing kernels (Macklin & Müller 2013, after Müller et al. 2003) in the units the
// fluid kernels work in: densities as ρ/ρ0, so a neighbour adds V·W with V its rest volume (m³) and
// no mass or ρ0 appears. The float twin of src/sim/fluid/sph_kernels.h, which documents them:
//   poly6(r²)     = 315/(64π h³) (1 − r²/h²)³                      (1/m³)
//   spikyGrad(r)  = −45/(π h⁴) (1 − |r|/h)² r/|r|                  (1/m⁴)
//   wallDensity(δ) = Φ(δ), wallGradient(δ) = G(δ): a wall's half space at rest density
//   edgeDensity(a, b) = Q and its slopes: the quarter space where two walls' half spaces overlap
#ifndef FLUID_KERNELS_GLSL
#define FLUID_KERNELS_GLSL

uniform float uH;           // smoothing radius h, m
uniform float uPoly6Coef;   // 315 / (64 π h³)
uniform float uSpikyCoef;   // −45 / (π h⁴)
uniform float uVolume;      // V0 = m / ρ0 of a fluid particle, m³ (calibrated on the rest lattice)

float poly6(float r2) {
  const float q = max(1.0 - r2 / (uH * uH), 0.0);
  return uPoly6Coef * q * q * q;
}

vec3 spikyGrad(vec3 r, float len) {  // len = |r| in (0, h)
  const float q = 1.0 - len / uH;
  return (uSpikyCoef * q * q / len) * r;
}

float wallDensity(float delta) {
  const float s = clamp(delta / uH, -1.0, 1.0), s2 = s * s;
  return 0.5 - 315.0 / 256.0 * s * (1.0 + s2 * (-4.0 / 3.0 + s2 * (6.0 / 5.0 + s2 * (-4.0 / 7.0 + s2 / 9.0))));
}

float wallGradient(float delta) {
  const float u = 1.0 - clamp(abs(delta) / uH, 0.0, 1.0), u4 = u * u * u * u;
  return 30.0 / uH * (u4 / 4.0 - u4 * u / 5.0);
}

uniform vec4 uEdgeTable[73];  // Q(a, b) at a, b = i/16, entry [i + 17 j] (289 floats, 4 per vec4)

float edgeEntry(int i, int j) {
  const int k = i + 17 * j;
  return uEdgeTable[k >> 2][k & 3];
}

// (Q, ∂Q/∂a, ∂Q/∂b): the quarter space two walls share, a and b their distances in units of h.
vec3 edgeDensity(float a, float b) {
  const float x = clamp(a, 0.0, 1.0) * 16.0, y = clamp(b, 0.0, 1.0) * 16.0;
  const int i = min(int(x), 15), j = min(int(y), 15);
  const float fx = x - float(i), fy = y - float(j);
  const float q00 = edgeEntry(i, j), q10 = edgeEntry(i + 1, j), q01 = edgeEntry(i, j + 1), q11 = edgeEntry(i + 1, j + 1);
  const float lo = q00 + (q10 - q00) * fx, hi = q01 + (q11 - q01) * fx;
  return vec3(lo + (hi - lo) * fy, 16.0 * ((q10 - q00) + ((q11 - q01) - (q10 - q00)) * fy), 16.0 * (hi - lo));
}

#endif
