// Statistics and the density probe of particle water, for the fluid AND the balls: one metric for
// both models. The particles' configuration is measured with the fluid's kernel (poly6,
// support h = smoothing × spacing, rest volume from the rest lattice, walls' half spaces and the
// obstacles' boundary particles), so a ball configuration reads its compression as the fluid
// solver would see it. The probe sorts copies of the particles into its own grid (cell h): the
// model's state is not touched. shaders/fluid/stats.comp reduces per work group; the CPU adds the
// groups in double.
//
//   DensityProbe probe(shaders);
//   fluid::Stats s = probe.measure(balls, {.spacing = 2 * balls.radius()}, balls.gravity(), balls.time());
// Obstacle particles weigh with their own volumes where the model keeps them (the fluid), else
// with the rest lattice's V0 (the balls' solid obstacles sit on the HCP lattice of their spacing).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/shader_library.h"
#include "grid/grid.h"
#include "sim/fluid/fluid_kernels.h"
#include "sim/fluid/rest_lattice.h"
#include "sim/water/obstacles.h"
#include "sim/water/particle_water.h"

namespace tidepool::fluid {

struct Stats {
  double time = 0;             // simulated s
  std::size_t count = 0;       // particles
  double kinetic = 0;          // Σ ½ m |v|², J
  double potential = 0;        // Σ −m g·(x − domain min), J
  double compressionMean = 0;  // mean of max(ρ/ρ0 − 1, 0): the density error
  double compressionMax = 0;   // max of ρ/ρ0 − 1 (may be negative: nothing compressed)
  double densityMean = 0;      // mean of ρ/ρ0 − 1, signed (a free surface reads low)
  double maxSpeed = 0;         // m/s
  std::size_t nonFinite = 0;   // particles with NaN or infinite state
  std::size_t outside = 0;     // particles outside the walls
  double front = 0;            // surge front: largest x within one spacing of the floor, m (NaN: none)
  double backHeight = 0;       // largest z within one spacing of the back (x min) wall, m (NaN: none)
};

// The kernel the density is measured with.
struct DensityKernel {
  float spacing = 0.02f;           // d, m (the balls: 2r)
  float smoothing = 2.0f;          // h / d
  double restDensity = 1000.0;     // ρ0, kg/m³ (energies in J)
  Packing packing = Packing::Hcp;  // the rest lattice V0 is measured on: balls HCP, fluid cubic
};

class DensityProbe {
 public:
  explicit DensityProbe(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}
  Stats measure(const water::ParticleWater& water, const DensityKernel& kernel, glm::vec3 gravity, double time);

 private:
  gl::ShaderLibrary& m_shaders;
  std::unique_ptr<grid::UniformGrid> m_grid;
  gl::Buffer m_pos, m_vel, m_stats;
  std::optional<DensityKernel> m_restFor;  // the kernel m_rest was measured for
  RestLattice m_rest;
};

}  // namespace tidepool::fluid
