// `tidepool bench grid`: the uniform grid (src/grid) on N random positions in a cube of cells at
// about 1 and about 8 particles per cell: count (clear + atomicAdd pass), scan of the cell
// counts, reorder of positions + velocities, and the whole build + reorder as one timed span:
// total_ms from random order, sorted_ms from the last build's cell order (a running simulation).
// Beside it, in the same run: the scan of exactly N uint32, the naive Hillis-Steele scan of the
// same, and a compute-shader copy (gl::BufferOps) of the same N * 4 bytes as the bandwidth reference
// (glCopyBufferSubData runs far slower on some drivers: `tidepool bench memory`).
// GB/s = (bytes read + bytes written) / time:
//   scan     4 N read + 4 (N + 1) written (the minimum; the kernels move about 3 N words, see prefix_scan.h)
//   reorder  per particle: 16 position (cell) + 4 indexInCell + 4 cellStart read, 16 per array read and written
//   copy     4 N read + 4 N written
// Each row's results are compared with the CPU after timing (note column; --no-check skips it).
// Every number is the median of --repeats GL_TIME_ELAPSED queries after --warmup untimed runs.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <random>

#include "base/error.h"
#include "base/progress.h"
#include "bench/bench.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/window.h"
#include "grid/grid.h"
#include "grid/prefix_scan.h"
#include "io/echo.h"

namespace tidepool::bench {
namespace {

struct GridOptions {
  std::string sizes = "2^16..2^24";  // particle counts N
  std::string perCell = "1,8";       // target particles per cell
  int arrays = 2;                    // vec4 arrays reordered (positions, velocities, ...)
  bool noCheck = false;              // skip comparing every row's results with the CPU
};

// True when GL_TIME_ELAPSED reports under 1% of the wall-clock time of a 64 MiB copy.
bool timerQueriesAreBroken() {
  gl::Buffer a(64 << 20), b(64 << 20);
  Common once;
  once.repeats = 1;
  once.warmup = 1;
  const double glMs = medianMs(once, false, [&] { a.copyTo(b, a.size()); });
  const double wallMs = medianMs(once, true, [&] { a.copyTo(b, a.size()); });
  return glMs < 0.01 * wallMs;
}

double gbps(double bytes, double ms) { return ms > 0 ? bytes / (ms * 1e6) : 0; }

std::vector<double> parsePerCell(const std::string& text) {
  auto one = [](const std::string& token) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end || !(v > 0))
      throw Error("--ppc '" + io::printable(token) + "' is not a positive number");
    return v;
  };
  return parseList(text, one, "--ppc: no values given");
}

// The scans of N uint32 (the grid's and the naive one) with their buffers and those of the copy,
// allocated once for the largest N before anything else and shared by every row. Allocated per
// row instead, on the H100 the scans of 16M words measured after a row's 16M-particle random
// reorder ran 2-3x slower (the copy did not): the driver's placement of the new allocations.
struct WordScans {
  WordScans(Env& env, std::size_t maxN)
      : in(maxN * 4), out((maxN + 1) * 4), copy(maxN * 4), naive(env.shaders), scan(env.shaders) {
    naive.reserve(maxN);
    scan.reserve(maxN);
  }
  gl::Buffer in, out, copy;
  grid::NaiveScan naive;
  grid::PrefixScan scan;
};

// Compares the grid after build + reorder with the CPU (grid_reference.h); "" when right.
// Every array holds the positions, so dst[0] must be the positions in cell order.
std::string checkGrid(const gl::BufferOps& ops, const grid::UniformGrid& grid, const std::vector<glm::vec4>& pos,
                      const gl::Buffer& sorted) {
  const std::size_t n = pos.size();
  const std::vector<uint32_t> counts = grid::reference::histogram(grid.shape(), pos);
  if (ops.readBack<uint32_t>(grid.cellCount(), grid.cells()) != counts) return "WRONG cell counts; ";
  const std::vector<uint32_t> starts = grid::reference::exclusiveScan(counts);
  if (ops.readBack<uint32_t>(grid.cellStart(), grid.cells() + 1) != starts) return "WRONG cellStart; ";
  const std::vector<glm::vec4> got = ops.readBack<glm::vec4>(sorted, n);
  std::vector<bool> seen(n, false);
  std::size_t cell = 0;
  for (std::size_t j = 0; j < n; ++j) {
    while (starts[cell + 1] <= j) ++cell;
    const std::size_t id = std::size_t(got[j].w);
    if (id >= n || seen[id] || got[j] != pos[id]) return "WRONG reorder (particle lost or duplicated); ";
    seen[id] = true;
    if (grid::reference::cellOf(grid.shape(), glm::vec3(got[j])) != cell) return "WRONG reorder (cell order); ";
  }
  return "";
}

