#include "sim/water/probes.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <numbers>

#include "base/error.h"
#include "base/number_text.h"
#include "gl/kernel.h"
#include "gl/window.h"
#include "water/probe_bindings.glsl"

namespace tidepool::water {
namespace {

static_assert(kMaxProbes == PROBE_MAX_GAUGES);

struct GaugeUniforms {
  GLuint first = 0, count = 0;
  GLint gauges = 0;
  std::array<glm::vec4, PROBE_MAX_GAUGES> gauge{};  // x, y, 1/R², 4/(πR²)
  static constexpr auto fields() {
    using U = GaugeUniforms;
    return std::tuple{gl::field("uFirst", &U::first), gl::field("uCount", &U::count), gl::field("uGauges", &U::gauges),
                      gl::field("uGauge", &U::gauge)};
  }
};

std::string item(std::size_t i) { return "probes[" + std::to_string(i) + "]"; }

// W(s)·2πs / (disc integral) at s = u·R, per unit u: the radial weight of the kernel's mass.
double ringWeight(double u) { return 8.0 * u * std::pow(1.0 - u * u, 3.0); }  // ∫₀¹ = 1

}  // namespace

void visitProbes(ParamVisitor& v, std::vector<ProbeParams>& probes) {
  v.list(
      {"probes", "Probes",
       "measurements that validate --probe probes writes: gauges, pressures, forces, obstacle poses"},
      probes, kMaxProbes,
      [](ParamVisitor& v, ProbeParams& p) {
        v.choice({"kind", "Kind",
                  "gauge: water height at a vertical line; pressure: at a point (fluid); force: on an obstacle or "
                  "a wall; body: an obstacle's pose and velocity"},
                 p.kind, kProbeKindNames);
        v.vector({"at", "At", "gauge: the vertical line through (x, y), z unused; pressure: the point, m"}, p.at,
                 -100.0f, 100.0f);
        v.real({"radius", "Radius", "gauge: footprint radius, m (0: five particle spacings)"}, p.radius, 0.0f, 100.0f);
        v.integer({"obstacle", "Obstacle", "force, body: index in the obstacles list"}, p.obstacle, 0,
                  int(kMaxObstacles) - 1);
        v.choice({"wall", "Wall", "force: this wall (-x, +x, -y, +y, -z, +z) instead of an obstacle"}, p.wall,
                 kProbeWallNames);
      },
      [](std::size_t i, const ProbeParams& p) {
        return std::to_string(i) + ": " + kProbeKindNames[std::size_t(p.kind)];
      });
}

float gaugeRadius(const ProbeParams& p, float particleRadius) {
  return p.radius > 0.0f ? p.radius : 5.0f * spacing(particleRadius);
}

void checkProbes(const Setup& s) {
  auto inside = [&](glm::vec3 at, int axes) {
    for (int k = 0; k < axes; ++k)
      if (at[k] <= s.domainMin[k] || at[k] >= s.domainMax[k]) return false;
    return true;
  };
  for (std::size_t i = 0; i < s.probes.size(); ++i) {
    const ProbeParams& p = s.probes[i];
    const bool onObstacle = p.kind == ProbeKind::Body || (p.kind == ProbeKind::Force && p.wall == ProbeWall::None);
    if (onObstacle && std::size_t(p.obstacle) >= s.obstacles.size())
      throw Error(item(i) + ": obstacle " + std::to_string(p.obstacle) + " does not exist: the scene has " +
                  std::to_string(s.obstacles.size()) + " obstacle" + (s.obstacles.size() == 1 ? "" : "s"));
    if (p.kind == ProbeKind::Gauge && !inside(p.at, 2))
      throw Error(item(i) + ": the gauge at (" + numberText(p.at.x) + ", " + numberText(p.at.y) +
                  ") is not inside the domain's x (" + numberText(s.domainMin.x) + ", " + numberText(s.domainMax.x) +
                  ") and y (" + numberText(s.domainMin.y) + ", " + numberText(s.domainMax.y) + ")");
    if (p.kind == ProbeKind::Pressure && !inside(p.at, 3))
      throw Error(item(i) + ": the pressure probe at (" + numberText(p.at.x) + ", " + numberText(p.at.y) + ", " +
                  numberText(p.at.z) + ") is not inside the domain");
  }
}

std::vector<std::string> probeColumns(const std::vector<ProbeParams>& probes) {
  std::vector<std::string> out;
  auto add = [&](const std::string& prefix, std::initializer_list<const char*> names) {
    for (const char* c : names) out.push_back(prefix + "_" + c);
  };
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const std::string n = kProbeKindNames[std::size_t(probes[i].kind)] + std::to_string(i);
    switch (probes[i].kind) {
      case ProbeKind::Gauge: add(n, {"height_m"}); break;
      case ProbeKind::Pressure: add(n, {"pa"}); break;
      case ProbeKind::Force:
        if (probes[i].wall == ProbeWall::None)
          add(n, {"fx_n", "fy_n", "fz_n", "tx_n_m", "ty_n_m", "tz_n_m"});
        else
          add(n, {"normal_n"});
        break;
      case ProbeKind::Body:
        add(n, {"x_m", "y_m", "z_m", "qw", "qx", "qy", "qz", "vx_m_s", "vy_m_s", "vz_m_s", "wx_rad_s", "wy_rad_s",
                "wz_rad_s"});
        break;
    }
  }
  return out;
}

