#include "bench/bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include "base/error.h"
#include "base/progress.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/framebuffer.h"
#include "io/echo.h"

namespace tidepool::bench {

void Table::print() const {
  std::vector<std::size_t> width(m_columns.size());
  for (std::size_t c = 0; c < m_columns.size(); ++c) {
    width[c] = m_columns[c].size();
    for (const auto& r : m_rows)
      if (c < r.size()) width[c] = std::max(width[c], r[c].size());
  }
  auto line = [&](const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t c = 0; c < m_columns.size(); ++c) {
      const std::string& v = c < cells.size() ? cells[c] : "";
      out += (c ? "  " : "") + std::string(width[c] - v.size(), ' ') + v;
    }
    std::printf("%s\n", out.c_str());
  };
  line(m_columns);
  for (const auto& r : m_rows) line(r);
  std::fflush(stdout);
}

void Table::writeCsv(const std::string& path) const {
  std::ofstream out(path);
  if (!out) throw Error("cannot write CSV '" + io::printable(path, io::kMaxPathEcho) + "'");
  auto row = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) out << (c ? "," : "") << cells[c];
    out << "\n";
  };
  row(m_columns);
  for (const auto& r : m_rows) row(r);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void wakeGpu(gl::ShaderLibrary& shaders, double ms) {
  if (softwareRenderer()) return;
  const gl::BufferOps ops(shaders);
  gl::Buffer a(64 << 20), b(64 << 20);
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() < ms) {
    for (int i = 0; i < 20; ++i) ops.copy(i % 2 ? b : a, i % 2 ? a : b, a.size());
    glFinish();
  }
}

bool softwareRenderer() {  // declared in bench.h
  const GLubyte* r = glGetString(GL_RENDERER);
  const std::string renderer = r ? reinterpret_cast<const char*>(r) : "";
  return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

double medianMs(const Common& c, bool wallClock, const std::function<void()>& work) {
  gl::Query query = gl::Query::create();
  for (int i = 0; i < c.warmup; ++i) {
    work();
    Steps::tick(i + 1, c.warmup + c.repeats, "runs");
  }
  std::vector<double> ms;
  for (int i = 0; i < c.repeats; ++i) {
    Steps::tick(c.warmup + i, c.warmup + c.repeats, "runs");
    if (wallClock) {
      glFinish();
      const auto start = std::chrono::steady_clock::now();
      work();
      glFinish();
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      continue;
    }
    glBeginQuery(GL_TIME_ELAPSED, query.id());
    work();
    glEndQuery(GL_TIME_ELAPSED);
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &ns);
    ms.push_back(double(ns) * 1e-6);
  }
  return median(ms);
}

double gpuMedianMs(const Common& c, const std::function<void()>& work) {
  static const bool software = softwareRenderer();  // its timer queries do not measure its execution
  return medianMs(c, software, work);
}

double PassTimes::median(const std::string& pass) const {
  const auto it = passes.find(pass);
  return it == passes.end() ? 0.0 : bench::median(it->second);
}

bool PassTimes::timersRead() const {
  if (software) return false;
  for (const auto& [name, ms] : passes)
    for (double v : ms)
      if (v >= 1e-4) return true;  // 100 ns: below any real dispatch, above llvmpipe's 1 ns
  return false;
}

std::string PassTimes::cell(const std::string& pass, int decimals) const {
  if (!timersRead()) return kNotMeasured;
  return has(pass) ? fixed(median(pass), decimals) : "-";
}

double PassTimes::frameMs() const { return bench::median(!wall.empty() ? wall : !stream.empty() ? stream : totals); }

double PassTimes::streamMeanMs() const {
  double sum = 0;
  for (double ms : stream) sum += ms;
  return stream.empty() ? 0.0 : sum / double(stream.size());
}

StepWindow parseStepWindow(const std::string& text) {
  static const std::regex form(R"((\d+):(\d+))");
  std::smatch m;
  if (!std::regex_match(text, m, form) || std::stoi(m[1]) >= std::stoi(m[2]))
    throw Error("--steps '" + io::printable(text) + "' is not FIRST:LAST with FIRST < LAST (e.g. 10:310)");
  return {std::stoi(m[1]), std::stoi(m[2])};
}