// The main table's columns; a row that was not measured is N, ppc and a note, the rest blank.
const char* const kColumns[] = {
    "N",          "cells",        "ppc",      "count_ms", "scan_ms",   "reorder_ms",   "total_ms",
    "sorted_ms",  "scanN_ms",     "naive_ms", "copy_ms",  "scan_GBps", "reorder_GBps", "copy_GBps",
    "scan/copy%", "naive/scan_x", "grid_MiB", "note"};

std::vector<std::string> noteRow(std::size_t n, const std::string& ppc, const std::string& note) {
  std::vector<std::string> row(std::size(kColumns));
  row.front() = std::to_string(n);
  row[2] = ppc;
  row.back() = note;
  return row;
}

std::vector<std::string> runRow(Env& env, const GridOptions& opt, WordScans& words, bool wallClock, std::size_t n,
                                double perCell) {
  const std::size_t limit = gl::storageBlockBytes();
  const std::string nText = std::to_string(n);
  if (n * sizeof(glm::vec4) > limit)
    return noteRow(n, "",
                   "skipped: " + std::to_string(n * sizeof(glm::vec4) >> 20) +
                       " MiB of positions exceed this driver's SSBO limit of " + std::to_string(limit >> 20) + " MiB");
  // The scan target is stated for N uint32: scan, naive scan and copy of exactly those bytes,
  // timed first, in the buffers allocated at the start (WordScans).
  std::mt19937 scanRng(uint32_t(n) * 7u + 1u);
  std::string scanNote;
  std::vector<uint32_t> values(n);
  for (uint32_t& v : values) v = scanRng() % 16;
  words.in.upload(values.data(), n * 4);
  gl::Buffer &in = words.in, &out = words.out, &copy = words.copy;
  grid::PrefixScan& scan = words.scan;
  grid::NaiveScan& naive = words.naive;
  const std::vector<uint32_t> want = opt.noCheck ? std::vector<uint32_t>() : grid::reference::exclusiveScan(values);
  const gl::BufferOps ops(env.shaders);
  wakeGpu(env.shaders);  // after the last row's CPU check the GPU has idled
  const double uscanMs = medianMs(env.common, wallClock, [&] { scan.run(in, out, n); });
  if (!opt.noCheck && ops.readBack<uint32_t>(out, n + 1) != want) scanNote += "WRONG scan; ";
  const double naiveMs = medianMs(env.common, wallClock, [&] { naive.run(in, out, n); });
  if (!opt.noCheck && ops.readBack<uint32_t>(out, n + 1) != want) scanNote += "WRONG naive scan; ";
  const double copyMs = medianMs(env.common, wallClock, [&] { ops.copy(in, copy, n * 4); });

  // A cube of side s cells of size 1 holding about perCell particles per cell.
  const uint32_t side = std::max<uint32_t>(1, uint32_t(std::lround(std::cbrt(double(n) / perCell))));
  grid::UniformGrid grid(env.shaders,
                         {.domainMin = glm::vec3(0.0f), .domainMax = glm::vec3(float(side)), .cellSize = 1.0f}, n);

  std::mt19937 rng(uint32_t(n) ^ uint32_t(perCell * 1000));
  std::uniform_real_distribution<float> u(0.0f, float(side));
  std::vector<glm::vec4> pos(n);
  for (std::size_t i = 0; i < n; ++i) pos[i] = glm::vec4(u(rng), u(rng), u(rng), float(i));
  std::vector<gl::Buffer> src, dst;
  for (int a = 0; a < opt.arrays; ++a) {
    src.emplace_back(n * sizeof(glm::vec4));
    dst.emplace_back(n * sizeof(glm::vec4));
  }
  std::vector<grid::ReorderArray> arrays, back;
  for (int a = 0; a < opt.arrays; ++a) {
    arrays.push_back({&src[a], &dst[a]});
    back.push_back({&dst[a], &src[a]});  // from cell order
  }
  const gl::Buffer& positions = src[0];

  const double scanBytes = 4.0 * n + 4.0 * (n + 1);
  const double copyBytes = 8.0 * n;
  const double scanGbps = gbps(scanBytes, uscanMs), copyGbps = gbps(copyBytes, copyMs);
  for (gl::Buffer& b : src) b.upload(pos.data(), n * sizeof(glm::vec4));
  wakeGpu(env.shaders);  // the CPU has been filling positions
  const double countMs = medianMs(env.common, wallClock, [&] { grid.countParticles(positions, n); });
  const double scanMs = medianMs(env.common, wallClock, [&] { grid.scanCells(); });
  const double reorderMs = medianMs(env.common, wallClock, [&] { grid.reorder(positions, arrays); });
  const double totalMs = medianMs(env.common, wallClock, [&] {
    grid.build(positions, n);
    grid.reorder(positions, arrays);
  });
  std::string note = (opt.noCheck ? "" : checkGrid(ops, grid, pos, dst[0])) + scanNote;
  if (note.empty() && !opt.noCheck) note = "checked";
  // A running simulation rebuilds from last step's cell order, barely changed: the same build
  // with the arrays already sorted (dst) as input, moving them back into src.
  wakeGpu(env.shaders);  // after the check
  const double sortedMs = medianMs(env.common, wallClock, [&] {
    grid.build(dst[0], n);
    grid.reorder(dst[0], back);
  });
  const double reorderBytes = double(n) * (16 + 4 + 4 + 32.0 * opt.arrays);
  return {nText,
          std::to_string(grid.cells()),
          fixed(double(n) / double(grid.cells()), 2),
          fixed(countMs, 4),
          fixed(scanMs, 4),
          fixed(reorderMs, 4),
          fixed(totalMs, 4),
          fixed(sortedMs, 4),
          fixed(uscanMs, 4),
          fixed(naiveMs, 4),
          fixed(copyMs, 4),
          fixed(scanGbps, 1),
          fixed(gbps(reorderBytes, reorderMs), 1),
          fixed(copyGbps, 1),
          fixed(copyGbps > 0 ? 100.0 * scanGbps / copyGbps : 0, 1),
          fixed(uscanMs > 0 ? naiveMs / uscanMs : 0, 1),
          fixed(double(grid.memoryBytes()) / double(1 << 20), 2),
          note};
}

