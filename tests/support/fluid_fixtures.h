// Fluid parameters that several test files start from; each test then sets what it is about.
#pragma once

#include <glm/glm.hpp>

#include "sim/fluid/fluid_params.h"
#include "support/body_fixtures.h"

namespace tidepool::test {

// A tank [0, tank] filled `depth` deep (particles `spacing` apart, dt 2 ms) with one dynamic box
// of half extents `half` and `density` kg/m³, centred at `centre`.
inline fluid::Params tankWithABox(float spacing, glm::vec3 tank, float depth, glm::vec3 centre, glm::vec3 half,
                                  float density) {
  fluid::Params p;
  p.setSpacing(spacing);
  p.domainMax = tank;
  p.fill = water::Fill::Slab;
  p.slabHeight = depth;
  p.dt = 0.002f;
  p.obstacles = {dynamicBox(half, centre, density)};
  return p;
}

}  // namespace tidepool::test
