// The water half of "model": "auto" (scene/auto_method.h): which accuracy keys a water scene
// states, which study measures them, and how a row of balls or fluid becomes settings for the
// scene. Both studies hold rows of both models (column `model`), measured on the same metric, so
// the pick compares them: the cheapest row that meets the bound decides the model as well.
//
// clang-format off
//   key            study (assets/accuracy/)   column               rows' method
//   densityError   fluid-density              density_error_mean   "pbf, 4 iterations" | "spring-dashpot, symplectic-euler"
//   frontError     water-front                front_error          (the same)
// clang-format on
//
// A fluid row sets solver.iterations and engine.dt, engine.substeps (rescaled: the frame keeps
// its simulated time dt x substeps); a balls row sets what a balls "method": "auto" pick sets
// (auto_models.h: ballsSettings) on the scene's particles as balls (asBalls, scene/water_stage.h:
// the same water volume, radius = spacing · 2^(1/6) / 2). Rows whose resolution names a spacing
// ("spacing 0.02 m") apply only to scenes of that spacing.
#pragma once

#include <string>
#include <vector>

#include "io/csv.h"
#include "scene/auto_select.h"
#include "sim/balls/balls_params.h"
#include "sim/fluid/fluid_params.h"

namespace tidepool::automethod {

struct WaterSource {
  const char* key;      // in the scene's "accuracy" object
  const char* column;   // the study CSV's metric column
  const char* study;    // assets/accuracy/<study>.csv
  const char* words;    // how the window and the log name it: "density error"
  bool percent;         // shown as a percentage (a fraction in the data)
  const char* meaning;  // for messages and docs
};
const std::vector<WaterSource>& waterSources();
const WaterSource* waterSource(const std::string& key);  // nullptr: not a water key
std::string waterKeys();                                 // "densityError, frontError"

// `value` of `source`'s metric in words: "density error 0.35%", "front error 0.0123".
std::string waterValue(const WaterSource& source, double value);

struct WaterInput {
  const fluid::Params& fluid;  // the scene's params, as read from the file (fluid form)
  const balls::Params& balls;  // the same particles as balls
  const WaterSource& metric;
  const io::CsvTable& table;  // the study's rows
  std::string where;          // "file: scene.accuracy"
};

// Candidates (model "balls" or "fluid") from the rows that apply to the scene's spacing; rows past
// a stability margin or needing more than 1000 substeps are left out. Throws Error naming the
// file and line of a row it cannot read, or the measured spacings when none is the scene's.
std::vector<Candidate> waterCandidates(const WaterInput& in);

}  // namespace tidepool::automethod
