// Benchmarks: `tidepool bench <name> [options]`. Each benchmark registers one sub-subcommand and
// prints a compact table (and optional CSV). Timings come from GL timer queries, reported as
// medians over repeats; nothing here is ever asserted in a test.
#pragma once

#include <array>

#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "base/error.h"
#include "gl/context.h"
#include "gl/gpu_profiler.h"
#include "gl/shader_library.h"

namespace tidepool::bench {

// Options every benchmark shares.
struct Common {
  std::string backend = "auto";
  std::string csv;   // write the table as CSV here too
  int repeats = 20;  // timed repeats per configuration (medians are reported)
  int warmup = 3;
};

struct Env {
  const Common& common;
  gl::ShaderLibrary& shaders;
  std::string device;  // GL_RENDERER, for tables and CSV
};

struct Benchmark {
  CLI::App* sub;
  std::function<int(Env&)> run;
};

// Each benchmark's registration function (bench/<name>_bench.cpp).
using Registrar = Benchmark (*)(CLI::App& bench);
const std::vector<Registrar>& registrars();

// A table printed with aligned columns and optionally written as CSV.
class Table {
 public:
  explicit Table(std::vector<std::string> columns) : m_columns(std::move(columns)) {}
  void add(std::vector<std::string> row) { m_rows.push_back(std::move(row)); }
  void print() const;                            // to stdout
  void writeCsv(const std::string& path) const;  // throws Error

 private:
  std::vector<std::string> m_columns;
  std::vector<std::vector<std::string>> m_rows;
};

double median(std::vector<double> values);

// The timed window of steps of a step benchmark, `--steps FIRST:LAST` (steps [first, last) are timed).
struct StepWindow {
  int first = 10, last = 310;
};
StepWindow parseStepWindow(const std::string& text);  // throws Error naming the option

// Median milliseconds of `work` over common.repeats runs, after common.warmup untimed runs: GPU
// time from a GL_TIME_ELAPSED query around each run, or with `wallClock` the wall clock between
// two glFinish calls (for drivers whose timer queries do not measure execution: llvmpipe reports
// 1 ns). `work` must not open GpuProfiler scopes (queries cannot nest).
double medianMs(const Common& common, bool wallClock, const std::function<void()>& work);
// medianMs on the wall clock on a software renderer (softwareRenderer()), else GPU time.
double gpuMedianMs(const Common& common, const std::function<void()>& work);

// Per-pass times of a run of profiled frames (balls steps, renderer frames): `frame` is called
// warmup + timed times, each inside one GpuProfiler frame; the warm-up frames are not kept. The
// passes are clocked by GL_TIME_ELAPSED around each with the frames queued back to back (what the
// UI shows; on the H100 a pass's time then includes its wait behind the passes before it); the
// frame's own time comes from PassTimes::stream.

struct PassTimes {
  std::map<std::string, std::vector<double>> passes;  // GPU ms per timed frame, by scope name (summed within a frame)
  std::vector<double> totals;                         // the scopes' sum per timed frame
  std::vector<double> wall;                           // ms around glFinish per timed frame, on a software renderer only
  // GPU time from one frame's start to the next's, by GL_TIMESTAMP queries between the frames (the
  // GPU writes each when every command before it has completed): what CUDA events around each
  // step measure. Empty on a software renderer. Its sum is the window's time on the GPU.
  std::vector<double> stream;
  bool software = false;   // timed on a software renderer (timePasses sets it)
  double sustainedMs = 0;  // wall clock of all timed frames back to back (glFinish before and after) / frames
  bool has(const std::string& pass) const { return passes.count(pass) > 0; }
  double median(const std::string& pass) const;  // 0 when the pass never ran
  // Whether the per-pass timer queries measured anything: not on a software renderer, nor where
  // every pass read 0 (llvmpipe answers 0 or 1 ns).
  bool timersRead() const;
  // A pass's median as a table cell: kNotMeasured where the timers read nothing, "-" also where
  // the pass never ran (a view without it).
  std::string cell(const std::string& pass, int decimals) const;
  // Median frame: the wall clock on software or with wallClock, else the stream clock.
  double frameMs() const;
  double streamMeanMs() const;  // 0 without the stream clock
};
// wallClock: time whole frames around glFinish, as on a software renderer, for frames that wait
// on the GPU part-way (a read-back): GL_TIME_ELAPSED across such a wait misses part of the frame
// (docs/PERFORMANCE.md, "Per-pass timers on queued steps").
PassTimes timePasses(int warmup, int timed, const std::function<void(gl::GpuProfiler&)>& frame, bool wallClock = false);

// Keeps the GPU busy with buffer copies for about `ms` of wall-clock time. GPUs lower their clocks
// when idle, and a few warm-up repeats of a sub-millisecond kernel do not bring them back: on the
// H100 the 16M scan measured 2.5x slower after the CPU had spent a second checking the last row
// (or after a 1 s sleep). Benchmarks call it before timing work that follows CPU-side pauses.
// No-op on a software renderer.
void wakeGpu(gl::ShaderLibrary& shaders, double ms = 200.0);

// True on llvmpipe / softpipe, whose GL timer queries do not measure execution.
bool softwareRenderer();

// The cell of a GPU-time column whose timer queries read nothing on this driver.
inline constexpr const char* kNotMeasured = "-";
// A line to print under tables measured on a software renderer (empty for hardware): its times
// are wall clock, and its GPU-timer columns show kNotMeasured.
std::string timingCaveat(const std::string& device);
// A benchmark's last lines: `table`, the timing caveat (followed by `note`, e.g. "; frame ms is the
// wall clock there") and `table` as CSV when --csv asks for it. Returns 0, the exit status.
int finish(const Env& env, const Table& table, const std::string& note = "");
// The same after `table` was printed (life prints its crossover table between the two).
int finishPrinted(const Env& env, const Table& table, const std::string& note = "");
std::string fixed(double value, int decimals);
// "a,b" -> {"a", "b"}; an empty item stays (",b" -> {"", "b"}) for the parser to refuse.
std::vector<std::string> splitCommas(const std::string& text);
// Each item of a comma list read by `one` (which throws Error naming a bad item); throws
// Error(`none`) when there is no item.
template <class One>
auto parseList(const std::string& text, One&& one, const std::string& none) {
  std::vector<decltype(one(std::string()))> out;
  for (const std::string& item : splitCommas(text)) out.push_back(one(item));
  if (out.empty()) throw Error(none);
  return out;
}
// "a,b" of a choice's names -> its values in that order, for `option` (e.g. "--format");
// throws Error naming the bad token and the names ("'x' is not vtk or ply").
template <class E, std::size_t N>
std::vector<E> parseChoices(const std::string& text, const std::array<const char*, N>& names,
                            const std::string& option) {
  std::string all;
  for (std::size_t k = 0; k < N; ++k) all += (k == 0 ? "" : k + 1 == N ? " or " : ", ") + std::string(names[k]);
  auto one = [&](const std::string& token) {
    for (std::size_t k = 0; k < N; ++k)
      if (token == names[k]) return E(k);
    throw Error(option + " '" + token + "' is not " + all);
  };
  return parseList(text, one, option + ": nothing given (" + all + ")");
}
// "65536,1M,16M", "2^16..2^24" or "512..4096" (doubling) -> sizes; throws Error naming the bad token.
std::vector<std::size_t> parseSizes(const std::string& text);
// "on,off" -> flags in that order for `option` (e.g. "--deterministic"); throws Error naming the bad token.
std::vector<bool> parseOnOff(const std::string& text, const std::string& option);

}  // namespace tidepool::bench
