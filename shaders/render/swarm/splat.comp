#version 430 core
// Compute splatting of 1-px swarm points: each particle adds itself to its pixel's counters
// with atomics, (count, r, g, b) per pixel, colours in units of 1/255. This bypasses the
// raster pipeline (point setup and blending), which on compute-first GPUs is the bottleneck
// for tens of millions of points; splat_resolve.frag turns the counters into colours.
// Pixel (0,0) is bottom-left, as gl_FragCoord counts.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "swarm/bindings.glsl"
#include "swarm/state.glsl"
#include "render/swarm/color.glsl"

layout(std430, binding = SWARM_COLOR_BINDING) readonly buffer Colors { uint colors[]; };
layout(std430, binding = SWARM_SPLAT_BINDING) buffer Splat { uint splat[]; };  // 4 per pixel
uniform uint uCount;
uniform ivec2 uSize;     // target pixels
uniform int uColorMode;  // 0: single colour (count only), 1: per-particle colour, 2: velocity hue

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  vec2 pos, vel;
  loadParticle(i, pos, vel);
  const ivec2 px = ivec2(floor((0.5 * pos + 0.5) * vec2(uSize)));
  if (any(lessThan(px, ivec2(0))) || any(greaterThanEqual(px, uSize))) return;
  const uint base = 4u * uint(px.y * uSize.x + px.x);
  atomicAdd(splat[base], 1u);
  if (uColorMode == 0) return;
  const vec3 c = uColorMode == 1 ? unpackUnorm4x8(colors[i]).rgb : hueRamp(0.5 + 0.5 * atan(vel.y, vel.x) / 3.14159265);
  const uvec3 c8 = uvec3(round(c * 255.0));
  atomicAdd(splat[base + 1u], c8.r);
  atomicAdd(splat[base + 2u], c8.g);
  atomicAdd(splat[base + 3u], c8.b);
}
