#include "scene/life_stage.h"

#include <cmath>
#include <filesystem>

#include "base/log.h"
#include "render/life_view.h"
#include "scene/scene.h"
#include "sim/life/life.h"

namespace tidepool {
namespace {

constexpr const char* kSaveName = "particle-life-system.json";
constexpr int kMaxSeed = 999999999;  // ImGui sliders take at most half the int range

// The web app's controls: what generateRules() takes, plus where to load rules from instead.
struct Setup {
  std::string rules;  // rules JSON path, preset name (assets/rules/<name>.json) or share code; empty: generate
  int species = 8;
  int particleCount = 65536;
  float width = 1024, height = 576;
  float friction = 10, centralForce = 0;
  bool symmetricForces = false, loopingBorders = false;
  int seed = 0;

  bool operator==(const Setup&) const = default;
};

void visit(ParamVisitor& v, Setup& s, bool withRules) {
  if (withRules)
    v.text({"rules", "Rules", "rules JSON path, preset name (assets/rules) or share code; overrides the values below"},
           s.rules);
  v.integer({"species", "Species", "1-20; a change generates new rules"}, s.species, 1, life::kMaxSpecies);
  v.integer({"particle_count", "Particles", "respawns"}, s.particleCount, 1, life::kMaxParticles);
  v.real({"width", "Width", "box width, world units (respawns)"}, s.width, 16.0f, 65536.0f);
  v.real({"height", "Height", "box height, world units (respawns)"}, s.height, 16.0f, 65536.0f);
  v.real({"friction", "Friction", "1/s: v *= exp(-friction dt)"}, s.friction, 0.0f, 100.0f);
  v.real({"central_force", "Central force", "1/s^2: pull toward the centre"}, s.centralForce, 0.0f, 10.0f);
  v.flag({"symmetric_forces", "Symmetric forces", "average (i,j) and (j,i)"}, s.symmetricForces);
  v.flag({"looping_borders", "Looping borders", "torus instead of walls"}, s.loopingBorders);
  v.integer({"seed", "Seed", "rule generator seed; a change generates new rules"}, s.seed, 0, kMaxSeed);
}

struct ViewSettings {
  LifeViewParams look;
  float zoom = 1.0f;       // 1: the whole box fits the image
  glm::vec3 centre{0.0f};  // world units (z unused)
};

void visit(ParamVisitor& v, ViewSettings& s) {
  visit(v, s.look);
  v.real({"zoom", "Zoom", "1: the box fits the image"}, s.zoom, 0.01f, 1000.0f);
  v.vector({"centre", "Centre", "world point at the image centre (z unused)"}, s.centre, -1e5f, 1e5f);
}

life::Rules rulesFor(const Setup& s) {
  return life::generateRules({s.species,
                              s.particleCount,
                              {s.width, s.height},
                              s.friction,
                              s.centralForce,
                              s.symmetricForces,
                              s.loopingBorders,
                              std::uint32_t(s.seed)});
}

Setup setupOf(const life::Rules& r, std::string rulesSource) {
  return {std::move(rulesSource),
          r.speciesCount(),
          r.particleCount,
          r.size.x,
          r.size.y,
          r.friction,
          r.centralForce,
          r.symmetricForces,
          r.loopingBorders,
          int(r.seed % (kMaxSeed + 1u))};
}

// A path as given, then assets/rules/<name>[.json]; anything else is tried as a share code.
life::Rules resolveRules(const std::string& text, const std::string& where) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::string path = text;
  if (!fs::exists(path, ec))
    for (const fs::path& c : {findAssetDir() / "rules" / text, findAssetDir() / "rules" / (text + ".json")})
      if (fs::exists(c, ec)) path = c.string();
  if (!fs::exists(path, ec) && !life::looksLikeShareCode(text))
    throw Error(where + ".rules: '" + io::printable(text) +
                "' is neither a rules file, a preset in assets/rules nor a share code");
  try {
    return life::loadRules(path);
  } catch (const Error& e) {
    throw Error(where + ".rules: " + e.what());
  }
}

class LifeStage final : public ModelStage<life::Life> {
 public:
  LifeStage(gl::ShaderLibrary& shaders, const life::Rules& rules, const Setup& setup, const life::Params& params,
            const ViewSettings& view)
      : ModelStage(shaders, rules, params), m_view(shaders), m_setup(setup), m_applied(setup), m_settings(view) {
    m_shareCode = life::encodeShareCode(rules);
  }

