#version 430 core
// Advances particle life from the force pass's accelerations a (mass 1). One kernel, three uses:
//   EULER (the article's symplectic Euler), after the forces at p:
//     v = (v + a·dt + push)·exp(-friction·dt); p += v·dt
//   velocity Verlet, a_prev kept in vel.zw:
//     VERLET_DRIFT, before the grid pass:  p += v·dt + a_prev/2·dt^2
//     VERLET_KICK, after the forces at the new p:  v = (v + (a_prev + a)/2·dt + push)·exp(-friction·dt)
//   STORE_ACCEL: vel.zw = a only (the Verlet start: the forces at the initial positions).
// The friction factor is exact for any dt: with no forces |v| decays as exp(-friction·t).
// push is the mouse brush: uPushVelocity·exp(-|p - uPushPoint|^2 / uPushRadius^2).
// Borders, wherever p moves: LOOPING wraps into the box; otherwise the wall clamps p and
// reflects that velocity component. The state is read and written through life/state.glsl
// (fp32 or packed fp16); everything in between is fp32.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "life/bindings.glsl"
#include "life/box.glsl"
#include "life/state.glsl"

layout(std430, binding = LIFE_POSITIONS) buffer Positions { LifePosition positions[]; };
layout(std430, binding = LIFE_VELOCITIES) buffer Velocities { LifeVelocity velocities[]; };
#if !VERLET_DRIFT
layout(std430, binding = LIFE_ACCELERATIONS) readonly buffer Accelerations { vec2 accelerations[]; };
#endif

uniform uint uCount;
uniform float uDt;           // s
uniform float uDamping;      // exp(-friction·dt)
uniform vec2 uPushPoint;     // world units
uniform vec2 uPushVelocity;  // world units / s added at the brush centre (0: no brush)
uniform float uPushRadius;   // world units

vec2 push(vec2 p) {
  if (uPushVelocity == vec2(0.0)) return vec2(0.0);
  const vec2 r = boxDelta(uPushPoint, p);
  return uPushVelocity * exp(-dot(r, r) / (uPushRadius * uPushRadius));
}

void keepInBox(inout vec4 p, inout vec4 v) {
  const vec2 half_ = 0.5 * uBoxSize;
#if LOOPING
  p.xy -= uBoxSize * floor((p.xy + half_) / uBoxSize);  // rounding may land on +half_: the grid clamps it
#else
  for (int k = 0; k < 2; ++k) {
    if (p[k] < -half_[k]) {
      p[k] = -half_[k];
      v[k] = -v[k];
    }
    if (p[k] > half_[k]) {
      p[k] = half_[k];
      v[k] = -v[k];
    }
  }
#endif
}

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  vec4 p = unpackPosition(positions[i]);
  vec4 v = unpackVelocity(velocities[i]);
#if STORE_ACCEL
  v.zw = accelerations[i];
#elif VERLET_DRIFT
  p.xy += v.xy * uDt + 0.5 * v.zw * uDt * uDt;
  keepInBox(p, v);
  positions[i] = packPosition(p);
#elif VERLET_KICK
  const vec2 a = accelerations[i];
  v.xy = (v.xy + 0.5 * (v.zw + a) * uDt + push(p.xy)) * uDamping;
  v.zw = a;
#else
  const vec2 a = accelerations[i];
  v.xy = (v.xy + a * uDt + push(p.xy)) * uDamping;
  v.zw = a;
  p.xy += v.xy * uDt;
  keepInBox(p, v);
  positions[i] = packPosition(p);
#endif
  velocities[i] = packVelocity(v);
}
