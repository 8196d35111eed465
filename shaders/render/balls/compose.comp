#version 430 core
// Compose pass, one thread per pixel (a compute pass: on compute-first GPUs such as the H100 the
// raster path's full-screen passes and clears are several times slower). Each pixel's scene is
// the colour and depth of the obstacles the raster drew into the target (uScene 1; the raster
// clears depth only, and only in their rectangle, so a pixel outside it or still at the far plane
// takes the background), or the background at the far plane when there were none (uScene 0: the
// target is neither cleared nor read), with the domain box's lines over it (the nearest of the
// line fragments GL would draw, within their depth). Where the nearest ball is in front of that scene the G-buffer is shaded
// and written over it; water lets the scene through per channel (Beer–Lambert over the
// thickness), which is how an obstacle shows through thin water:
//   out = clamp(colour) + clamp(transmit) * scene
// (the fixed-point blend of the fragment compose this replaces). The target's depth is left as
// the scene's: nothing is drawn after the compose.
//   balls: diffuse + ambient (+ a small highlight), opaque
//   water: normals from the (blurred) depth, Schlick Fresnel toward the sky, specular,
//          absorption tint, foam (and lone balls as spray); with uEnvironment (environment.glsl) the surroundings are a sky
//          and a tiled floor, seen through the water along the ray refracted at its surface
//          (Snell, index uIor) and reflected in it
#include "render/balls/bindings.glsl"
layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = BALLS_VIEW_GBUFFER) uniform sampler2D uGBuffer;  // RG normal xy, B thickness m, A depth m
layout(binding = BALLS_VIEW_FOAM) uniform sampler2D uFoam;
layout(binding = BALLS_VIEW_DEPTH) uniform sampler2D uDepth;            // window depth of the nearest ball
layout(binding = BALLS_VIEW_SCENE_DEPTH) uniform sampler2D uSceneDepth;  // the target's, uScene 1
#include "render/balls/scene_rect.glsl"
layout(binding = BALLS_VIEW_COMPOSE_TARGET, rgba8) uniform image2D uTarget;

uniform ivec2 uSize;        // px
uniform int uBalls;         // 0: no G-buffer this frame (no balls): the scene only
uniform int uScene;         // 0: the target holds nothing yet (the background)
uniform vec4 uLines[24];    // box: segment k from uLines[2k] to uLines[2k+1], window x, y (px), z
uniform int uLineCount;     // segments
uniform vec3 uLineColor;    // linear RGB
uniform mat4 uInvView;      // view -> world (directions: upper 3x3)
uniform vec2 uInvFocal;     // 1 / proj[0][0], 1 / proj[1][1]
uniform int uOrtho;         // 1: orthographic camera (view rays along -z)
uniform vec2 uDepthRange;   // near, far (m), for the depth debug view
uniform int uMode;          // 0 balls, 1 water
uniform int uDebug;         // 0 final, 1 local position, 2 world normals, 3 thickness, 4 depth, 5 view normals
uniform vec3 uWaterColor;   // linear RGB: balls' albedo; water's transmittance after 1/absorption m
uniform float uAbsorption;  // 1/m
uniform vec3 uBackground;   // linear RGB, the sky's horizon
uniform float uF0;          // Fresnel reflectance at normal incidence
uniform float uSpecular;    // highlight strength
uniform int uFoamOn;         // 0: foam off
uniform float uThicknessScale;  // m shown as white in the thickness view
uniform vec3 uLightView;    // towards the key light, view space
uniform float uDepthStep;   // m: a larger depth difference to a neighbour is a silhouette, not a slope
uniform float uIor;         // water's index of refraction (1: straight through)
uniform float uScattering;  // the share of the absorbed light sent back, in the water's colour
uniform float uSpray;       // water: how white a lone ball (a droplet) is drawn, as foam (0: as water)
uniform float uRadius;      // the balls', m
#include "render/balls/environment.glsl"
#include "render/balls/water_optics.glsl"

const vec3 kFoamColor = vec3(0.92, 0.96, 1.0);
const vec3 kZenith = vec3(0.55, 0.68, 0.85);
const float kRefractionBlur = 0.05;  // rad: the spread of refracted rays from sub-pixel ripples

vec3 seedSky(vec3 worldDir) { return mix(uBackground + 0.08, kZenith, clamp(worldDir.z, 0.0, 1.0)); }

