// Shading shared by the 3D ripples view's compute ray caster (raycast.comp) and its
// raster variant (surface.frag, walls.frag): sky, lit floor (tiles x caustics),
// absorption, Fresnel; the water surface seen from above and the glass walls seen from outside.
// The floor tiles are sampled by the caller between waterView() and waterColor(): with the
// fragment's derivatives when rasterising, with quad gradients in compute.
#ifndef RENDER_RIPPLES_SHADING_GLSL
#define RENDER_RIPPLES_SHADING_GLSL

#include "render/ripples/view_3d.glsl"
#include "render/ripples/bindings.glsl"

layout(binding = RIPPLES_VIEW_FLOOR_UNIT) uniform sampler2D uFloor;        // tiles
layout(binding = RIPPLES_VIEW_CAUSTICS_UNIT) uniform sampler2D uCaustics;  // light on the floor: 1 = flat water
uniform float uTileRepeat;    // tiles across the tank width
uniform vec3 uWaterColor;     // linear RGB
uniform float uViewDistance;  // world units of water that absorb ~63% (Beer-Lambert)
uniform float uAmbient;       // floor light without sun
uniform vec3 uEye;            // world
uniform int uOrtho;           // 1: orthographic camera, every view ray along uViewDir
uniform vec3 uViewDir;        // world, unit: the camera's view direction

// Unit direction of the view ray that reaches `world`.
vec3 viewRay(vec3 world) { return uOrtho != 0 ? uViewDir : normalize(world - uEye); }

const vec3 kBackground = vec3(0.07, 0.08, 0.1);  // behind the tank

vec3 sky(vec3 dir) { return mix(vec3(0.62, 0.68, 0.74), vec3(0.18, 0.32, 0.58), clamp(dir.z, 0.0, 1.0)); }

// The caustics texture has one level: texture() and a compute shader's level 0 agree.
float floorLight(vec2 xy) { return uAmbient + (1.0 - uAmbient) * texture(uCaustics, xy / uTank).r; }

// The light on a wall `z` above the floor at its foot `foot`: the floor's caustics show only near
// the floor. Higher up the glass shows the water column, not the floor's light; a caustic spot at
// the foot drawn the wall's full height reads as a bright vertical streak.
const float kWallCausticsHeight = 0.04;  // world units above the floor where the foot's light shows
float wallLight(vec2 foot, float z) {
  const float caustic = mix(texture(uCaustics, foot / uTank).r, 1.0, smoothstep(0.0, kWallCausticsHeight, z));
  return uAmbient + (1.0 - uAmbient) * caustic;
}

vec3 absorb(vec3 color, float pathLength) { return mix(uWaterColor, color, exp(-pathLength / uViewDistance)); }

float schlick(float cosine) { return 0.02 + 0.98 * pow(1.0 - cosine, 5.0); }  // water, F0 = 0.02

// The water surface at `world` seen from uEye: the view ray refracts to the lit floor (absorbed
// along its path), reflects the sky with Schlick's Fresnel, plus a sun highlight.
struct WaterView {
  vec3 normal;   // faces the eye
  vec3 view;     // eye -> surface, unit
  vec2 floorXy;  // where the refracted ray ends (on the floor, or at a wall's foot), world xy
  float path;    // refracted path length in the water, world units
  bool onWall;   // the refracted ray leaves the tank through a wall before reaching the floor
  float wallZ;   // and how high on the wall, world z
};

WaterView waterView(vec3 world) {
  WaterView w;
  w.normal = surfaceNormal(world.xy);
  w.view = viewRay(world);
  if (dot(w.normal, w.view) > 0.0) w.normal = -w.normal;  // grazing views of steep waves
  const vec3 r = refract(w.view, w.normal, kEtaAirWater);
  // The refracted ray ends on the floor, or on a wall if it leaves the tank first; a wall shows
  // the floor tile at its foot, dimmed.
  float t = world.z / max(-r.z, 1e-3);
  const vec2 exitT = mix(-world.xy, uTank - world.xy, step(0.0, r.xy)) / (r.xy + vec2(1e-6));
  const float tWall = min(exitT.x, exitT.y);
  w.onWall = tWall < t;
  w.path = min(t, tWall);
  w.floorXy = clamp(world.xy + w.path * r.xy, vec2(0.0), uTank);
  w.wallZ = max(world.z + w.path * r.z, 0.0);
  return w;
}

// tiles: the floor texture at w.floorXy * uTileRepeat.
vec3 waterColor(WaterView w, vec3 tiles) {
  const float light = w.onWall ? wallLight(w.floorXy, w.wallZ) : floorLight(w.floorXy);
  const vec3 below = absorb(tiles * light * (w.onWall ? 0.6 : 1.0), w.path);
  const float fresnel = schlick(clamp(dot(-w.view, w.normal), 0.0, 1.0));
  vec3 color = mix(below, sky(reflect(w.view, w.normal)), fresnel);
  return color + vec3(1.6) * pow(max(dot(reflect(-uSunDir, w.normal), -w.view), 0.0), 600.0);
}

// A tank wall at `world` (below the local water surface), outward normal `normal`: water seen
// through glass, darker with depth, lit as wallLight() says, a faint sky reflection on the glass
// and a bright meniscus line at the surface.
vec3 wallColor(vec3 world, vec3 normal) {
  const float surface = surfaceZ(clamp(world.xy, vec2(0.0), uTank));
  const vec3 v = viewRay(world);
  const float depth = surface - world.z;
  const vec2 foot = clamp(world.xy - normal.xy * 0.01, vec2(0.0), uTank);
  const float light = wallLight(foot, world.z);
  const vec3 inside = absorb(vec3(0.55, 0.72, 0.76) * light, 0.1 + 1.5 * depth);
  const float fresnel = 0.5 * schlick(clamp(dot(-v, normal), 0.0, 1.0));
  const float rim = smoothstep(0.006, 0.0, depth);
  return mix(inside, sky(reflect(v, normal)), fresnel) + vec3(0.35 * rim);
}

#endif
