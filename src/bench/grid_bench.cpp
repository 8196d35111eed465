// `tidepool bench grid`: the uniform grid (src/grid) on N random positions in a cube of cells at
// about 1 and about 8 particles per cell: count (clear + atomicAdd pass), scan of the cell
// counts, reorder of positions + velocities, and the whole build + reorder as one timed span:
// total_ms from random order, sorted_ms from the last build's cell order (a running simulation).
// --reorder scatter,gather gives one row per reorder mode (grid/reorder_mode.h), measured one
// after the other on the same positions, each with its own grid made at the start of the row.
// Beside it, in the same run: the scan of exactly N uint32, the naive Hillis-Steele scan of the
// same, and a compute-shader copy (gl::BufferOps) of the same N * 4 bytes as the bandwidth reference
// (glCopyBufferSubData runs far slower on some drivers: `tidepool bench memory`).
// GB/s = (bytes read + bytes written) / time:
//   scan     4 N read + 4 (N + 1) written (the minimum; the kernels move about 3 N words, see prefix_scan.h)
//   reorder  per particle: 16 position (cell) + 4 indexInCell + 4 cellStart read, 16 per array read and written;
//            gather: + 4 permutation written, and read again by each batch of 2 arrays
//   copy     4 N read + 4 N written
// Each row's results are compared with the CPU after timing (note column; --no-check skips it).
// --scan-shapes 256x4,512x8,256x4f0,... adds a table of the N-uint32 scan per work-group shape
// (f<B>: ScanConfig::fuseMaxBlocks, so 256x4f0,256x4f4096 compares 3 against 2 dispatches up to 16M).
// Every number is the median of --repeats GL_TIME_ELAPSED queries after --warmup untimed runs.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <memory>
#include <random>

#include "base/error.h"
#include "bench/bench.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/window.h"
#include "grid/grid.h"
#include "grid/prefix_scan.h"

