#version 430 core
// Compute raster, pass 3 (see render/balls/splat.glsl), one thread per pixel: the ball whose id
// the id pass left in keys[] is hit again by the pixel's eye ray, and the G-buffer gets what the
// fragment path writes there (normal xy, thickness, view depth; foam; window depth, 1 = empty).
// keys[] and thickness[] are put back to empty for the next frame, so no clear pass is needed.
#include "render/balls/splat.glsl"
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = BALLS_VIEW_VELOCITIES) readonly buffer Velocities { vec4 velocities[]; };
layout(std430, binding = BALLS_VIEW_SPLAT_THICKNESS) buffer Thickness { uint thickness[]; };
layout(binding = BALLS_VIEW_SPLAT_SURFACE, rgba32f) writeonly uniform image2D uSurface;
layout(binding = BALLS_VIEW_SPLAT_FOAM, r16f) writeonly uniform image2D uFoam;
layout(binding = BALLS_VIEW_SPLAT_DEPTH, r32f) writeonly uniform image2D uDepth;
uniform float uThicknessUnit;  // m per unit of thickness[]
uniform int uHasFoam;          // 0: the velocity buffer is not bound

void main() {
  const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, uSize))) return;
  const uint i = pixelIndex(px);
  const uint key = keys[i];
  const float thick = float(thickness[i]) * uThicknessUnit;
  keys[i] = kEmpty;
  thickness[i] = 0u;
  SplatHit hit;
  // An untagged key (no ball matched its depth) would be a bug in the passes before: left empty.
  if (key == kEmpty || key < kTag || !splatHit(px, ballCentre(key & ~kTag), hit)) {
    imageStore(uSurface, px, vec4(0.0, 0.0, thick, 0.0));
    imageStore(uFoam, px, vec4(0.0));
    imageStore(uDepth, px, vec4(1.0));
    return;
  }
  const uint ball = key & ~kTag;
  imageStore(uSurface, px, vec4(hit.normal.xy, thick, hit.depth));
  imageStore(uFoam, px, vec4(uHasFoam != 0 ? velocities[ball].w : 0.0));
  imageStore(uDepth, px, vec4(hit.window));
}
