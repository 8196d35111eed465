#version 430 core
// Depth-aware separable Gaussian blur of the G-buffer (one axis per dispatch, AXIS 0 = x, 1 = y).
// A work group filters one run of a row (or column): it loads the run plus an apron of APRON
// texels on each side into shared memory once, then every output texel filters from there.
// The kernel radius follows the on-screen ball size at that pixel (scale x projected radius,
// sigma = radius / 2, at most APRON); the kernel stops at empty texels and at depth steps between
// neighbours above the threshold, so silhouettes and layers stay sharp. All four channels are
// blurred: the compose pass takes the water's normals from differences of the smoothed depth (A),
// as in screen-space fluid rendering (van der Laan, Green & Sainz 2009), so the balls' bumps melt
// into one surface.
#include "render/balls_bindings.glsl"

#ifndef AXIS
#define AXIS 0
#endif
#define GROUP 256
#define APRON 16

layout(local_size_x = GROUP) in;

layout(binding = BALLS_VIEW_BLUR_IN) uniform sampler2D uSource;
layout(binding = BALLS_VIEW_BLUR_OUT, rgba32f) writeonly uniform image2D uTarget;

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
  // Both sides are walked outwards. A depth step above the threshold between neighbours ends that
  // side (later taps there count as the centre itself): walking, rather than comparing with the
  // centre, still smooths a surface seen at a grazing angle (centimetres of depth across the
  // kernel, millimetres per texel) while a droplet in front of the pool stays apart. An empty
  // texel on either side ends both: the kernel stays symmetric up to a silhouette, so the surface
  // there is smoothed less but not tilted toward the inside (which streaks it).
  vec4 sum = centre;
  float weights = 1.0;
  float lastA = centre.a, lastB = centre.a;  // depth of the last texel taken on each side, 0 = ended
  for (int i = 1; i <= taps; ++i) {
    const vec4 a = tile[local - i], b = tile[local + i];
    if ((lastA > 0.0 && a.a <= 0.0) || (lastB > 0.0 && b.a <= 0.0)) break;  // a silhouette: end both
    if (lastA > 0.0 && abs(a.a - lastA) >= uDepthThreshold) lastA = 0.0;
    if (lastB > 0.0 && abs(b.a - lastB) >= uDepthThreshold) lastB = 0.0;
    const float w = exp(k * float(i * i));
    sum += w * ((lastA > 0.0 ? a : centre) + (lastB > 0.0 ? b : centre));
    weights += 2.0 * w;
    if (lastA > 0.0) lastA = a.a;
    if (lastB > 0.0) lastB = b.a;
  }
  imageStore(uTarget, texel, sum / weights);
}
