#include "sweep/sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "base/error.h"
#include "base/progress.h"
#include "base/source_dir.h"
#include "io/csv.h"
#include "io/echo.h"
#include "io/json.h"
#include "io/video.h"

namespace tidepool::sweep {
namespace fs = std::filesystem;

namespace {
std::string csvNumber(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : "inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// A CSV field: quoted when it holds a comma or a quote (method names such as "phase-speed error,
// 10 cells per wavelength").
std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

bool onPath(const std::string& tool) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  for (std::size_t start = 0, end; start <= dirs.size(); start = end + 1) {
    end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    if (end > start && fs::exists(fs::path(dirs.substr(start, end - start)) / tool)) return true;
  }
  return false;
}

std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

Result runStudy(const Study& study, Env& env) {
  Result r = study.run(env);
  if (r.chart.pareto) markPareto(r.rows);
  return r;
}

Result emptyResult(std::string model, std::vector<std::string> metrics, ChartSpec chart) {
  return {std::move(model), std::move(metrics), {}, std::move(chart)};
}

void addCostRow(Result& result, Row row, double error) {
  row.x = row.costMsPerSimS;
  row.y = error;
  announce(row);
  result.rows.push_back(std::move(row));
}

void announce(const Row& row) {
  std::string text = row.model.empty() ? row.method : row.model + " " + row.method;
  char number[64];
  if (row.dt > 0) {
    std::snprintf(number, sizeof number, ", dt %.3g s", row.dt);
    text += number;
  }
  if (!row.resolution.empty()) text += ", " + row.resolution;
  if (row.costMsPerSimS > 0) {
    std::snprintf(number, sizeof number, ": %.3g ms per simulated s", row.costMsPerSimS);
    text += number;
  }
  Steps::note(text + (row.stable ? "" : " (unstable)"));
}

void markPareto(std::vector<Row>& rows) {
  for (Row& r : rows) {
    r.pareto = r.stable && std::isfinite(r.x) && std::isfinite(r.y);
    for (const Row& o : rows)
      if (&o != &r && o.stable && o.x <= r.x && o.y <= r.y && (o.x < r.x || o.y < r.y)) r.pareto = false;
  }
}

void writeCsv(const Result& result, const std::string& study, const std::string& device, const fs::path& path) {
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  std::ofstream out(path);
  if (!out) throw Error("cannot write '" + io::shownPath(path) + "'");
  out << "study,model,method,dt,substeps,resolution,gpu_ms_per_sim_s";
  for (const std::string& m : result.metrics) out << "," << m;
  out << ",chart_x,chart_y,stable,pareto,device\n";
  for (const Row& r : result.rows) {
    out << study << "," << csvField(r.model.empty() ? result.model : r.model) << "," << csvField(r.method) << ","
        << csvNumber(r.dt) << "," << r.substeps << "," << csvField(r.resolution) << "," << csvNumber(r.costMsPerSimS);
    for (double m : r.metrics) out << "," << csvNumber(m);
    out << "," << csvNumber(r.x) << "," << csvNumber(r.y) << "," << (r.stable ? 1 : 0) << "," << (r.pareto ? 1 : 0)
        << ",\"" << device << "\"\n";
  }
}

void writeChartSpec(const Result& result, const fs::path& path) {
  const ChartSpec& c = result.chart;
  io::Json j = {{"model", result.model}, {"metrics", result.metrics},
                {"title", c.title},      {"x_label", c.xLabel},
                {"y_label", c.yLabel},   {"log_x", c.logX},
                {"log_y", c.logY},       {"pareto", c.pareto},
                {"marker_x", c.markerX}, {"marker_label", c.markerLabel}};
  io::writeJsonFile(path, j);
}

Result readResult(const fs::path& csv, const fs::path& spec, std::string& device) {
  Result r;
  const io::Json j = io::readJsonFile(spec);
  try {
    r.model = j.at("model").get<std::string>();
    r.metrics = j.at("metrics").get<std::vector<std::string>>();
    r.chart = {j.at("title").get<std::string>(),   j.at("x_label").get<std::string>(),
               j.at("y_label").get<std::string>(), j.at("log_x").get<bool>(),
               j.at("log_y").get<bool>(),          j.at("pareto").get<bool>(),
               j.at("marker_x").get<double>(),     j.at("marker_label").get<std::string>()};
  } catch (const io::Json::exception& e) {
    throw Error("'" + io::shownPath(spec) + "': " + io::printable(e.what(), 200));
  }
  std::istringstream lines(io::readTextFile(csv));
  std::string line;
  std::vector<std::string> header;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> f = io::splitCsvLine(line);
    const std::string where = io::shownPath(csv) + ":" + std::to_string(number);
    if (header.empty()) {
      header = f;
      if (header.size() != 12 + r.metrics.size() || header[7 + r.metrics.size()] != "chart_x")
        throw Error(where + ": not a sweep CSV with chart_x/chart_y columns for " + std::to_string(r.metrics.size()) +
                    " metrics (rerun the study to rewrite it)");
      continue;
    }
    if (f.size() != header.size())
      throw Error(where + ": " + std::to_string(f.size()) + " fields, the header has " + std::to_string(header.size()));
    auto number_ = [&](std::size_t i) {
      char* end = nullptr;
      const double v = std::strtod(f[i].c_str(), &end);
      if (end == f[i].c_str() || *end) throw Error(where + ": " + header[i] + " '" + f[i] + "' is not a number");
      return v;
    };
    Row row;
    if (f[1] != r.model) row.model = f[1];
    row.method = f[2];
    row.dt = number_(3);
    row.substeps = int(number_(4));
    row.resolution = f[5];
    row.costMsPerSimS = number_(6);
    for (std::size_t m = 0; m < r.metrics.size(); ++m) row.metrics.push_back(number_(7 + m));
    const std::size_t k = 7 + r.metrics.size();
    row.x = number_(k);
    row.y = number_(k + 1);
    row.stable = number_(k + 2) != 0;
    row.pareto = number_(k + 3) != 0;
    device = f[k + 4];
    r.rows.push_back(row);
  }
  if (r.rows.empty()) throw Error("'" + csv.string() + "' holds no rows");
  return r;
}

void drawChart(const Result& result, const std::string& device, const fs::path& base) {
  if (!onPath("gnuplot")) throw Error("charts need gnuplot, which is not installed (apt-get install gnuplot-nox)");
  std::error_code ec;
  fs::create_directories(base.parent_path(), ec);
  // One gnuplot data block per method (in first-seen order), then the Pareto front. A row of its
  // own model (a study of several) names it: "balls: spring-dashpot, symplectic-euler".
  std::vector<std::string> order;
  std::map<std::string, std::vector<const Row*>> byMethod;
  for (const Row& r : result.rows) {
    const std::string curve = r.model.empty() ? r.method : r.model + ": " + r.method;
    if (!byMethod.count(curve)) order.push_back(curve);
    byMethod[curve].push_back(&r);
  }
  const fs::path dat = fs::path(base.string() + ".dat.tmp");
  {
    std::ofstream out(dat);
    for (const std::string& m : order) {
      std::string title = m;  // gnuplot's enhanced text would take '_' for a subscript
      std::replace(title.begin(), title.end(), '_', '-');
      out << "\"" << title << "\" \"y\"\n";
      for (const Row* r : byMethod[m])
        if (std::isfinite(r->x) && std::isfinite(r->y) && (!result.chart.logY || r->y > 0))
          out << csvNumber(r->x) << " " << csvNumber(r->y) << "\n";
      out << "\n\n";
    }
    std::vector<const Row*> front;
    for (const Row& r : result.rows)
      if (r.pareto) front.push_back(&r);
    std::sort(front.begin(), front.end(), [](const Row* a, const Row* b) { return a->x < b->x; });
    out << "\"Pareto front\" \"y\"\n";
    for (const Row* r : front) out << csvNumber(r->x) << " " << csvNumber(r->y) << "\n";
  }
  const bool software = device.find("llvmpipe") != std::string::npos || device.find("softpipe") != std::string::npos;
  const ChartSpec& c = result.chart;
  const std::string title =
      c.title + "\n{/*0.8 " + device + (software ? " (software renderer: development figures)" : "") + "}";
  const fs::path script = sourceDir() / "bench" / "chart.gp";
  const std::string cmd = "gnuplot -c " + quoted(script.string()) + " " + quoted(dat.string()) + " " +
                          quoted(base.string()) + " " + quoted(title) + " " + quoted(c.xLabel) + " " +
                          quoted(c.yLabel) + " " + (c.logX ? "1" : "0") + (c.logY ? "1" : "0") +
                          (c.pareto ? "1" : "0") + " " + std::to_string(order.size()) + " " + csvNumber(c.markerX) +
                          " " + quoted(c.markerLabel.empty() ? "-" : c.markerLabel);
  const int status = std::system(cmd.c_str());
  fs::remove(dat, ec);
  if (status != 0) throw Error("gnuplot failed drawing '" + base.string() + ".png' (see its message above)");
}

}  // namespace tidepool::sweep
