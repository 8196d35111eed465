#include "sim/water/water_init.h"

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "base/error.h"
#include "sim/water/mesh_solid.h"
#include "sim/water/probes.h"

namespace tidepool::water {
namespace {

constexpr float kPi = 3.14159265358979f;

void addJitter(std::vector<glm::vec4>& points, float amount) {
  if (amount <= 0) return;
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> u(-amount, amount);
  for (glm::vec4& q : points) q += glm::vec4(u(rng), u(rng), u(rng), 0.0f);
}

float capsuleDistance(glm::vec3 q, glm::vec3 c, float halfLength, float radius) {
  const float x = std::clamp(q.x - c.x, -halfLength, halfLength);
  return glm::length(q - glm::vec3(c.x + x, c.y, c.z)) - radius;
}

}  // namespace

std::vector<glm::vec3> hcpLattice(glm::vec3 lo, glm::vec3 hi, float r) {
  std::vector<glm::vec3> out;
  const float sx = 2 * r, sy = r * std::sqrt(3.0f), sz = 2 * r * std::sqrt(6.0f) / 3;
  for (int k = 0; lo.z + k * sz <= hi.z; ++k) {
    const float z = lo.z + k * sz;
    const float yShift = (k % 4 == 1 || k % 4 == 3) ? sy / 3 : (k % 4 == 2 ? 2 * sy / 3 : 0.0f);
    for (int j = 0; lo.y + yShift + j * sy <= hi.y; ++j) {
      const float y = lo.y + yShift + j * sy;
      const float xShift = ((k % 2) ? r : 0.0f) + ((j % 2) ? r : 0.0f);
      for (int i = 0; lo.x + std::fmod(xShift, sx) + i * sx <= hi.x; ++i)
        out.emplace_back(lo.x + std::fmod(xShift, sx) + i * sx, y, z);
    }
  }
  return out;
}

double fillVolume(const Setup& p) {
  if (p.fill != Fill::Block && p.fill != Fill::Slab) return 0;
  glm::vec3 lo = glm::max(p.fillMin, p.domainMin), hi = glm::min(p.fillMax, p.domainMax);
  if (p.fill == Fill::Slab) {
    lo = p.domainMin;
    hi = glm::vec3(p.domainMax.x, p.domainMax.y, std::min(p.domainMax.z, p.domainMin.z + p.slabHeight));
  }
  const glm::dvec3 extent = glm::max(glm::dvec3(hi - lo), glm::dvec3(0.0));
  return extent.x * extent.y * extent.z;
}

namespace {
double hcpCell(double r) { return 4.0 * std::sqrt(2.0) * r * r * r; }  // volume per ball of the HCP lattice
}  // namespace

double estimatedWater(const Setup& p) {
  switch (p.fill) {
    case Fill::Random: return p.randomCount;
    case Fill::Lattice: return p.latticeCount;
    case Fill::None: return 0;
    default: return fillVolume(p) / hcpCell(p.radius);
  }
}

double obstacleBound(const std::vector<ObstacleParams>& obstacles, float radius) {
  double n = 0;
  for (const ObstacleParams& o : obstacles) {
    const glm::dvec3 box = 2.0 * glm::dvec3(glm::abs(o.size)) + 2.0 * double(radius);
    n += box.x * box.y * box.z / hcpCell(radius);
  }
  return n;
}

namespace {
// m³ a random fill's balls may occupy (their centres' box, widened by r a side) or a lattice fill's
// domain; 0 for the other fills.
double fillSpace(const Setup& p) {
  if (p.fill != Fill::Random && p.fill != Fill::Lattice) return 0;
  glm::dvec3 extent = glm::dvec3(p.domainMax - p.domainMin);
  if (p.fill == Fill::Random) {  // centres in [a, b], as waterParticles draws them
    const glm::dvec3 a(glm::max(p.fillMin, p.domainMin + p.radius)), b(glm::min(p.fillMax, p.domainMax - p.radius));
    extent = glm::max(b - a, glm::dvec3(0.0)) + 2.0 * double(p.radius);
  }
  return extent.x * extent.y * extent.z;
}
}  // namespace

double fillCapacity(const Setup& p) {
  if (p.fill != Fill::Random && p.fill != Fill::Lattice) return INFINITY;
  return std::max(1.0, std::floor(fillSpace(p) / hcpCell(p.radius)));
}

void checkWaterRequest(const char* model, const char* particle, const std::string& size, double fillParticles,
                       const Setup& w, const sim::ParticleCost& cost) {
  const std::string key = size.substr(0, size.find(' '));  // "particles.radius"
  checkProbes(w);
  // An inverted region would silently make no particles.
  if ((w.fill == Fill::Block || w.fill == Fill::Random) && glm::any(glm::lessThanEqual(w.fillMax, w.fillMin))) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "%s: particles.fill_max = [%g, %g, %g] must exceed fill_min = [%g, %g, %g] on every axis", model,
                  double(w.fillMax.x), double(w.fillMax.y), double(w.fillMax.z), double(w.fillMin.x),
                  double(w.fillMin.y), double(w.fillMin.z));
    throw Error(line);
  }
  if (const double capacity = fillCapacity(w); fillParticles > capacity) {
    const bool random = w.fill == Fill::Random;
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: particles.%s_count = %.0f %ss do not fit in %s (%.3g m^3 with %s): at most %.0f do, even "
                  "hexagonally close packed (74%% of the space); lower particles.%s_count, widen %s or lower %s",
                  model, random ? "random" : "lattice", fillParticles, particle,
                  random ? "the random fill's region" : "the domain", fillSpace(w), size.c_str(), capacity,
                  random ? "random" : "lattice",
                  random ? "particles.fill_min .. fill_max" : "particles.domain_min .. domain_max", key.c_str());
    throw Error(line);
  }
  sim::checkParticleRequest(model, particle,
                            fillParticles + (w.tap ? w.tapMax : 0) + obstacleBound(w.obstacles, w.radius), size, cost,
                            "raise " + key + " or shrink the fill and the obstacles");
}

