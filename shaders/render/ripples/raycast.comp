#version 430 core
// The 3D ripples view as a compute ray caster, one invocation per pixel of the render target:
// the ray from the orbit camera meets the glass walls facing the eye (cut at the local water
// height), the heightfield surface (render/ripples/trace.glsl: exact per dual cell, tiles skip
// the rest) and the ball; the nearest is shaded as the raster variant shades it
// (render/ripples/shading.glsl, render/ripples/ball_shading.glsl). It replaces rasterising the surface
// mesh, walls and ball, which on compute-first GPUs (H100: few raster units) costs far more.
// Pixel (0,0) is the bottom-left one, as gl_FragCoord counts. Writes colour only: nothing reads
// the target's depth after this view.
#include "render/ripples/bindings.glsl"
layout(local_size_x = RIPPLES_VIEW_GROUP, local_size_y = RIPPLES_VIEW_GROUP) in;
#include "render/ripples/ball_shading.glsl"
#include "render/ripples/quad_gradient.glsl"
#include "render/ripples/shading.glsl"
#include "render/ripples/trace.glsl"

layout(binding = RIPPLES_VIEW_COLOR_IMAGE, rgba8) writeonly uniform image2D uTarget;
uniform ivec2 uTargetSize;  // pixels
uniform mat4 uInvViewProj;  // clip -> world
uniform float uWallTop;     // world z of the walls' top edge
uniform vec4 uBall;         // world centre, radius; radius 0: no ball
uniform vec3 uBallColor;    // linear RGB

const int kNothing = 0, kWall = 1, kWater = 2, kBall = 3;

// Entry and exit t of the slab lo <= o + t d <= hi (empty: entry > exit).
vec2 slab(float o, float d, float lo, float hi) {
  if (abs(d) < 1e-12) return o >= lo && o <= hi ? vec2(-kHuge, kHuge) : vec2(kHuge, -kHuge);
  const float t0 = (lo - o) / d, t1 = (hi - o) / d;
  return vec2(min(t0, t1), max(t0, t1));
}

// t where the ray enters the ball, or kHuge.
float ballHit(vec3 o, vec3 d) {
  if (uBall.w <= 0.0) return kHuge;
  const vec3 oc = o - uBall.xyz;
  const float b = dot(oc, d), c = dot(oc, oc) - uBall.w * uBall.w;
  const float h = b * b - c;
  if (h < 0.0) return kHuge;
  const float t = -b - sqrt(h);
  return t > 0.0 ? t : kHuge;
}

void main() {
  const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  const vec2 ndc = (vec2(px) + 0.5) / vec2(uTargetSize) * 2.0 - 1.0;
  // Perspective: from the eye. Orthographic: parallel rays from the pixel's point on the near plane.
  const vec4 far = uInvViewProj * vec4(ndc, 1.0, 1.0), onNear = uInvViewProj * vec4(ndc, -1.0, 1.0);
  const vec3 origin = uOrtho != 0 ? onNear.xyz / onNear.w : uEye;
  const vec3 dir = uOrtho != 0 ? uViewDir : normalize(far.xyz / far.w - uEye);
  const GridRay ray = gridRay(origin, dir);

  // The tank's xy prism; the walls are its faces the ray enters through (the raster variant
  // culls the others as back faces).
  const vec2 sx = slab(origin.x, dir.x, 0.0, uTank.x), sy = slab(origin.y, dir.y, 0.0, uTank.y);
  const float tIn = max(sx.x, sy.x), tOut = min(sx.y, sy.y);
  const float tBall = ballHit(origin, dir);
  int kind = tBall < kHuge ? kBall : kNothing;
  float t = tBall;
  vec3 wallNormal = vec3(0.0);
  if (tIn > 0.0 && tIn <= tOut && tIn < t) {
    const vec3 p = origin + tIn * dir;
    if (p.z >= 0.0 && p.z <= uWallTop && p.z <= surfaceZ(clamp(p.xy, vec2(0.0), uTank))) {
      kind = kWall;
      t = tIn;
      wallNormal = sx.x > sy.x ? vec3(-sign(dir.x), 0.0, 0.0) : vec3(0.0, -sign(dir.y), 0.0);
    }
  }
  if (kind != kWall) {
    const vec2 zRange = surfaceRange();
    const vec2 sz = slab(origin.z, dir.z, zRange.x - 1e-6, zRange.y + 1e-6);
    const float ta = max(max(tIn, sz.x), 0.0), tb = min(min(tOut, sz.y), t);
    const float tWater = ta <= tb ? traceSurface(ray, ta, tb) : -1.0;
    if (tWater >= 0.0) {
      kind = kWater;
      t = tWater;
    }
  }

  const vec3 hit = origin + t * dir;
  WaterView water;
  if (kind == kWater) water = waterView(hit);
  vec2 ddx, ddy;
  const vec2 tileUv = kind == kWater ? water.floorXy * uTileRepeat : vec2(0.0);
  quadGradient(tileUv, kind == kWater, ddx, ddy);  // before any invocation leaves: it holds a barrier
  if (any(greaterThanEqual(px, uTargetSize))) return;

  vec3 color = kBackground;
  if (kind == kWater) color = waterColor(water, textureGrad(uFloor, tileUv, ddx, ddy).rgb);
  else if (kind == kWall) color = wallColor(hit, wallNormal);
  else if (kind == kBall) color = ballColor(uBallColor, (hit - uBall.xyz) / uBall.w, -dir, uSunDir);
  imageStore(uTarget, px, vec4(color, 1.0));
}
