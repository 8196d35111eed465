#include "sim/water/body_contacts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace tidepool::water {
namespace {

// A sparse grid of cell 2r + margin over one body's particles near another: cell -> particles.
struct CellHash {
  double cell = 1;
  std::unordered_map<std::uint64_t, std::vector<glm::dvec3>> cells;
  static std::uint64_t key(glm::ivec3 c) {
    return (std::uint64_t(std::uint32_t(c.x) & 0x1fffffu) << 42) |
           (std::uint64_t(std::uint32_t(c.y) & 0x1fffffu) << 21) | std::uint64_t(std::uint32_t(c.z) & 0x1fffffu);
  }
  glm::ivec3 at(glm::dvec3 p) const { return glm::ivec3(glm::floor(p / cell)); }
  void add(glm::dvec3 p) { cells[key(at(p))].push_back(p); }
};

// A body's or obstacle's particles in the world at its present pose (the rotation made once, not
// per particle).
struct Placer {
  glm::dmat3 rotation;
  glm::dvec3 position, centre;
  explicit Placer(const ContactBody& c)
      : rotation(c.body ? c.body->rotation() : glm::dmat3(c.pose.rotation)),
        position(c.body ? c.body->state().position : glm::dvec3(c.pose.centre)),
        centre(c.body ? c.body->mass().centre : glm::dvec3(0.0)) {}
  glm::dvec3 operator()(glm::vec4 own) const { return position + rotation * (glm::dvec3(own) - centre); }
};

glm::dvec3 originOf(const ContactBody& c) { return c.body ? c.body->origin() : glm::dvec3(c.pose.centre); }

// A side of a contact: a body, a kinematic obstacle, or a wall (neither; it moves at `wall`).
glm::dvec3 velocityAt(const ContactBody* c, glm::dvec3 at, glm::dvec3 wall) {
  if (!c) return wall;
  if (c->body) return c->body->velocityAt(at);
  return glm::dvec3(c->pose.velocity) + glm::cross(glm::dvec3(c->pose.omega), at - glm::dvec3(c->pose.centre));
}
double inverseMassAt(const ContactBody* c, glm::dvec3 at, glm::dvec3 n) {
  return c && c->body ? c->body->inverseMassAt(at, n) : 0.0;
}
void applyImpulse(const ContactBody* c, glm::dvec3 impulse, glm::dvec3 at) {
  if (c && c->body) c->body->applyImpulse(impulse, at);
}

void wallContacts(const std::vector<ContactBody>& bodies, const Walls& walls, const ContactSettings& s,
                  std::vector<BodyContact>& out) {
  const glm::dvec3 lo = glm::dvec3(walls.min) + s.radius, hi = glm::dvec3(walls.max) - s.radius;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    if (!bodies[k].body) continue;  // a kinematic obstacle goes where its pose says
    const glm::dvec3 origin = bodies[k].body->origin();
    const double near = bodies[k].reach + s.margin;
    if (glm::all(glm::greaterThan(origin - near, glm::dvec3(walls.min))) &&
        glm::all(glm::lessThan(origin + near, glm::dvec3(walls.max))))
      continue;
    const Placer place(bodies[k]);
    for (const glm::vec4& q : *bodies[k].particles) {
      const glm::dvec3 p = place(q);
      for (int axis = 0; axis < 3; ++axis) {
        const double below = p[axis] - lo[axis], above = hi[axis] - p[axis];
        if (below < s.margin) {
          BodyContact c{.a = int(k), .point = p, .gap = below};
          c.normal[axis] = 1.0;
          c.point[axis] -= s.radius;
          c.wallVelocity[axis] = walls.minVel[axis];
          out.push_back(c);
        }
        if (above < s.margin) {
          BodyContact c{.a = int(k), .point = p, .gap = above};
          c.normal[axis] = -1.0;
          c.point[axis] += s.radius;
          c.wallVelocity[axis] = walls.maxVel[axis];
          out.push_back(c);
        }
      }
    }
  }
}

