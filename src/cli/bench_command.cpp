#include "bench/bench.h"
#include "cli/commands.h"
#include "gl/info.h"

namespace tidepool::cli {

Command addBench(CLI::App& app) {
  auto* sub = app.add_subcommand("bench", "GPU benchmarks: per-pass medians from GL timer queries");
  auto common = std::make_shared<bench::Common>();
  sub->add_option("--backend", common->backend, "auto, egl or osmesa")->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  sub->add_option("--csv", common->csv, "also write the table as CSV to this file");
  sub->add_option("--repeats", common->repeats, "timed repeats per configuration")->check(CLI::Range(1, 100000));
  sub->add_option("--warmup", common->warmup, "untimed runs first")->check(CLI::Range(0, 1000));
  sub->require_subcommand(1);
  sub->fallthrough();  // shared options may follow the benchmark name
  auto benches = std::make_shared<std::vector<bench::Benchmark>>();
  for (bench::Registrar r : bench::registrars()) benches->push_back(r(*sub));
  for (bench::Benchmark& b : *benches)  // shown by `tidepool bench <name> --help` too
    b.sub->footer(
        "Options of every benchmark, before or after its name: --csv FILE (the table as CSV), --repeats N "
        "(timed repeats), --warmup N (untimed runs first), --backend auto|egl|osmesa");
  return {sub, [sub, common, benches] {
            auto context = gl::createHeadlessContext({gl::parseBackend(common->backend), false});
            gl::ShaderLibrary shaders(gl::ShaderLibrary::findRoot());
            bench::Env env{*common, shaders, gl::queryInfo().renderer};
            for (bench::Benchmark& b : *benches)
              if (b.sub->parsed()) return b.run(env);
            (void)sub;
            return 2;
          }};
}

}  // namespace tidepool::cli
