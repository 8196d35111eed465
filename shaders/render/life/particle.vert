#version 430 core
// One quad (two triangles, 6 vertices) per particle without vertex buffers: particle =
// gl_VertexID / 6, corner = gl_VertexID % 6. Positions and species colours come straight from
// the life model's SSBOs. vOffset is the corner offset from the particle in world units.
#include "life/bindings.glsl"
#include "life/state.glsl"

layout(std430, binding = LIFE_POSITIONS) readonly buffer Positions { LifePosition positions[]; };
layout(std430, binding = LIFE_SPECIES_COLORS) readonly buffer Colors { vec4 colors[]; };

uniform vec2 uCentre;     // camera centre (world units)
uniform vec2 uExtent;     // half the visible width and height (world units)
uniform float uHalfSize;  // quad half-size (world units)

out vec2 vOffset;
flat out vec3 vColor;

const vec2 kCorners[6] = vec2[6](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
  const vec4 p = unpackPosition(positions[gl_VertexID / 6]);
  vOffset = kCorners[gl_VertexID % 6] * uHalfSize;
  vColor = colors[int(p.w)].rgb;
  gl_Position = vec4((p.xy + vOffset - uCentre) / uExtent, 0.0, 1.0);
}
