#include "render/obstacle_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <tuple>

namespace tidepool {
namespace {

// Distance to the union of the balls, exact within 2r of a ball; farther points read 2r.
class UnionDistance {
 public:
  UnionDistance(const std::vector<glm::vec4>& balls, float radius, glm::vec3 lo, glm::vec3 hi)
      : m_balls(balls), m_radius(radius), m_cell(2.0f * radius), m_lo(lo) {
    m_dims = glm::ivec3(glm::floor((hi - lo) / m_cell)) + 1;
    m_start.assign(std::size_t(m_dims.x) * m_dims.y * m_dims.z + 1, 0);
    for (const glm::vec4& b : balls) ++m_start[bucket(cellOf(glm::vec3(b)))];
    for (std::size_t i = 1; i < m_start.size(); ++i) m_start[i] += m_start[i - 1];  // inclusive
    m_order.resize(balls.size());
    for (std::size_t i = 0; i < balls.size(); ++i) m_order[--m_start[bucket(cellOf(glm::vec3(balls[i])))]] = int(i);
  }

  float operator()(glm::vec3 q) const {
    const glm::ivec3 c = cellOf(q);
    float best = m_cell + m_radius;
    for (int z = std::max(c.z - 1, 0); z <= std::min(c.z + 1, m_dims.z - 1); ++z)
      for (int y = std::max(c.y - 1, 0); y <= std::min(c.y + 1, m_dims.y - 1); ++y)
        for (int x = std::max(c.x - 1, 0); x <= std::min(c.x + 1, m_dims.x - 1); ++x) {
          const std::size_t b = bucket({x, y, z});
          for (int i = m_start[b]; i < m_start[b + 1]; ++i)
            best = std::min(best, glm::length(q - glm::vec3(m_balls[std::size_t(m_order[std::size_t(i)])])));
        }
    return std::min(best - m_radius, m_cell);
  }

 private:
  glm::ivec3 cellOf(glm::vec3 q) const {
    return glm::clamp(glm::ivec3(glm::floor((q - m_lo) / m_cell)), glm::ivec3(0), m_dims - 1);
  }
  std::size_t bucket(glm::ivec3 c) const { return (std::size_t(c.z) * m_dims.y + c.y) * m_dims.x + c.x; }

  const std::vector<glm::vec4>& m_balls;
  float m_radius, m_cell;
  glm::vec3 m_lo;
  glm::ivec3 m_dims;
  std::vector<int> m_start, m_order;  // balls of bucket b: m_order[m_start[b] .. m_start[b + 1])
};

// Taubin's λ|μ smoothing (1995): a shrinking Laplacian step, then an inflating one. It takes out
// the balls' bumps (a wavelength of two grid cells) and keeps the shape's size.
void smooth(std::vector<glm::vec3>& positions, const std::vector<int>& triangles) {
  std::vector<std::vector<int>> neighbours(positions.size());
  for (std::size_t t = 0; t < triangles.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      neighbours[std::size_t(triangles[t + k])].push_back(triangles[t + (k + 1) % 3]);
      neighbours[std::size_t(triangles[t + (k + 1) % 3])].push_back(triangles[t + k]);
    }
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  constexpr int kRounds = 10;
  constexpr float kShrink = 0.5f, kInflate = -0.53f;
  std::vector<glm::vec3> next(positions.size());
  for (int round = 0; round < 2 * kRounds; ++round) {
    const float factor = round % 2 == 0 ? kShrink : kInflate;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      glm::vec3 mean(0.0f);
      for (int j : neighbours[i]) mean += positions[std::size_t(j)];
      next[i] = neighbours[i].empty() ? positions[i]
                                      : positions[i] + factor * (mean / float(neighbours[i].size()) - positions[i]);
    }
    positions.swap(next);
  }
}

}  // namespace

