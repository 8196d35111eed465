// Contact laws between balls of radius r (and with fixed bodies and walls), selected at compile
// time. Each returns the acceleration of ball i (m/s^2) for one contact:
//   n       unit normal from the other body to i;  overlap  δ = contact distance − distance > 0
//   relVel  v_i − v_other;  massRatio  m_eff / m_i (1/2 for two equal balls, 1 for a fixed body)
//   share   the seed's w_other/(w_i + w_other): 1/2 between balls, 1 against a fixed body
//
// CONTACT_PENALTY       water-webgpu: Δv = factor · share · δ per step (walls: 2 · δ)
// CONTACT_SPRING        linear spring-dashpot (DEM): a = (m_eff/m_i)·(k1·δ − g1·v_n)·n, with
//                       k1 = (π² + ln²e)/t_c², g1 = −2 ln e / t_c per unit effective mass, so every
//                       contact lasts t_c and restitutes e; optional Coulomb friction
// CONTACT_CUDA          NVIDIA CUDA "particles": Δv = spring·δ·n − damping·relVel − shear·v_t per step
#ifndef BALLS_CONTACT_GLSL
#define BALLS_CONTACT_GLSL

uniform float uDt;             // s
uniform float uPenaltyFactor;  // seed: 0.96
uniform float uSpringK1;       // 1/s^2 per unit effective mass
uniform float uDashpotG1;      // 1/s per unit effective mass
uniform float uFriction;       // Coulomb coefficient
uniform float uCudaSpring;
uniform float uCudaDamping;
uniform float uCudaShear;

vec3 contactAccel(vec3 n, float overlap, vec3 relVel, float massRatio, float share) {
#if defined(CONTACT_PENALTY)
  return uPenaltyFactor * share * overlap / uDt * n;
#elif defined(CONTACT_CUDA)
  const vec3 tangential = relVel - dot(relVel, n) * n;
  return (uCudaSpring * overlap * n - uCudaDamping * relVel - uCudaShear * tangential) / uDt;
#else
  const float vn = dot(relVel, n);
  const float normal = massRatio * (uSpringK1 * overlap - uDashpotG1 * vn);
  vec3 a = normal * n;
  if (uFriction > 0.0) {
    const vec3 vt = relVel - vn * n;
    const float speed = length(vt);
    if (speed > 1e-12) a -= min(uFriction * abs(normal), massRatio * uDashpotG1 * speed) * (vt / speed);
  }
  return a;
#endif
}

// A wall is a fixed body: same law, except the seed's walls push with 2 · δ.
vec3 wallAccel(vec3 n, float overlap, vec3 relVel) {
#if defined(CONTACT_PENALTY)
  return 2.0 * overlap / uDt * n;
#elif defined(CONTACT_CUDA)
  return vec3(0.0);  // the CUDA sample clamps at the walls instead (confineToDomain, walls.glsl)
#else
  return contactAccel(n, overlap, relVel, 1.0, 1.0);
#endif
}

#endif
