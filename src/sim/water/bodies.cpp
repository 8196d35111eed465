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

void Bodies::advance(double dt, glm::dvec3 gravity, const Walls& walls, const Obstacles& obstacles) {
  std::vector<ContactBody> bodies;
  for (std::size_t k = 0; k < m_bodies.size(); ++k)
    if (m_bodies[k]) bodies.push_back({&*m_bodies[k], &obstacles.body(k).particles, obstacles.body(k).reach});
  stepBodies(bodies, dt, gravity, walls, obstacles.radius());
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
