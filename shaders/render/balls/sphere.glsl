// Ray-traced sphere impostors, shared by the G-buffer and thickness passes (gbuffer.vert and
// sphere_fragment.glsl).
//
// Each ball is one quad (6 vertices from gl_VertexID) facing the eye, perpendicular to the ray
// through the ball's centre and placed at the sphere's nearest point, sized to the tangent cone:
// it covers the exact perspective silhouette and lies in front of every visible surface point,
// so the fragment depth only grows (layout(depth_greater) keeps early depth rejection).
// The fragment intersects its eye ray with the sphere: exact silhouette, depth, normal and chord.
// Orthographic cameras (`ortho`): every eye ray runs along -z from the plane z = 0, so the quad
// faces +z, lies at the sphere's front and is the sphere's size.
#include "render/balls/bindings.glsl"

layout(std430, binding = BALLS_VIEW_POSITIONS) readonly buffer Positions { vec4 positions[]; };

const vec2 kCorners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

// View-space corner `corner` (0..5) of ball `ball`'s quad; w = 0 culls (eye inside the ball).
vec4 sphereQuadCorner(int ball, int corner, mat4 modelView, float radius, bool ortho, out vec3 centreView) {
  centreView = (modelView * vec4(positions[ball].xyz, 1.0)).xyz;
  if (ortho) return vec4(centreView + vec3(1.01 * radius * kCorners[corner], radius), 1.0);
  const float d = length(centreView);
  if (d <= radius * 1.001) return vec4(0.0);
  const vec3 w = centreView / d;  // eye -> centre
  const vec3 u = normalize(abs(w.y) < 0.99 ? cross(w, vec3(0, 1, 0)) : cross(w, vec3(1, 0, 0)));
  const vec3 v = cross(u, w);
  // Tangent cone half-angle a: sin a = r/d. At distance d - r along w its radius is (d - r) tan a;
  // 1% margin for the rasteriser.
  const float halfSize = 1.01 * (d - radius) * radius / sqrt(d * d - radius * radius);
  const vec2 c = kCorners[corner];
  return vec4(w * (d - radius) + halfSize * (c.x * u + c.y * v), 1.0);
}

struct SphereHit {
  vec3 point;   // view space, m
  vec3 normal;  // view space, unit
  float chord;  // length of the eye ray inside the sphere, m
};

// Eye ray through `quadPoint` (view space) against the sphere; false when it misses.
bool intersectSphere(vec3 quadPoint, vec3 centre, float radius, bool ortho, out SphereHit hit) {
  const vec3 origin = ortho ? vec3(quadPoint.xy, 0.0) : vec3(0.0);
  const vec3 dir = ortho ? vec3(0.0, 0.0, -1.0) : normalize(quadPoint);
  const float b = dot(dir, centre - origin);
  // (half chord)^2 from the ray's distance to the centre, not as b^2 - |c|^2 + r^2: that form
  // cancels (metres squared of which r^2 is a ten-thousandth) and adds millimetres of chord at
  // the silhouettes.
  const vec3 off = origin + b * dir - centre;
  const float disc = radius * radius - dot(off, off);
  if (disc < 0.0) return false;
  const float root = sqrt(disc);
  hit.point = origin + (b - root) * dir;
  hit.normal = (hit.point - centre) / radius;
  hit.chord = 2.0 * root;
  return true;
}

// Whether `proj` is glm::ortho's (last row 0, 0, 0, 1) rather than glm::perspective's (0, 0, -1, 0).
bool isOrthographic(mat4 proj) { return proj[3][3] == 1.0; }

// Window depth of a view-space point (default glDepthRange 0..1).
float windowDepth(mat4 proj, vec3 p) {
  const vec4 clip = proj * vec4(p, 1.0);
  return 0.5 * clip.z / clip.w + 0.5;
}
