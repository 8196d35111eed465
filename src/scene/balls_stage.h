// The balls scene: the ball model, its renderer and an orbit camera (left drag rotates, right
// drag pans, wheel zooms). Live statistics are refreshed every few frames for the status line.
#pragma once

#include "scene/scene.h"
#include "scene/stage.h"
#include "sim/balls/balls_params.h"

namespace tidepool {

// The balls model's parameters of a scene (its "view" group is read and dropped).
balls::Params ballsParams(const Scene& scene);

std::unique_ptr<Stage> createBallsStage(const io::Json& params, const std::string& where, gl::ShaderLibrary& shaders);

}  // namespace tidepool