double gaugeKernelInside(glm::vec2 at, double radius, glm::vec2 lo, glm::vec2 hi) {
  if (at.x - radius >= lo.x && at.x + radius <= hi.x && at.y - radius >= lo.y && at.y + radius <= hi.y) return 1.0;
  // Rings of the disc (midpoint rule in u = s/R), each weighted by the fraction of its circle
  // inside the rectangle (midpoint rule in the angle): 1e-4 of the kernel's mass or better.
  constexpr int kRings = 256, kAngles = 1024;
  double sum = 0;
  for (int r = 0; r < kRings; ++r) {
    const double u = (r + 0.5) / kRings, s = u * radius;
    int inside = 0;
    for (int a = 0; a < kAngles; ++a) {
      const double t = 2.0 * std::numbers::pi * (a + 0.5) / kAngles;
      const double x = at.x + s * std::cos(t), y = at.y + s * std::sin(t);
      inside += x >= lo.x && x <= hi.x && y >= lo.y && y <= hi.y;
    }
    sum += ringWeight(u) * inside / kAngles;
  }
  return sum / kRings;
}

std::vector<double> Probes::gaugeSums(const ParticleWater& water, const std::vector<glm::vec4>& gauges) {
  GaugeUniforms u;
  u.gauges = GLint(gauges.size());
  std::copy(gauges.begin(), gauges.end(), u.gauge.begin());
  std::vector<double> sums(gauges.size(), 0.0);
  const gl::Kernel<GaugeUniforms> kernel(m_shaders, "water/gauge.comp", {PROBE_POS, PROBE_PARTIALS});
  for (const gl::Window& w : gl::windows(water.count(), sizeof(glm::vec4))) {
    const std::size_t groups = (w.count + PROBE_GROUP_SIZE - 1) / PROBE_GROUP_SIZE;
    const std::size_t bytes = groups * PROBE_MAX_GAUGES * sizeof(float);
    if (m_partials.size() < bytes) m_partials = gl::Buffer(bytes);
    gl::bindWindow(water.positions(), PROBE_POS, w, sizeof(glm::vec4));
    m_partials.bindBase(GL_SHADER_STORAGE_BUFFER, PROBE_PARTIALS);
    u.first = GLuint(w.first);
    u.count = GLuint(w.end());
    kernel.dispatchThreads(w.count, u);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<float> partials = m_partials.read<float>(groups * PROBE_MAX_GAUGES);
    for (std::size_t g = 0; g < groups; ++g)
      for (std::size_t k = 0; k < gauges.size(); ++k) sums[k] += partials[g * PROBE_MAX_GAUGES + k];
  }
  return sums;
}

