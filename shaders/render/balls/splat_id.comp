#version 430 core
// Compute raster, pass 2 (see render/balls/splat.glsl): every ball walks its pixels again and,
// where its window depth is the least one the depth pass left in keys[], writes kTag | its id
// there. A tagged key matches no depth, so of balls at exactly equal depth one id stays. Same
// split as the depth pass: BIG 0 one thread per ball (big balls are the list's, unless the list
// overflowed: then this pass draws them too, which is harmless as writing an id is idempotent),
// BIG 1 one work group per listed ball.
#ifndef BIG
#define BIG 0
#endif
#include "render/balls/splat.glsl"
#if BIG
layout(local_size_x = BIG_GROUP) in;
#else
layout(local_size_x = 128) in;
#endif
#include "common/index.glsl"

void idPixel(ivec2 px, vec3 centre, uint ball) {
  SplatHit hit;
  if (!splatHit(px, centre, hit)) return;
  const uint i = pixelIndex(px);
  if (keys[i] == floatBitsToUint(hit.window)) keys[i] = kTag | ball;
}

void main() {
#if BIG
  const uint ball = bigList[gl_WorkGroupID.x];
#else
  const uint ball = globalIndex();
  if (ball >= uCount) return;
#endif
  const vec3 centre = ballCentre(ball);
  ivec2 lo, hi;
  if (!footprint(centre, lo, hi)) return;
  const ivec2 box = hi - lo + 1;
  const int pixels = box.x * box.y;
#if BIG
  for (int k = int(gl_LocalInvocationID.x); k < pixels; k += BIG_GROUP)
    idPixel(lo + ivec2(k % box.x, k / box.x), centre, ball);
#else
  if (pixels > SMALL_PIXELS && bigOverflow == 0u) return;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) idPixel(ivec2(x, y), centre, ball);
#endif
}
