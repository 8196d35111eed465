// Top view of the ripples heightfield after water-simulation-gpu's 2D renderer: the eye looks
// straight down, the view ray refracts through the surface normal onto a tiled floor at depth
// uFloorDepth, water colour deepens with the refracted path length, plus a specular glint.
// The state SSBO is read directly; normals come from central differences interpolated
// bilinearly between cells, so the picture stays smooth when a cell covers several pixels.
// Shared by view_2d.comp (the view) and view_2d.frag (its raster variant); each samples
// the floor its own way between topViewRay() and topViewColor().
#ifndef RENDER_RIPPLES_VIEW_2D_GLSL
#define RENDER_RIPPLES_VIEW_2D_GLSL

#include "render/ripples/surface.glsl"
#include "render/ripples/bindings.glsl"

uniform vec2 uUvScale;       // screen uv -> grid uv (aspect-preserving "cover")
uniform vec2 uUvOffset;
uniform float uSlopeScale;   // exaggerates slopes: 1 = physical (height m / cell size m)
uniform float uFloorDepth;   // in grid widths
uniform float uEta;          // refraction index ratio air/water (seed: 0.9)
uniform vec3 uWaterColor;
uniform float uViewDistance; // refracted path length (grid widths) at which the water is opaque
uniform vec3 uLightDir;
uniform float uTileRepeat;   // floor tiles across the grid
layout(binding = RIPPLES_VIEW_FLOOR_UNIT) uniform sampler2D uFloor;
uniform vec4 uSphere;        // xy: centre (grid uv), z: radius (grid widths), w: centre height / radius; z = 0: none

const vec3 kTopEye = vec3(0.0, 0.0, -1.0);

struct TopView {
  vec3 normal;     // of the water surface
  bool seesFloor;  // the refracted ray goes down
  vec2 tileUv;     // where it meets the floor, floor texture coordinates
  float tint;      // 0: clear floor .. 1: only water colour
};

TopView topViewRay(vec2 uv) {
  TopView s;
  s.normal = normalize(vec3(-slopeBilinear(uv) * uSlopeScale, 1.0));
  vec3 r = refract(kTopEye, s.normal, uEta);
  s.seesFloor = r.z < 0.0;
  s.tileUv = uv * uTileRepeat;
  s.tint = 1.0;
  if (s.seesFloor) {
    r *= uFloorDepth / -r.z;
    s.tileUv = (uv + r.xy) * uTileRepeat;
    s.tint = clamp(length(r) / uViewDistance, 0.0, 1.0);
  }
  return s;
}

// ground: the floor texture at s.tileUv.
vec3 topViewColor(TopView s, vec2 uv, vec3 ground) {
  const vec3 n = s.normal;
  vec3 color = s.seesFloor ? mix(ground, uWaterColor, s.tint) : uWaterColor;
  const float glint = smoothstep(0.98, 1.0, dot(reflect(normalize(uLightDir), n), -kTopEye));
  color += vec3(glint);
  if (uSphere.z > 0.0) {
    // The part of the ball above the water, seen from straight above.
    const vec2 d = (uv - uSphere.xy) * vec2(1.0, float(uSize.y) / float(uSize.x)) / uSphere.z;
    const float r2 = dot(d, d);
    if (r2 < 1.0 && uSphere.w + sqrt(1.0 - r2) > 0.0) {
      const vec3 ballNormal = vec3(d, sqrt(1.0 - r2));
      const float light = 0.3 + 0.7 * max(dot(ballNormal, -normalize(uLightDir)), 0.0);
      color = vec3(0.85, 0.35, 0.12) * light + vec3(0.4) * pow(max(ballNormal.z, 0.0), 60.0);
    }
  }
  return color;
}

#endif
