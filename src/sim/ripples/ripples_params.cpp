#include "sim/ripples/ripples_params.h"

#include <cmath>

namespace tidepool::ripples {

void visit(ParamVisitor& v, Params& p) {
  v.choice({"rule", "Rule", "wave: wave equation; seed: the original spring + tension model"}, p.rule, kRuleNames);
  v.integer({"width", "Width", "cells (re-allocates)"}, p.width, 16, 4096);
  v.integer({"height", "Height", "cells (re-allocates)"}, p.height, 16, 4096);
  v.realDouble({"frame_seconds", "Frame seconds", "simulated seconds per frame"}, p.frameSeconds, 1e-4f, 1.0f);
  v.real({"cell_size", "Cell size", "dx, metres"}, p.cellSize, 1e-4f, 10.0f);
  v.real({"wave_speed", "Wave speed", "c, m/s (wave rule)"}, p.waveSpeed, 0.0f, 100.0f);
  v.real({"vel_damping", "Velocity damping", "1/s"}, p.velDamping, 0.0f, 50.0f);
  v.real({"pos_damping", "Positional damping", "1/s, smooths heights toward the neighbour mean"}, p.posDamping, 0.0f,
         50.0f);
  v.choice({"boundary", "Boundary", "reflecting (mirrored), absorbing (sponge layer) or periodic"}, p.boundary,
           kBoundaryNames);
  v.integer({"sponge_cells", "Sponge width", "cells of the absorbing layer"}, p.spongeCells, 1, 512);
  v.real({"sponge_damping", "Sponge damping", "1/s at the outermost cell"}, p.spongeDamping, 0.0f, 1000.0f);
  v.flag({"auto_substeps", "Auto substeps", "keep the Courant number under the target"}, p.autoSubsteps);
  v.real({"courant_target", "Courant target", "fraction of the 2D limit 1/sqrt(2)"}, p.courantTarget, 0.05f, 1.5f);
  v.integer({"substeps", "Substeps", "per frame when auto substeps is off"}, p.substeps, 1, 256);
  if (v.beginGroup({"seed", "Seed rule", "constants of water-simulation-gpu"})) {
    v.real({"elasticity", "Elasticity k", "spring toward rest height"}, p.seedElasticity, 0.0f, 10.0f);
    v.real({"propagation", "Propagation c", "pull toward the neighbour mean"}, p.seedPropagation, 0.0f, 200.0f);
    v.real({"friction", "Friction", "velocity factor per step"}, p.seedFriction, 0.5f, 1.0f);
    v.real({"time_scale", "Time scale", "seed dt = time scale x the step's dt"}, p.seedTimeScale, 0.1f, 100.0f);
    v.endGroup();
  }
  if (v.beginGroup({"touch", "Touch", "mouse and drops: cosine bump"})) {
    v.real({"radius", "Radius", "fraction of the grid width"}, p.touchRadius, 0.001f, 0.5f);
    v.real({"depth", "Depth", "m; negative pushes down"}, p.touchDepth, -1.0f, 1.0f);
    v.real({"rain", "Rain", "random drops per second"}, p.rainRate, 0.0f, 1000.0f);
    v.endGroup();
  }
  if (v.beginGroup({"sphere", "Sphere", "a ball circling through the surface"})) {
    v.flag({"enabled", "Enabled", ""}, p.sphere);
    v.real({"radius", "Radius", "m"}, p.sphereRadius, 0.001f, 100.0f);
    v.real({"height", "Height", "centre above the rest surface, m"}, p.sphereHeight, -100.0f, 100.0f);
    v.real({"orbit", "Orbit", "path radius, grid widths"}, p.sphereOrbit, 0.0f, 0.5f);
    v.real({"period", "Period", "seconds per round"}, p.spherePeriod, 0.1f, 1000.0f);
    v.real({"coupling", "Coupling", "fraction of the displaced column moved per step"}, p.sphereCoupling, 0.0f, 1.0f);
    v.endGroup();
  }
}

glm::vec3 sphereCentre(const Params& p, double t) {
  const double width = p.width * double(p.cellSize), height = p.height * double(p.cellSize);
  const double angle = 2.0 * 3.14159265358979 * t / p.spherePeriod;
  return {float(0.5 * width + p.sphereOrbit * width * std::cos(angle)),
          float(0.5 * height + p.sphereOrbit * width * std::sin(angle)), p.sphereHeight};
}

int substepsFor(const Params& p) {
  if (!p.autoSubsteps || p.rule == Rule::Seed) return p.substeps;
  const double limit = p.courantTarget * kCourantLimit2D;
  const double perFrame = p.waveSpeed * p.frameSeconds / p.cellSize;
  return std::max(1, int(std::ceil(perFrame / limit - 1e-9)));
}

}  // namespace tidepool::ripples
