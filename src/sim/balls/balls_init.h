// Initial states of the balls model, built on the CPU: water fills (block, slab, random, the CUDA
// sample's benchmark lattice) and obstacle particles from shapes, on a hexagonal close-packed
// lattice (water-webgpu's strides: 2r, r·√3, 2r·√6/3) as a solid fill or a surface shell.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "sim/balls/balls_params.h"

namespace tidepool::balls {

// Points of the HCP lattice of spacing 2r inside [lo, hi].
std::vector<glm::vec3> hcpLattice(glm::vec3 lo, glm::vec3 hi, float r);

// The lattice fill's derived radius and gravity (CUDA sample: r = width/(2G), g x 64/G with G
// the next power of two >= ceil(N^(1/3))). Other fills return the parameters unchanged.
Params resolved(const Params& p);

// Water particles (vec4: position m, w = 1). Deterministic: same parameters, same particles.
std::vector<glm::vec4> waterParticles(const Params& p);

// Obstacle particles in the obstacle's own frame (vec4: position m, w = 0: immovable).
std::vector<glm::vec4> obstacleParticles(const Params& p);

// Inside test of the obstacle shape (local = world at rest).
bool insideObstacle(const Params& p, glm::vec3 q);

}  // namespace tidepool::balls
