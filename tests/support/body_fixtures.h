// Obstacle parameters that several body tests start from.
#pragma once

#include <glm/glm.hpp>

#include "sim/water/setup.h"

namespace tidepool::test {

// A box of half extents `half` at `centre`, turned by `degrees` (x, y, z), that the water and its
// contacts move: a rigid body of `density` kg/m³.
inline water::ObstacleParams dynamicBox(glm::vec3 half, glm::vec3 centre, float density,
                                        glm::vec3 degrees = glm::vec3(0.0f)) {
  water::ObstacleParams o;
  o.shape = water::Shape::Box;
  o.size = half;
  o.centre = centre;
  o.orientation = degrees;
  o.dynamic = true;
  o.density = density;
  return o;
}

}  // namespace tidepool::test
