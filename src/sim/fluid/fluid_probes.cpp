// What the probes read of the fluid (sim/water/probes.h): the pressure, from the solver's
// p_i = −ρ0 Λ_i / dt² of the last step (shaders/fluid/pressure.comp), and the loads on the walls
// and obstacles (boundary_loads.h).
#include <cmath>

#include "fluid/bindings.glsl"
#include "sim/fluid/fluid.h"

namespace tidepool::fluid {
namespace {

constexpr std::size_t kBatch = 8;  // = FLUID_PRESSURE_BATCH in pressure.comp

struct PressureUniforms {
  GLuint count = 0;
  float pressureScale = 0;  // −ρ0 / dt²
  GLint points = 0;
  std::array<glm::vec4, kBatch> point{};
  SphUniforms sph;
  static constexpr auto fields() {
    using U = PressureUniforms;
    return std::tuple{gl::field("uCount", &U::count), gl::field("uPressureScale", &U::pressureScale),
                      gl::field("uPoints", &U::points), gl::field("uPoint", &U::point), gl::field(&U::sph)};
  }
};

}  // namespace

std::vector<double> Fluid::pressures(const std::vector<glm::vec3>& points) {
  if (!m_densitiesValid) return std::vector<double>(points.size(), NAN);  // no step since reset
  const gl::Kernel<PressureUniforms> kernel(m_shaders, "fluid/pressure.comp", {FLUID_POS, FLUID_PRESSURE, FLUID_OUT});
  const std::size_t groups = (m_count + FLUID_GROUP_SIZE - 1) / FLUID_GROUP_SIZE;
  gl::Buffer partials(groups * 2 * kBatch * sizeof(float));
  std::vector<double> out;
  for (std::size_t first = 0; first < points.size(); first += kBatch) {
    const std::size_t n = std::min(kBatch, points.size() - first);
    PressureUniforms u{.count = GLuint(m_count),
                       .pressureScale = float(-m_params.restDensity / (double(m_params.dt) * m_params.dt)),
                       .points = GLint(n),
                       .sph = sph()};
    for (std::size_t g = 0; g < n; ++g) u.point[g] = glm::vec4(points[first + g], 0.0f);
    m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_POS);
    m_lambdaSum.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRESSURE);
    partials.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
    kernel.dispatchThreads(m_count, u);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<float> read = partials.read<float>(groups * 2 * kBatch);
    for (std::size_t g = 0; g < n; ++g) {
      double weighted = 0, weights = 0;
      for (std::size_t w = 0; w < groups; ++w) {
        weighted += read[w * 2 * kBatch + 2 * g];
        weights += read[w * 2 * kBatch + 2 * g + 1];
      }
      out.push_back(weights > 0 ? weighted / weights : 0.0);  // no water within h: 0 Pa
    }
  }
  return out;
}

water::Loads Fluid::loads() {
  // No step since reset, or none that measured.
  if (!m_loadsOn || !m_densitiesValid) return water::Loads::unmeasured(m_obstacles.size());
  water::Loads out = m_loads.read(loadScale());
  if (!m_loads.walls()) out.unmeasuredWalls();
  return out;
}

}  // namespace tidepool::fluid
