#version 430 core
// Sub-pixel particles (radius under a pixel): the pixel's exact coverage by the particle's
// bounding square of side 2·radius, scaled by pi/4 to the disc's area. Per axis, d = overlap of
// the pixel [o - 1/2, o + 1/2] (pixels) with [-r, r]; alpha = (pi/4)·d.x·d.y. Summed over the
// pixels it is pi·r^2 whatever the sub-pixel position: a particle keeps its brightness as it
// moves or as the zoom changes, instead of flickering in and out of pixel centres.
#include "render/life/coverage.glsl"

void main() {
  const vec2 o = vOffset * uPixelsPerUnit;  // pixels
  const float r = uRadius * uPixelsPerUnit;
  const vec2 d = max(min(o + 0.5, vec2(r)) - max(o - 0.5, vec2(-r)), vec2(0.0));
  writeCoverage(0.78539816 * d.x * d.y);
}