namespace tidepool::bench {
namespace {

struct GridOptions {
  std::string sizes = "2^16..2^24";  // particle counts N
  std::string perCell = "1,8";       // target particles per cell
  int arrays = 2;                    // vec4 arrays reordered (positions, velocities, ...)
  std::string scanShapes = "256x4";  // PrefixScan work-group shapes; the first one is the grid's
  std::string reorder = "scatter";   // reorder modes, one row each
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
    if (end == token.c_str() || *end || !(v > 0)) throw Error("--ppc '" + token + "' is not a positive number");
    return v;
  };
  return parseList(text, one, "--ppc: no values given");
}

// "256x4,512x8,256x4p,256x4f0" -> scan shapes (invocations x uvec4 per invocation; p: scan-then-propagate;
// f<B>: fuse the offsets into the block scan for levels of up to B blocks, f0 never; default ScanConfig's).
std::vector<grid::ScanConfig> parseShapes(const std::string& text) {
  auto one = [](const std::string& token) {
    unsigned g = 0, v = 0, fuse = 0;
    int end = 0, fuseEnd = 0;
    grid::ScanConfig config;
    bool ok =
        std::sscanf(token.c_str(), "%ux%u%n", &g, &v, &end) == 2 && std::isdigit(static_cast<unsigned char>(token[0]));
    const std::string suffix = ok ? token.substr(std::size_t(end)) : "";
    if (suffix == "p") {
      config.propagate = true;
    } else if (!suffix.empty()) {
      ok = suffix[0] == 'f' && suffix.size() > 1 && std::isdigit(static_cast<unsigned char>(suffix[1])) &&
           std::sscanf(suffix.c_str(), "f%u%n", &fuse, &fuseEnd) == 1 && std::size_t(fuseEnd) == suffix.size();
      config.fuseMaxBlocks = fuse;
    }
    if (!ok)
      throw Error("--scan-shapes '" + token +
                  "' is not like 256x4, 256x4p or 256x4f4096 (invocations x uvec4 per invocation, "
                  "p: scan-then-propagate, f<B>: sum the block offsets in the block scan up to B blocks)");
    config.groupSize = g;
    config.vecsPerThread = v;
    return config;
  };
  return parseList(text, one, "--scan-shapes: no shapes given");
}

std::string shapeText(const grid::ScanConfig& c) {
  std::string text = std::to_string(c.groupSize) + "x" + std::to_string(c.vecsPerThread);
  if (c.propagate) return text + "p";
  if (c.fuseMaxBlocks != grid::ScanConfig{}.fuseMaxBlocks) text += "f" + std::to_string(c.fuseMaxBlocks);
  return text;
}

// The scans of N uint32 (one per work-group shape, and the naive one) with their buffers and
// those of the copy, allocated once for the largest N before anything else and shared by every
// row. Allocated per row instead, on the H100 the scans of 16M words measured after a row's
// 16M-particle random reorder ran 2-3x slower (the copy did not): the driver's placement of the
// new allocations.
struct WordScans {
  WordScans(Env& env, const std::vector<grid::ScanConfig>& shapes, std::size_t maxN)
      : in(maxN * 4), out((maxN + 1) * 4), copy(maxN * 4), naive(env.shaders) {
    naive.reserve(maxN);
    for (const grid::ScanConfig& shape : shapes) {
      try {
        scans.push_back(std::make_unique<grid::PrefixScan>(env.shaders, shape));
        scans.back()->reserve(maxN);
        errors.emplace_back();
      } catch (const Error& e) {  // an unsupported shape: its rows say why
        scans.push_back(nullptr);
        errors.push_back(e.what());
      }
    }
  }
  gl::Buffer in, out, copy;
  grid::NaiveScan naive;
  std::vector<std::unique_ptr<grid::PrefixScan>> scans;  // per shape; null where it failed
  std::vector<std::string> errors;                       // per shape
};

// Scan of N uint32 with each shape against the copy of the same bytes (only with several shapes).
void addShapeRows(Env& env, Table& table, WordScans& words, bool wallClock, std::size_t n,
                  const std::vector<grid::ScanConfig>& shapes) {
  if ((n + 1) * 4 > gl::storageBlockBytes()) return;
  std::vector<uint32_t> values(n);
  std::mt19937 rng{uint32_t(n)};
  uint64_t sum = 0;
  for (uint32_t& v : values) sum += v = rng() % 16;
  words.in.upload(values.data(), n * 4);
  gl::Buffer &in = words.in, &out = words.out, &copy = words.copy;
  const gl::BufferOps ops(env.shaders);
  wakeGpu(env.shaders);
  const double copyMs = medianMs(env.common, wallClock, [&] { ops.copy(in, copy, n * 4); });
  const double copyGbps = gbps(8.0 * n, copyMs);
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    grid::PrefixScan* scan = words.scans[s].get();
    if (!scan) {
      table.add({std::to_string(n), shapeText(shapes[s]), "", "", "", "", "", "error: " + words.errors[s]});
      continue;
    }
    const double ms = medianMs(env.common, wallClock, [&] { scan->run(in, out, n); });
    const bool right = ops.readBack<uint32_t>(out, 1, n)[0] == uint32_t(sum);
    const double g = gbps(8.0 * n + 4, ms);
    table.add({std::to_string(n), shapeText(shapes[s]), std::to_string(scan->dispatchesFor(n)), fixed(ms, 4),
               fixed(g, 1), fixed(copyGbps, 1), fixed(copyGbps > 0 ? 100.0 * g / copyGbps : 0, 1),
               right ? "" : "WRONG total"});
  }
}

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
const char* const kColumns[] = {"N",          "cells",        "ppc",       "reorder",      "count_ms",
                                "scan_ms",    "reorder_ms",   "total_ms",  "sorted_ms",    "scanN_ms",
                                "naive_ms",   "copy_ms",      "scan_GBps", "reorder_GBps", "copy_GBps",
                                "scan/copy%", "naive/scan_x", "grid_MiB",  "note"};

