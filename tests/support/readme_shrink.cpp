#include "support/readme_shrink.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

namespace tidepool::test {
namespace {

struct Rule {
  std::string option;
  bool takesValue = true;
  std::string shrunk;  // empty: kept as written
};

struct Kind {
  std::vector<Rule> rules;
  std::vector<std::pair<std::string, std::string>> added;  // when absent
  std::size_t maxPositionals = 1;                          // the scene
};

const std::vector<Rule> kRenderAndRun = {
    {"--frames", true, "2"},
    {"--size", true, "64x48"},
    {"--out"},
    {"--checkpoint"},
    {"--resume"},
    {"--checkpoint-every", true, "0.001"},
    {"--resolution", true, "1.5"},
    {"--fit-gpu", false, ""},
    {"--budget", true, "100"},
    {"--set"},
    {"--rules"},
    {"--backend"},
};

// Scenes too big for llvmpipe, and the --resolution that makes them small: 100,000,000 balls x 0.05³.
const std::map<std::string, std::string> kHugeScenes = {{"hundred-million", "0.05"}};

const std::map<std::string, Kind>& kinds() {
  static const std::map<std::string, Kind> k = [] {
    std::map<std::string, Kind> m;
    m["render"] = {kRenderAndRun, {{"--frames", "2"}, {"--size", "64x48"}}};
    for (Rule r : std::vector<Rule>{{"--video"},
                                    {"--export"},
                                    {"--every", true, "1"},
                                    {"--no-frames", false, ""},
                                    {"--surface-format"},
                                    {"--surface-resolution", true, "16"},
                                    {"--quiet", false, ""}})
      m["render"].rules.push_back(r);
    m["run"] = m["render"];
    m["run"].rules = kRenderAndRun;
    m["info"] = {{{"--backend"}}, {}, 0};
    m["check-resume"] = {{{"--frames", true, "1"}, {"--size", true, "32x18"}, {"--out"}, {"--backend"}},
                         {{"--frames", "1"}, {"--size", "32x18"}}};
    m["validate"] = {{{"--probe"}, {"--csv"}, {"--backend"}, {"--every", true, "5"}, {"--until", true, "0.02"}},
                     {{"--until", "0.02"}}};
    const std::vector<Rule> bench = {{"--repeats", true, "1"}, {"--warmup", true, "0"}, {"--csv"}, {"--backend"}};
    const auto benchKind = [&](std::vector<Rule> own, std::vector<std::pair<std::string, std::string>> added) {
      own.insert(own.end(), bench.begin(), bench.end());
      added.insert(added.begin(), {"--repeats", "1"});
      return Kind{own, added};
    };
    // --n sizes lattice scenes only: seed-slab (a block fill) runs at its 693,523 balls, some 15 s
    // here, as the bench takes no --set or --resolution.
    m["bench balls"] = benchKind({{"--n", true, "4096"}, {"--steps", true, "1:3"}, {"--deterministic"}},
                                 {{"--n", "4096"}, {"--steps", "1:3"}});
    m["bench fluid"] =
        benchKind({{"--n", true, "4096"}, {"--steps", true, "1:3"}, {"--iterations"}, {"--deterministic"}},
                  {{"--n", "4096"}, {"--steps", "1:3"}});
    m["bench grid"] = benchKind({{"--n", true, "65536"}, {"--ppc"}}, {{"--n", "65536"}});
    m["bench render"] =
        benchKind({{"--n", true, "4096"}, {"--size", true, "64x48"}, {"--settle", true, "1"}, {"--look"}},
                  {{"--n", "4096"}, {"--size", "64x48"}, {"--settle", "1"}});
    m["bench export"] = benchKind({{"--frames", true, "1"}, {"--format"}}, {{"--frames", "1"}});
    m["bench surface"] =
        benchKind({{"--particles", true, "4096"}, {"--resolution", true, "16"}, {"--steps", true, "1"}},
                  {{"--particles", "4096"}, {"--resolution", "16"}, {"--steps", "1"}});
    return m;
  }();
  return k;
}

std::string numbered(const std::string& dir, const char* stem, int index, const std::string& ext) {
  char name[64];
  std::snprintf(name, sizeof name, "/%s_%05d.%s", stem, index, ext.c_str());
  return dir + name;
}

// Where a checkpoint goes without --checkpoint: beside the output (scene/checkpoint.h).
std::string defaultCheckpoint(std::string out, const std::string& video, const std::string& stem) {
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  if (!out.empty()) return out + ".ckpt";
  if (!video.empty()) return std::filesystem::path(video).replace_extension(".ckpt").string();
  return stem + ".ckpt";
}

class Shrinker {
 public:
  void add(const ReadmeCommand& c) {
    const std::string where = "README.md:" + std::to_string(c.line) + ": `" + c.text + "`: ";
    if (c.args.empty()) return m_out.errors.push_back(where + "no subcommand");
    std::string kindName = c.args[0];
    std::size_t i = 1;
    if (kindName == "bench" && c.args.size() > 1) kindName += " " + c.args[i++];
    const auto kind = kinds().find(kindName);
    if (kind == kinds().end())
      return m_out.errors.push_back(where + "no shrink rules for `" + kindName + "`: add them to readme_shrink.cpp");
    ShrunkCommand s{.source = c};
    s.args.assign(c.args.begin(), c.args.begin() + std::ptrdiff_t(i));
    std::vector<std::string> positionals;
    std::map<std::string, std::string> given;  // option -> value as it runs ("" for a flag)
    std::vector<std::string> options;
    for (; i < c.args.size(); ++i) {
      const std::string& a = c.args[i];
      if (a.rfind("--", 0) != 0) {
        positionals.push_back(a);
        continue;
      }
      const std::string name = a.substr(0, a.find('='));
      const auto rule = std::find_if(kind->second.rules.begin(), kind->second.rules.end(),
                                     [&](const Rule& r) { return r.option == name; });
      if (rule == kind->second.rules.end())
        return m_out.errors.push_back(where + "no shrink rule for `" + name + "` of `" + kindName +
                                      "`: add one to readme_shrink.cpp");
      std::string value;
      if (rule->takesValue) {
        if (a.find('=') != std::string::npos)
          value = a.substr(a.find('=') + 1);
        else if (i + 1 < c.args.size())
          value = c.args[++i];
        else
          return m_out.errors.push_back(where + "`" + name + "` without its value");
        if (!rule->shrunk.empty()) value = rule->shrunk;
      }
      if (name == "--resolution" && !positionals.empty() && kHugeScenes.count(positionals[0]))
        value = kHugeScenes.at(positionals[0]);
      options.push_back(name);
      options.push_back(value);
      given[name] = value;
    }
    if (positionals.size() > kind->second.maxPositionals)
      return m_out.errors.push_back(where + "more words than `" + kindName + "` takes");
    std::vector<std::pair<std::string, std::string>> added = kind->second.added;
    if (given.count("--fit-gpu")) added.push_back({"--budget", "100"});
    if (!positionals.empty() && kHugeScenes.count(positionals[0]))
      added.push_back({"--resolution", kHugeScenes.at(positionals[0])});
    for (const auto& [name, value] : added)
      if (!given.count(name)) {
        options.push_back(name);
        options.push_back(value);
        given[name] = value;
      }
    s.args.insert(s.args.end(), positionals.begin(), positionals.end());
    for (std::size_t k = 0; k < options.size(); k += 2) {
      s.args.push_back(options[k]);
      if (!options[k + 1].empty()) s.args.push_back(options[k + 1]);
    }
    s.folder = m_folders++;
    if (kindName == "render" || kindName == "run") {
      const std::string scene = positionals.empty() ? "default" : positionals[0];
      if (!expectClip(s, where, kindName, scene, given)) return;
    } else if (kindName == "validate" || kindName.rfind("bench", 0) == 0) {
      if (given.count("--csv")) s.files.push_back(given["--csv"]);
      s.printsTable = kindName != "validate" || !given.count("--csv");
    } else if (kindName == "info") {
      s.printsTable = true;
    }
    m_out.commands.push_back(s);
  }

