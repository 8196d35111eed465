// `tidepool check-resume <scene>`: does a resumed run equal the uninterrupted one on this GPU? It
// renders the scene three times through the same path as `render`: 2N steps straight (frames 0 to
// 2N), N steps with a checkpoint (frames 0 to N), and N steps resumed from it (frames N + 1 to 2N);
// then compares the two final checkpoints (every state buffer and every value the scene keeps,
// byte for byte) and the two frames numbered 2N.
// docs/RELIABILITY.md ("Resume on your GPU") says what it has found and where.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>

#include "app/headless.h"
#include "base/log.h"
#include "cli/commands.h"
#include "io/checkpoint_diff.h"
#include "io/json.h"

namespace tidepool::cli {
namespace {

std::filesystem::path temporaryFolder() {
  std::string name = (std::filesystem::temp_directory_path() / "tidepool-check-resume-XXXXXX").string();
  if (!mkdtemp(name.data())) throw Error("cannot create a temporary folder in " + name);
  return name;
}

std::vector<char> fileBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot read " + io::printable(file.string(), 200));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path frameFile(const std::filesystem::path& dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", frame);
  return dir / name;
}

struct Opts {
  std::string scene, size = "160x90", backend = "auto";
  int frames = 30;
  std::filesystem::path out;  // empty: a temporary folder, removed after
};

int checkResume(const Opts& o) {
  RenderJob base;
  base.scene = o.scene;
  base.backend = gl::parseBackend(o.backend);
  base.progress = false;
  int w = 0, h = 0;
  parseSize(o.size, w, h);
  base.width = w;
  base.height = h;
  const bool keep = !o.out.empty();
  const std::filesystem::path dir = keep ? o.out : temporaryFolder();
  const int n = o.frames;
  const auto job = [&](const char* name, int frames, const std::filesystem::path& resume) {
    RenderJob j = base;
    j.frames = resume.empty() ? frames + 1 : frames;  // a fresh run's frame 0 is the starting state: `frames` steps
    j.outDir = dir / name;
    j.checkpoint = dir / (std::string(name) + ".ckpt");
    j.resume = resume;
    return j;
  };
  log::setLevel(log::Level::Warn);
  std::optional<std::string> stateDiff;
  bool sameFrame = false;
  try {
    renderHeadless(job("straight", 2 * n, {}));
    renderHeadless(job("first", n, {}));
    renderHeadless(job("resumed", n, dir / "first.ckpt"));
    stateDiff = io::checkpointDifference(io::readCheckpointFile(dir / "straight.ckpt"),
                                         io::readCheckpointFile(dir / "resumed.ckpt"));
    sameFrame = fileBytes(frameFile(dir / "straight", 2 * n)) == fileBytes(frameFile(dir / "resumed", 2 * n));
  } catch (...) {
    log::setLevel(log::Level::Info);
    if (!keep) std::filesystem::remove_all(dir);
    throw;
  }
  log::setLevel(log::Level::Info);
  if (!keep) std::filesystem::remove_all(dir);
  const std::string runs = std::to_string(n) + " frames resumed from a checkpoint after " + std::to_string(n);
  if (stateDiff)
    throw Error("resume is not exact: " + runs + " differ from " + std::to_string(2 * n) + " straight: " + *stateDiff);
  if (!sameFrame)
    throw Error("resume is not exact: the state matches but the last frame's picture differs (" + runs + ")");
  std::printf("resume is exact: %s equal %d straight, every state buffer and value and the last frame bit for bit%s\n",
              runs.c_str(), 2 * n, keep ? (" (runs in " + io::printable(dir.string(), 200) + ")").c_str() : "");
  return 0;
}

}  // namespace

Command addCheckResume(CLI::App& app) {
  auto* sub =
      app.add_subcommand("check-resume", "check that a resumed run equals the uninterrupted one here, bit for bit");
  auto o = std::make_shared<Opts>();
  sub->add_option("scene", o->scene, "scene file, or a name from assets/scenes (e.g. cup)")->required();
  sub->add_option("--frames", o->frames, "N: 2N frames straight against N, a checkpoint, and N more (default 30)")
      ->check(CLI::Range(1, 100000));
  sub->add_option("--size", o->size, "image size WIDTHxHEIGHT of the compared frames (default 160x90)");
  sub->add_option("--out", o->out, "keep the three runs and their checkpoints in this folder");
  sub->add_option("--backend", o->backend, "auto, egl or osmesa")->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  return {sub, [o] { return checkResume(*o); }};
}

}  // namespace tidepool::cli
