#version 430 core
// The 2D ripples view as a compute pass, one invocation per pixel of the render target: the
// same shading as the raster variant (render/ripples/view_2d.glsl), without the raster pipeline,
// which on compute-first GPUs (H100) costs more than the shading itself. Pixel (0,0) is the
// bottom-left one, as gl_FragCoord counts.
#include "render/ripples/bindings.glsl"
layout(local_size_x = RIPPLES_VIEW_GROUP, local_size_y = RIPPLES_VIEW_GROUP) in;
#include "render/ripples/quad_gradient.glsl"
#include "render/ripples/view_2d.glsl"

layout(binding = RIPPLES_VIEW_COLOR_IMAGE, rgba8) writeonly uniform image2D uTarget;
uniform ivec2 uTargetSize;  // pixels

void main() {
  const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  const vec2 uv = (vec2(px) + 0.5) / vec2(uTargetSize) * uUvScale + uUvOffset;
  const TopView s = topViewRay(uv);
  vec2 ddx, ddy;
  quadGradient(s.tileUv, true, ddx, ddy);  // before any invocation leaves: it holds a barrier
  if (any(greaterThanEqual(px, uTargetSize))) return;
  imageStore(uTarget, px, vec4(topViewColor(s, uv, textureGrad(uFloor, s.tileUv, ddx, ddy).rgb), 1.0));
}
