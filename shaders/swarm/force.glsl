// The swarm force law (particles-webgpu seed), in world units:
//   a(x, t) = gravity + sum_k s_k d_k / (|d_k|^2 + eps),  d_k = attractor_k(t) - x
// a 1/r force (2D log potential): a circular orbit of any radius around s has speed sqrt(s).
// Attractors are given at three times of the step: level 0 = t, 1 = t + dt/2, 2 = t + dt.
#ifndef SWARM_FORCE_GLSL
#define SWARM_FORCE_GLSL

uniform vec4 uAttractors[3 * SWARM_MAX_ATTRACTORS];  // xy: world position, z: strength (units^2/s^2)
uniform int uAttractorCount;
uniform vec2 uGravity;   // world units/s^2
uniform float uEpsilon;  // world units^2

vec2 swarmForce(vec2 x, int level) {
  vec2 f = uGravity;
  for (int k = 0; k < uAttractorCount; ++k) {
    const vec4 a = uAttractors[level * SWARM_MAX_ATTRACTORS + k];
    const vec2 d = a.xy - x;
    // max(): a particle exactly on an attractor with eps = 0 gets no force instead of NaN.
    f += a.z * d / max(dot(d, d) + uEpsilon, 1e-30);
  }
  return f;
}

#endif
