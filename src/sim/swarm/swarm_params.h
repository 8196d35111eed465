// Parameters of the swarm model (particles-webgpu seed): N free 2D particles pulled by
// attractors, force = gravity + sum_k s_k * d_k / (|d_k|^2 + eps), friction per unit time.
//
// Units: positions are stored in NDC [-1,1]^2; the physics runs in world units, where
// world = ndc * (aspect, 1), so a circle stays round in a wide image. Time is simulated seconds.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "base/param.h"

namespace tidepool::sim {

enum class Integrator { ExplicitEuler, SymplecticEuler, Verlet, Rk4 };
inline constexpr std::array<const char*, 4> kIntegratorNames = {"explicit_euler", "symplectic_euler", "verlet", "rk4"};

enum class Storage { Fp32, Fp16 };  // fp16: packHalf2x16, 8 bytes per particle instead of 16
inline constexpr std::array<const char*, 2> kStorageNames = {"fp32", "fp16"};

enum class Preset { None, Orbit, Sines, CentralAttractive, CentralRepulsive };
inline constexpr std::array<const char*, 5> kPresetNames = {"none", "orbit", "sines", "central_attractive",
                                                            "central_repulsive"};

inline constexpr int kMaxSwarmParticles = 64 << 20;  // the JSON/UI ceiling; the GPU may allow less

struct SwarmParams {
  int particles = 1 << 20;          // count; changing it re-allocates
  Storage storage = Storage::Fp32;  // changing it resets
  Integrator integrator = Integrator::SymplecticEuler;
  double frameSeconds = 1.0 / 30;  // s one frame stands for (the hue cycle's clock); x speed is simulated
  float speed = 0.5f;              // simulated seconds per frame second: a frame is speed x frameSeconds
  int substeps = 1;                // integrator steps per frame (at least)
  float maxDt = 0.0f;              // s: 0 none; else more substeps until one step is at most this ("method": "auto")
  float gravity = 0.3f;            // world units / s^2, downwards (seed: 3 x 0.1)
  float friction = 0.06f;          // 1/s: v *= exp(-friction dt) (seed: 0.9995 per 1/120 s)
  float epsilon = 0.01f;           // world units^2: softening of the 1/r force
  bool bounce = true;              // mirror walls at the image border, else free flight
  Preset preset = Preset::Orbit;   // animated attractors
  float mouseStrength = 7.0f;      // strength of the mouse attractor (left button)
  int seed = 1;                    // initial positions (uniform in the box)
};

void visit(ParamVisitor& v, SwarmParams& p);

// Simulated seconds of one frame: speed x frameSeconds.
inline double swarmFrameSeconds(const SwarmParams& p) { return double(p.speed) * p.frameSeconds; }

// Integrator steps in a frame: substeps, or more where maxDt asks.
inline int swarmSubsteps(const SwarmParams& p) {
  const double simSeconds = swarmFrameSeconds(p);
  const int needed = p.maxDt > 0 ? int(std::ceil(simSeconds / p.maxDt - 1e-9)) : 1;
  return std::max(p.substeps, needed);
}

}  // namespace tidepool::sim