void pairContacts(const std::vector<ContactBody>& bodies, const ContactSettings& s, std::vector<BodyContact>& out) {
  const double touch = 2.0 * s.radius, reachPair = touch + s.margin;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      if (!bodies[i].body && !bodies[j].body) continue;  // two kinematic obstacles
      const glm::dvec3 ca = originOf(bodies[i]), cb = originOf(bodies[j]);
      if (glm::distance(ca, cb) > bodies[i].reach + bodies[j].reach + s.margin) continue;
      // b's particles that a's could reach, hashed; then a's that b's could reach, against them.
      CellHash hash{.cell = reachPair, .cells = {}};
      const Placer placeA(bodies[i]), placeB(bodies[j]);
      for (const glm::vec4& q : *bodies[j].particles) {
        const glm::dvec3 p = placeB(q);
        if (glm::distance(p, ca) <= bodies[i].reach + reachPair) hash.add(p);
      }
      if (hash.cells.empty()) continue;
      for (const glm::vec4& q : *bodies[i].particles) {
        const glm::dvec3 p = placeA(q);
        if (glm::distance(p, cb) > bodies[j].reach + reachPair) continue;
        const glm::ivec3 c = hash.at(p);
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const auto cell = hash.cells.find(CellHash::key(c + glm::ivec3(dx, dy, dz)));
              if (cell == hash.cells.end()) continue;
              for (const glm::dvec3& o : cell->second) {
                const double dist = glm::distance(p, o);
                if (dist >= reachPair || dist <= 0.0) continue;
                out.push_back(BodyContact{
                    .a = int(i), .b = int(j), .point = 0.5 * (p + o), .normal = (p - o) / dist, .gap = dist - touch});
              }
            }
      }
    }
}

struct Row {
  BodyContact contact;
  double normalImpulse = 0;
  glm::dvec3 frictionImpulse{0.0};
};

}  // namespace

std::vector<BodyContact> findContacts(const std::vector<ContactBody>& bodies, const Walls& walls,
                                      const ContactSettings& s) {
  std::vector<BodyContact> out;
  wallContacts(bodies, walls, s, out);
  pairContacts(bodies, s, out);
  return out;
}

void resolveContacts(const std::vector<ContactBody>& bodies, const std::vector<BodyContact>& contacts, double dt,
                     const ContactSettings& s) {
  std::vector<Row> rows;
  rows.reserve(contacts.size());
  for (const BodyContact& c : contacts) rows.push_back({c});
  for (int it = 0; it < s.iterations; ++it)
    for (Row& row : rows) {
      const BodyContact& c = row.contact;
      const ContactBody* a = &bodies[std::size_t(c.a)];
      const ContactBody* b = c.b >= 0 ? &bodies[std::size_t(c.b)] : nullptr;  // null: a wall
      auto relative = [&] { return velocityAt(a, c.point, glm::dvec3(0.0)) - velocityAt(b, c.point, c.wallVelocity); };
      auto apply = [&](glm::dvec3 impulse) {
        applyImpulse(a, impulse, c.point);
        applyImpulse(b, -impulse, c.point);
      };
      auto inverse = [&](glm::dvec3 dir) { return inverseMassAt(a, c.point, dir) + inverseMassAt(b, c.point, dir); };
      // Normal: the closing speed the gap allows, or the push out of an overlap.
      const double target = c.gap > 0.0 ? -c.gap / dt : -s.baumgarte * c.gap / dt;
      const double vn = glm::dot(relative(), c.normal), k = inverse(c.normal);
      if (!(k > 0.0)) continue;  // a hinged body pushed along its axis or through it: nothing moves
      const double next = std::max(0.0, row.normalImpulse + (target - vn) / k);
      apply((next - row.normalImpulse) * c.normal);
      row.normalImpulse = next;
      // Friction: stop the sliding, up to μ times the normal impulse.
      const glm::dvec3 v = relative(), slide = v - glm::dot(v, c.normal) * c.normal;
      const double speed = glm::length(slide);
      glm::dvec3 friction = row.frictionImpulse;
      const double ks = speed > 0.0 ? inverse(slide / speed) : 0.0;
      if (ks > 0.0) friction -= slide / (speed * ks) * speed;
      const double most = s.friction * row.normalImpulse, size = glm::length(friction);
      if (size > most) friction *= most / size;
      apply(friction - row.frictionImpulse);
      row.frictionImpulse = friction;
    }
}

void stepBodies(const std::vector<ContactBody>& bodies, double dt, glm::dvec3 gravity, const Walls& walls,
                double radius) {
  double fastest = 0;
  for (const ContactBody& c : bodies) {
    if (c.body) {
      c.body->accelerate(dt, gravity);
      fastest = std::max(fastest, glm::length(c.body->velocity()) + glm::length(c.body->omega()) * c.reach);
    } else {
      fastest = std::max(fastest, double(glm::length(c.pose.velocity) + glm::length(c.pose.omega) * float(c.reach)));
    }
  }
  const ContactSettings settings{.radius = radius, .margin = std::max(0.5 * radius, 2.0 * fastest * dt)};
  resolveContacts(bodies, findContacts(bodies, walls, settings), dt, settings);
  for (const ContactBody& c : bodies)
    if (c.body) c.body->move(dt);
}

}  // namespace tidepool::water
