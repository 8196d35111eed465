#version 430 core
// The narrow-range filter (Truong & Yuksel 2018, "A Narrow-Range Filter for Screen-Space Fluid
// Rendering") in water_blur.comp's frame, for the A/B in docs/ACCURACY.md ("The water's rendered
// surface"): copy it over water_blur.comp in a TIDEPOOL_SHADER_DIR copy. Per side, a tap behind
// the side's range (or empty) counts as the centre pushed back one ball radius, a tap in front of
// it drops itself and its mirror tap, and a tap inside widens the range; the value is the
// weighted mean. The ball radius is read as uDepthThreshold / 12 (the default depth_threshold).
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
  // Narrow-range filter (Truong & Yuksel 2018), one axis.
  const float T = uDepthThreshold, r = uDepthThreshold / 12.0;
  const vec4 clamped = vec4(centre.rgb, centre.a + r);
  float hiA = centre.a + T, loA = centre.a - T, hiB = hiA, loB = loA;
  vec4 sum = centre;
  float wsum = 1.0;
  for (int i = 1; i <= taps; ++i) {
    float wa = exp(k * float(i * i)), wb = wa;
    vec4 a = tile[local - i], b = tile[local + i];
    bool dropA = false, dropB = false;
    if (a.a <= 0.0 || a.a > hiA) a = clamped;
    else if (a.a < loA) dropA = true;
    else { hiA = max(hiA, a.a + T); loA = min(loA, a.a - T); }
    if (b.a <= 0.0 || b.a > hiB) b = clamped;
    else if (b.a < loB) dropB = true;
    else { hiB = max(hiB, b.a + T); loB = min(loB, b.a - T); }
    if (dropA || dropB) wa = wb = 0.0;
    sum += wa * a + wb * b;
    wsum += wa + wb;
  }
  imageStore(uTarget, texel, sum / wsum);
}
