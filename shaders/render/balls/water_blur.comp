#version 430 core
// Depth-aware separable Gaussian blur of the G-buffer (one axis per dispatch, AXIS 0 = x, 1 = y).
// A work group filters one run of a row (or column): it loads the run plus an apron of APRON
// texels on each side into shared memory once, then every output texel filters from there.
// The kernel radius follows the on-screen ball size at that pixel (scale x projected radius,
// sigma = radius / 2, at most APRON); each side of the kernel stops at an empty texel or a depth
// step between neighbours above the threshold, so silhouettes and layers stay sharp, and a
// weighted line fit (not the mean) keeps one-sided kernels from tilting the surface. All four channels are
// blurred: the compose pass takes the water's normals from differences of the smoothed depth (A),
// as in screen-space fluid rendering (van der Laan, Green & Sainz 2009), so the balls' bumps melt
// into one surface.
#include "render/balls/bindings.glsl"

#ifndef AXIS
#define AXIS 0
#endif
#define GROUP 256
#define APRON 16

layout(local_size_x = GROUP) in;

layout(binding = BALLS_VIEW_BLUR_IN) uniform sampler2D uSource;
layout(binding = BALLS_VIEW_BLUR_OUT, rgba32f) writeonly uniform image2D uTarget;

uniform float uPixelRadius;    // px: kernel radius of a ball at view depth 1 m (scale x r x focal px)
uniform int uPerspective;      // 1: the radius shrinks as 1 / depth; 0 (orthographic): uPixelRadius everywhere
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
  const float radius = min(uPerspective != 0 ? uPixelRadius / centre.a : uPixelRadius, float(APRON));
  const int taps = int(radius);
  const float sigma = max(0.5 * radius, 0.5);
  const float k = -0.5 / (sigma * sigma);
  // Both sides are walked outwards; a side ends at an empty texel (a silhouette) or at a depth
  // step above the threshold between neighbours (walking, rather than comparing with the centre,
  // still smooths a surface seen at a grazing angle: centimetres of depth across the kernel,
  // millimetres per texel, while a droplet in front of the pool stays apart). What is left is
  // often one-sided, so the value is not the weighted mean but the weighted least-squares line
  // through the taps, read at the centre: the mean of a one-sided kernel on a sloping surface
  // tilts it toward the inside, while the line keeps a plane where it is. This lets the kernel
  // reach into the surface below the water's top edge, whose balls a kernel cut short at the
  // silhouette left as a row of unsmoothed bumps (a picket fence of normals). With S_j the
  // weighted sums of x^j and T_j those of x^j v: v(0) = (S2 T0 - S1 T1) / (S0 S2 - S1^2).
  float s0 = 1.0, s1 = 0.0, s2 = 0.0;
  vec4 t0 = centre, t1 = vec4(0.0);
  float lastA = centre.a, lastB = centre.a;  // depth of the last texel taken on each side, 0 = ended
  for (int i = 1; i <= taps && (lastA > 0.0 || lastB > 0.0); ++i) {
    const float w = exp(k * float(i * i)), x = float(i);
    const vec4 a = tile[local - i], b = tile[local + i];
    if (lastA > 0.0 && a.a > 0.0 && abs(a.a - lastA) >= uDepthThreshold) lastA = 0.0;
    if (lastB > 0.0 && b.a > 0.0 && abs(b.a - lastB) >= uDepthThreshold) lastB = 0.0;
    if (lastA > 0.0 && a.a > 0.0) {
      s0 += w, s1 -= w * x, s2 += w * x * x;
      t0 += w * a, t1 -= w * x * a;
      lastA = a.a;
    }
    if (lastB > 0.0 && b.a > 0.0) {
      s0 += w, s1 += w * x, s2 += w * x * x;
      t0 += w * b, t1 += w * x * b;
      lastB = b.a;
    }
  }
  const float det = s0 * s2 - s1 * s1;  // 0 when only the centre was taken
  imageStore(uTarget, texel, det > 1e-6 * s0 * s2 ? (s2 * t0 - s1 * t1) / det : t0 / s0);
}
