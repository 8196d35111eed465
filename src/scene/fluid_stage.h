// The fluid scene: position-based fluid water (sim/fluid) in the water stage it shares with the
// balls (scene/water_stage.h: the same view and camera; the window switches between the models).
//
//   { "model": "fluid",
//     "params": { "particles": {"spacing": 0.01, "domain_max": [1, 0.25, 0.6], ...},
//                 "solver": {"iterations": 4, ...}, "engine": {"dt": 0.0016, "substeps": 10},
//                 "obstacles": [...], "view": {...} } }
#pragma once

#include "scene/balls_stage.h"
#include "scene/scene.h"
#include "scene/stage.h"
#include "sim/fluid/fluid_params.h"

namespace tidepool {

struct FluidSceneParams {
  fluid::Params model;
  BallsViewSettings view;
};

void visit(ParamVisitor& v, FluidSceneParams& p);

ModelEntry fluidModel();  // "fluid" in scene files

// A fluid scene's params; throws Error naming the file when the scene is another model's.
const FluidSceneParams& fluidScene(const Scene& scene);

}  // namespace tidepool
