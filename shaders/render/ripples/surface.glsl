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

float heightBilinear(vec2 uv) {
  const vec2 g = uv * vec2(uSize) - 0.5;
  const ivec2 c = ivec2(floor(g));
  const vec2 f = g - vec2(c);
  return mix(mix(heightAt(c), heightAt(c + ivec2(1, 0)), f.x), mix(heightAt(c + ivec2(0, 1)), heightAt(c + ivec2(1, 1)), f.x),
             f.y);
}

vec2 slopeBilinear(vec2 uv) {
  const vec2 g = uv * vec2(uSize) - 0.5;
  const ivec2 c = ivec2(floor(g));
  const vec2 f = g - vec2(c);
  return mix(mix(slopeAt(c), slopeAt(c + ivec2(1, 0)), f.x), mix(slopeAt(c + ivec2(0, 1)), slopeAt(c + ivec2(1, 1)), f.x),
             f.y);
}

#endif
