// Probes: what an engineer measures in a water scene, read from the running model (balls or fluid)
// through its ParticleWater interface, so both models are measured alike. A scene lists them in
// `params.probes` (up to kMaxProbes):
//   gauge  {"kind": "gauge", "at": [x, y, z], "radius": R}  the water height at the vertical line
//          through (x, y) (z is ignored): the rest volume of the particles near the line per unit
//          area, h = V · Σ_i W(|xy_i − at|) / ∫ W over the disc inside the walls, with the 2D
//          kernel W(s) = 4/(πR⁸)·(R² − s²)³ (s < R; its integral over the whole disc is 1). Every
//          particle above the floor counts, spray included; a particle's rest volume V is the
//          model's (setup.h, volumePerParticle), so a compressed column still reads the height
//          it would have at rest. R = 0: five spacings.
//   pressure {"kind": "pressure", "at": [x, y, z]}  the water's pressure at the point (Pa): the
//          fluid's, from its solver, p_i = −ρ0 Λ_i / dt² with Λ_i the sum of particle i's λ over
//          the step's iterations (its position correction is SPH's pressure acceleration times
//          dt²), interpolated by Shepard's Σ V p_i W / Σ V W (poly6, support h; 0 where no
//          particle is within h). The balls have no pressure field: a pressure probe on them is
//          an Error (a contact stress is not the fluid's pressure at rest).
//   force  {"kind": "force", "obstacle": k} or {"kind": "force", "wall": "-z"}  what the water
//          exerted on obstacle k (force, N, and torque about its centre, N·m) or on a wall (its
//          force along the wall's outward normal, N) during the last step (sim/water/boundary_loads.h).
//          The fluid's: from the momentum its boundary corrections gave the water, F = −m ΣΔx / dt².
//          The balls': from the accelerations the boundary's contacts gave the balls, F = −m Σa
//          with m = ρ0 times a ball's rest volume (the cuda-sample law's walls clamp rather than
//          push: NaN). A model measures loads only while a force probe is listed.
//   body   {"kind": "body", "obstacle": k}  obstacle k's pose and velocity as placed at the last
//          step: centre (m), orientation (unit quaternion w, x, y, z), velocity (m/s), angular
//          velocity (rad/s).
// Sums over particles are reduced per work group in a fixed order on the GPU and the groups are
// added in double on the CPU (shaders/water/gauge.comp, shaders/fluid/pressure.comp): the same
// run reads the same values.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "base/param.h"
#include "gl/buffer.h"
#include "gl/shader_library.h"
#include "sim/water/particle_water.h"
#include "sim/water/setup.h"

namespace tidepool::water {

void visitProbes(ParamVisitor& v, std::vector<ProbeParams>& probes);

// Throws Error naming the first probe the setup cannot measure ("probes[1]: obstacle 3 does not
// exist: the scene has 2 obstacles"; a gauge outside the domain or wider than it).
void checkProbes(const Setup& s);

// The columns of one probe, in the order Probes::measure() returns their values.
std::vector<std::string> probeColumns(const std::vector<ProbeParams>& probes);

// ∫ W over the part of the disc of radius R about `at` that lies inside [lo, hi] (x, y), as a
// fraction of the whole disc's (1 when the disc lies inside).
double gaugeKernelInside(glm::vec2 at, double radius, glm::vec2 lo, glm::vec2 hi);

// The gauge's footprint radius R as measured: its radius, or five spacings d = 2r.
float gaugeRadius(const ProbeParams& p, float particleRadius);

class Probes {
 public:
  explicit Probes(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}
  // One value per column of probeColumns(water.water().probes). Throws Error for probes the
  // setup cannot measure (checkProbes), and for those the model cannot (a pressure or a force on
  // the balls) unless `unmeasured` is given: then those read NaN and it says why.
  std::vector<double> measure(ParticleWater& water, std::string* unmeasured = nullptr);

 private:
  std::vector<double> gaugeSums(const ParticleWater& water, const std::vector<glm::vec4>& gauges);

  gl::ShaderLibrary& m_shaders;
  gl::Buffer m_partials;
};

}  // namespace tidepool::water
