// Heightfield ray casting for the 3D ripples view (raycast.comp). The water surface is
// the bilinear interpolation of the cell heights that surfaceZ() samples, so over one dual cell
// (the square between four cell centres) the surface height along a ray is a quadratic in t and
// the crossing is solved exactly: no step size to tune, no thin crest missed. Tiles of dual
// cells with their height range (tiles.comp) let the ray skip the water it passes above
// or below, one tile at a time (Amanatides & Woo 1987 grid traversal, on both levels).
// Grid coordinates: q = xy * size.x + 0.5 along both axes, dual cell k = floor(q) in [0, size];
// dual cell k spans cell centres k-1 .. k (heightAt clamps the edge ones).
#ifndef RENDER_RIPPLES_TRACE_GLSL
#define RENDER_RIPPLES_TRACE_GLSL

#include "common/ordered_float.glsl"
#include "render/ripples/view_3d.glsl"
#include "render/ripples/bindings.glsl"

layout(std430, binding = RIPPLES_VIEW_TILES) readonly buffer Tiles { vec2 tiles[]; };  // min, max height m
layout(std430, binding = RIPPLES_VIEW_RANGE) readonly buffer Range { uint range[2]; };
uniform ivec2 uTiles;  // tiles along x and y

const float kHuge = 3.0e38;

struct GridRay {
  vec3 origin, dir;  // world, dir unit
  vec2 q0, dq;       // grid coordinates at t = 0 and their change per unit t
  bvec2 moving;      // dq is not ~0
  vec2 invDq;        // 1 / dq where moving
  ivec2 stepDir;     // sign of dq where moving, else 0
};

GridRay gridRay(vec3 origin, vec3 dir) {
  GridRay r;
  r.origin = origin;
  r.dir = dir;
  const float s = float(uSize.x);
  r.q0 = origin.xy * s + 0.5;
  r.dq = dir.xy * s;
  r.moving = greaterThan(abs(r.dq), vec2(1e-12));
  r.invDq = vec2(r.moving.x ? 1.0 / r.dq.x : 0.0, r.moving.y ? 1.0 / r.dq.y : 0.0);
  r.stepDir = ivec2(sign(r.dq)) * ivec2(r.moving);
  return r;
}

// Ray parameters where the ray crosses the far edges of `cell` (side `side` in grid units).
vec2 boundaryT(GridRay ray, ivec2 cell, float side) {
  const vec2 bound = (vec2(cell) + step(0.0, ray.dq)) * side;
  return mix(vec2(kHuge), (bound - ray.q0) * ray.invDq, ray.moving);
}

// One step of the traversal (Amanatides & Woo): into the neighbour across the edge the ray
// crosses first; that axis's next crossing lies tDelta further on.
void stepCell(GridRay ray, vec2 tDelta, inout ivec2 cell, inout vec2 tNext) {
  if (tNext.x < tNext.y) {
    cell.x += ray.stepDir.x;
    tNext.x += tDelta.x;
  } else {
    cell.y += ray.stepDir.y;
    tNext.y += tDelta.y;
  }
}

// Smallest root of c + b t + a t^2 in [0, len], or -1. A little slack at both ends: a crossing
// on a cell edge belongs to either cell.
float firstRoot(float a, float b, float c, float len) {
  const float slack = 1e-3 * len;
  const float disc = b * b - 4.0 * a * c;
  if (disc >= 0.0) {
    const float q = -0.5 * (b + (b < 0.0 ? -sqrt(disc) : sqrt(disc)));  // no cancellation
    float r1 = q != 0.0 ? c / q : -1.0;
    float r2 = a != 0.0 ? q / a : -1.0;
    if (r2 < r1) {
      const float s = r1;
      r1 = r2;
      r2 = s;
    }
    if (r1 >= -slack && r1 <= len + slack) return clamp(r1, 0.0, len);
    if (r2 >= -slack && r2 <= len + slack) return clamp(r2, 0.0, len);
  }
  // Round-off can hide a crossing that the end values show.
  const float end = c + (b + a * len) * len;
  return (c <= 0.0) != (end <= 0.0) ? len * c / (c - end) : -1.0;
}

