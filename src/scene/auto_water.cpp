#include "scene/auto_water.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "base/error.h"
#include "scene/auto_models.h"

namespace tidepool::automethod {
namespace {

// The spacing a row was measured at, from its resolution ("spacing 0.02 m", "N = 3900, spacing
// 0.02 m"); NaN when it names none (the row then applies at any spacing).
double rowSpacing(const io::CsvTable& t, std::size_t row) {
  const std::string& text = t.text(row, "resolution");
  const std::size_t at = text.find("spacing ");
  if (at == std::string::npos) return NAN;
  const char* start = text.c_str() + at + 8;
  char* end = nullptr;
  const double d = std::strtod(start, &end);
  if (end == start || !(d > 0) || std::string(end).rfind(" m", 0) != 0)
    throw Error(t.where(row) + ": resolution '" + text + "' does not read as 'spacing <metres> m'");
  return d;
}

bool sameSpacing(double a, double b) { return std::abs(a / b - 1.0) < 1e-3; }

std::string ms(double seconds) { return formatValue(seconds * 1e3) + " ms"; }

// A fluid row, method "pbf, <k> iterations": the solver's iterations, and the step rescaled so
// that the frame keeps its simulated time.
bool fluidRow(const WaterInput& in, std::size_t r, double frame, Candidate& c) {
  const io::CsvTable& t = in.table;
  const std::string method = t.text(r, "method");
  std::istringstream words(method);
  std::string pbf, iterationsWord, extra;
  int iterations = 0;
  if (!(words >> pbf >> iterations >> iterationsWord) || words >> extra || pbf != "pbf," ||
      (iterationsWord != "iterations" && iterationsWord != "iteration") || iterations < 1 || iterations > 100)
    throw Error(t.where(r) + ": method '" + method + "' is not 'pbf, <1 to 100> iterations'");
  if (t.has("iterations") && t.number(r, "iterations") != iterations)
    throw Error(t.where(r) + ": method '" + method + "' but iterations " + t.text(r, "iterations"));
  const double dt = t.number(r, "dt");
  if (!(dt > 0) || frame / dt - 1e-6 > 1000) return false;  // the param's range
  const int substeps = std::max(1, int(std::ceil(frame / dt - 1e-6)));
  const float runDt = float(frame / substeps);
  c.step = dt;
  c.label = "fluid, " + std::to_string(iterations) + (iterations == 1 ? " iteration" : " iterations") + ", dt " +
            ms(frame / substeps);
  c.settings = {
      pick("solver.iterations", &fluid::Params::iterations, iterations),
      {"engine.dt", true, [runDt](SceneParams& p) { p.model<fluid::Params>().water.dt = runDt; }},
      {"engine.substeps", true, [substeps](SceneParams& p) { p.model<fluid::Params>().water.substeps = substeps; }}};
  return true;
}

// A balls row: as a balls "method": "auto" pick (ballsSettings), on the scene's particles as balls.
bool ballsRow(const WaterInput& in, std::size_t r, double frame, Candidate& c) {
  const BallsMethod m = parseBallsMethod(in.table, r);
  const double dt = in.table.number(r, "dt");
  double contactTime = decimal(in.balls.contactTime);
  std::string extra;
  if (m.contact == balls::Contact::SpringDashpot && m.stepsPerContact > 0) {
    contactTime = m.stepsPerContact * dt;
    extra = ", t_c = " + ms(contactTime);
  }
  c.settings = ballsSettings(m, dt, contactTime, frame);
  if (c.settings.empty()) return false;
  c.step = dt;
  c.label = "balls, " + m.words + ", dt " + ms(frame / std::max(1, int(std::ceil(frame / dt - 1e-6)))) + extra;
  return true;
}

}  // namespace

const std::vector<WaterSource>& waterSources() {
  static const std::vector<WaterSource> table = {
      {"densityError", "density_error_mean", "fluid-density", "density error", true,
       "mean |rho/rho0 - 1| over the particles of the study's water, over its run"},
      {"frontError", "front_error", "water-front", "front error", false,
       "RMS error of the dam break's surge front against the finest run of the same model"},
  };
  return table;
}

const WaterSource* waterSource(const std::string& key) {
  for (const WaterSource& s : waterSources())
    if (key == s.key) return &s;
  return nullptr;
}

std::string waterKeys() {
  std::string out;
  for (const WaterSource& s : waterSources()) out += (out.empty() ? "" : ", ") + std::string(s.key);
  return out;
}

std::string waterValue(const WaterSource& source, double value) {
  return std::string(source.words) + " " + (source.percent ? formatValue(100.0 * value) + "%" : formatValue(value));
}

std::vector<Candidate> waterCandidates(const WaterInput& in) {
  const io::CsvTable& t = in.table;
  const double spacing = decimal(in.fluid.spacing);
  const double frame = decimal(in.fluid.water.dt) * in.fluid.water.substeps;
  std::vector<double> measured;  // the spacings rows name
  std::vector<Candidate> out;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double rowAt = rowSpacing(t, r);
    if (std::isfinite(rowAt) &&
        std::none_of(measured.begin(), measured.end(), [&](double d) { return sameSpacing(d, rowAt); }))
      measured.push_back(rowAt);
    if (std::isfinite(rowAt) && !sameSpacing(rowAt, spacing)) continue;
    Candidate c;
    c.model = t.text(r, "model");
    c.cost = t.number(r, "gpu_ms_per_sim_s");
    c.stable = t.number(r, "stable") != 0;
    c.errors = {std::abs(t.number(r, in.metric.column))};
    c.family = c.model + ": " + t.text(r, "method") + " at " + t.text(r, "resolution");
    bool applies = false;
    if (c.model == "fluid")
      applies = fluidRow(in, r, frame, c);
    else if (c.model == "balls")
      applies = ballsRow(in, r, frame, c);
    else
      throw Error(t.where(r) + ": model '" + c.model + "' is not balls or fluid");
    if (applies) out.push_back(std::move(c));
  }
  if (out.empty() && !measured.empty()) {
    std::sort(measured.begin(), measured.end());
    std::string list;
    for (double d : measured) list += (list.empty() ? "" : ", ") + formatValue(d);
    throw Error(in.where + ": no row of " + std::string(in.metric.study) + " was measured at this scene's spacing " +
                formatValue(spacing) + " m (measured: " + list + " m)");
  }
  return out;
}

}  // namespace tidepool::automethod