std::vector<glm::vec4> waterParticles(const Setup& p, const std::function<bool(glm::vec3)>& occupied) {
  const float r = p.radius;
  const glm::vec3 lo = p.domainMin + r, hi = p.domainMax - r;
  std::vector<glm::vec4> out;
  switch (p.fill) {
    case Fill::Block:
    case Fill::Slab: {
      glm::vec3 a = glm::max(p.fillMin + r, lo), b = glm::min(p.fillMax - r, hi);
      if (p.fill == Fill::Slab) {
        a = lo;
        b = glm::vec3(hi.x, hi.y, std::min(hi.z, p.domainMin.z + p.slabHeight - r));
      }
      for (const glm::vec3& q : hcpLattice(a, b, r))
        if (!occupied || !occupied(q)) out.emplace_back(q, 1.0f);
      break;
    }
    case Fill::Random: {
      std::mt19937 rng(42);
      const glm::vec3 a = glm::max(p.fillMin, lo), b = glm::min(p.fillMax, hi);
      std::uniform_real_distribution<float> ux(a.x, b.x), uy(a.y, b.y), uz(a.z, b.z);
      for (int i = 0; i < p.randomCount; ++i) out.emplace_back(ux(rng), uy(rng), uz(rng), 1.0f);
      break;
    }
    case Fill::Lattice: {
      // CUDA sample: a cubic lattice of spacing 2r from the corner, edge ceil(N^(1/3)).
      const int side = int(std::ceil(std::cbrt(double(p.latticeCount)) - 1e-9));
      for (int i = 0; int(out.size()) < p.latticeCount; ++i) {
        const int x = i % side, y = (i / side) % side, z = i / (side * side);
        out.emplace_back(lo + 2.0f * r * glm::vec3(x, y, z), 1.0f);
      }
      break;
    }
    case Fill::None: break;
  }
  addJitter(out, p.jitter * r);
  return out;
}

Obstacle::Obstacle(const ObstacleParams& o, float radius) : m_params(o), m_radius(radius) {
  if (o.shape != Shape::Mesh) return;
  const io::TriangleMesh mesh = io::readObj(io::findMesh(o.mesh));  // errors name the file and line
  if (!o.shell) {
    const io::EdgeCheck check = io::checkClosed(mesh);
    if (!check.closed())
      throw Error("mesh '" + o.mesh + "' is " + check.describe() +
                  ": a solid fill needs a closed mesh; fix the mesh or make the obstacle a shell");
  }
  m_mesh = std::make_unique<MeshSolid>(placeMesh(mesh, glm::vec3(0.0f), o.size, glm::mat3(1.0f)));
}

Obstacle::~Obstacle() = default;

const io::TriangleMesh* Obstacle::mesh() const { return m_mesh ? &m_mesh->mesh() : nullptr; }

