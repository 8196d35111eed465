// The particle-life state, one slot per particle in two arrays (src/sim/life/life.h), stored in
// one of two precisions and always computed in fp32:
//   LIFE_FP16 = 0: positions vec4 (x, y, 0, species), velocities vec4 (vx, vy, ax, ay): 32 B
//   LIFE_FP16 = 1: positions uvec2 (packHalf2x16(x, y), species), velocities uvec2
//                  (packHalf2x16(vx, vy), packHalf2x16(ax, ay)): 16 B, rounded to 11 bits
// Shaders declare the arrays with LifePosition / LifeVelocity elements and go through these.
#ifndef LIFE_STATE_GLSL
#define LIFE_STATE_GLSL

#ifndef LIFE_FP16
#define LIFE_FP16 0
#endif

#if LIFE_FP16
#define LifePosition uvec2
#define LifeVelocity uvec2
vec4 unpackPosition(uvec2 s) { return vec4(unpackHalf2x16(s.x), 0.0, float(s.y)); }
uvec2 packPosition(vec4 p) { return uvec2(packHalf2x16(p.xy), uint(p.w)); }
vec4 unpackVelocity(uvec2 s) { return vec4(unpackHalf2x16(s.x), unpackHalf2x16(s.y)); }
uvec2 packVelocity(vec4 v) { return uvec2(packHalf2x16(v.xy), packHalf2x16(v.zw)); }
#else
#define LifePosition vec4
#define LifeVelocity vec4
vec4 unpackPosition(vec4 s) { return s; }
vec4 packPosition(vec4 p) { return p; }
vec4 unpackVelocity(vec4 s) { return s; }
vec4 packVelocity(vec4 v) { return v; }
#endif

#endif
