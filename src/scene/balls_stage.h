// The balls scene: the ball model, its renderer and an orbit camera (left drag rotates, right
// drag pans, wheel zooms). Live statistics are refreshed every few frames for the status line.
//
//   { "model": "balls",
//     "params": { "particles": {...}, "engine": {"dt": 0.0005, ...}, "obstacles": [...],
//                 "view": { "mode": "water", "camera": {"distance": 2.4} } } }
#pragma once

#include "render/balls_view_params.h"
#include "render/orbit_camera.h"
#include "scene/scene.h"
#include "scene/stage.h"
#include "sim/balls/balls_params.h"

namespace tidepool {

// The "view" group: how the balls are drawn and seen (benchmarks render without a stage).
struct BallsViewSettings {
  BallsViewParams look;
  OrbitCameraParams camera{glm::vec3(0.5f, 0.5f, 0.35f), 2.4f, -1.0f, 0.45f, 45.0f};
};

// A balls scene's "params": the model's keys, and "view".
struct BallsSceneParams {
  balls::Params model;
  BallsViewSettings view;
};

void visit(ParamVisitor& v, BallsViewSettings& s);
void visitViewGroup(ParamVisitor& v, BallsViewSettings& s);  // the "view" group (balls and fluid scenes)
void visit(ParamVisitor& v, BallsSceneParams& p);

ModelEntry ballsModel();  // "balls" in scene files

// A balls scene's params; throws Error naming the file when the scene is another model's.
const BallsSceneParams& ballsScene(const Scene& scene);
balls::Params ballsParams(const Scene& scene);  // ballsScene(scene).model

}  // namespace tidepool
