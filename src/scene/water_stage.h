// The stage of particle water, for balls scenes and fluid scenes alike: the active model (balls or
// fluid), the water view reading it (render/balls_view.h reads either through sim::ParticleWater),
// an orbit camera (left drag rotates, right drag pans, wheel zooms). The UI's "Water model" choice
// (or the M key) switches between the two keeping the particle set: the other model starts from
// the current particles' positions and velocities, with the shared keys (domain, fill, walls, tap,
// obstacles) carried over and its own keys (contact law, or the PBF solver) as they were.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "scene/balls_stage.h"
#include "scene/stage.h"
#include "sim/fluid/fluid_params.h"

namespace tidepool {

enum class WaterModel { Balls, Fluid };
constexpr std::array<const char*, 2> kWaterModelNames = {"balls", "fluid"};

// The balls parameters a fluid scene's particles would be as balls, and the fluid parameters of a
// balls scene's; `own` keeps the target's own keys. The water keeps its volume: balls at rest pack
// hexagonally (√2 per (2r)³), the fluid's rest lattice is cubic (one per d³), so d = 2r / 2^(1/6)
// (a resting pile of balls is resting fluid, and back).
balls::Params asBalls(const fluid::Params& f, balls::Params own);
fluid::Params asFluid(const balls::Params& b, fluid::Params own);

// The stage of a balls scene or a fluid scene (the other model's parameters follow by asFluid or
// asBalls); an error building it (a missing mesh, too many particles) is prefixed with `where`.
std::unique_ptr<Stage> createWaterStage(gl::ShaderLibrary& shaders, const balls::Params& balls,
                                        const BallsViewSettings& view, const std::string& where);
std::unique_ptr<Stage> createWaterStage(gl::ShaderLibrary& shaders, const fluid::Params& fluid,
                                        const BallsViewSettings& view, const std::string& where);

}  // namespace tidepool
