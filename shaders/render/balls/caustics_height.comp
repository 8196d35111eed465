#version 430 core
// Caustics, first pass: the water's top over the floor. One invocation per ball adds its top (its
// centre's height above the floor plus its radius) to the floor cell under it, keeping the
// highest (atomicMax on the float's bits: positive floats order as their bits do), so that the
// result is the same whatever the order. With COVER the balls are an obstacle's: each marks its
// cell covered (kCovered, above every float's bits), and the water's top there is not used (the
// floor under an obstacle is lit as dry floor). caustics_light.comp clears the cells.
#include "render/balls/bindings.glsl"
#include "render/balls/caustics_cells.glsl"
layout(local_size_x = 256) in;
#include "common/index.glsl"

layout(std430, binding = BALLS_VIEW_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = BALLS_VIEW_CAUSTICS_TOPS) buffer Tops { uint tops[]; };  // float bits, 0: dry

uniform uint uCount;
uniform mat4 uBoxFromBalls;  // the balls' frame -> the domain box's (z up, the floor at uFloorMin.z)
uniform vec3 uFloorMin;      // m, box frame
uniform vec2 uCellSize;      // m
uniform ivec2 uCells;
uniform float uRadius;       // m

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  const vec3 p = (uBoxFromBalls * vec4(positions[i].xyz, 1.0)).xyz;
  const ivec2 cell = ivec2(floor((p.xy - uFloorMin.xy) / uCellSize));
  const float top = p.z + uRadius - uFloorMin.z;
  if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, uCells)) || !(top > 0.0)) return;
#if COVER
  atomicMax(tops[cell.y * uCells.x + cell.x], kCovered);
#else
  atomicMax(tops[cell.y * uCells.x + cell.x], floatBitsToUint(top));
#endif
}
