#version 430 core
// Compute raster, pass 1 (see render/balls/splat.glsl): every pixel a ball covers gets the ball's
// window depth by atomicMin into keys[] and, with uThickness on, in front of the scene's meshes,
// the ball's chord added to thickness[] in fixed point (the fragment path's additive thickness
// pass, depth-tested against the scene). BIG 0: one thread per ball, which hands balls of more
// than SMALL_PIXELS pixels to the big list; BIG 1: one work group per listed ball.
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

layout(std430, binding = BALLS_VIEW_SPLAT_THICKNESS) buffer Thickness { uint thickness[]; };
layout(binding = BALLS_VIEW_SCENE_DEPTH) uniform sampler2D uSceneDepth;  // window depth of the meshes
uniform int uThickness;         // 0: depth only
uniform int uScene;             // 0: no meshes (uSceneDepth is not read)
#include "render/balls/scene_rect.glsl"
uniform float uThicknessUnit;   // m per unit of thickness[]

void splatPixel(ivec2 px, vec3 centre) {
  SplatHit hit;
  if (!splatHit(px, centre, hit)) return;
  const uint i = pixelIndex(px);
  const uint key = floatBitsToUint(hit.window);
  if (key < keys[i]) atomicMin(keys[i], key);  // a stale read only costs a needless atomic
  if (uThickness != 0 && (uScene == 0 || !inSceneRect(px) || hit.window < texelFetch(uSceneDepth, px, 0).r))
    atomicAdd(thickness[i], uint(hit.chord / uThicknessUnit + 0.5));
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
    splatPixel(lo + ivec2(k % box.x, k / box.x), centre);
#else
  if (pixels > SMALL_PIXELS) {
    // Into the list when it has room (a failed claim is given back, so the count ends at the
    // entries written); else this thread draws the ball itself and the id pass is told to.
    const uint slot = atomicAdd(bigGroups, 1u);
    if (slot < uBigCapacity) {
      bigList[slot] = ball;
      return;
    }
    atomicAdd(bigGroups, 0xFFFFFFFFu);
    bigOverflow = 1u;
  }
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) splatPixel(ivec2(x, y), centre);
#endif
}
