#include "sim/water/mesh_solid.h"

#include <algorithm>
#include <cmath>

#include "sim/water/water_init.h"

namespace tidepool::water {
namespace {

constexpr int kBinsPerAxis = 32;  // yz bins of triangles for the rows

// Which side of the projected edge a -> b the point p lies on: > 0 left, < 0 right, never 0.
// Evaluated with the edge in one canonical direction, so the two triangles sharing it see the
// same number; a point on the edge is moved by a symbolic (ε, ε²) to decide.
double edgeSide(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const bool swap = b.x < a.x || (b.x == a.x && b.y < a.y);
  if (swap) std::swap(a, b);
  double s = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
  if (s == 0) s = a.y != b.y ? -(b.y - a.y) : (b.x - a.x);  // d/dε at p + (ε, ε²), then d/dε²
  return swap ? -s : s;
}

// Unperturbed edge function, for the barycentric weights of the crossing.
double edgeValue(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

}  // namespace

io::TriangleMesh placeMesh(const io::TriangleMesh& mesh, glm::vec3 centre, glm::vec3 size,
                           const glm::mat3& orientation) {
  const glm::vec3 lo = mesh.boundsMin(), hi = mesh.boundsMax(), half = 0.5f * (hi - lo), middle = 0.5f * (hi + lo);
  float scale = 1e30f;
  for (int k = 0; k < 3; ++k)
    if (half[k] > 0) scale = std::min(scale, size[k] / half[k]);
  if (scale == 1e30f) scale = 0.0f;
  io::TriangleMesh out = mesh;
  for (glm::vec3& v : out.vertices) v = centre + orientation * (scale * (v - middle));
  return out;
}

MeshSolid::MeshSolid(io::TriangleMesh placed) : m_mesh(std::move(placed)) {
  m_lo = m_mesh.boundsMin();
  m_hi = m_mesh.boundsMax();
  const glm::vec2 extent = glm::max(glm::vec2(m_hi.y - m_lo.y, m_hi.z - m_lo.z), glm::vec2(1e-12f));
  m_bins = glm::ivec2(kBinsPerAxis);
  m_binSize = extent / glm::vec2(m_bins);
  m_binTriangles.assign(std::size_t(m_bins.x * m_bins.y), {});
  auto bin = [&](float y, float z) {
    return glm::clamp(glm::ivec2(glm::floor((glm::vec2(y, z) - glm::vec2(m_lo.y, m_lo.z)) / m_binSize)), glm::ivec2(0),
                      m_bins - 1);
  };
  for (std::size_t t = 0; t < m_mesh.triangles.size(); ++t) {
    glm::vec3 a = m_mesh.vertices[m_mesh.triangles[t].x], b = m_mesh.vertices[m_mesh.triangles[t].y],
              c = m_mesh.vertices[m_mesh.triangles[t].z];
    const glm::ivec2 from = bin(std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z}));
    const glm::ivec2 to = bin(std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z}));
    for (int j = from.y; j <= to.y; ++j)
      for (int i = from.x; i <= to.x; ++i) m_binTriangles[std::size_t(i + m_bins.x * j)].push_back(unsigned(t));
  }
}

const std::vector<float>& MeshSolid::row(float y, float z) const {
  const auto key = std::make_pair(y, z);
  if (auto it = m_rows.find(key); it != m_rows.end()) return it->second;
  std::vector<float> hits;
  const glm::ivec2 b = glm::clamp(glm::ivec2(glm::floor((glm::vec2(y, z) - glm::vec2(m_lo.y, m_lo.z)) / m_binSize)),
                                  glm::ivec2(0), m_bins - 1);
  const glm::dvec2 p(y, z);
  for (unsigned t : m_binTriangles[std::size_t(b.x + m_bins.x * b.y)]) {
    const glm::uvec3 tri = m_mesh.triangles[t];
    const glm::vec3 a = m_mesh.vertices[tri.x], bb = m_mesh.vertices[tri.y], c = m_mesh.vertices[tri.z];
    const glm::dvec2 pa(a.y, a.z), pb(bb.y, bb.z), pc(c.y, c.z);
    const double sa = edgeSide(pb, pc, p), sb = edgeSide(pc, pa, p), sc = edgeSide(pa, pb, p);
    if (!((sa > 0 && sb > 0 && sc > 0) || (sa < 0 && sb < 0 && sc < 0))) continue;
    // Barycentric weights from the unperturbed edge values (a point on an edge gets weight 0 there).
    const double wa = edgeValue(pb, pc, p), wb = edgeValue(pc, pa, p), wc = edgeValue(pa, pb, p);
    const double sum = wa + wb + wc;
    if (sum == 0) continue;  // no projected area: a generic ray misses it
    hits.push_back(float((wa * a.x + wb * bb.x + wc * c.x) / sum));
  }
  std::sort(hits.begin(), hits.end());
  if (hits.size() % 2) hits.pop_back();  // an open mesh: the last crossing has no partner
  return m_rows.emplace(key, std::move(hits)).first->second;
}

bool MeshSolid::inside(glm::vec3 q) const {
  if (glm::any(glm::lessThan(q, m_lo)) || glm::any(glm::greaterThan(q, m_hi))) return false;
  const std::vector<float>& segments = row(q.y, q.z);
  for (std::size_t k = 0; k + 1 < segments.size(); k += 2)
    if (q.x >= segments[k] && q.x <= segments[k + 1]) return true;
  return false;
}

float MeshSolid::distance(glm::vec3 q, float limit) const {
  if (glm::any(glm::lessThan(q, m_lo - limit)) || glm::any(glm::greaterThan(q, m_hi + limit))) return limit;
  float best = limit;
  for (const glm::uvec3& t : m_mesh.triangles) {
    const glm::vec3 a = m_mesh.vertices[t.x], b = m_mesh.vertices[t.y], c = m_mesh.vertices[t.z];
    if (glm::any(glm::lessThan(q + best, glm::min(a, glm::min(b, c)))) ||
        glm::any(glm::greaterThan(q - best, glm::max(a, glm::max(b, c)))))
      continue;  // its bounds are farther than the best so far
    best = std::min(best, pointTriangleDistance(q, a, b, c));
  }
  return best;
}

std::vector<glm::vec3> meshLatticePoints(const MeshSolid& solid, float r, bool shell) {
  const io::TriangleMesh& m = solid.mesh();
  glm::vec3 lo = m.boundsMin() - r, hi = m.boundsMax() + r;
  if (shell) {
    // Whole lattice periods (x: 2r, y: 2 rows, z: 4 layers) keep the points of the solid's lattice.
    const glm::vec3 period(2 * r, 2 * r * std::sqrt(3.0f), 8 * r * std::sqrt(6.0f) / 3);
    lo -= period;
    hi += period;
  }
  std::vector<glm::vec3> out;
  const float band = kShellHalfWidth * r;
  for (const glm::vec3& q : hcpLattice(lo, hi, r))
    if (shell ? solid.distance(q, band) < band : solid.inside(q)) out.push_back(q);
  return out;
}

float pointTriangleDistance(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  // Closest point by Voronoi region of the triangle.
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return glm::length(p - a);
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return glm::length(p - b);
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return glm::length(p - c);
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
  const float denom = 1.0f / (va + vb + vc);
  return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

}  // namespace tidepool::water
