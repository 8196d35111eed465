// Balls parameters that several test files start from; each test then sets what it is about.
#pragma once

#include <glm/glm.hpp>

#include "sim/balls/balls_params.h"

namespace tidepool::test {

// An empty box [0, size] for balls of radius r (the rest of the parameters at their defaults).
inline balls::Params emptyBox(float radius, glm::vec3 size) {
  balls::Params p;
  p.fill = water::Fill::None;
  p.radius = radius;
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = size;
  return p;
}

// The step and obstacle tests' tank: an empty 0.4 x 0.3 x 0.5 m box for balls of 2 cm radius,
// stepped at 0.2 ms with a contact time of 4 ms.
inline balls::Params emptyTank() {
  balls::Params p = emptyBox(0.02f, glm::vec3(0.4f, 0.3f, 0.5f));
  p.dt = 2e-4f;
  p.contactTime = 0.004f;
  return p;
}

}  // namespace tidepool::test
