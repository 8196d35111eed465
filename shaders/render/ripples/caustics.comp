#version 430 core
// Caustics as a compute splat, one invocation per light point: the point's sunlight, refracted
// at the surface (causticLanding), lands in one floor texel, whose counter it increments. The
// counts are exact integers, so no light is lost to blending precision; the resolve pass
// (caustics_resolve.comp) scales them to light and clears them. This replaces drawing
// one GL_POINT per light point, which the H100's few raster units made the slowest pass.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "render/ripples/view_3d.glsl"
#include "render/ripples/bindings.glsl"

layout(std430, binding = RIPPLES_VIEW_LIGHT) buffer Light { uint light[]; };
uniform ivec2 uLightGrid;  // light points along x and y
uniform ivec2 uLightSize;  // floor texels along x and y

void main() {
  const uint i = globalIndex();
  if (i >= uint(uLightGrid.x * uLightGrid.y)) return;
  const ivec2 q = ivec2(i % uint(uLightGrid.x), i / uint(uLightGrid.x));
  const vec2 xy = (vec2(q) + 0.5) / vec2(uLightGrid) * uTank;
  // The texel a 1-px point at this position would cover: floor of the window coordinate.
  const ivec2 texel = clamp(ivec2(floor(causticLanding(xy) * vec2(uLightSize))), ivec2(0), uLightSize - 1);
  atomicAdd(light[texel.y * uLightSize.x + texel.x], 1u);
}
