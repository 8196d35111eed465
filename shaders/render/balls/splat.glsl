// Compute rasteriser of the balls' sphere impostors, shared by its three kernels (splat_depth.comp,
// splat_id.comp, splat_resolve.comp; the first two walk the pixels with splat_walk.glsl). On GPUs
// with few raster units (the H100) the fragment path's quads are raster-bound; here the shader cores do
// the coverage: each ball bounds its silhouette in pixels, then intersects the eye ray through
// every pixel centre in that box with the sphere, as the fragment path does per fragment.
//
// Per-pixel state lives in two uint SSBOs (GL 4.3 has neither 64-bit nor float atomics):
//   keys[p]       kEmpty, then (depth pass) the least window-depth bits of a ball covering p
//                 (window depths in [0, 1) are positive floats, whose bits order as uints), then
//                 (id pass) kTag | the id of the ball with that depth; the resolve reads it and
//                 puts kEmpty back for the next frame
//   thickness[p]  sum of chord lengths in units of uThicknessUnit (m), same reset
// Packing depth and id into one 32-bit key would leave 12 bits of depth for a million balls,
// so the id takes a second pass over the balls instead.
//
// Balls whose box holds more than SMALL_PIXELS pixels go to a list drawn by one work group per
// ball (an indirect dispatch), so a close-up ball does not keep one thread looping for ages.
#include "render/balls/bindings.glsl"

#define SMALL_PIXELS 256
#define BIG_GROUP 256
const uint kEmpty = 0xFFFFFFFFu;
const uint kTag = 0x80000000u;  // above the bits of any window depth in [0, 1)

layout(std430, binding = BALLS_VIEW_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = BALLS_VIEW_SPLAT_KEYS) buffer Keys { uint keys[]; };
// Header for glDispatchComputeIndirect (groups, 1, 1), a flag set when the list was full, the list.
layout(std430, binding = BALLS_VIEW_SPLAT_BIG) buffer Big {
  uint bigGroups;
  uint bigY, bigZ;
  uint bigOverflow;
  uint bigList[];
};

uniform mat4 uModelView;   // simulation -> view
uniform vec2 uProjDepth;   // proj[2][2], proj[3][2]: window depth from view depth
uniform vec2 uFocal;       // proj[0][0], proj[1][1] (a symmetric projection, as the compose assumes)
uniform int uOrtho;        // 1: orthographic (glm::ortho): rays along -z from the plane z = 0
uniform ivec2 uSize;       // image px
uniform float uRadius;     // m
uniform uint uCount;       // balls
uniform uint uBigCapacity; // entries bigList holds

vec3 ballCentre(uint ball) { return (uModelView * vec4(positions[ball].xyz, 1.0)).xyz; }

// Pixel range [lo, hi] along one image axis holding the sphere's silhouette: the planes through
// the eye and the other axis tangent to the sphere have slopes s (x = s * depth) solving
// (c - s z)^2 = r^2 (1 + s^2); z: view depth of the centre (m, > r). One pixel of margin.
ivec2 axisRange(float c, float z, float focal, int size) {
  const float r2 = uRadius * uRadius;
  const float w = uRadius * sqrt(max(c * c + z * z - r2, 0.0));
  const float inv = 1.0 / (z * z - r2);
  const float sLo = (c * z - w) * inv, sHi = (c * z + w) * inv;
  const float halfSize = 0.5 * float(size);
  return ivec2(floor(halfSize * (sLo * focal + 1.0) - 0.5) - 1.0, ceil(halfSize * (sHi * focal + 1.0) - 0.5) + 1.0);
}

// The ball's pixel box (inclusive, clipped to the image); false when nothing can be drawn: the
// eye is inside or behind the ball's front, or it lies wholly outside the depth range or image.
// A ball straddling the eye plane gets the whole image (the big path draws it).
bool footprint(vec3 centre, out ivec2 lo, out ivec2 hi) {
  const float z = -centre.z;
  const float near = uOrtho != 0 ? (uProjDepth.y + 1.0) / uProjDepth.x : uProjDepth.y / (uProjDepth.x - 1.0);
  const float far = uOrtho != 0 ? (uProjDepth.y - 1.0) / uProjDepth.x : uProjDepth.y / (uProjDepth.x + 1.0);
  if (z + uRadius <= near || z - uRadius >= far) return false;
  if (uOrtho != 0) {
    // Parallel rays: the silhouette is the disc of radius r around the centre's pixel.
    const vec2 halfSize = 0.5 * vec2(uSize);
    const vec2 a = halfSize * ((centre.xy - uRadius) * uFocal + 1.0) - 0.5;
    const vec2 b = halfSize * ((centre.xy + uRadius) * uFocal + 1.0) - 0.5;
    lo = max(ivec2(floor(a)) - 1, ivec2(0));
    hi = min(ivec2(ceil(b)) + 1, uSize - 1);
  } else if (dot(centre, centre) <= 1.001 * 1.001 * uRadius * uRadius) {
    return false;
  } else if (z > uRadius * 1.001) {
    const ivec2 x = axisRange(centre.x, z, uFocal.x, uSize.x), y = axisRange(centre.y, z, uFocal.y, uSize.y);
    lo = max(ivec2(x.x, y.x), ivec2(0));
    hi = min(ivec2(x.y, y.y), uSize - 1);
  } else {
    lo = ivec2(0);
    hi = uSize - 1;
  }
  return all(lessThanEqual(lo, hi));
}

struct SplatHit {
  float depth;   // view depth of the front point, m
  float window;  // its window depth, in [0, 1)
  float chord;   // length of the eye ray inside the ball, m
  vec3 normal;   // view space, unit
};

// The eye ray through pixel px's centre against the ball; false when it misses or the front
// point is outside the depth range. The ray origin + t dir, dir = (ndc / focal, -1) from the eye
// (perspective) or (0, 0, -1) from (ndc / focal, 0) (orthographic), reaches view depth t at
// parameter t. `precise`: the depth and id passes must compute the same bits for one pixel.
bool splatHit(ivec2 px, vec3 centre, out SplatHit hit) {
  const vec2 ndc = 2.0 * (vec2(px) + 0.5) / vec2(uSize) - 1.0;
  precise vec3 origin = uOrtho != 0 ? vec3(ndc / uFocal, 0.0) : vec3(0.0);
  precise vec3 dir = uOrtho != 0 ? vec3(0.0, 0.0, -1.0) : vec3(ndc / uFocal, -1.0);
  precise float a = dot(dir, dir);
  precise float along = dot(dir, centre - origin) / a;  // ray parameter of the point nearest the centre
  precise vec3 off = origin + along * dir - centre;
  precise float h2 = uRadius * uRadius - dot(off, off);  // (half chord)^2 * a
  if (h2 < 0.0) return false;
  precise float halfChord = sqrt(h2 / a);
  precise float depth = along - halfChord;
  precise float ndcZ = uOrtho != 0 ? uProjDepth.y - uProjDepth.x * depth : uProjDepth.y / depth - uProjDepth.x;
  precise float window = 0.5 * ndcZ + 0.5;
  if (!(window >= 0.0 && window < 1.0)) return false;
  hit.depth = depth;
  hit.window = window;
  hit.chord = 2.0 * halfChord * sqrt(a);
  hit.normal = (origin + depth * dir - centre) / uRadius;
  return true;
}

uint pixelIndex(ivec2 px) { return uint(px.y * uSize.x + px.x); }
