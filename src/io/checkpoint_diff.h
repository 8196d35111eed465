// Where two checkpoints differ, in one line: `tidepool check-resume` and the checkpoint tests hold
// a resumed run to the uninterrupted one with it, bit for bit.
#pragma once

#include <optional>
#include <string>

#include "io/checkpoint_file.h"

namespace tidepool::io {

// nullopt: the same model, scene, parameters, time, step count and entries, byte for byte.
// Otherwise what differs, e.g. "2 of 23 entries differ: 'model.velocities' (219872 of 220000
// bytes, the first at byte 0), 'stage.balls_stats' (...)".
std::optional<std::string> checkpointDifference(const Checkpoint& a, const Checkpoint& b);

}  // namespace tidepool::io
