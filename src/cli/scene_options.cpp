#include "cli/scene_options.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "cli/commands.h"
#include "io/echo.h"
#include "scene/checkpoint.h"

namespace tidepool::cli {
namespace {

// Nesting of a JSON value: 0 for a number or string, 1 for [1, 2], 2 for {"a": [1]}. The value
// came through parseJson, so it is at most kMaxJsonDepth deep and the recursion is bounded.
int jsonDepth(const io::Json& value) {
  int deepest = 0;
  if (value.is_structured())
    for (const io::Json& child : value) deepest = std::max(deepest, jsonDepth(child));
  return value.is_structured() ? deepest + 1 : 0;
}

bool isName(std::string_view s) {
  const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  const auto letterOrDigit = [&](char c) { return letter(c) || std::isdigit(static_cast<unsigned char>(c)); };
  return !s.empty() && letter(s[0]) && std::all_of(s.begin() + 1, s.end(), letterOrDigit);
}

std::string shownSet(const std::string& text) { return "--set '" + io::printable(text) + "'"; }

}  // namespace

void addCheckpointOptions(CLI::App* sub, CheckpointOpts& o) {
  sub->add_option("--resume", o.resume,
                  "start from this checkpoint (a file --checkpoint wrote) instead of t = 0; render numbers its "
                  "frames on after the checkpoint's. --set takes live keys on top of the checkpoint's parameters "
                  "(view, and physics as the window edits it mid-run: engine, walls, ...); keys the checkpoint "
                  "fixes (particles, grid size), --resolution and --fit-gpu are refused");
  sub->add_option("--checkpoint", o.checkpoint,
                  "write checkpoints to this file (atomically; default: beside the output, e.g. out/dam.ckpt)");
  sub->add_option("--checkpoint-every", o.every,
                  "save a checkpoint every this many simulated seconds, and after the last frame")
      ->check(finitePositive());
}

void addResolutionOptions(CLI::App* sub, ResolutionOpts& o) {
  sub->add_option("--resolution", o.resolution,
                  "water: refine the particle spacing R times, keeping the setup (counts x R^3, dt / R; "
                  "sets params.particles.resolution)")
      ->check(finiteRange(0.05, 64.0));
  sub->add_flag("--fit-gpu", o.fit, "water: the finest resolution whose frame (steps + render) fits --budget here");
  sub->add_option("--budget", o.budgetMs, "with --fit-gpu: ms per frame (default 33.3, 30 frames/s)")
      ->check(finiteRange(0.1, 1e6));
  sub->add_option("--set", o.sets,
                  "set a scene parameter, KEY=VALUE (e.g. view.mode=water); repeatable; with --resume, live keys "
                  "only");
}

// The value as JSON when it reads as JSON (3, true, [0,1,0]), else as text. Read in one pass,
// under the size and depth limits of a scene file: the dotted key's names count as levels of
// nesting, as they do in the object they become.
io::Json setOverride(const std::string& text) {
  const std::string shown = shownSet(text);
  if (text.size() > io::kMaxJsonFileBytes)
    throw Error(shown + ": " + io::byteSize(text.size()) + ", larger than the " + io::byteSize(io::kMaxJsonFileBytes) +
                " allowed for JSON");
  const std::size_t equals = text.find('=');
  std::vector<std::string> keys;
  for (std::size_t begin = 0; equals != std::string::npos && begin <= equals;) {
    const std::size_t dot = std::min(text.find('.', begin), equals);
    keys.push_back(text.substr(begin, dot - begin));
    if (!isName(keys.back()) || keys.size() > std::size_t(io::kMaxJsonDepth)) break;
    begin = dot + 1;
  }
  if (equals == std::string::npos || equals + 1 == text.size() || keys.empty() || !isName(keys.back()))
    throw Error(shown + " is not KEY=VALUE with a params key (e.g. view.mode=water)");
  if (keys.size() > std::size_t(io::kMaxJsonDepth))
    throw Error(shown + ": the key is nested deeper than the " + std::to_string(io::kMaxJsonDepth) +
                " levels a scene may nest");
  const std::string valueText = text.substr(equals + 1);
  io::Json patch;
  try {
    patch = io::parseJson(valueText, "--set");
  } catch (const Error&) {
    patch = valueText;
  }
  if (keys.size() + std::size_t(jsonDepth(patch)) > std::size_t(io::kMaxJsonDepth))
    throw Error(shown + ": the key and the value together are nested deeper than the " +
                std::to_string(io::kMaxJsonDepth) + " levels a scene may nest");
  for (auto key = keys.rbegin(); key != keys.rend(); ++key) {
    io::Json level = io::Json::object();
    level[*key] = std::move(patch);
    patch = std::move(level);
  }
  return patch;
}

std::vector<ParamOverride> sceneOverrides(const ResolutionOpts& o, const std::string& rules) {
  std::vector<ParamOverride> out;
  if (!rules.empty()) out.push_back({"--rules '" + io::printable(rules) + "'", {{"rules", rules}}});
  for (const std::string& set : o.sets) out.push_back({shownSet(set), setOverride(set)});
  if (o.resolution > 0)
    out.push_back({"--resolution " + io::Json(o.resolution).dump(), {{"particles", {{"resolution", o.resolution}}}}});
  return out;
}

io::Json merged(const std::vector<ParamOverride>& overrides) {
  io::Json all;
  for (const ParamOverride& o : overrides) {
    if (!all.is_object()) all = io::Json::object();
    all.merge_patch(o.patch);
  }
  return all;
}

Scene checkSceneOptions(const std::string& sceneArg, const std::vector<ParamOverride>& overrides,
                        const ResolutionOpts& o, const std::string& resume) {
  const auto refuse = [&](const std::string& option, const std::string& what) {
    throw Error(option + ": changes the simulation state (" + what +
                ") and cannot be applied to a resumed run (checkpoint " + io::shownPath(resume) +
                "); drop it or start without --resume");
  };
  if (!resume.empty() && o.fit) refuse("--fit-gpu", "it picks particles.resolution");
  Scene scene = loadSceneWith(resolveScenePath(sceneArg), overrides);
  if (resume.empty()) return scene;
  for (const ParamOverride& p : overrides)
    if (const std::optional<StateKeyHit> hit = stateKeyIn(scene.model, p.patch)) {
      const std::string option = p.origin.substr(0, p.origin.find(' '));  // "--set", "--rules", "--resolution"
      refuse(option == "--set" ? option + " " + io::printable(hit->key) : option, hit->what);
    }
  return scene;
}

}  // namespace tidepool::cli
