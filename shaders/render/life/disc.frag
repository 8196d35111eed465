#version 430 core
// Disc of radius uRadius world units with an analytic 1-pixel antialiased edge:
// alpha = clamp(R' - |o| + 0.5, 0, 1) in pixels, o the pixel centre's offset. A linear ramp of
// one pixel centred on R' covers pi·(R'^2 + 1/12) pixels on average, so R' = sqrt(R^2 - 1/12)
// makes the disc's total brightness pi·R^2 — the same as the sub-pixel splats
// (point.frag) the view switches to below one pixel per unit, so zooming across that
// threshold does not change brightness. Used when the radius covers at least one pixel.
#include "render/life/coverage.glsl"

void main() {
  const float r = uRadius * uPixelsPerUnit;  // pixels
  const float edge = sqrt(max(r * r - 1.0 / 12.0, 0.0));
  writeCoverage(clamp(edge - length(vOffset) * uPixelsPerUnit + 0.5, 0.0, 1.0));
}