  ShrunkCommands finish() { return std::move(m_out); }

 private:
  // The frames, video, exports and checkpoint a render or a run without a display promises.
  bool expectClip(ShrunkCommand& s, const std::string& where, const std::string& kind, const std::string& scene,
                  std::map<std::string, std::string>& given) {
    const int frames = std::stoi(given["--frames"]);
    const std::string stem = std::filesystem::path(scene).stem().string();
    int first = 0;
    if (given.count("--resume")) {
      const auto from = m_checkpoints.find(std::filesystem::path(given["--resume"]).lexically_normal().string());
      if (from == m_checkpoints.end()) {
        m_out.errors.push_back(where + "resumes `" + given["--resume"] + "`, which no README command before it writes");
        return false;
      }
      s.folder = from->second.first;
      first = from->second.second;  // a resumed render numbers its frames on
    }
    const std::string video = given.count("--video") ? given["--video"] : "";
    std::string out = given.count("--out") ? given["--out"] : "";
    if (kind == "run")
      out = (out.empty() ? "out" : out) + "/" + stem;
    else if (out.empty() && video.empty())
      out = "out/" + stem;
    if (!out.empty() && !given.count("--no-frames"))
      for (int f = first; f < first + frames; ++f) s.files.push_back(numbered(out, "frame", f, "png"));
    if (!video.empty()) {
      s.files.push_back(video);
      s.needsFfmpeg = true;
    }
    if (given.count("--export")) {
      const std::string format = given["--export"];
      const std::string surface = given.count("--surface-format") ? given["--surface-format"] : "ply";
      const int every = given.count("--every") ? std::stoi(given["--every"]) : 1;
      if (format != "vtk" && format != "ply" && format != "surface") {
        m_out.errors.push_back(where + "no files known for `--export " + format + "`");
        return false;
      }
      for (int f = first; f < first + frames; ++f)
        if (f % every == 0)
          s.files.push_back(format == "surface" ? numbered(out, "surface", f, surface == "vtk" ? "vtp" : surface)
                                                : numbered(out, "frame", f, format == "vtk" ? "vtp" : "ply"));
      if (format == "vtk") s.files.push_back(out + "/particles.pvd");
      if (format == "surface" && surface == "vtk") s.files.push_back(out + "/surface.pvd");
    }
    if (given.count("--checkpoint") || given.count("--checkpoint-every")) {
      const std::string file =
          given.count("--checkpoint") ? given["--checkpoint"] : defaultCheckpoint(out, video, stem);
      s.files.push_back(file);
      m_checkpoints[std::filesystem::path(file).lexically_normal().string()] = {s.folder, first + frames};
    }
    return true;
  }

  ShrunkCommands m_out;
  int m_folders = 0;
  std::map<std::string, std::pair<int, int>> m_checkpoints;  // file -> its folder, the next frame's number
};

}  // namespace

ShrunkCommands shrinkReadmeCommands(const std::vector<ReadmeCommand>& commands) {
  Shrinker shrinker;
  for (const ReadmeCommand& c : commands) shrinker.add(c);
  return shrinker.finish();
}

}  // namespace tidepool::test
