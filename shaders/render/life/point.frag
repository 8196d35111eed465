#version 430 core
// Sub-pixel particles (radius under a pixel): the pixel's exact coverage by the particle's
// bounding square of side 2·radius, scaled by pi/4 to the disc's area. Per axis, d = overlap of
// the pixel [o - 1/2, o + 1/2] (pixels) with [-r, r]; alpha = (pi/4)·d.x·d.y. Summed over the
// pixels it is pi·r^2 whatever the sub-pixel position: a particle keeps its brightness as it
// moves or as the zoom changes, instead of flickering in and out of pixel centres.
in vec2 vOffset;
flat in vec3 vColor;
uniform float uRadius;
uniform float uPixelsPerUnit;
uniform float uExposure;
out vec4 fragColor;

void main() {
  const vec2 o = vOffset * uPixelsPerUnit;  // pixels
  const float r = uRadius * uPixelsPerUnit;
  const vec2 d = max(min(o + 0.5, vec2(r)) - max(o - 0.5, vec2(-r)), vec2(0.0));
  const float alpha = 0.78539816 * d.x * d.y;
  if (alpha <= 0.0) discard;
  fragColor = vec4(vColor * uExposure, alpha);
}
