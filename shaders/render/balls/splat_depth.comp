#version 430 core
// Compute raster, pass 1 (see splat.glsl): every pixel a ball covers gets the ball's window depth
// by atomicMin into keys[] and, with uThickness on, in front of the scene's meshes, the ball's
// chord added to thickness[] in fixed point (the fragment path's additive thickness pass,
// depth-tested against the scene). BIG 0 hands balls of more than SMALL_PIXELS pixels to the big
// list (splat_walk.glsl).
#include "render/balls/splat.glsl"

layout(std430, binding = BALLS_VIEW_SPLAT_THICKNESS) buffer Thickness { uint thickness[]; };
layout(binding = BALLS_VIEW_SCENE_DEPTH) uniform sampler2D uSceneDepth;  // window depth of the meshes
uniform int uThickness;         // 0: depth only
uniform int uScene;             // 0: no meshes (uSceneDepth is not read)
#include "render/balls/scene_rect.glsl"
uniform float uThicknessUnit;   // m per unit of thickness[]

void splatPixel(ivec2 px, vec3 centre, uint ball) {
  SplatHit hit;
  if (!splatHit(px, centre, hit)) return;
  const uint i = pixelIndex(px);
  const uint key = floatBitsToUint(hit.window);
  if (key < keys[i]) atomicMin(keys[i], key);  // a stale read only costs a needless atomic
  if (uThickness != 0 && (uScene == 0 || !inSceneRect(px) || hit.window < texelFetch(uSceneDepth, px, 0).r))
    atomicAdd(thickness[i], uint(hit.chord / uThicknessUnit + 0.5));
}

// Into the list when it has room (a failed claim is given back, so the count ends at the entries
// written); else this thread draws the ball itself and the id pass is told to.
bool drawsBigBall(uint ball) {
  const uint slot = atomicAdd(bigGroups, 1u);
  if (slot < uBigCapacity) {
    bigList[slot] = ball;
    return false;
  }
  atomicAdd(bigGroups, 0xFFFFFFFFu);
  bigOverflow = 1u;
  return true;
}

#include "render/balls/splat_walk.glsl"
