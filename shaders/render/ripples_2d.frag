#version 430 core
// Top view of the ripples heightfield after water-simulation-gpu's 2D renderer: the eye looks
// straight down, the view ray refracts through the surface normal onto a tiled floor at depth
// uFloorDepth, water colour deepens with the refracted path length, plus a specular glint.
// The state SSBO is read directly; normals come from central differences interpolated
// bilinearly between cells, so the picture stays smooth when a cell covers several pixels.
#include "render/ripples_surface.glsl"

uniform vec2 uUvScale;       // screen uv -> grid uv (aspect-preserving "cover")
uniform vec2 uUvOffset;
uniform float uSlopeScale;   // exaggerates slopes: 1 = physical (height m / cell size m)
uniform float uFloorDepth;   // in grid widths
uniform float uEta;          // refraction index ratio air/water (seed: 0.9)
uniform vec3 uWaterColor;
uniform float uViewDistance; // refracted path length (grid widths) at which the water is opaque
uniform vec3 uLightDir;
uniform float uTileRepeat;   // floor tiles across the grid
uniform sampler2D uFloor;
uniform vec4 uSphere;        // xy: centre (grid uv), z: radius (grid widths), w: centre height / radius; z = 0: none

in vec2 vUv;
out vec4 fragColor;

void main() {
  const vec2 uv = vUv * uUvScale + uUvOffset;
  const vec3 n = normalize(vec3(-slopeBilinear(uv) * uSlopeScale, 1.0));
  const vec3 eye = vec3(0.0, 0.0, -1.0);
  vec3 r = refract(eye, n, uEta);
  vec3 color = uWaterColor;
  if (r.z < 0.0) {
    r *= uFloorDepth / -r.z;
    const vec3 ground = texture(uFloor, (uv + r.xy) * uTileRepeat).rgb;
    color = mix(ground, uWaterColor, clamp(length(r) / uViewDistance, 0.0, 1.0));
  }
  const float glint = smoothstep(0.98, 1.0, dot(reflect(normalize(uLightDir), n), -eye));
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
  fragColor = vec4(color, 1.0);
}
