// The box walls of the fluid: each wall's half space at rest density adds Φ(δ) to ρ/ρ0 and
// −G(δ)·n (n into the fluid) to the constraint gradient (fluid/kernels.glsl). The collision
// keeps every particle half a spacing from each wall (clampToWalls after every position change),
// as the balls' radius does: a particle's volume reaches the wall, never into it. (Without it the
// wall's half space would let the first layer sink to the plane: a single particle moving in a
// continuum reads the same density wherever it is, so the density constraint alone cannot hold it.)
#ifndef FLUID_WALLS_GLSL
#define FLUID_WALLS_GLSL

uniform vec3 uWallMin;  // current wall positions, m
uniform vec3 uWallMax;
uniform float uWallScale;  // makes a resting lattice's first layer read ρ0 (src/sim/fluid/rest_lattice.h)

// Σ over the six walls within h: the density (ρ/ρ0) and the gradient of the constraint; less
// the quarter spaces of each pair of walls within h, which the two half spaces both counted.
void wallsDensity(vec3 p, inout float density, inout vec3 gradient) {
  float rho = 0.0;
  vec3 grad = vec3(0.0);
  vec3 near = vec3(2.0 * uH);  // per axis: distance to the nearer wall, and which one (−1 min, +1 max)
  vec3 side = vec3(0.0);
  for (int k = 0; k < 3; ++k) {
    const float below = p[k] - uWallMin[k], above = uWallMax[k] - p[k];
    if (below < uH) {
      rho += wallDensity(below);
      grad[k] -= wallGradient(below);
    }
    if (above < uH) {
      rho += wallDensity(above);
      grad[k] += wallGradient(above);
    }
    near[k] = min(below, above);
    side[k] = below <= above ? -1.0 : 1.0;
  }
  for (int k = 0; k < 2; ++k)
    for (int l = k + 1; l < 3; ++l) {
      if (near[k] >= uH || near[l] >= uH) continue;
      const vec3 q = edgeDensity(near[k] / uH, near[l] / uH);
      rho -= q.x;
      // d/dp of −Q: δ grows with p at a min wall, shrinks at a max wall.
      grad[k] += side[k] * q.y / uH;
      grad[l] += side[l] * q.z / uH;
    }
  density += uWallScale * rho;
  gradient += uWallScale * grad;
}

uniform float uWallInset;  // d / 2, m

vec3 clampToWalls(vec3 p) { return clamp(p, uWallMin + uWallInset, uWallMax - uWallInset); }

// Per axis, the wall nearer p: −1 the one at the minimum, +1 the one at the maximum.
vec3 wallSides(vec3 p) {
  return mix(vec3(1.0), vec3(-1.0), lessThanEqual(p - uWallMin, uWallMax - p));
}

#endif
