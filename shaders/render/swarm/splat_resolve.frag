#version 430 core
// Resolves the splat counters (splat.comp) into the image, matching the raster modes:
//   additive (uMode 0): sum of colour * opacity, clipped at 1 like RGBA8 blending;
//   opaque   (uMode 1): the mean colour of the pixel's particles;
//   high quality (uMode 2): mean colour * (1 - exp(-opacity * count)), never clipping.
#include "swarm/bindings.glsl"

layout(std430, binding = SWARM_SPLAT_BINDING) readonly buffer Splat { uint splat[]; };
uniform ivec2 uSize;
uniform int uMode;
uniform int uSingle;    // 1: colour sums were not counted; use uColor
uniform vec3 uColor;
uniform float uOpacity;
out vec4 fragColor;

void main() {
  const ivec2 px = ivec2(gl_FragCoord.xy);
  const uint base = 4u * uint(px.y * uSize.x + px.x);
  const float count = float(splat[base]);
  if (count == 0.0) {
    fragColor = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  const vec3 sum = uSingle != 0 ? uColor * count : vec3(splat[base + 1u], splat[base + 2u], splat[base + 3u]) / 255.0;
  vec3 rgb;
  if (uMode == 0) rgb = min(sum * uOpacity, vec3(1.0));
  else if (uMode == 1) rgb = sum / count;
  else rgb = sum / count * (1.0 - exp(-uOpacity * count));
  fragColor = vec4(rgb, 1.0);
}
