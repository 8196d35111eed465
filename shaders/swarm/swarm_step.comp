#version 430 core
// One integrator step of the swarm (one particle per invocation, updated in place).
// INTEGRATOR: 0 explicit Euler, 1 symplectic Euler (the seed's), 2 velocity Verlet, 3 classical RK4.
// The state is read and written once: the step is bound by memory bandwidth, so RK4's four
// force evaluations cost little. Physics in world units x = pos * uAspect; friction is applied
// as the exact decay exp(-friction dt) after the conservative step (operator splitting).
#include "swarm/bindings.glsl"
layout(local_size_x = SWARM_WORK_GROUP) in;
#include "common/index.glsl"
#include "swarm/state.glsl"
#include "swarm/force.glsl"

uniform uint uCount;
uniform float uDt;       // simulated seconds
uniform float uDamping;  // exp(-friction * dt)
uniform vec2 uAspect;    // (width / height, 1)
uniform int uBounce;     // 1: mirror walls at NDC +-1; 0: free flight

// Perfect reflection at the walls, per axis; the clamp keeps a particle that crossed more than
// a whole box width in one step inside anyway.
void bounce(inout vec2 p, inout vec2 v) {
  for (int a = 0; a < 2; ++a) {
    if (p[a] < -1.0) { p[a] = -2.0 - p[a]; v[a] = -v[a]; }
    if (p[a] > 1.0) { p[a] = 2.0 - p[a]; v[a] = -v[a]; }
  }
  p = clamp(p, -1.0, 1.0);
}

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  vec2 p, v;
  loadParticle(i, p, v);
  vec2 x = p * uAspect;
  const float h = uDt;
#if INTEGRATOR == 0
  const vec2 a = swarmForce(x, 0);
  x += h * v;
  v += h * a;
#elif INTEGRATOR == 1
  v += h * swarmForce(x, 0);
  x += h * v;
#elif INTEGRATOR == 2
  const vec2 vHalf = v + 0.5 * h * swarmForce(x, 0);
  x += h * vHalf;
  v = vHalf + 0.5 * h * swarmForce(x, 2);
#elif INTEGRATOR == 3
  const vec2 k1x = v, k1v = swarmForce(x, 0);
  const vec2 k2x = v + 0.5 * h * k1v, k2v = swarmForce(x + 0.5 * h * k1x, 1);
  const vec2 k3x = v + 0.5 * h * k2v, k3v = swarmForce(x + 0.5 * h * k2x, 1);
  const vec2 k4x = v + h * k3v, k4v = swarmForce(x + h * k3x, 2);
  x += (h / 6.0) * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
  v += (h / 6.0) * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
#else
#error "INTEGRATOR must be 0..3"
#endif
  v *= uDamping;
  p = x / uAspect;
  if (uBounce != 0) bounce(p, v);
  storeParticle(i, p, v);
}