bool Obstacle::inside(glm::vec3 q) const {
  if (m_mesh) return m_mesh->inside(q);
  const glm::vec3 s = m_params.size;
  const float r = m_radius;
  switch (m_params.shape) {
    case Shape::None:
    case Shape::Mesh: return false;
    case Shape::Sphere: return glm::length(q) <= s.x;
    case Shape::Box: return glm::all(glm::lessThanEqual(glm::abs(q), s));
    case Shape::Capsule: return capsuleDistance(q, glm::vec3(0.0f), s.z, s.x) <= 0.0f;
    case Shape::Cup: {
      // Open cylinder with a bottom: radius s.x, height s.z from the base up, walls 2.5 balls thick.
      const float wall = std::max(2.5f * r * 2.0f, 0.12f * s.x);
      const float rho = glm::length(glm::vec2(q));
      if (q.z < 0.0f || q.z > s.z || rho > s.x) return false;
      return rho >= s.x - wall || q.z <= wall;
    }
    case Shape::Helix: {
      // A ramp winding 1.5 turns up from the base to s.z between radii 0.3 s.x and s.x.
      const float rho = glm::length(glm::vec2(q));
      if (rho < 0.3f * s.x || rho > s.x) return false;
      const float turns = 1.5f, thickness = 3.0f * r;
      const float pitch = s.z / turns;
      float angle = std::atan2(q.y, q.x);
      if (angle < 0) angle += 2 * kPi;
      for (int t = 0; t < 2; ++t) {
        const float rampZ = pitch * (angle / (2 * kPi) + float(t));
        if (rampZ <= s.z && std::abs(q.z - rampZ) <= 0.5f * thickness) return true;
      }
      return false;
    }
  }
  return false;
}

double Obstacle::volume(std::size_t particles) const {
  const glm::dvec3 s(m_params.size);
  const double pi = glm::pi<double>();
  if (!m_params.shell) {
    if (m_mesh) {  // the divergence theorem over the closed surface's triangles
      const io::TriangleMesh& m = m_mesh->mesh();
      double six = 0;
      for (const glm::uvec3& t : m.triangles)
        six +=
            glm::dot(glm::dvec3(m.vertices[t.x]), glm::cross(glm::dvec3(m.vertices[t.y]), glm::dvec3(m.vertices[t.z])));
      return std::abs(six) / 6.0;
    }
    if (m_params.shape == Shape::Sphere) return 4.0 / 3.0 * pi * s.x * s.x * s.x;
    if (m_params.shape == Shape::Box) return 8.0 * s.x * s.y * s.z;
    if (m_params.shape == Shape::Capsule) return pi * s.x * s.x * (2.0 * s.z + 4.0 / 3.0 * s.x);
  }
  return double(particles) * double(volumePerParticle(m_radius, Packing::Hcp));
}

std::vector<glm::vec4> Obstacle::particles() const {
  const ObstacleParams& o = m_params;
  std::vector<glm::vec4> out;
  const float r = m_radius;
  if (m_mesh) {
    for (const glm::vec3& q : meshLatticePoints(*m_mesh, r, o.shell)) out.emplace_back(q, 0.0f);
    return out;
  }
  if (o.shape == Shape::None) return out;
  const glm::vec3 s = o.size;
  glm::vec3 lo = -glm::vec3(s.x, s.x, s.z) - 2 * r, hi = glm::vec3(s.x, s.x, s.z) + 2 * r;
  if (o.shape == Shape::Box) {
    lo = -s - r;
    hi = s + r;
  } else if (o.shape == Shape::Capsule) {
    lo = -glm::vec3(s.z + s.x, s.x, s.x) - r;
    hi = glm::vec3(s.z + s.x, s.x, s.x) + r;
  }
  const float d = 2.0f * r;
  for (const glm::vec3& q : hcpLattice(lo, hi, r)) {
    if (!inside(q)) continue;
    if (o.shell) {
      // Keep particles with a neighbour position outside: the surface layer only.
      bool surface = false;
      for (const glm::vec3 step : {glm::vec3(d, 0, 0), glm::vec3(-d, 0, 0), glm::vec3(0, d, 0), glm::vec3(0, -d, 0),
                                   glm::vec3(0, 0, d), glm::vec3(0, 0, -d)})
        surface |= !inside(q + step);
      if (!surface) continue;
    }
    out.emplace_back(q, 0.0f);
  }
  // A box's particles lie as far inside each face as inside the opposite one: the lattice's layers
  // start where its box does, so the room left inside each face differs (up to a layer spacing);
  // shifted by half the difference, both faces keep the same room (the particles stay inside)
  // and the particles' centre of mass is the box's.
  if (!out.empty() && o.shape == Shape::Box) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec4& q : out) {
      lo = glm::min(lo, glm::vec3(q));
      hi = glm::max(hi, glm::vec3(q));
    }
    const glm::vec3 shift = -0.5f * (lo + hi);
    for (glm::vec4& q : out) q += glm::vec4(shift, 0.0f);
  }
  return out;
}

}  // namespace tidepool::water