// Window depth of the nearest box line covering px, or `depth` when none is nearer. A line is
// drawn as GL draws a one-pixel line: for an x-major segment one pixel per column whose centre
// lies in the segment's span, the one whose centre is within half a pixel of the line (y-major
// likewise by rows); depth is linear along it in window space.
float lineDepth(ivec2 px, float depth) {
  const vec2 c = vec2(px) + 0.5;
  for (int k = 0; k < uLineCount; ++k) {
    const vec3 a = uLines[2 * k].xyz, b = uLines[2 * k + 1].xyz;
    const vec2 d = b.xy - a.xy;
    const bool xMajor = abs(d.x) >= abs(d.y);
    const float major = xMajor ? d.x : d.y;
    if (major == 0.0) continue;
    const float t = ((xMajor ? c.x : c.y) - (xMajor ? a.x : a.y)) / major;
    if (!(t >= 0.0 && t < 1.0)) continue;
    const float minor = xMajor ? a.y + t * d.y : a.x + t * d.x;
    if (int(floor(minor)) != (xMajor ? px.y : px.x)) continue;
    depth = min(depth, mix(a.z, b.z, t));
  }
  return depth;
}

vec3 viewPosition(ivec2 px, float depth) {  // depth: view depth (m)
  const vec2 ndc = 2.0 * ((vec2(px) + 0.5) / vec2(uSize)) - 1.0;
  return vec3(ndc * uInvFocal * (uOrtho != 0 ? 1.0 : depth), -depth);
}

// Slope of the surface along `axis` at p: the one-sided difference with the smaller depth step
// (so no difference crosses a silhouette); false when neither neighbour is on the surface.
bool surfaceSlope(ivec2 px, ivec2 axis, vec3 p, out vec3 slope) {
  const ivec2 last = uSize - 1;
  const ivec2 qa = clamp(px + axis, ivec2(0), last), qb = clamp(px - axis, ivec2(0), last);
  const float da = texelFetch(uGBuffer, qa, 0).a, db = texelFetch(uGBuffer, qb, 0).a;
  const bool okA = qa != px && da > 0.0 && abs(da + p.z) < uDepthStep;
  const bool okB = qb != px && db > 0.0 && abs(db + p.z) < uDepthStep;
  if (!okA && !okB) return false;
  const bool useA = okA && (!okB || abs(da + p.z) <= abs(db + p.z));
  slope = useA ? viewPosition(qa, da) - p : p - viewPosition(qb, db);
  return true;
}

// The view depth (m) of a window depth of the scene (GL's default depth range).
float viewDepth(float window) {
  const float n = uDepthRange.x, f = uDepthRange.y;
  return uOrtho != 0 ? n + window * (f - n) : 2.0 * n * f / (f + n - (2.0 * window - 1.0) * (f - n));
}

// The eye's ray through px, world.
void eyeRay(ivec2 px, out vec3 origin, out vec3 dir) {
  const vec3 p = viewPosition(px, 1.0);
  origin = (uInvView * vec4(uOrtho != 0 ? vec3(p.xy, 0.0) : vec3(0.0), 1.0)).xyz;
  dir = normalize(mat3(uInvView) * (uOrtho != 0 ? vec3(0.0, 0.0, -1.0) : p));
}

// 1 where the ball at px is a droplet, alone: no more water along the ray than its own chord,
// and nothing at its depth two of its radii away on screen, left, right, above or below.
float droplet(ivec2 px, vec4 g) {
  const float chord = 2.0 * uRadius * sqrt(max(1.0 - dot(g.rg, g.rg), 0.04));
  if (g.b > 1.3 * chord) return 0.0;
  const float reach = 2.0 * uRadius / (uInvFocal.y * (uOrtho != 0 ? 1.0 : g.a)) * 0.5 * float(uSize.y);  // px
  const ivec2 last = uSize - 1;
  for (int k = 0; k < 4; ++k) {
    const ivec2 step = ivec2(k == 0 ? 1 : k == 1 ? -1 : 0, k == 2 ? 1 : k == 3 ? -1 : 0);
    const ivec2 q = clamp(px + ivec2(round(reach * vec2(step))), ivec2(0), last);
    const float d = texelFetch(uGBuffer, q, 0).a;
    if (d > 0.0 && abs(d - g.a) < 2.0 * uRadius) return 0.0;
  }
  return 1.0;
}

