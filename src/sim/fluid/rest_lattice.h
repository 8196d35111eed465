// The rest state of particles on a lattice of spacing d: a particle's rest volume
// V0 = 1 / Σ_j W(x_0 − x_j) (so that a particle deep inside a resting fill reads ρ0 exactly: the
// mass m = ρ0·V0 absorbs the kernel's discretisation error, 5% at h/d = 1.5, see sph_kernels_test),
// and the constraint-gradient sum Σ_j |V0 ∇W|² that scales the relaxation ε and s_corr.
// The fluid fills blocks on a cubic lattice (it tiles a box exactly: the water's volume is the
// block's, with no gaps at the walls to settle into); balls and obstacle particles sit on the HCP
// lattice of sim/water/water_init.h (√2 particles per d³). Obstacle particles get boundary volumes (Akinci et al.
// 2012).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "sim/water/setup.h"

namespace tidepool::fluid {

using water::Packing;  // the lattices of sim/water/setup.h's particle size

struct RestLattice {
  double volume = 0;     // V0, m³
  double gradients = 0;  // Σ_j |V0 ∇W_spiky(x_0 − x_j)|², 1/m²
  // The walls' half spaces are continuous, the lattice beside them is not: a first layer half a
  // spacing off a wall would read 2.6% too dense at h = 2d (cubic). The walls' terms are scaled by
  // this factor, which makes that layer read exactly ρ0 (0.88 at h = 2d, cubic).
  double wallScale = 1;
};
RestLattice restLattice(double spacing, double h, Packing packing);  // h: smoothing radius, m

// Rest volumes of one obstacle's particles (own frame, spacing d), for the density sum:
//   solid fill: `solidVolume` each, the HCP lattice's V0 (the solid reads like resting fluid)
//   shell:      Akinci et al. 2012, V_b = 1 / Σ_k W(x_b − x_k) over the shell's particles, which
//               makes a single layer weigh as much as the half space behind it
std::vector<float> boundaryVolumes(const std::vector<glm::vec4>& particles, bool shell, double h, double solidVolume);

}  // namespace tidepool::fluid
