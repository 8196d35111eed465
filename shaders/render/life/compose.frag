#version 430 core
// Compose the life HDR image into the 8-bit target: ACES filmic tone map (Narkowicz 2015),
// gamma 1/2.2, then blue-noise dithering: per channel c = 255x rounds up when its fraction
// exceeds the pixel's blue-noise threshold, else down, so smooth glows show no bands.
#include "render/life/bindings.glsl"

layout(binding = LIFE_VIEW_HDR_UNIT) uniform sampler2D uHdr;
layout(binding = LIFE_VIEW_BLUE_NOISE_UNIT) uniform sampler2D uBlueNoise;  // R32F thresholds in (0, 1), tiled by pixel
uniform int uDither;
out vec4 fragColor;

vec3 aces(vec3 x) { return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy);
  const vec3 mapped = pow(aces(max(texelFetch(uHdr, pixel, 0).rgb, vec3(0.0))), vec3(1.0 / 2.2));
  const vec3 c = mapped * 255.0;
  vec3 q;
  if (uDither != 0) {
    const float noise = texelFetch(uBlueNoise, pixel % textureSize(uBlueNoise, 0), 0).r;
    q = floor(c) + step(vec3(noise), fract(c));
  } else {
    q = floor(c + 0.5);
  }
  fragColor = vec4(q / 255.0, 1.0);
}
