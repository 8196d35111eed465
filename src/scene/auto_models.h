// The per-model half of "method": "auto" (scene/auto_method.h): which accuracy keys each model
// states, which study measures them, and how a study row becomes settings for a scene: writes to
// fields of the model's typed params (Setting), some of them rescaled rather than chosen (the
// balls' dt and substeps keep the frame's simulated time; the ripples' grid keeps the pool's size),
// which a scene may state without conflicting with "method": "auto".
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/csv.h"
#include "io/json.h"
#include "scene/auto_select.h"
#include "sim/balls/balls_params.h"

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

// A balls row's method: "<contact>[ tc = K dt][, <integrator>]" (balls-settle and the water
// studies), or with `integratorOnly` the integrator of a spring-dashpot bounce (balls-restitution).
struct BallsMethod {
  balls::Contact contact = balls::Contact::SpringDashpot;
  std::optional<balls::Integrator> integrator;  // none: the row names none
  double stepsPerContact = 0;                   // K when the row ties the contact time to the step
  std::string words;                            // "spring-dashpot, symplectic-euler"
};
BallsMethod parseBallsMethod(const io::CsvTable& t, std::size_t row, bool integratorOnly = false);  // throws: file:line
// What a balls row at step `dt` (s) writes into a scene whose frame lasts `frame` s: the contact
// law, the integrator (when named), t_c (when tied to dt) and dt, substeps rescaled to keep the
// frame. Empty when the row is past the stability margin at `contactTime` or needs > 1000 substeps.
Settings ballsSettings(const BallsMethod& m, double dt, double contactTime, double frame);

// The number a scene wrote for a float parameter: the shortest decimal that reads back as that
// float (0.0002f -> 0.0002), so that the frame's simulated time dt x substeps is the scene's
// 0.0002 x 25 = 0.005 s, which the picked substeps then divide.
double decimal(float value);

// Index of `name` in a model's names, or -1.
template <std::size_t N>
int indexOf(const std::array<const char*, N>& names, const std::string& name) {
  const auto it = std::find_if(names.begin(), names.end(), [&](const char* n) { return name == n; });
  return it == names.end() ? -1 : int(it - names.begin());
}

// A setting of one field of the model's params, by its key in scene files and its member:
// pick("engine.contact", &balls::Params::contact, balls::Contact::SpringDashpot).
template <class Model, class T>
Setting pick(const char* key, T Model::*field, std::type_identity_t<T> value) {
  return {key, false, [field, value](SceneParams& p) { p.model<Model>().*field = value; }};
}
// One the scene may state too: the pick rescales it (the frame's time, the pool's size).
template <class Model, class T>
Setting rescale(const char* key, T Model::*field, std::type_identity_t<T> value) {
  Setting s = pick(key, field, value);
  s.rescaled = true;
  return s;
}

// Accuracy keys that are not bounds but describe the scene (ripples: wavelength, wavelengthCells).
std::vector<std::string> extraKeys(const std::string& model);

}  // namespace tidepool::automethod
