#include <algorithm>

#include "base/error.h"
#include "base/progress.h"
#include "base/source_dir.h"
#include "cli/commands.h"
#include "gl/context.h"
#include "gl/info.h"
#include "scene/auto/auto.h"
#include "sweep/sweep.h"

namespace tidepool::cli {

namespace {

// A sweep's output folder: as given; else with --ship the repository's (shipped figures), else
// out/sweep in the working folder, so that a user's run never rewrites files the repository tracks.
std::filesystem::path folder(const std::string& given, bool ship, const char* shipped) {
  if (!given.empty()) return given;
  return ship ? sourceDir() / shipped : std::filesystem::path("out/sweep");
}

}  // namespace

Command addSweep(CLI::App& app) {
  auto* sub = app.add_subcommand("sweep", "speed-against-accuracy studies: CSV rows and gnuplot charts");
  struct Opts {
    std::string backend = "auto", csvDir, chartDir;  // empty: out/sweep here, or with --ship the repository's
    bool quick = false, noChart = false, fromCsv = false, ship = false;
  };
  auto o = std::make_shared<Opts>();
  sub->add_option("--backend", o->backend, "auto, egl or osmesa")->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  sub->add_option("--csv-dir", o->csvDir,
                  "folder for <study>.csv (default: out/sweep here; with --ship bench/results)");
  sub->add_option("--chart-dir", o->chartDir,
                  "folder for <study>.png and .svg (default: out/sweep here; with --ship docs/charts)");
  sub->add_flag("--quick", o->quick, "fewer points (smoke runs)");
  sub->add_flag("--no-chart", o->noChart, "write the CSV only");
  sub->add_flag("--from-csv", o->fromCsv,
                "run nothing: redraw the chart from <csv-dir>/<study>.csv and .chart.json (rows measured "
                "elsewhere, e.g. on the GPU machine with --no-chart); with --no-chart and --ship, only ship");
  sub->add_flag("--ship", o->ship,
                "write the repository's figures: the CSV to bench/results/, the chart to docs/charts/ and, for a "
                "study \"method\": \"auto\" and \"model\": \"auto\" read, the CSV to assets/accuracy/ too");
  sub->require_subcommand(1);
  sub->fallthrough();
  auto chosen = std::make_shared<std::vector<std::pair<CLI::App*, const sweep::Study*>>>();
  for (const sweep::Study& s : sweep::studies()) chosen->emplace_back(sub->add_subcommand(s.name, s.summary), &s);
  return {sub, [o, chosen] {
            // Refused before a long run, not after it.
            if (o->ship && o->quick) throw Error("--ship: --quick rows are smoke-test figures; ship a full run");
            const std::filesystem::path csvDir = folder(o->csvDir, o->ship, "bench/results");
            const std::filesystem::path chartDir = folder(o->chartDir, o->ship, "docs/charts");
            const auto ship = [&](const std::string& study, const std::filesystem::path& csv) {
              const std::vector<std::string> read = shippedStudies();
              if (o->ship && std::find(read.begin(), read.end(), study) != read.end())
                std::printf("shipped %s\n", shipStudy(study, csv).c_str());
            };
            if (o->fromCsv) {
              for (const auto& [app, study] : *chosen) {
                if (!app->parsed()) continue;
                const std::filesystem::path csv = csvDir / (std::string(study->name) + ".csv");
                std::string device;
                const sweep::Result result =
                    sweep::readResult(csv, csvDir / (std::string(study->name) + ".chart.json"), device);
                if (!o->noChart) {
                  const std::filesystem::path base = chartDir / study->name;
                  sweep::drawChart(result, device, base);
                  std::printf("redrew %s.png and .svg from %zu rows measured on %s\n", base.c_str(), result.rows.size(),
                              device.c_str());
                }
                ship(study->name, csv);
                return 0;
              }
              return 2;
            }
            auto context = gl::createHeadlessContext({gl::parseBackend(o->backend), false});
            gl::ShaderLibrary shaders(gl::ShaderLibrary::findRoot());
            sweep::Env env{shaders, gl::queryInfo().renderer, o->quick};
            for (const auto& [app, study] : *chosen) {
              if (!app->parsed()) continue;
              std::printf("sweep %s on %s%s\n", study->name, env.device.c_str(), o->quick ? " (quick)" : "");
              std::fflush(stdout);
              Steps steps("sweep " + std::string(study->name), 1, "study");
              steps.begin(study->summary);
              const sweep::Result result = sweep::runStudy(*study, env);
              steps.finish();
              const std::filesystem::path csv = csvDir / (std::string(study->name) + ".csv");
              sweep::writeCsv(result, study->name, env.device, csv);
              sweep::writeChartSpec(result, csvDir / (std::string(study->name) + ".chart.json"));
              std::printf("wrote %zu rows to %s\n", result.rows.size(), csv.c_str());
              ship(study->name, csv);
              if (!o->noChart) {
                const std::filesystem::path base = chartDir / study->name;
                sweep::drawChart(result, env.device, base);
                std::printf("wrote %s.png and .svg\n", base.c_str());
              }
              return 0;
            }
            return 2;
          }};
}

}  // namespace tidepool::cli
