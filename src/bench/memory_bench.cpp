// `tidepool bench memory --bytes 1M..1G`: the device's memory bandwidth as the other benchmarks'
// "% of copy" columns see it: a compute-shader copy and fill (gl::BufferOps, what every model
// uses) beside the driver's glCopyBufferSubData and glClearBufferData of the same bytes, all in
// one run. GB/s counts bytes read + written (copy: 2 x bytes; fill: bytes).
#include <cstdio>

#include "base/progress.h"
#include "bench/bench.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"

namespace tidepool::bench {
namespace {

std::string sizeText(std::size_t bytes) {
  if (bytes >= (std::size_t(1) << 30) && bytes % (std::size_t(1) << 30) == 0)
    return std::to_string(bytes >> 30) + " GiB";
  if (bytes >= (std::size_t(1) << 20) && bytes % (std::size_t(1) << 20) == 0)
    return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " B";
}

int run(Env& env, const std::string& sizes) {
  std::printf("memory bandwidth on %s: medians of %d repeats (%d warm-up), GB/s = bytes read + written / time\n",
              env.device.c_str(), env.common.repeats, env.common.warmup);
  Table table({"bytes", "kernel copy ms", "kernel copy GB/s", "glCopyBufferSubData GB/s", "kernel fill GB/s",
               "glClearBufferData GB/s"});
  const gl::BufferOps ops(env.shaders);
  Steps steps("bench memory", int(parseSizes(sizes).size()));
  for (std::size_t bytes : parseSizes(sizes)) {
    bytes &= ~std::size_t(3);
    steps.begin(sizeText(bytes));
    gl::Buffer a, b;
    try {
      a = gl::Buffer(bytes);
      b = gl::Buffer(bytes);
    } catch (const Error& e) {
      std::printf("skipped %s: %s\n", sizeText(bytes).c_str(), e.what());
      continue;
    }
    ops.fill(a, 1);
    const double copyMs = gpuMedianMs(env.common, [&] { ops.copy(a, b, bytes); });
    const double glCopyMs = gpuMedianMs(env.common, [&] { a.copyTo(b, bytes); });
    const double fillMs = gpuMedianMs(env.common, [&] { ops.fill(b, 0); });
    const double clearMs = gpuMedianMs(env.common, [&] { b.fillZero(); });
    auto gbps = [](double moved, double ms) { return ms > 0 ? fixed(moved / (ms * 1e6), 1) : std::string("-"); };
    table.add({sizeText(bytes), fixed(copyMs, 4), gbps(2.0 * bytes, copyMs), gbps(2.0 * bytes, glCopyMs),
               gbps(double(bytes), fillMs), gbps(double(bytes), clearMs)});
  }
  steps.finish();
  return finish(env, table);
}

}  // namespace

Benchmark addMemoryBench(CLI::App& bench) {
  auto* sub = bench.add_subcommand("memory", "copy and fill bandwidth: compute shaders vs glCopyBufferSubData/glClear");
  auto sizes = std::make_shared<std::string>("1M..1G");
  sub->add_option("--bytes", *sizes, "buffer sizes in bytes, e.g. 1M..1G or 64M,256M")->capture_default_str();
  return {sub, [sizes](Env& env) { return run(env, *sizes); }};
}

}  // namespace tidepool::bench
