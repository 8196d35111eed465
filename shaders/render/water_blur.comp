#version 430 core
// Depth-aware separable Gaussian blur of the G-buffer (one axis per dispatch, AXIS 0 = x, 1 = y).
// A work group filters one run of a row (or column): it loads the run plus an apron of APRON
// texels on each side into shared memory once, then every output texel filters from there.
// The kernel radius follows the on-screen ball size at that pixel (scale x projected radius,
// sigma = radius / 2, at most APRON); neighbours whose view depth differs from the centre's by
// more than the threshold, or that are empty, are left out and the weights renormalised, so
// silhouettes and depth steps stay sharp. RGB (normal xy, thickness) are blurred, A (depth) kept.
#include "render/balls_bindings.glsl"

#ifndef AXIS
#define AXIS 0
#endif
#define GROUP 256
#define APRON 16

layout(local_size_x = GROUP) in;

layout(binding = BALLS_VIEW_BLUR_IN) uniform sampler2D uSource;
layout(binding = BALLS_VIEW_BLUR_OUT, rgba16f) writeonly uniform image2D uTarget;

uniform float uPixelRadius;    // px: kernel radius of a ball at view depth 1 m (scale x r x focal px)
uniform float uDepthThreshold; // m

shared vec4 tile[GROUP];

void main() {
  const ivec2 size = textureSize(uSource, 0);
  const int lineLength = AXIS == 0 ? size.x : size.y;
  const int useful = GROUP - 2 * APRON;
  const int local = int(gl_LocalInvocationID.x);
  const int along = int(gl_WorkGroupID.x) * useful + local - APRON;  // position on the line
  const int line = int(gl_WorkGroupID.y);
  const ivec2 texel = AXIS == 0 ? ivec2(along, line) : ivec2(line, along);
  const bool inside = along >= 0 && along < lineLength;
  tile[local] = inside ? texelFetch(uSource, texel, 0) : vec4(0.0);  // A = 0: empty, never used
  barrier();

  if (!inside || local < APRON || local >= GROUP - APRON) return;
  const vec4 centre = tile[local];
  if (centre.a <= 0.0) {
    imageStore(uTarget, texel, centre);
    return;
  }
  const float radius = min(uPixelRadius / centre.a, float(APRON));
  const int taps = int(radius);
  const float sigma = max(0.5 * radius, 0.5);
  const float k = -0.5 / (sigma * sigma);
  vec3 sum = centre.rgb;
  float weights = 1.0;
  for (int i = 1; i <= taps; ++i) {
    const float w = exp(k * float(i * i));
    const vec4 a = tile[local - i], b = tile[local + i];
    if (a.a > 0.0 && abs(a.a - centre.a) < uDepthThreshold) { sum += w * a.rgb; weights += w; }
    if (b.a > 0.0 && abs(b.a - centre.a) < uDepthThreshold) { sum += w * b.rgb; weights += w; }
  }
  imageStore(uTarget, texel, vec4(sum / weights, centre.a));
}
