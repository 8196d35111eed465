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
  fragColor = vec4(color + vec3(glint), 1.0);
}
