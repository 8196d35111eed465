#include "sim/water/bodies.h"

#include <algorithm>
#include <cmath>

#include "sim/water/water_init.h"

namespace tidepool::water {
namespace {
bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

MassProperties massOf(const ObstacleBody& b) {
  return massProperties(b.particles, b.shape->volume(b.particles.size()), double(b.built.density));
}
}  // namespace

void Bodies::sync(const std::vector<ObstacleParams>& params, const Obstacles& obstacles) {
  m_bodies.resize(obstacles.size());
  m_made.resize(obstacles.size());
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    const ObstacleBody& b = obstacles.body(k);
    const ObstacleParams& o = params[k];
    if (!o.dynamic || b.particles.empty()) {
      m_bodies[k].reset();
      continue;
    }
    Tracked& made = m_made[k];
    const bool moved = made.centre != o.centre || made.orientation != o.orientation || made.hingeAxis != o.hingeAxis ||
                       made.hingeAt != o.hingeAt;
    if (!m_bodies[k] || moved)
      m_bodies[k].emplace(massOf(b), o);
    else if (made.id != b.id || made.density != o.density)
      m_bodies[k]->setMass(massOf(b));
    made = {b.id, o.centre, o.orientation, o.hingeAxis, o.hingeAt, o.density};
  }
}

bool Bodies::any() const {
  return std::any_of(m_bodies.begin(), m_bodies.end(), [](const auto& b) { return b.has_value(); });
}

std::vector<ObstaclePose> Bodies::poses(const std::vector<ObstacleParams>& params, double time) const {
  std::vector<ObstaclePose> out = posesAt(params, time);
  for (std::size_t k = 0; k < out.size(); ++k)
    if (dynamic(k)) out[k] = m_bodies[k]->pose();
  return out;
}

void Bodies::setLoads(const Loads& loads, const Obstacles& obstacles) {
  for (std::size_t k = 0; k < m_bodies.size() && k < loads.obstacles.size(); ++k) {
    if (!m_bodies[k]) continue;
    BodyState& s = m_bodies[k]->state();
    const Load& l = loads.obstacles[k];
    // About the centre of mass: τ_c = τ_o − (c − o) × F.
    const glm::dvec3 origin(obstacles.pose(k).centre);
    const bool measured = finite(l.force) && finite(l.torque);  // no water: NaN
    s.force = measured ? l.force : glm::dvec3(0.0);
    s.torque = measured ? l.torque - glm::cross(s.position - origin, l.force) : glm::dvec3(0.0);
  }
}

void Bodies::advance(double dt, glm::dvec3 gravity, const Walls& walls, const Obstacles& obstacles,
                     const std::vector<ObstaclePose>& poses) {
  std::vector<ContactBody> bodies;
  for (std::size_t k = 0; k < m_bodies.size(); ++k) {
    const ObstacleBody& o = obstacles.body(k);
    if (m_bodies[k])
      bodies.push_back({&*m_bodies[k], &o.particles, o.reach, {}});
    else if (!o.particles.empty() && k < poses.size())
      bodies.push_back({nullptr, &o.particles, o.reach, poses[k]});
  }
  pull(dt, gravity);
  stepBodies(bodies, dt, gravity, walls, obstacles.radius());
}

void Bodies::pull(double dt, glm::dvec3 gravity) {
  if (!m_grab || !dynamic(m_grab->obstacle)) return;
  RigidBody& b = *m_bodies[m_grab->obstacle];
  const glm::dvec3 at = b.state().position + b.rotation() * m_grab->anchor;
  const glm::dvec3 change = (m_grab->target - at) / kPullTime - b.velocityAt(at);
  const glm::dmat3 k = b.inverseMassMatrixAt(at);
  glm::dvec3 impulse(0.0);
  if (b.hinge()) {  // K is u uᵀ / I: only along u can the point move
    const glm::dvec3 u = k * change;
    if (glm::length(u) > 0.0) {
      const glm::dvec3 along = glm::normalize(u);
      impulse = along * (glm::dot(along, change) / glm::dot(along, k * along));
    }
  } else {
    impulse = glm::inverse(k) * change;
  }
  const double most = kPullMost * b.mass().mass * std::max(glm::length(gravity), 9.81) * dt,
               size = glm::length(impulse);
  if (size > most) impulse *= most / size;
  if (size > 0.0) b.applyImpulse(impulse, at);
}

std::optional<std::pair<std::size_t, double>> Bodies::pick(const Obstacles& obstacles, glm::dvec3 origin,
                                                           glm::dvec3 direction) const {
  std::optional<std::pair<std::size_t, double>> best;
  const double r = obstacles.radius();
  for (std::size_t k = 0; k < m_bodies.size() && k < obstacles.size(); ++k) {
    if (!m_bodies[k]) continue;
    const ObstaclePose pose = m_bodies[k]->pose();
    const glm::dvec3 centre(pose.centre);
    const double along = glm::dot(centre - origin, direction), reach = obstacles.body(k).reach + r;
    if (glm::length(centre - origin - along * direction) > reach) continue;
    for (const glm::vec4& q : obstacles.body(k).particles) {
      const glm::dvec3 p(pose.place(glm::vec3(q)));
      const double t = glm::dot(p - origin, direction), miss2 = glm::dot(p - origin, p - origin) - t * t;
      if (miss2 > r * r) continue;
      const double hit = t - std::sqrt(r * r - miss2);
      if (hit > 0.0 && (!best || hit < best->second)) best = std::make_pair(k, hit);
    }
  }
  return best;
}

glm::dvec3 Bodies::anchorAt(std::size_t k, glm::dvec3 world) const {
  const RigidBody& b = *m_bodies[k];
  return glm::transpose(b.rotation()) * (world - b.state().position);
}

std::vector<BodyState> Bodies::states() const {
  std::vector<BodyState> out(m_bodies.size());
  for (std::size_t k = 0; k < m_bodies.size(); ++k)
    if (m_bodies[k]) out[k] = m_bodies[k]->state();
  return out;
}

void Bodies::setStates(const std::vector<BodyState>& states) {
  for (std::size_t k = 0; k < m_bodies.size() && k < states.size(); ++k)
    if (m_bodies[k]) m_bodies[k]->state() = states[k];
}

}  // namespace tidepool::water