  void visitParams(ParamVisitor& v) override {
    if (v.beginGroup({"rules", "Rules", "the system (web-app controls); share it with the code below"})) {
      visit(v, m_setup, false);
      // 42 characters for rules straight from a seed, ~1.6k for edited ones (8 species): show the
      // start; the panel's button copies it all.
      std::string preview = m_shareCode.size() > 28 ? m_shareCode.substr(0, 24) + "..." : m_shareCode;
      if (!m_error.empty()) v.text({"error", "Refused", "the last edit, load or save did not happen"}, m_error);
      v.text({"share_code", "Share code", "tidepool run life --rules <code>; 'Copy share code' copies it"}, preview);
      v.endGroup();
    }
    if (v.beginGroup({"model", "Stepping", ""})) {
      life::visit(v, m_model.params());
      v.endGroup();
    }
    if (v.beginGroup({"view", "View", "C centres, wheel zooms, right drag pans"})) {
      visit(v, m_settings.look);
      v.endGroup();
    }
  }
  void step(gl::GpuProfiler& profiler) override {
    applySetup();
    ModelStage::step(profiler);
  }
  void render(RenderTarget& target, gl::GpuProfiler& profiler) override {
    applySetup();
    if (!m_cameraPlaced) {
      m_view.camera() = LifeView::fit(m_model.rules().size, {target.width(), target.height()});
      m_view.camera().extentX /= m_settings.zoom;
      m_view.camera().centre = glm::vec2(m_settings.centre);
      m_cameraPlaced = true;
    }
    m_view.params() = m_settings.look;
    m_view.render(m_model, target, profiler);
  }
  void input(const Input& in) override {
    LifeCamera& cam = m_view.camera();
    const glm::vec2 here = m_view.toWorld(in.cursor, in.viewport);
    const glm::vec2 before = m_view.toWorld(in.cursor - in.cursorDelta, in.viewport);
    if (in.left && in.cursorDelta != glm::vec2(0.0f))
      m_model.push(here, (here - before) * m_model.params().pushStrength, cam.extentX / 16.0f);
    if (in.right) m_view.pan(in.cursor, in.cursorDelta, in.viewport);
    if (in.scroll != 0.0f) m_view.zoomAbout(in.cursor, in.scroll, in.viewport);
    m_view.glide(in.dt, in.viewport);
  }
  // The original's Restart: same rules, new random positions (reset() stays the seed's start,
  // which checkpoints and headless runs rely on).
  void restart() override { m_model.respawn(++m_restarts); }
  void key(int c) override {
    if (c == 'C') {
      m_cameraPlaced = false;
      m_settings.zoom = 1.0f;
      m_settings.centre = glm::vec3(0.0f);
    }
    if (c == 'W') {  // the web app's "Save system", under its suggested name (its S hides the panel)
      try {
        io::writeJsonFile(kSaveName, life::rulesToJson(m_model.rules()));
        log::info(std::string("saved the rules to ") + kSaveName);
      } catch (const Error& e) {
        m_error = std::string("not saved: ") + e.what();
      }
    }
    if (c == 'N') {
      life::SplitMix32 next(std::uint32_t(m_setup.seed) ^ 0x85ebca6bu);
      m_setup.seed = int(next.nextU32() % (kMaxSeed + 1u));  // a new seed, itself reproducible
    }
  }
  // A rules JSON dropped on the window: the web app's "Load system". The file is read and
  // validated whole before anything changes; errors show in the panel too.
  std::string dropFile(const std::string& path) override {
    try {
      const life::Rules rules = life::loadRules(path);
      m_model.setRules(rules, true);
      m_setup = m_applied = setupOf(rules, path);
      m_shareCode = life::encodeShareCode(rules);
      m_error.clear();
      m_cameraPlaced = false;
    } catch (const Error& e) {
      m_error = std::string("not loaded: ") + e.what();
    }
    return m_error;
  }
  std::string shareText() const override { return m_shareCode; }
  // The preset or file the rules came from (its name without .json), or the seed they were made
  // from once N or a species change made new ones.
  std::string running() const override {
    const std::string& from = m_applied.rules;
    if (from.empty()) return "seed " + std::to_string(m_applied.seed);
    std::error_code ec;
    if (life::looksLikeShareCode(from) && !std::filesystem::exists(from, ec)) return "share code";
    return std::filesystem::path(from).stem().string();
  }
  StageIndicators indicators() override {
    StageIndicators s = ModelStage::indicators();
    s.gridCells = m_model.grid().dims();
    s.cellSize = m_model.grid().params().cellSize;
    return s;
  }

