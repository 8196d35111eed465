// Reading the ripples state SSBO from render shaders: heights (m) and slopes (m/m), sampled
// bilinearly between cell centres at grid uv in [0,1]^2.
#ifndef RENDER_RIPPLES_SURFACE_GLSL
#define RENDER_RIPPLES_SURFACE_GLSL

#include "ripples/bindings.glsl"

layout(std430, binding = RIPPLES_STATE_IN) readonly buffer State { vec2 state[]; };

uniform ivec2 uSize;      // cells
uniform float uCellSize;  // m

float heightAt(ivec2 p) { return state[clamp(p.y, 0, uSize.y - 1) * uSize.x + clamp(p.x, 0, uSize.x - 1)].x; }

vec2 slopeAt(ivec2 p) {
  return vec2(heightAt(p + ivec2(1, 0)) - heightAt(p - ivec2(1, 0)),
              heightAt(p + ivec2(0, 1)) - heightAt(p - ivec2(0, 1))) / (2.0 * uCellSize);
}

// A bilinear sample at grid uv: the cell c whose centre is the nearest at or below-left of uv,
// and f in [0, 1)^2, how far uv lies from that centre towards the next ones.
struct Bilinear {
  ivec2 c;
  vec2 f;
};

Bilinear bilinear(vec2 uv) {
  const vec2 g = uv * vec2(uSize) - 0.5;
  const ivec2 c = ivec2(floor(g));
  return Bilinear(c, g - vec2(c));
}

float heightBilinear(vec2 uv) {
  const Bilinear s = bilinear(uv);
  const float below = mix(heightAt(s.c), heightAt(s.c + ivec2(1, 0)), s.f.x);
  return mix(below, mix(heightAt(s.c + ivec2(0, 1)), heightAt(s.c + ivec2(1, 1)), s.f.x), s.f.y);
}

vec2 slopeBilinear(vec2 uv) {
  const Bilinear s = bilinear(uv);
  const vec2 below = mix(slopeAt(s.c), slopeAt(s.c + ivec2(1, 0)), s.f.x);
  return mix(below, mix(slopeAt(s.c + ivec2(0, 1)), slopeAt(s.c + ivec2(1, 1)), s.f.x), s.f.y);
}

#endif
