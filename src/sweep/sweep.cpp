#include "sweep/sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

#include "base/error.h"
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
  if (!out) throw Error("cannot write '" + path.string() + "'");
  out << "study,model,method,dt,substeps,resolution,gpu_ms_per_sim_s";
  for (const std::string& m : result.metrics) out << "," << m;
  out << ",stable,pareto,device\n";
  for (const Row& r : result.rows) {
    out << study << "," << result.model << "," << r.method << "," << csvNumber(r.dt) << "," << r.substeps << ","
        << r.resolution << "," << csvNumber(r.costMsPerSimS);
    for (double m : r.metrics) out << "," << csvNumber(m);
    out << "," << (r.stable ? 1 : 0) << "," << (r.pareto ? 1 : 0) << ",\"" << device << "\"\n";
  }
}

void drawChart(const Result& result, const std::string& device, const fs::path& base) {
  if (!onPath("gnuplot")) throw Error("charts need gnuplot, which is not installed (apt-get install gnuplot-nox)");
  std::error_code ec;
  fs::create_directories(base.parent_path(), ec);
  // One gnuplot data block per method (in first-seen order), then the Pareto front.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const Row*>> byMethod;
  for (const Row& r : result.rows) {
    if (!byMethod.count(r.method)) order.push_back(r.method);
    byMethod[r.method].push_back(&r);
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
  const fs::path script = fs::path(TIDEPOOL_SOURCE_DIR) / "bench" / "chart.gp";
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