std::vector<std::string> noteRow(std::size_t n, const std::string& ppc, const std::string& note) {
  std::vector<std::string> row(std::size(kColumns));
  row.front() = std::to_string(n);
  row[2] = ppc;
  row.back() = note;
  return row;
}

std::vector<std::vector<std::string>> runRows(Env& env, const GridOptions& opt,
                                              const std::vector<grid::ReorderMode>& modes, WordScans& words,
                                              bool wallClock, std::size_t n, double perCell) {
  const std::size_t limit = gl::storageBlockBytes();
  const std::string nText = std::to_string(n);
  if (n * sizeof(glm::vec4) > limit)
    return {noteRow(n, "",
                    "skipped: " + std::to_string(n * sizeof(glm::vec4) >> 20) +
                        " MiB of positions exceed this driver's SSBO limit of " + std::to_string(limit >> 20) +
                        " MiB")};
  // The scan target is stated for N uint32: scan, naive scan and copy of exactly those bytes,
  // timed first, in the buffers allocated at the start (WordScans).
  std::mt19937 scanRng(uint32_t(n) * 7u + 1u);
  std::string scanNote;
  std::vector<uint32_t> values(n);
  for (uint32_t& v : values) v = scanRng() % 16;
  words.in.upload(values.data(), n * 4);
  gl::Buffer &in = words.in, &out = words.out, &copy = words.copy;
  if (!words.scans[0]) throw Error(words.errors[0]);
  grid::PrefixScan& scan = *words.scans[0];
  grid::NaiveScan& naive = words.naive;
  const std::vector<uint32_t> want = opt.noCheck ? std::vector<uint32_t>() : grid::reference::exclusiveScan(values);
  const gl::BufferOps ops(env.shaders);
  wakeGpu(env.shaders);  // after the last row's CPU check the GPU has idled
  const double uscanMs = medianMs(env.common, wallClock, [&] { scan.run(in, out, n); });
  if (!opt.noCheck && ops.readBack<uint32_t>(out, n + 1) != want) scanNote += "WRONG scan; ";
  const double naiveMs = medianMs(env.common, wallClock, [&] { naive.run(in, out, n); });
  if (!opt.noCheck && ops.readBack<uint32_t>(out, n + 1) != want) scanNote += "WRONG naive scan; ";
  const double copyMs = medianMs(env.common, wallClock, [&] { ops.copy(in, copy, n * 4); });

  // A cube of side s cells of size 1 holding about perCell particles per cell; one grid per mode.
  const uint32_t side = std::max<uint32_t>(1, uint32_t(std::lround(std::cbrt(double(n) / perCell))));
  std::vector<std::unique_ptr<grid::UniformGrid>> grids;
  for (grid::ReorderMode mode : modes)
    grids.push_back(std::make_unique<grid::UniformGrid>(
        env.shaders,
        grid::GridParams{
            .domainMin = glm::vec3(0.0f), .domainMax = glm::vec3(float(side)), .cellSize = 1.0f, .reorder = mode},
        n));
  const std::size_t cells = grids[0]->cells();

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
  std::vector<std::vector<std::string>> rows;
  for (std::size_t m = 0; m < modes.size(); ++m) {
    grid::UniformGrid& grid = *grids[m];
    // Random order again: the last mode's sorted runs left the sources in cell order.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // those shader writes land before the uploads
    for (gl::Buffer& b : src) b.upload(pos.data(), n * sizeof(glm::vec4));
    wakeGpu(env.shaders);  // the CPU has been filling positions (or checking)
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
    const double batches = std::ceil(double(opt.arrays) / GRID_REORDER_MAX_ARRAYS);
    const double reorderBytes = double(n) * (16 + 4 + 4 + 32.0 * opt.arrays +
                                             (modes[m] == grid::ReorderMode::Gather ? 4.0 + 4.0 * batches : 0.0));
    rows.push_back({nText, std::to_string(cells), fixed(double(n) / double(cells), 2),
                    grid::kReorderModeNames[std::size_t(modes[m])], fixed(countMs, 4), fixed(scanMs, 4),
                    fixed(reorderMs, 4), fixed(totalMs, 4), fixed(sortedMs, 4), fixed(uscanMs, 4), fixed(naiveMs, 4),
                    fixed(copyMs, 4), fixed(scanGbps, 1), fixed(gbps(reorderBytes, reorderMs), 1), fixed(copyGbps, 1),
                    fixed(copyGbps > 0 ? 100.0 * scanGbps / copyGbps : 0, 1),
                    fixed(uscanMs > 0 ? naiveMs / uscanMs : 0, 1),
                    fixed(double(grid.memoryBytes()) / double(1 << 20), 2), note});
  }
  return rows;
}

