// JSON <-> parameter structs through ParamVisitor. Reading validates: unknown keys (typos),
// wrong types and out-of-range values are errors naming the file and the key path, e.g.
//   scenes/dam.json: params.substeps = 0 is out of range [1, 64]
//   scenes/cup.json: params.obstacles[2].size[0] = 500 is out of range [0, 100]
// Keys that are absent keep their defaults.
#pragma once

#include <functional>
#include <string>

#include "base/param.h"
#include "io/json.h"

namespace tidepool {

using ParamVisit = std::function<void(ParamVisitor&)>;

// Reads `json` (an object, or null for "all defaults") into the struct visited by `visit`.
// `where` prefixes messages ("scenes/dam.json: params"). Throws Error.
void readParams(const io::Json& json, const ParamVisit& visit, const std::string& where);

// Writes the visited struct as a JSON object.
io::Json writeParams(const ParamVisit& visit);

}  // namespace tidepool
