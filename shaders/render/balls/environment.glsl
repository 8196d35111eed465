// What the water sits in, for the compose (render/balls/compose.comp), with uEnvironment: a sky
// (a gradient from the horizon, uBackground, to the zenith, uSkyColor, and the sun towards the
// key light) over a floor of square tiles at the bottom of the domain box, reaching past the box
// and fading into the horizon far away. Analytic, per ray: nothing is drawn or stored, so the
// water can look at it along any ray (the eye's, refracted through the surface, reflected).
// Without uEnvironment the surroundings are the flat background and the seed's sky. The box's
// four side walls are glass (throughTank), open at the top, on the floor. With uCaustics the floor
// inside the box takes the sunlight the water above it focuses and spreads (WaterCaustics).
#ifndef RENDER_BALLS_ENVIRONMENT_GLSL
#define RENDER_BALLS_ENVIRONMENT_GLSL

#include "render/balls/water_optics.glsl"

uniform int uEnvironment;      // 0: the flat background (the seed's look)
uniform vec3 uSkyColor;        // linear RGB at the zenith
uniform vec3 uSunWorld;        // unit, towards the sun (the key light), world
uniform mat4 uBoxFromWorld;    // world -> the domain box's frame (rigid; z its up)
uniform vec3 uFloorMin;        // the box's bottom corner in its frame, m (the floor: z = uFloorMin.z)
uniform vec3 uFloorMax;        // the opposite corner, m
uniform float uTileSize;       // floor tiles' edge, m
uniform float uPixelSpread;    // perspective: rad per pixel; orthographic: m per pixel
uniform float uGlass;          // the tank's walls' reflectance at normal incidence (0: no glass)
uniform int uCaustics;         // 1: the floor in the box takes the sunlight of uCausticsLight
layout(binding = BALLS_VIEW_CAUSTICS) uniform sampler2D uCausticsLight;  // over the box's floor, 1 = dry floor

const vec3 kSunColor = vec3(1.0, 0.94, 0.84);
const vec3 kTile = vec3(0.78, 0.80, 0.79), kGrout = vec3(0.30, 0.32, 0.33);
const float kGroutWidth = 0.03;  // of a tile, each side of a joint

vec3 skyColour(vec3 d) {  // d: world, unit
  vec3 c = mix(uBackground, uSkyColor, sqrt(clamp(d.z, 0.0, 1.0)));
  const float s = max(dot(d, uSunWorld), 0.0);
  return c + kSunColor * (0.2 * pow(s, 12.0) + 8.0 * smoothstep(0.99985, 0.99995, s));  // glow, disc
}

// The tiles' colour at floor point xy (box frame), averaged over a footprint of `spread` m.
vec3 tiles(vec2 xy, float spread) {
  const vec2 cell = xy / uTileSize, f = fract(cell);
  // Each tile a little lighter or darker than the next (a hash of its cell), as glazed tiles are.
  const float shade = fract(sin(dot(floor(cell), vec2(12.9898, 78.233))) * 43758.5453);
  const float joint = min(min(f.x, 1.0 - f.x), min(f.y, 1.0 - f.y));
  const vec3 sharp = joint < kGroutWidth ? kGrout : kTile * (0.92 + 0.12 * shade);
  // Far away a pixel covers several tiles: their mean, not an aliased pattern.
  const float groutShare = 1.0 - (1.0 - 2.0 * kGroutWidth) * (1.0 - 2.0 * kGroutWidth);
  const vec3 mean = mix(0.98 * kTile, kGrout, groutShare);
  return mix(sharp, mean, smoothstep(0.1, 0.5, spread / uTileSize));
}

// The colour along the ray from `origin` in world direction `d` (unit); `travelled`: how far the
// ray came before origin (m), for the footprint of a refracted or reflected ray; `blur`: how far
// its neighbours' rays turn from it (rad: a refracted ray's, from the surface's ripples finer than
// a pixel), so that the floor through rough water is a blur, not speckle.
vec3 environment(vec3 origin, vec3 d, float travelled, float blur) {
  const vec3 o = (uBoxFromWorld * vec4(origin, 1.0)).xyz, b = mat3(uBoxFromWorld) * d;
  if (b.z >= 0.0 || o.z < uFloorMin.z) return skyColour(d);
  const float t = (uFloorMin.z - o.z) / b.z;
  const vec2 hit = o.xy + t * b.xy;
  const float spread = (uPixelSpread * (uOrtho != 0 ? 1.0 : travelled + t) + blur * t) / max(-b.z, 0.05);
  const vec3 up = transpose(mat3(uBoxFromWorld)) * vec3(0.0, 0.0, 1.0);
  // The sun's share, focused and spread by the water above (render/balls/caustics_light.comp).
  float sun = 0.6 * max(dot(up, uSunWorld), 0.0);
  const vec2 onFloor = (hit - uFloorMin.xy) / (uFloorMax.xy - uFloorMin.xy);
  if (uCaustics != 0 && all(greaterThanEqual(onFloor, vec2(0.0))) && all(lessThanEqual(onFloor, vec2(1.0))))
    sun *= texture(uCausticsLight, onFloor).r;
  const vec3 lit = tiles(hit, spread) * (0.4 + sun);
  // Past a few box sizes the floor fades into the horizon.
  const vec2 centre = 0.5 * (uFloorMin.xy + uFloorMax.xy);
  const float size = length(uFloorMax.xy - uFloorMin.xy);
  const float fade = smoothstep(1.5 * size, 8.0 * size, length(hit - centre));
  return mix(lit, skyColour(normalize(vec3(d.xy, 0.0) + vec3(0.0, 0.0, 1e-4))), fade);
}

// `colour`, seen from `origin` (world) along d (unit) at `distance` m, behind the tank's glass:
// each side wall the ray crosses before it reflects the sky by Schlick's Fresnel and passes the
// rest, the farthest first.
vec3 throughTank(vec3 colour, vec3 origin, vec3 d, float distance) {
  const vec3 o = (uBoxFromWorld * vec4(origin, 1.0)).xyz, b = mat3(uBoxFromWorld) * d;
  const mat3 toWorld = transpose(mat3(uBoxFromWorld));
  vec4 hits[4];  // xyz: the wall's normal (box frame), w: the distance to it
  int count = 0;
  for (int axis = 0; axis < 2; ++axis)
    for (int side = 0; side < 2; ++side) {
      if (b[axis] == 0.0) continue;
      const float plane = side == 0 ? uFloorMin[axis] : uFloorMax[axis];
      const float t = (plane - o[axis]) / b[axis];
      if (!(t > 0.0 && t < distance)) continue;
      const vec3 hit = o + t * b;
      const int other = 1 - axis;
      if (hit[other] < uFloorMin[other] || hit[other] > uFloorMax[other] || hit.z < uFloorMin.z ||
          hit.z > uFloorMax.z)
        continue;
      vec3 n = vec3(0.0);
      n[axis] = side == 0 ? -1.0 : 1.0;
      hits[count++] = vec4(n, t);
    }
  for (int k = count - 1; k >= 0; --k) {  // a ray crosses two side walls at most
    const int at = count == 2 && hits[0].w > hits[1].w ? 1 - k : k;
    const vec3 n = toWorld * hits[at].xyz;
    const float fresnel = schlick(uGlass, abs(dot(d, n)));
    colour = mix(colour, skyColour(reflect(d, n)), fresnel);
  }
  return colour;
}

#endif