int runGridBench(Env& env, const GridOptions& opt) {
  const std::vector<std::size_t> sizes = parseSizes(opt.sizes);
  const std::vector<double> perCell = parsePerCell(opt.perCell);
  const std::vector<grid::ScanConfig> shapes = parseShapes(opt.scanShapes);
  const std::vector<grid::ReorderMode> modes = parseReorderModes(opt.reorder);
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
  WordScans words(env, shapes, maxWords);
  Table table(std::vector<std::string>(std::begin(kColumns), std::end(kColumns)));
  for (std::size_t n : sizes) {
    for (double ppc : perCell) {
      try {
        for (std::vector<std::string>& row : runRows(env, opt, modes, words, wallClock, n, ppc))
          table.add(std::move(row));
      } catch (const Error& e) {  // e.g. out of GPU memory: report the row, keep going
        table.add(noteRow(n, fixed(ppc, 2), std::string("error: ") + e.what()));
      }
    }
  }
  table.print();
  if (!env.common.csv.empty()) table.writeCsv(env.common.csv);
  if (shapes.size() > 1) {
    std::printf(
        "\nscan of N uint32 by work-group shape (invocations x uvec4 per invocation; p: scan-then-propagate; "
        "f<B>: offsets summed in the block scan up to B blocks, default %zu, f0 never)\n",
        grid::ScanConfig{}.fuseMaxBlocks);
    Table byShape({"N", "shape", "dispatches", "scan_ms", "scan_GBps", "copy_GBps", "scan/copy%", "note"});
    for (std::size_t n : sizes) addShapeRows(env, byShape, words, wallClock, n, shapes);
    byShape.print();
  }
  return 0;
}

}  // namespace

Benchmark addGridBench(CLI::App& bench) {
  auto opt = std::make_shared<GridOptions>();
  auto* sub = bench.add_subcommand("grid", "uniform grid: count, scan, reorder vs naive scan and buffer copy");
  sub->add_option("--n", opt->sizes, "particle counts, e.g. 2^16..2^24 or 65536,1M")->capture_default_str();
  sub->add_option("--ppc", opt->perCell, "target particles per cell, comma separated")->capture_default_str();
  sub->add_option("--arrays", opt->arrays, "vec4 arrays to reorder")->check(CLI::Range(1, 8))->capture_default_str();
  sub->add_option("--scan-shapes", opt->scanShapes,
                  "scan work-group shapes, e.g. 256x4,512x4,256x8,256x4p,256x4f0 (p: scan-then-propagate; f<B>: "
                  "the block scan sums its offset itself, 2 dispatches, for up to B blocks, f0 never; the first "
                  "is used in the main table's scanN, several add a table comparing them)")
      ->capture_default_str();
  sub->add_option("--reorder", opt->reorder,
                  "reorder modes, one row each, e.g. scatter,gather (scatter: one pass writing random slots; "
                  "gather: a permutation pass, then coalesced writes)")
      ->capture_default_str();
  sub->add_flag("--no-check", opt->noCheck, "skip comparing each row's grid and scans with the CPU");
  return {sub, [opt](Env& env) { return runGridBench(env, *opt); }};
}

}  // namespace tidepool::bench