// The ball's colour over `scene` at px (g: its G-buffer texel); `open`: nothing opaque behind it
// (the scene is the surroundings).
vec3 shade(ivec2 px, vec4 g, vec3 scene, bool open) {
  const vec3 p = viewPosition(px, g.a);  // view-space position, m
  const vec3 v = uOrtho != 0 ? vec3(0.0, 0.0, 1.0) : normalize(-p);  // towards the eye
  // Balls: the ray-traced normal. Water: the smoothed depth's, where both slopes exist (the
  // blurred ball normal at one-pixel features).
  vec3 n = normalize(vec3(g.rg, sqrt(max(1.0 - dot(g.rg, g.rg), 0.0))));
  vec3 dx, dy;
  if (uMode == 1 && surfaceSlope(px, ivec2(1, 0), p, dx) && surfaceSlope(px, ivec2(0, 1), p, dy)) {
    const vec3 m = cross(dx, dy);
    if (dot(m, m) > 0.0) n = normalize(dot(m, v) < 0.0 ? -m : m);
  }
  const mat3 toWorld = mat3(uInvView);
  if (uDebug == 1) return vec3(0.5 + 0.5 * g.rg, 0.5);
  if (uDebug == 2) return 0.5 + 0.5 * (toWorld * n);
  if (uDebug == 5) return 0.5 + 0.5 * n;  // screen space: x right, y up, z towards the eye
  if (uDebug == 3) return vec3(g.b / uThicknessScale);
  if (uDebug == 4) return vec3((g.a - uDepthRange.x) / (uDepthRange.y - uDepthRange.x));

  float foam = uFoamOn != 0 ? smoothstep(0.15, 0.6, texelFetch(uFoam, px, 0).r) : 0.0;
  if (uMode == 1 && uSpray > 0.0) foam = max(foam, uSpray * droplet(px, g));
  const float diffuse = max(dot(n, uLightView), 0.0);
  const float highlight = pow(max(dot(reflect(-uLightView, n), v), 0.0), 60.0);
  if (uMode == 0) {
    const vec3 albedo = mix(uWaterColor, kFoamColor, foam);
    return albedo * (0.35 + 0.65 * diffuse) + 0.2 * uSpecular * highlight;
  }
  vec3 through = transmittance(uWaterColor, uAbsorption, g.b);
  // Light scattered back toward the eye takes the water colour, in proportion to what is absorbed.
  vec3 body = uScattering * uWaterColor * (0.5 + 0.7 * diffuse) * (1.0 - dot(through, vec3(1.0 / 3.0)));
  body = mix(body, kFoamColor * (0.6 + 0.4 * diffuse), foam);
  through *= 1.0 - foam;
  const float cosine = clamp(dot(n, v), 0.0, 1.0);
  const float fresnel = schlick(uF0, cosine);
  vec3 reflected;
  if (uEnvironment != 0) {
    const vec3 surface = (uInvView * vec4(p, 1.0)).xyz;
    reflected = environment(surface, toWorld * reflect(-v, n), length(p), 0.0);
    if (open)  // the surroundings through the water, along the refracted ray
      scene = environment(surface, normalize(toWorld * refracted(-v, n, uIor)), length(p), kRefractionBlur);
  } else {
    reflected = seedSky(toWorld * reflect(-v, n));
  }
  const vec3 color = fresnel * reflected + (1.0 - fresnel) * body + uSpecular * highlight;
  return clamp(color, 0.0, 1.0) + clamp((1.0 - fresnel) * through, 0.0, 1.0) * scene;
}

void main() {
  const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, uSize))) return;
  vec3 scene = uBackground;
  float sceneDepth = 1.0;
  if (uScene != 0 && inSceneRect(px)) {
    // The scene pass clears depth only: where it drew nothing the colour is last frame's.
    sceneDepth = texelFetch(uSceneDepth, px, 0).r;
    if (sceneDepth < 1.0) scene = imageLoad(uTarget, px).rgb;
  }
  const float line = lineDepth(px, sceneDepth);
  if (line < sceneDepth) {
    scene = uLineColor;
    sceneDepth = line;
  }
  vec4 g = vec4(0.0);
  bool covered = false;  // a ball in front of the scene
  if (uBalls != 0) {
    g = texelFetch(uGBuffer, px, 0);
    covered = g.a > 0.0 && texelFetch(uDepth, px, 0).r < sceneDepth;
  }
  const bool open = sceneDepth == 1.0;  // nothing opaque: the surroundings
  if (open && uEnvironment != 0 && !covered) {  // (water shades its own, through the surface)
    vec3 origin, dir;
    eyeRay(px, origin, dir);
    scene = environment(origin, dir, 0.0, 0.0);
  }
  vec3 color = covered ? shade(px, g, scene, open) : scene;
  if (uEnvironment != 0 && uGlass > 0.0) {  // the tank's walls in front of what this pixel sees
    vec3 origin, dir;
    eyeRay(px, origin, dir);
    const float depth = covered ? g.a : open ? 1e30 : viewDepth(sceneDepth);
    color = throughTank(color, origin, dir, uOrtho != 0 ? depth : depth * length(viewPosition(px, 1.0)));
  }
  imageStore(uTarget, px, vec4(color, 1.0));
}
