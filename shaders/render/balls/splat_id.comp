#version 430 core
// Compute raster, pass 2 (see splat.glsl): every ball walks its pixels again and, where its
// window depth is the least one the depth pass left in keys[], writes kTag | its id there. A
// tagged key matches no depth, so of balls at exactly equal depth one id stays. Same split as the
// depth pass (splat_walk.glsl): big balls are the list's, unless the list overflowed; then this
// pass draws them too, which is harmless as writing an id is idempotent.
#include "render/balls/splat.glsl"

void splatPixel(ivec2 px, vec3 centre, uint ball) {
  SplatHit hit;
  if (!splatHit(px, centre, hit)) return;
  const uint i = pixelIndex(px);
  if (keys[i] == floatBitsToUint(hit.window)) keys[i] = kTag | ball;
}

bool drawsBigBall(uint ball) { return bigOverflow != 0u; }

#include "render/balls/splat_walk.glsl"
