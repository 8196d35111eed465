// Parameters of the ripples model (heightfield water), declared once for JSON and the UI.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "base/param.h"

namespace tidepool::ripples {

enum class Rule { Wave, Seed };
constexpr std::array<const char*, 2> kRuleNames = {"wave", "seed"};
enum class Boundary { Reflecting, Absorbing, Periodic };
constexpr std::array<const char*, 3> kBoundaryNames = {"reflecting", "absorbing", "periodic"};

constexpr float kCourantLimit2D = 0.70710678f;  // 1/√2: von Neumann limit of the 5-point leapfrog

struct Params {
  Rule rule = Rule::Wave;
  int width = 512, height = 512;   // cells
  double frameSeconds = 1.0 / 30;  // simulated s per frame
  float cellSize = 0.02f;          // dx, m
  float waveSpeed = 2.0f;          // c, m/s (wave rule)
  float velDamping = 0.3f;         // 1/s: v *= max(0, 1 - velDamping·dt)
  float posDamping = 0.0f;         // 1/s: h += (mean4 - h)·min(posDamping·dt, 1)
  Boundary boundary = Boundary::Reflecting;
  int spongeCells = 24;         // absorbing boundary width, cells
  float spongeDamping = 20.0f;  // 1/s at the outermost cell
  bool autoSubsteps = true;     // pick substeps so that C <= courantTarget · 1/√2
  float courantTarget = 0.5f;   // fraction of the 2D limit used by autoSubsteps
  int substeps = 4;             // per frame when autoSubsteps is off
  // The seed rule (water-simulation-gpu), in its own units: heights in "range units", dt = timeScale·frame s.
  float seedElasticity = 0.7f;    // k: spring toward the rest height
  float seedPropagation = 20.0f;  // c: pull toward the mean of the 4 neighbours
  float seedFriction = 0.995f;    // velocity factor per step
  float seedTimeScale = 10.0f;    // seed: its dt = 10 x the step's dt
  // Interaction (mouse, drops): the seed's cosine bump.
  float touchRadius = 0.03f;  // fraction of the grid width
  float touchDepth = -0.04f;  // m; dragging uses a tenth of it per frame
  float rainRate = 0.0f;      // random drops per second
  // A sphere circling through the surface (scenes), pushing the water aside.
  bool sphere = false;
  float sphereRadius = 0.5f;    // m
  float sphereHeight = 0.0f;    // centre above the rest surface, m (0: half submerged)
  float sphereOrbit = 0.25f;    // radius of its circular path, grid widths
  float spherePeriod = 8.0f;    // s per round
  float sphereCoupling = 0.5f;  // fraction of the displaced column moved per step
};

void visit(ParamVisitor& v, Params& p);

// Courant number C = c·dt/dx of the wave rule for a given step.
inline float courant(const Params& p, double dt) { return float(p.waveSpeed * dt / p.cellSize); }

// Centre of the sphere at time t: metres from the grid corner, z above the rest surface.
glm::vec3 sphereCentre(const Params& p, double t);

// Substeps per frame (of p.frameSeconds): fixed, or the fewest that keep C under courantTarget·1/√2.
int substepsFor(const Params& p);

}  // namespace tidepool::ripples
