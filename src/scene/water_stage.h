// The stage of particle water, for balls scenes and fluid scenes alike: the running model (balls or
// fluid, a WaterRun of scene/water_runs.h), the water view reading it (render/balls_view.h reads
// either through water::ParticleWater), an orbit camera (left drag rotates, right drag pans, wheel
// zooms). The UI's "Water model" choice (or the M key) switches between the two keeping the
// particle set: the other model starts from the current particles' positions and velocities, with
// the water setup carried over (water::switched) and its own keys (contact law, or the PBF solver)
// as they were.
#pragma once

#include <memory>
#include <string>

#include "scene/balls_stage.h"
#include "scene/stage.h"
#include "scene/water_runs.h"
#include "sim/fluid/fluid_params.h"

namespace tidepool {

// The stage of a balls scene or a fluid scene (the other model's parameters follow by asFluid or
// asBalls); an error building it (a missing mesh, too many particles) is prefixed with `where`.
std::unique_ptr<Stage> createWaterStage(gl::ShaderLibrary& shaders, const balls::Params& balls,
                                        const BallsViewSettings& view, const std::string& where);
std::unique_ptr<Stage> createWaterStage(gl::ShaderLibrary& shaders, const fluid::Params& fluid,
                                        const BallsViewSettings& view, const std::string& where);

}  // namespace tidepool
