#version 430 core
// Compose pass (full-screen triangle into the scene target, depth test less, dual-source blend
// ONE + SRC1_COLOR): shades each covered pixel from the G-buffer and writes the balls' true depth,
// so meshes and water composite both ways. Water lets the scene behind it through per channel
// (Beer–Lambert over the thickness), which is how an obstacle shows through thin water.
//   balls: diffuse + ambient (+ a small highlight), opaque
//   water: normals from the (blurred) depth, Schlick Fresnel toward a sky gradient, specular,
//          absorption tint, foam
#include "render/balls_bindings.glsl"

layout(binding = BALLS_VIEW_GBUFFER) uniform sampler2D uGBuffer;  // RG normal xy, B thickness m, A depth m
layout(binding = BALLS_VIEW_FOAM) uniform sampler2D uFoam;
layout(binding = BALLS_VIEW_DEPTH) uniform sampler2D uDepth;      // window depth of the nearest ball

uniform mat4 uInvView;      // view -> world (directions: upper 3x3)
uniform vec2 uInvFocal;     // 1 / proj[0][0], 1 / proj[1][1]
uniform vec2 uViewport;     // px
uniform vec2 uDepthRange;   // near, far (m), for the depth debug view
uniform int uMode;          // 0 balls, 1 water
uniform int uDebug;         // 0 final, 1 local position, 2 normals, 3 thickness, 4 depth
uniform vec3 uWaterColor;   // linear RGB: balls' albedo; water's transmittance after 1/absorption m
uniform float uAbsorption;  // 1/m
uniform vec3 uBackground;   // linear RGB, the sky's horizon
uniform float uF0;          // Fresnel reflectance at normal incidence
uniform float uSpecular;    // highlight strength
uniform int uFoamOn;         // 0: foam off
uniform float uThicknessScale;  // m shown as white in the thickness view
uniform vec3 uLightView;    // towards the key light, view space
uniform float uDepthStep;   // m: a larger depth difference to a neighbour is a silhouette, not a slope

layout(location = 0, index = 0) out vec4 color;
layout(location = 0, index = 1) out vec4 transmit;  // how much of the scene behind shows through

const vec3 kFoamColor = vec3(0.92, 0.96, 1.0);
const vec3 kZenith = vec3(0.55, 0.68, 0.85);

vec3 sky(vec3 worldDir) { return mix(uBackground + 0.08, kZenith, clamp(worldDir.z, 0.0, 1.0)); }

vec3 viewPosition(ivec2 px, float depth) {  // depth: view depth (m)
  const vec2 ndc = 2.0 * ((vec2(px) + 0.5) / uViewport) - 1.0;
  return vec3(ndc * uInvFocal * depth, -depth);
}

// Slope of the surface along `axis` at p: the one-sided difference with the smaller depth step
// (so no difference crosses a silhouette); false when neither neighbour is on the surface.
bool surfaceSlope(ivec2 px, ivec2 axis, vec3 p, out vec3 slope) {
  const ivec2 last = ivec2(uViewport) - 1;
  const ivec2 qa = clamp(px + axis, ivec2(0), last), qb = clamp(px - axis, ivec2(0), last);
  const float da = texelFetch(uGBuffer, qa, 0).a, db = texelFetch(uGBuffer, qb, 0).a;
  const bool okA = qa != px && da > 0.0 && abs(da + p.z) < uDepthStep;
  const bool okB = qb != px && db > 0.0 && abs(db + p.z) < uDepthStep;
  if (!okA && !okB) return false;
  const bool useA = okA && (!okB || abs(da + p.z) <= abs(db + p.z));
  slope = useA ? viewPosition(qa, da) - p : p - viewPosition(qb, db);
  return true;
}

void main() {
  const ivec2 px = ivec2(gl_FragCoord.xy);
  const vec4 g = texelFetch(uGBuffer, px, 0);
  const float depth = texelFetch(uDepth, px, 0).r;
  if (g.a <= 0.0 || depth >= 1.0) discard;
  gl_FragDepth = depth;

  const vec3 p = viewPosition(px, g.a);  // view-space position, m
  const vec3 v = normalize(-p);          // towards the eye
  // Balls: the ray-traced normal. Water: the smoothed depth's, where both slopes exist (the
  // blurred ball normal at one-pixel features).
  vec3 n = normalize(vec3(g.rg, sqrt(max(1.0 - dot(g.rg, g.rg), 0.0))));
  vec3 dx, dy;
  if (uMode == 1 && surfaceSlope(px, ivec2(1, 0), p, dx) && surfaceSlope(px, ivec2(0, 1), p, dy)) {
    const vec3 m = cross(dx, dy);
    if (dot(m, m) > 0.0) n = normalize(dot(m, v) < 0.0 ? -m : m);
  }
  const mat3 toWorld = mat3(uInvView);
  transmit = vec4(0.0);
  if (uDebug == 1) { color = vec4(0.5 + 0.5 * g.rg, 0.5, 1.0); return; }
  if (uDebug == 2) { color = vec4(0.5 + 0.5 * (toWorld * n), 1.0); return; }
  if (uDebug == 3) { color = vec4(vec3(g.b / uThicknessScale), 1.0); return; }
  if (uDebug == 4) { color = vec4(vec3((g.a - uDepthRange.x) / (uDepthRange.y - uDepthRange.x)), 1.0); return; }

  const float foam = uFoamOn != 0 ? smoothstep(0.15, 0.6, texelFetch(uFoam, px, 0).r) : 0.0;
  const float diffuse = max(dot(n, uLightView), 0.0);
  const float highlight = pow(max(dot(reflect(-uLightView, n), v), 0.0), 60.0);
  if (uMode == 0) {
    const vec3 albedo = mix(uWaterColor, kFoamColor, foam);
    color = vec4(albedo * (0.35 + 0.65 * diffuse) + 0.2 * uSpecular * highlight, 1.0);
    return;
  }
  // Beer–Lambert: sigma = -absorption ln(waterColor) per channel, so T = waterColor^(absorption d).
  vec3 through = pow(max(uWaterColor, vec3(1e-3)), vec3(uAbsorption * g.b));
  // Light scattered back toward the eye takes the water colour, in proportion to what is absorbed.
  vec3 body = uWaterColor * (0.5 + 0.7 * diffuse) * (1.0 - dot(through, vec3(1.0 / 3.0)));
  body = mix(body, kFoamColor * (0.6 + 0.4 * diffuse), foam);
  through *= 1.0 - foam;
  const float cosine = clamp(dot(n, v), 0.0, 1.0);
  const float fresnel = uF0 + (1.0 - uF0) * pow(1.0 - cosine, 5.0);
  const vec3 reflected = sky(toWorld * reflect(-v, n));
  color = vec4(fresnel * reflected + (1.0 - fresnel) * body + uSpecular * highlight, 1.0);
  transmit = vec4((1.0 - fresnel) * through, 1.0);
}
