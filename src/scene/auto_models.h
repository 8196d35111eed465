// The per-model half of "method": "auto" (scene/auto_method.h): which accuracy keys each model
// states, which study measures them, and how a study row becomes settings for a scene: writes to
// fields of the model's typed params (Setting), some of them rescaled rather than chosen (the
// balls' dt and substeps keep the frame's simulated time; the ripples' grid keeps the pool's size),
// which a scene may state without conflicting with "method": "auto".
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "io/csv.h"
#include "io/json.h"
#include "scene/auto_select.h"

namespace tidepool::automethod {

inline constexpr double kStabilityMargin = 0.9;  // picks stay under 90% of a known stability limit

struct Source {
  const char* model;
  const char* key;                   // in the scene's "accuracy" object
  const char* column;                // the study CSV's metric column
  std::vector<const char*> studies;  // assets/accuracy/<study>.csv, all read
  const char* meaning;               // for messages and docs
};
const std::vector<Source>& sources();

struct Tables {
  std::vector<std::pair<std::string, io::CsvTable>> studies;  // name, rows
};

struct ModelInput {
  const SceneParams& params;           // the scene's typed params, as read from the file
  const io::Json& accuracy;            // the scene's accuracy object (extra keys such as wavelength)
  std::vector<const Source*> metrics;  // one per bound, in order
  const Tables& tables;
  std::string where;  // "file: scene.accuracy"
};

// Candidates from every row of the model's tables (rows past a stability margin or that the
// scene cannot run are left out). Throw Error naming the file and line of a row they cannot read.
std::vector<Candidate> swarmCandidates(const ModelInput& in);
std::vector<Candidate> ripplesCandidates(const ModelInput& in);
std::vector<Candidate> ballsCandidates(const ModelInput& in);

// Accuracy keys that are not bounds but describe the scene (ripples: wavelength, wavelengthCells).
std::vector<std::string> extraKeys(const std::string& model);

}  // namespace tidepool::automethod
