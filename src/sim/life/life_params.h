// Parameters of the life model that are not part of the rules (life_rules.h): how it steps.
#pragma once

#include <array>

#include "scene/param.h"

namespace tidepool::life {

enum class Integrator { Euler, Verlet };
constexpr std::array<const char*, 2> kIntegratorNames = {"euler", "verlet"};

struct Params {
  Integrator integrator = Integrator::Euler;  // euler: the article's symplectic Euler
  float maxDt = 0.025f;                       // s: dt = min(maxDt, frame seconds), one step per frame
  float pushStrength = 20.0f;                 // mouse brush: velocity added per unit of drag (the article's 20)
};

inline void visit(ParamVisitor& v, Params& p) {
  v.choice({"integrator", "Integrator", "euler: symplectic Euler (the article's); verlet: velocity Verlet"},
           p.integrator, kIntegratorNames);
  v.real({"max_dt", "Max dt", "s; each frame advances min(max dt, frame time) in one step"}, p.maxDt, 1e-4f, 0.1f);
  v.real({"push_strength", "Push strength", "mouse brush: velocity per unit of drag"}, p.pushStrength, 0.0f, 200.0f);
}

}  // namespace tidepool::life