  // The refusal the panel shows comes before the parameters: it is one of their keys while set.
  void visitSetupState(sim::StateVisitor& v) override { v.text("stage.error", m_error, 4096); }
  // The rules as they run (bit-identical through a share code: they may come from a file, a
  // drop or edits the setup cannot say), then the model. The setup read back describes them.
  void visitState(sim::StateVisitor& v) override {
    std::string code = life::encodeShareCode(m_model.rules());
    v.text("stage.rules", code, std::size_t(1) << 20);
    if (v.loading()) {
      try {
        const life::Rules rules = life::decodeShareCode(code);
        life::validateRules(rules, "entry 'stage.rules'");
        m_model.setRules(rules, true);
      } catch (const Error& e) {
        v.fail(std::string("entry 'stage.rules': ") + e.what());
      }
      m_shareCode = code;
      m_applied = m_setup;
      m_cameraPlaced = false;
    }
    ModelStage::visitState(v);
  }

  std::optional<ExportSource> exportSource() override { return lifeSource(m_model); }

 private:
  // Applies UI edits of the setup: a new seed or species count generates new rules; the box or
  // count respawns; the rest changes the running system.
  void applySetup() {
    if (m_setup == m_applied) return;
    life::Rules rules = m_model.rules();
    if (m_setup.seed != m_applied.seed || m_setup.species != m_applied.species) {
      rules = rulesFor(m_setup);
      m_setup.rules.clear();  // made from the seed: no longer the preset or file named
    } else {
      rules.particleCount = m_setup.particleCount;
      rules.size = {m_setup.width, m_setup.height};
      rules.friction = m_setup.friction;
      rules.centralForce = m_setup.centralForce;
      rules.symmetricForces = m_setup.symmetricForces;
      rules.loopingBorders = m_setup.loopingBorders;
    }
    try {
      m_model.setRules(rules, false);
      m_shareCode = life::encodeShareCode(rules);
      m_error.clear();
    } catch (const Error& e) {
      m_setup = m_applied;  // e.g. looping in a box smaller than twice the radius: keep the old rules
      m_error = std::string("not applied: ") + e.what();
      return;
    }
    m_applied = m_setup;
  }

  LifeView m_view;
  Setup m_setup, m_applied;
  ViewSettings m_settings;
  std::string m_shareCode;
  std::string m_error;  // why the last edit of the setup was refused
  bool m_cameraPlaced = false;
  std::uint32_t m_restarts = 0;  // R presses: each draws the particles from another stream
};

// A life scene's "params": the setup's keys, "model" (stepping) and "view".
struct LifeSceneParams {
  Setup setup;
  life::Params model;
  ViewSettings view;
};

void visit(ParamVisitor& v, LifeSceneParams& p) {
  visit(v, p.setup, true);
  if (v.beginGroup({"model", "Stepping", ""})) {
    life::visit(v, p.model);
    v.endGroup();
  }
  if (v.beginGroup({"view", "View", ""})) {
    visit(v, p.view);
    v.endGroup();
  }
}

SceneParams parseLifeParams(const io::Json& params, const std::string& where) {
  return readSceneParams<LifeSceneParams>(params, where);
}

std::unique_ptr<Stage> createLifeStage(const SceneParams& params, const std::string& where,
                                       gl::ShaderLibrary& shaders) {
  const LifeSceneParams& p = params.as<LifeSceneParams>();
  Setup setup = p.setup;
  life::Rules rules;
  if (!setup.rules.empty()) {
    rules = resolveRules(setup.rules, where);
    setup = setupOf(rules, setup.rules);
  } else {
    rules = rulesFor(setup);
    life::validateRules(rules, where);
  }
  return std::make_unique<LifeStage>(shaders, rules, setup, p.model, p.view);
}

}  // namespace

ModelEntry lifeModel() {
  // The setup (rules, counts, box, forces) is the state's: its keys sit at the top of a scene's
  // params but under "rules" in a running stage's.
  static constexpr const char* kSetup = "life's rules: species, forces, box and particles";
  return {"life",
          "particle life: species with asymmetric forces, glow + HDR view, shareable rules",
          parseLifeParams,
          createLifeStage,
          {{"rules", kSetup},
           {"species", kSetup},
           {"particle_count", kSetup},
           {"width", kSetup},
           {"height", kSetup},
           {"friction", kSetup},
           {"central_force", kSetup},
           {"symmetric_forces", kSetup},
           {"looping_borders", kSetup},
           {"seed", kSetup},
           {"model.storage", "the precision the state is stored in"}}};
}

}  // namespace tidepool
