// The walk over a ball's pixels, shared by the depth and id passes of the compute raster
// (splat_depth.comp, splat_id.comp; the scheme is in splat.glsl). Include it last: the kernel
// defines before it
//   void splatPixel(ivec2 px, vec3 centre, uint ball)  what the pass does at one covered pixel
//   bool drawsBigBall(uint ball)  BIG 0: whether this thread draws a ball of more than
//                                 SMALL_PIXELS pixels itself (else the big list's groups do)
// BIG 0: one thread per ball; BIG 1: one work group per ball of the big list (an indirect dispatch).
#ifndef BIG
#define BIG 0
#endif
#if BIG
layout(local_size_x = BIG_GROUP) in;
#else
layout(local_size_x = 128) in;
#endif
#include "common/index.glsl"

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
    splatPixel(lo + ivec2(k % box.x, k / box.x), centre, ball);
#else
  if (pixels > SMALL_PIXELS && !drawsBigBall(ball)) return;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) splatPixel(ivec2(x, y), centre, ball);
#endif
}
