// Speed-against-accuracy studies: `tidepool sweep <study>` runs one headless, writes a CSV row per
// run to <study>.csv and draws its chart with gnuplot (bench/chart.gp) into <study>.png and .svg
// (out/sweep/ by default; the shipped ones, with --ship, in bench/results/ and docs/charts/):
// measured cost on x, error on y, one curve per method, a point per dt / resolution, the Pareto
// front marked. The device is written into every row and into the chart title; software-renderer
// runs are labelled as development figures.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "gl/shader_library.h"

namespace tidepool::sweep {

struct Row {
  std::string
      model;  // the model of this row where a study measures several (water: balls, fluid); empty: Result::model
  std::string method;  // curve: integrator, contact model, Courant number...
  double dt = 0;       // s (0 when not applicable)
  int substeps = 1;
  std::string resolution;       // N, grid size or cells per wavelength
  double costMsPerSimS = 0;     // measured GPU ms per simulated second
  std::vector<double> metrics;  // in the order of Study::metrics
  bool stable = true;
  double x = 0, y = 0;  // the chart's coordinates (usually cost and one metric)
  bool pareto = false;  // no other row is both cheaper and more accurate
};

struct ChartSpec {
  std::string title, xLabel, yLabel;
  bool logX = true, logY = true;
  bool pareto = true;  // mark the Pareto front (cost-vs-error charts)
  double markerX = 0;  // a vertical line (e.g. a theoretical limit); 0: none
  std::string markerLabel = "";
};

struct Result {
  std::string model;                 // written into every row whose Row::model is empty
  std::vector<std::string> metrics;  // CSV column names of Row::metrics
  std::vector<Row> rows;
  ChartSpec chart;
};

struct Env {
  gl::ShaderLibrary& shaders;
  std::string device;  // GL_RENDERER
  bool quick = false;  // fewer points (tests, smoke runs)
};

struct Study {
  const char* name;
  const char* summary;
  std::function<Result(Env&)> run;
};

const std::vector<Study>& studies();

// Runs the study; on a cost-against-error chart (chart.pareto) marks the rows on the Pareto front.
Result runStudy(const Study& study, Env& env);
// A result with no rows yet: the model, the CSV names of Row::metrics and the chart (by default a
// cost-against-error chart: log axes, the Pareto front marked).
Result emptyResult(std::string model, std::vector<std::string> metrics, ChartSpec chart = {});
// Adds `row` to a cost-against-error chart: at its cost on x, `error` on y; announces it.
void addCostRow(Result& result, Row row, double error);
// A line on stderr for a row just measured, while the command's Steps (base/progress.h) is alive:
// "sweep balls-dt: verlet, dt 0.002 s, 64k: 12.3 ms per simulated s (40 s so far)".
void announce(const Row& row);

void markPareto(std::vector<Row>& rows);  // minimises (x, y) among stable rows
void writeCsv(const Result& result, const std::string& study, const std::string& device,
              const std::filesystem::path& path);
// The chart's settings beside the CSV (<study>.chart.json), so that charts can be redrawn from
// rows measured elsewhere (the GPU machine has no gnuplot): `tidepool sweep <study> --from-csv`.
void writeChartSpec(const Result& result, const std::filesystem::path& path);
// Reads a CSV written by writeCsv and its chart settings; returns the rows (model where it is not
// the result's, method, chart x and y, stable, pareto) and the device they were measured on.
// Throws Error naming the file and line.
Result readResult(const std::filesystem::path& csv, const std::filesystem::path& spec, std::string& device);
// Draws the chart with gnuplot into <base>.png and <base>.svg; throws Error when gnuplot is
// missing or fails.
void drawChart(const Result& result, const std::string& device, const std::filesystem::path& base);

}  // namespace tidepool::sweep
