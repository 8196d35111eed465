// The bodies coupled to a particle-water model (body_coupling.h).
#include "sim/water/body_coupling.h"

namespace tidepool::water {

void BodyCoupling::reset(const std::vector<ObstacleParams>& params) {
  m_bodies = {};
  m_bodies.sync(params, m_obstacles);
  m_restored = m_pending = false;
  settle(0.0);
}

void BodyCoupling::requestLoads(bool measured) {
  m_pending = m_bodies.any() && measured;
  if (m_pending)
    m_loads.request();
  else if (m_bodies.any())  // no water measured them: no load
    m_bodies.setLoads(Loads::unmeasured(m_obstacles.size()), m_obstacles);
}

void BodyCoupling::receiveLoads(double scale) {
  if (!m_pending) return;
  m_pending = false;
  m_bodies.setLoads(m_loads.received(scale), m_obstacles);
}

void BodyCoupling::move(double dt, double scale, glm::dvec3 gravity, const Walls& walls,
                        const std::vector<ObstaclePose>& poses) {
  if (!m_bodies.any()) return;
  if (m_restored) {
    const std::size_t n = m_state.size() / sizeof(BodyState);
    if (n == m_obstacles.size()) m_bodies.setStates(m_state.read<BodyState>(n));
  }
  m_restored = false;
  receiveLoads(scale);
  m_bodies.advance(dt, gravity, walls, m_obstacles, poses);
}

void BodyCoupling::settle(double scale) {
  if (!m_bodies.any() || m_restored) return;  // restored: m_state holds them
  receiveLoads(scale);
  const std::vector<BodyState> states = m_bodies.states();
  const std::size_t bytes = states.size() * sizeof(BodyState);
  if (m_state.size() != bytes) m_state = gl::Buffer(bytes);
  m_state.upload(states.data(), bytes);
}

std::optional<sim::StateBuffer> BodyCoupling::stateBuffer(double scale) {
  if (!m_bodies.any()) return std::nullopt;
  settle(scale);
  return sim::StateBuffer{"bodies", &m_state, m_state.size()};
}

void BodyCoupling::restored() {
  m_restored = true;
  m_pending = false;
}

}  // namespace tidepool::water
