#version 430 core
// Height bounds for the 3D view's ray caster: min and max height (m) of each tile of
// RIPPLES_VIEW_TILE^2 dual cells (a dual cell spans four cell centres, the bilinear patch that
// surfaceZ() interpolates; bilinear values stay within the corners' range), and of the whole
// grid (atomics on order-preserving bits, which the caller resets to "empty" first).
// Dual cell k covers cell centres k-1 .. k along each axis, k = 0 .. size (edge cells repeat).
#include "render/ripples/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
#include "render/ripples/surface.glsl"
#include "common/ordered_float.glsl"

layout(std430, binding = RIPPLES_VIEW_TILES) writeonly buffer Tiles { vec2 tiles[]; };
layout(std430, binding = RIPPLES_VIEW_RANGE) buffer Range { uint range[2]; };
uniform ivec2 uTiles;  // tiles along x and y

shared vec2 sBounds[64];

void main() {
  const ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
  vec2 bounds = vec2(3.4e38, -3.4e38);
  if (all(lessThan(tile, uTiles))) {
    const ivec2 first = tile * RIPPLES_VIEW_TILE - 1;
    for (int y = 0; y <= RIPPLES_VIEW_TILE; ++y)
      for (int x = 0; x <= RIPPLES_VIEW_TILE; ++x) {
        const float h = heightAt(first + ivec2(x, y));
        bounds = vec2(min(bounds.x, h), max(bounds.y, h));
      }
    tiles[tile.y * uTiles.x + tile.x] = bounds;
  }
  const uint i = gl_LocalInvocationIndex;
  sBounds[i] = bounds;
  barrier();
  for (uint stride = 32u; stride > 0u; stride >>= 1) {
    if (i < stride) sBounds[i] = vec2(min(sBounds[i].x, sBounds[i + stride].x), max(sBounds[i].y, sBounds[i + stride].y));
    barrier();
  }
  if (i == 0u) {
    atomicMin(range[0], orderedBits(sBounds[0].x));
    atomicMax(range[1], orderedBits(sBounds[0].y));
  }
}