std::vector<MeshVertex> fileMesh(const io::TriangleMesh& mesh) {
  std::vector<MeshVertex> out;
  out.reserve(3 * mesh.triangles.size());
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 a = mesh.vertices[t.x], b = mesh.vertices[t.y], c = mesh.vertices[t.z];
    const glm::vec3 cross = glm::cross(b - a, c - a);
    const float length = glm::length(cross);
    const glm::vec4 normal(length > 0.0f ? cross / length : glm::vec3(0.0f, 0.0f, 1.0f), 0.0f);
    for (const glm::vec3& v : {a, b, c}) out.push_back({glm::vec4(v, 1.0f), normal});
  }
  return out;
}

std::vector<MeshVertex> ballUnionMesh(const std::vector<glm::vec4>& balls, float radius) {
  if (balls.empty()) return {};
  const float h = radius;  // grid spacing
  // The union of balls 1.5x larger has no gaps between packed balls (the largest hole of a close
  // packing is 1.41 r from its balls) and shallower dimples; the surface moves back by 0.5 r at the
  // end.
  const float grown = 1.5f * radius;
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec4& b : balls) lo = glm::min(lo, glm::vec3(b)), hi = glm::max(hi, glm::vec3(b));
  lo -= grown + 2.0f * h;  // two samples of outside all round: the surface never meets the border
  hi += grown + 2.0f * h;
  const glm::ivec3 n = glm::ivec3(glm::ceil((hi - lo) / h)) + 1;
  const auto point = [&](int x, int y, int z) { return (std::size_t(z) * n.y + y) * n.x + x; };
  const auto position = [&](int x, int y, int z) { return lo + h * glm::vec3(x, y, z); };

  const UnionDistance distance(balls, grown, lo, hi);
  std::vector<float> d(std::size_t(n.x) * n.y * n.z);
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) d[point(x, y, z)] = distance(position(x, y, z));

  // The gaps between packed balls (and a shell obstacle's hollow) are closed pockets: fill every
  // outside sample the border cannot reach, so only the outer surface is meshed.
  std::vector<char> reached(d.size(), 0);
  std::vector<glm::ivec3> stack = {{0, 0, 0}};
  reached[0] = 1;
  while (!stack.empty()) {
    const glm::ivec3 p = stack.back();
    stack.pop_back();
    for (const glm::ivec3 step : {glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0), glm::ivec3(0, -1, 0),
                                  glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)}) {
      const glm::ivec3 q = p + step;
      if (glm::any(glm::lessThan(q, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(q, n))) continue;
      const std::size_t i = point(q.x, q.y, q.z);
      if (reached[i] || d[i] < 0.0f) continue;
      reached[i] = 1;
      stack.push_back(q);
    }
  }
  for (std::size_t i = 0; i < d.size(); ++i)
    if (!reached[i] && d[i] >= 0.0f) d[i] = -0.5f * h;

  // One vertex per cube the surface crosses: the mean of the crossings on its twelve edges.
  const glm::ivec3 cubes = n - 1;
  const auto cube = [&](int x, int y, int z) { return (std::size_t(z) * cubes.y + y) * cubes.x + x; };
  std::vector<int> vertexOf(std::size_t(cubes.x) * cubes.y * cubes.z, -1);
  std::vector<glm::vec3> positions;
  for (int z = 0; z < cubes.z; ++z)
    for (int y = 0; y < cubes.y; ++y)
      for (int x = 0; x < cubes.x; ++x) {
        std::array<float, 8> v;
        int inside = 0;
        for (int c = 0; c < 8; ++c) {
          v[c] = d[point(x + (c & 1), y + ((c >> 1) & 1), z + (c >> 2))];
          inside += v[c] < 0.0f;
        }
        if (inside == 0 || inside == 8) continue;
        glm::vec3 sum(0.0f);
        int crossings = 0;
        for (int a = 0; a < 8; ++a)
          for (int axis = 0; axis < 3; ++axis) {
            const int b = a | (1 << axis);
            if (b == a || (v[a] < 0.0f) == (v[b] < 0.0f)) continue;
            const glm::vec3 pa(a & 1, (a >> 1) & 1, a >> 2), pb(b & 1, (b >> 1) & 1, b >> 2);
            sum += pa + (pb - pa) * (v[a] / (v[a] - v[b]));
            ++crossings;
          }
        vertexOf[cube(x, y, z)] = int(positions.size());
        positions.push_back(position(x, y, z) + h * sum / float(crossings));
      }

  // One quad per crossed grid edge, joining the vertices of the four cubes around it.
  std::vector<int> triangles;

  for (int z = 1; z < n.z - 1; ++z)
    for (int y = 1; y < n.y - 1; ++y)
      for (int x = 1; x < n.x - 1; ++x) {
        const glm::ivec3 p(x, y, z);
        const bool in = d[point(x, y, z)] < 0.0f;
        for (int axis = 0; axis < 3; ++axis) {
          glm::ivec3 q = p;
          ++q[axis];
          if (in == (d[point(q.x, q.y, q.z)] < 0.0f)) continue;
          const int u = (axis + 1) % 3, w = (axis + 2) % 3;
          // The cubes around the edge, counter-clockwise about +axis (axis, u, w right-handed); the
          // quad faces +axis when the edge leaves the inside, -axis (reversed) when it enters.
          std::array<int, 4> quad;
          for (int k = 0; k < 4; ++k) {
            glm::ivec3 c = p;
            c[u] -= (k == 1 || k == 2) ? 1 : 0;
            c[w] -= (k >= 2) ? 1 : 0;
            quad[std::size_t(k)] = vertexOf[cube(c.x, c.y, c.z)];
          }
          if (!in) std::swap(quad[1], quad[3]);
          triangles.insert(triangles.end(), {quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]});
        }
      }

  smooth(positions, triangles);
  std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    const glm::vec3 a = positions[std::size_t(triangles[t])], b = positions[std::size_t(triangles[t + 1])],
                    c = positions[std::size_t(triangles[t + 2])];
    for (int k = 0; k < 3; ++k) normals[std::size_t(triangles[t + k])] += glm::cross(b - a, c - a);  // area-weighted
  }

  for (std::size_t i = 0; i < normals.size(); ++i) {
    const float length = glm::length(normals[i]);
    normals[i] = length > 0.0f ? normals[i] / length : glm::vec3(0.0f, 0.0f, 1.0f);
    positions[i] -= (grown - radius) * normals[i];
  }

  std::vector<MeshVertex> out;
  out.reserve(triangles.size());
  for (int v : triangles)
    out.push_back({glm::vec4(positions[std::size_t(v)], 1.0f), glm::vec4(normals[std::size_t(v)], 0.0f)});
  return out;
}

