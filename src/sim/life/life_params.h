// Parameters of the life model that are not part of the rules (life_rules.h): how it steps.
#pragma once

#include <array>

#include "base/param.h"

namespace tidepool::life {

enum class Integrator { Euler, Verlet };
constexpr std::array<const char*, 2> kIntegratorNames = {"euler", "verlet"};

// How the state is stored (shaders/life/state.glsl); it is always computed in fp32.
enum class Storage { Fp32, Fp16 };
constexpr std::array<const char*, 2> kStorageNames = {"fp32", "fp16"};

struct Params {
  Integrator integrator = Integrator::Euler;  // euler: the article's symplectic Euler
  Storage storage = Storage::Fp32;            // fp16: packHalf2x16 positions and velocities, half the bytes
  float maxDt = 0.025f;                       // s: one step of this per frame (a generation)
  float pushStrength = 20.0f;                 // mouse brush: velocity added per unit of drag (the article's 20)
  bool deterministic = true;                  // bit-identical runs: the grid orders each cell by index
};

inline void visit(ParamVisitor& v, Params& p) {
  v.choice({"integrator", "Integrator", "euler: symplectic Euler (the article's); verlet: velocity Verlet"},
           p.integrator, kIntegratorNames);
  v.choice({"storage", "Storage",
            "fp32: 32 B of state per particle; fp16 (packHalf2x16, computed in fp32): 16 B, positions and velocities "
            "rounded to 11 significant bits every step (docs/ACCURACY.md, life-precision)"},
           p.storage, kStorageNames);
  v.real({"max_dt", "Max dt", "s; each frame is one step of this (recovery halves it)"}, p.maxDt, 1e-4f, 0.1f);
  v.real({"push_strength", "Push strength", "mouse brush: velocity per unit of drag"}, p.pushStrength, 0.0f, 200.0f);
  v.flag({"deterministic", "Deterministic", "bit-identical runs: the grid orders each cell's particles by index"},
         p.deterministic);
}

}  // namespace tidepool::life
