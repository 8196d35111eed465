// What the two particle fragment shaders share (disc.frag from a pixel per world unit up,
// point.frag below): a particle adds its colour into the HDR image (blend SRC_ALPHA + ONE)
// weighted by the part of the pixel it covers, so its total brightness is pi·R^2 in both.
in vec2 vOffset;        // from the particle, world units
flat in vec3 vColor;    // the species' colour
uniform float uRadius;  // world units
uniform float uPixelsPerUnit;
uniform float uExposure;
out vec4 fragColor;

// alpha: the pixel's coverage by the particle, in [0, 1]; nothing is written where it is 0.
void writeCoverage(float alpha) {
  if (alpha <= 0.0) discard;
  fragColor = vec4(vColor * uExposure, alpha);
}