// First t in [ta, tb] where the ray meets the bilinear surface over dual cell k, or -1.
float patchHit(GridRay ray, ivec2 k, float ta, float tb) {
  const float z00 = worldZ(heightAt(k - 1)), z10 = worldZ(heightAt(k + ivec2(0, -1)));
  const float z01 = worldZ(heightAt(k + ivec2(-1, 0))), z11 = worldZ(heightAt(k));
  const vec2 f = ray.q0 + ta * ray.dq - vec2(k);  // position in the patch at ta, ~[0,1]^2
  const vec2 g = ray.dq;
  const float e1 = z10 - z00, e2 = z01 - z00, e3 = z00 - z10 - z01 + z11;
  // Surface height along the ray: s0 + s1 (t - ta) + s2 (t - ta)^2.
  const float s0 = z00 + e1 * f.x + e2 * f.y + e3 * f.x * f.y;
  const float s1 = e1 * g.x + e2 * g.y + e3 * (f.x * g.y + f.y * g.x);
  const float s2 = e3 * g.x * g.y;
  const float r = firstRoot(-s2, ray.dir.z - s1, ray.origin.z + ta * ray.dir.z - s0, tb - ta);
  return r < 0.0 ? -1.0 : ta + r;
}

// First crossing in [ta, tb], the ray's stretch over one tile, dual cell by dual cell; or -1.
float traceTile(GridRay ray, ivec2 tile, float ta, float tb) {
  const ivec2 lo = tile * RIPPLES_VIEW_TILE, hi = min(lo + (RIPPLES_VIEW_TILE - 1), uSize);
  ivec2 k = clamp(ivec2(floor(ray.q0 + ta * ray.dq)), lo, hi);
  vec2 tNext = boundaryT(ray, k, 1.0);
  const vec2 tDelta = abs(ray.invDq);
  for (int i = 0; i < 2 * RIPPLES_VIEW_TILE + 2; ++i) {
    const float t1 = min(min(tNext.x, tNext.y), tb);
    if (t1 >= ta) {
      const float t = patchHit(ray, k, ta, t1);
      if (t >= 0.0) return t;
    }
    if (t1 >= tb) break;
    stepCell(ray, tDelta, k, tNext);
    if (any(lessThan(k, lo)) || any(greaterThan(k, hi))) break;
    ta = max(ta, t1);
  }
  return -1.0;
}

// World z range of the whole surface (tiles.comp's atomics).
vec2 surfaceRange() { return vec2(worldZ(fromOrderedBits(range[0])), worldZ(fromOrderedBits(range[1]))); }

// First crossing of the water surface in [ta, tb] (a stretch inside the tank), or -1.
float traceSurface(GridRay ray, float ta, float tb) {
  const float side = float(RIPPLES_VIEW_TILE);
  const float eps = 1e-6;  // world z: flat tiles have min = max
  ivec2 tile = clamp(ivec2(floor((ray.q0 + ta * ray.dq) / side)), ivec2(0), uTiles - 1);
  vec2 tNext = boundaryT(ray, tile, side);
  const vec2 tDelta = side * abs(ray.invDq);
  for (int i = 0; i < 2 * (uTiles.x + uTiles.y) + 4; ++i) {
    const float t1 = min(min(tNext.x, tNext.y), tb);
    const vec2 bounds = tiles[tile.y * uTiles.x + tile.x];
    const float za = ray.origin.z + ta * ray.dir.z, zb = ray.origin.z + t1 * ray.dir.z;
    if (t1 >= ta && max(za, zb) >= worldZ(bounds.x) - eps && min(za, zb) <= worldZ(bounds.y) + eps) {
      const float t = traceTile(ray, tile, ta, t1);
      if (t >= 0.0) return t;
    }
    if (t1 >= tb) break;
    stepCell(ray, tDelta, tile, tNext);
    if (any(lessThan(tile, ivec2(0))) || any(greaterThanEqual(tile, uTiles))) break;
    ta = max(ta, t1);
  }
  return -1.0;
}

#endif
