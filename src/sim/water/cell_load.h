// How crowded a state of particle water may be when it comes from a file (a checkpoint): a step's
// contact and neighbour passes visit every pair in neighbouring grid cells, so a million particles
// at one point cost a million squared per step. Water at rest packs 1.41 balls of radius r per
// cube of edge 2r (close packing, 74 %); a loaded state with more than kMaxPerDiameterCube in one
// such cube is squeezed far beyond anything a step produces, and is refused.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>

namespace tidepool::water {

class ParticleWater;

inline constexpr std::size_t kMaxPerDiameterCube = 64;

// The most of `positions` (m) in one cube of a lattice of edge 2r from the origin (CPU: a sort).
std::size_t mostInOneCube(std::span<const glm::vec4> positions, float radius);
// nullopt, or "<n> particles in one cube of edge 2r = <e> m, at most 64 (...)".
std::optional<std::string> overcrowded(const ParticleWater& water);

}  // namespace tidepool::water