std::vector<double> Probes::measure(ParticleWater& water, std::string* unmeasured) {
  const Setup& s = water.water();
  checkProbes(s);
  const float r = water.radius();
  const glm::vec2 lo(water.wallMin()), hi(water.wallMax());
  std::vector<glm::vec4> gauges;
  std::vector<double> inside;     // each gauge's kernel mass inside the walls
  std::vector<glm::vec3> points;  // pressure probes
  for (const ProbeParams& p : s.probes)
    if (p.kind == ProbeKind::Gauge) {
      const double R = gaugeRadius(p, r);
      gauges.push_back({p.at.x, p.at.y, float(1.0 / (R * R)), float(4.0 / (std::numbers::pi * R * R))});
      inside.push_back(gaugeKernelInside(glm::vec2(p.at), R, lo, hi));
    } else if (p.kind == ProbeKind::Pressure) {
      points.push_back(p.at);
    }
  const std::vector<double> sums = gauges.empty() ? std::vector<double>{} : gaugeSums(water, gauges);
  // What the model cannot measure throws, or with `unmeasured` reads NaN and says why there.
  auto measured = [&](auto read, auto none) {
    if (!unmeasured) return read();
    try {
      return read();
    } catch (const Error& e) {
      *unmeasured = e.what();
      return none();
    }
  };
  const std::vector<double> pressures =
      points.empty()
          ? std::vector<double>{}
          : measured([&] { return water.pressures(points); }, [&] { return std::vector<double>(points.size(), NAN); });
  const bool forces = std::ranges::any_of(s.probes, [](const ProbeParams& p) { return p.kind == ProbeKind::Force; });
  const Loads loads =
      !forces ? Loads{}
              : measured([&] { return water.loads(); }, [&] { return Loads::unmeasured(s.obstacles.size()); });
  const double volume = volumePerParticle(r, water.packing());

  std::vector<double> out;
  std::size_t gauge = 0, pressure = 0;
  for (const ProbeParams& p : s.probes) {
    switch (p.kind) {
      case ProbeKind::Gauge:
        out.push_back(inside[gauge] > 0 ? volume * sums[gauge] / inside[gauge] : NAN);
        ++gauge;
        break;
      case ProbeKind::Pressure: out.push_back(pressures.at(pressure++)); break;
      case ProbeKind::Force: {
        if (p.wall != ProbeWall::None) {  // along the wall's outward normal: the water pushes it out
          const std::size_t w = std::size_t(p.wall) - 1;
          out.push_back((w % 2 == 0 ? -1.0 : 1.0) * loads.walls.at(w).force[int(w / 2)]);
          break;
        }
        // An obstacle added since the last step (the window's panel) has no loads yet: NaN.
        const std::size_t k = std::size_t(p.obstacle);
        const Load l = k < loads.obstacles.size() ? loads.obstacles[k] : Load::unmeasured();
        for (int c = 0; c < 3; ++c) out.push_back(l.force[c]);
        for (int c = 0; c < 3; ++c) out.push_back(l.torque[c]);
        break;
      }
      case ProbeKind::Body: {
        if (std::size_t(p.obstacle) >= water.obstacles().size()) {  // added since the last step: not placed yet
          out.insert(out.end(), 13, NAN);
          break;
        }
        const ObstaclePose& pose = water.obstacles().pose(std::size_t(p.obstacle));
        glm::quat q = glm::normalize(glm::quat_cast(pose.rotation));
        if (q.w < 0) q = -q;  // one of the two quaternions of a rotation: w ≥ 0
        for (float x : {pose.centre.x, pose.centre.y, pose.centre.z, q.w, q.x, q.y, q.z, pose.velocity.x,
                        pose.velocity.y, pose.velocity.z, pose.omega.x, pose.omega.y, pose.omega.z})
          out.push_back(x);
        break;
      }
    }
  }
  return out;
}

}  // namespace tidepool::water