int runGridBench(Env& env, const GridOptions& opt) {
  const std::vector<std::size_t> sizes = parseSizes(opt.sizes);
  const std::vector<double> perCell = parsePerCell(opt.perCell);
  std::printf("device: %s\n", env.device.c_str());
  const bool wallClock = timerQueriesAreBroken();
  std::printf("grid: %d vec4 arrays reordered; scanN/naive/copy on N uint32; medians of %d repeats (ms, GB/s); %s\n",
              opt.arrays, env.common.repeats,
              wallClock ? "WALL CLOCK around glFinish (this driver's GL timer queries are not meaningful)"
                        : "GL_TIME_ELAPSED queries");
  std::fflush(stdout);
  std::size_t maxWords = 0;
  for (std::size_t n : sizes) {
    if (n == 0 || n > grid::PrefixScan::kMaxCount) throw Error("--n: sizes must be between 1 and 2^31");
    if ((n + 1) * 4 <= gl::storageBlockBytes()) maxWords = std::max(maxWords, n);
  }
  WordScans words(env, maxWords);
  Table table(std::vector<std::string>(std::begin(kColumns), std::end(kColumns)));
  Steps steps("bench grid", int(sizes.size() * perCell.size()));
  for (std::size_t n : sizes) {
    for (double ppc : perCell) {
      steps.begin("n " + std::to_string(n) + ", " + fixed(ppc, 2) + " per cell");
      try {
        table.add(runRow(env, opt, words, wallClock, n, ppc));
      } catch (const Error& e) {  // e.g. out of GPU memory: report the row, keep going
        table.add(noteRow(n, fixed(ppc, 2), std::string("error: ") + e.what()));
      }
    }
  }
  steps.finish();
  table.print();
  if (!env.common.csv.empty()) table.writeCsv(env.common.csv);
  return 0;
}

}  // namespace

Benchmark addGridBench(CLI::App& bench) {
  auto opt = std::make_shared<GridOptions>();
  auto* sub = bench.add_subcommand("grid", "uniform grid: count, scan, reorder vs naive scan and buffer copy");
  sub->add_option("--n", opt->sizes, "particle counts, e.g. 2^16..2^24 or 65536,1M")->capture_default_str();
  sub->add_option("--ppc", opt->perCell, "target particles per cell, comma separated")->capture_default_str();
  sub->add_option("--arrays", opt->arrays, "vec4 arrays to reorder")->check(CLI::Range(1, 8))->capture_default_str();
  sub->add_flag("--no-check", opt->noCheck, "skip comparing each row's grid and scans with the CPU");
  return {sub, [opt](Env& env) { return runGridBench(env, *opt); }};
}

}  // namespace tidepool::bench