std::pair<glm::vec3, glm::vec3> meshBounds(const std::vector<MeshVertex>& mesh) {
  if (mesh.empty()) return {glm::vec3(1.0f), glm::vec3(-1.0f)};
  glm::vec3 lo(mesh.front().position), hi = lo;
  for (const MeshVertex& v : mesh) {
    lo = glm::min(lo, glm::vec3(v.position));
    hi = glm::max(hi, glm::vec3(v.position));
  }
  return {lo, hi};
}

void ObstacleMeshes::update(const water::Obstacles& obstacles, float radius) {
  std::vector<Entry> next(obstacles.size());
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    const water::ObstacleBody& body = obstacles.body(k);
    const auto old = std::find_if(m_meshes.begin(), m_meshes.end(), [&](const Entry& e) { return e.id == body.id; });
    if (old != m_meshes.end()) {
      next[k] = std::move(*old);
      continue;
    }
    const std::vector<MeshVertex> mesh = body.mesh ? fileMesh(*body.mesh) : ballUnionMesh(body.particles, radius);
    next[k].id = body.id;
    next[k].count = mesh.size();
    std::tie(next[k].lo, next[k].hi) = meshBounds(mesh);
    if (!mesh.empty()) next[k].vertices = gl::Buffer(std::span<const MeshVertex>(mesh), GL_STATIC_DRAW);
    ++m_builds;
  }
  m_meshes = std::move(next);
}

}  // namespace tidepool
