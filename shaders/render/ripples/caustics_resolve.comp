#version 430 core
// Light on the floor from the caustics counters (caustics.comp): points landed x weight,
// where the weight (texels / light points) makes flat water light every texel with 1. Clears
// each counter after reading it, ready for the next frame. With uFlat, writes 1 everywhere
// (caustics off) and leaves the counters alone.
#include "render/ripples/bindings.glsl"
layout(local_size_x = RIPPLES_VIEW_GROUP, local_size_y = RIPPLES_VIEW_GROUP) in;

layout(std430, binding = RIPPLES_VIEW_LIGHT) buffer Light { uint light[]; };
layout(binding = RIPPLES_VIEW_LIGHT_IMAGE, r16f) writeonly uniform image2D uLightImage;
uniform ivec2 uLightSize;  // texels
uniform float uWeight;     // light of one point: texels / light points
uniform int uFlat;         // 1: no caustics, light 1 everywhere

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, uLightSize))) return;
  float l = 1.0;
  if (uFlat == 0) {
    const int i = texel.y * uLightSize.x + texel.x;
    l = float(light[i]) * uWeight;
    light[i] = 0u;
  }
  imageStore(uLightImage, texel, vec4(l, 0.0, 0.0, 0.0));
}