PassTimes timePasses(int warmup, int timed, const std::function<void(gl::GpuProfiler&)>& frame, bool wallClock) {
  const bool software = wallClock || softwareRenderer();  // timer queries that do not measure: time whole frames
  gl::GpuProfiler profiler;
  std::vector<gl::GpuProfiler::FrameTimes> frames;  // the timed ones, as they complete
  PassTimes t;
  t.software = softwareRenderer();
  std::chrono::steady_clock::time_point windowStart;
  // A timestamp before each timed frame and one after the last (not on software: it does not measure).
  std::vector<gl::Query> marks;
  auto mark = [&] {
    if (softwareRenderer()) return;
    marks.push_back(gl::Query::create());
    glQueryCounter(marks.back().id(), GL_TIMESTAMP);
  };
  for (int i = 0; i < warmup + timed; ++i) {
    if (software || i == warmup) glFinish();
    const auto start = std::chrono::steady_clock::now();
    if (i == warmup) windowStart = start;
    if (i >= warmup) mark();
    profiler.beginFrame();
    frame(profiler);
    profiler.endFrame();
    if (software) {
      glFinish();
      if (i >= warmup)
        t.wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    if (i + 1 == warmup) {
      profiler.finish();
      profiler.takeCompleted();  // warm-up frames are not timed
    }
    Steps::tick(i + 1, warmup + timed, "frames");
    // The profiler keeps only the last few frames: collect them as they complete.
    if (i >= warmup)
      for (gl::GpuProfiler::FrameTimes& f : profiler.takeCompleted()) frames.push_back(std::move(f));
  }
  if (timed > 0) mark();
  glFinish();
  for (std::size_t k = 1; k < marks.size(); ++k) {
    GLuint64 before = 0, after = 0;
    glGetQueryObjectui64v(marks[k - 1].id(), GL_QUERY_RESULT, &before);
    glGetQueryObjectui64v(marks[k].id(), GL_QUERY_RESULT, &after);
    t.stream.push_back(double(after - before) * 1e-6);
  }
  if (timed > 0)
    t.sustainedMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - windowStart).count() / timed;
  profiler.finish();
  for (gl::GpuProfiler::FrameTimes& f : profiler.takeCompleted()) frames.push_back(std::move(f));
  for (const auto& f : frames) {
    double total = 0;
    std::map<std::string, double> frameMs;  // a pass that runs several times a frame (solver iterations): summed
    for (const auto& [name, ms] : f.passes) {
      frameMs[name] += ms;
      total += ms;
    }
    for (const auto& [name, ms] : frameMs) t.passes[name].push_back(ms);
    t.totals.push_back(total);
  }
  return t;
}

std::string timingCaveat(const std::string& device) {
  if (device.find("llvmpipe") == std::string::npos && device.find("softpipe") == std::string::npos) return "";
  return "note: " + device + " is a software renderer: its GPU timer queries read 0, so per-pass GPU columns show '" +
         kNotMeasured +
         "' and the other times are wall clock around glFinish, for development only (GPU figures: "
         "docs/PERFORMANCE.md)";
}

int finish(const Env& env, const Table& table, const std::string& note) {
  table.print();
  return finishPrinted(env, table, note);
}

int finishPrinted(const Env& env, const Table& table, const std::string& note) {
  if (const std::string caveat = timingCaveat(env.device); !caveat.empty())
    std::printf("%s%s\n", caveat.c_str(), note.c_str());
  if (!env.common.csv.empty()) table.writeCsv(env.common.csv);
  return 0;
}

std::vector<std::string> splitCommas(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
  return out;
}

std::string fixed(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

std::vector<std::size_t> parseSizes(const std::string& text) {
  static const std::regex number(R"((\d+)([kKmMgG]?))");
  static const std::regex power(R"(2\^(\d+))");
  static const std::regex range(R"(2\^(\d+)\.\.2\^(\d+))");
  static const std::regex doubling(R"((\d+[kKmMgG]?)\.\.(\d+[kKmMgG]?))");
  auto one = [&](const std::string& token) -> std::size_t {
    std::smatch m;
    if (std::regex_match(token, m, power) && std::stoi(m[1]) < 40) return std::size_t(1) << std::stoi(m[1]);
    if (std::regex_match(token, m, number)) {
      std::size_t v = std::stoull(m[1]);
      if (m[2] == "k" || m[2] == "K") v <<= 10;
      if (m[2] == "m" || m[2] == "M") v <<= 20;
      if (m[2] == "g" || m[2] == "G") v <<= 30;
      return v;
    }
    throw Error("size '" + io::printable(token) + "' is not a number like 65536, 64k, 16M, 1G or 2^20");
  };
  std::vector<std::size_t> out;
  for (const std::string& token : splitCommas(text)) {
    std::smatch m;
    if (std::regex_match(token, m, range)) {
      for (int k = std::stoi(m[1]); k <= std::stoi(m[2]) && k < 40; ++k) out.push_back(std::size_t(1) << k);
    } else if (std::regex_match(token, m, doubling)) {
      const std::size_t last = one(m[2]);
      for (std::size_t v = one(m[1]); v > 0 && v <= last; v *= 2) out.push_back(v);
    } else {
      out.push_back(one(token));
    }
  }
  if (out.empty()) throw Error("no sizes given");
  return out;
}

std::vector<bool> parseOnOff(const std::string& text, const std::string& option) {
  auto one = [&](const std::string& token) {
    if (token != "on" && token != "off") throw Error(option + " '" + io::printable(token) + "' is not on or off");
    return token == "on";
  };
  return parseList(text, one, option + ": nothing given (on, off or on,off)");
}

}  // namespace tidepool::bench
