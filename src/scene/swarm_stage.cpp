#include "scene/swarm_stage.h"

#include <cmath>
#include <optional>
#include <utility>

#include "base/log.h"
#include "io/json.h"
#include "io/png.h"
#include "render/swarm_renderer.h"
#include "scene/scene.h"
#include "sim/swarm/swarm.h"

namespace tidepool {
namespace {

void visitAll(ParamVisitor& v, sim::SwarmParams& simParams, SwarmViewParams& view) {
  sim::visit(v, simParams);
  if (v.beginGroup({"view", "View", "how the particles are drawn"})) {
    visit(v, view);
    v.endGroup();
  }
}

// A swarm scene's "params": the model's keys, and "view".
struct SwarmSceneParams {
  sim::SwarmParams model;
  SwarmViewParams view;
};
void visit(ParamVisitor& v, SwarmSceneParams& p) { visitAll(v, p.model, p.view); }

// "colors" -> assets/textures/colors.png; anything else is a path to a PNG. A file that cannot be
// read or decoded is refused on one line naming the key after `where` ("x.json: params") and the
// file, both escaped: "x.json: params.view.image = 'a.png': file not found: 'a.png'".
io::Image loadSwarmImage(const std::string& nameOrPath, const std::string& where) {
  try {
    std::error_code ec;  // a name too long for a path is "not found", not an exception
    const std::filesystem::path asset = findAssetDir() / "textures" / (nameOrPath + ".png");
    return io::readPng(std::filesystem::exists(asset, ec) ? asset : std::filesystem::path(nameOrPath));
  } catch (const Error& e) {
    throw Error(where + ".view.image = '" + io::printable(nameOrPath, 120) + "': " + io::printable(e.what(), 400));
  }
}

class SwarmStage final : public ModelStage<sim::Swarm> {
 public:
  // `image`: view.image decoded (the scene's image mode), or nullopt.
  SwarmStage(const sim::SwarmParams& simParams, const SwarmViewParams& view, std::optional<io::Image> image,
             gl::ShaderLibrary& shaders)
      : ModelStage(shaders, simParams), m_renderer(shaders), m_view(view) {
    if (image) {
      m_image = std::move(*image);
      m_imageName = view.image;
    }
    if (view.colorMode != SwarmColorMode::Image) m_otherMode = view.colorMode;
  }

  void visitParams(ParamVisitor& v) override { visitAll(v, m_model.params(), m_view); }

  // A count that does not fit is refused here, with an Error (the UI's edits are refused earlier,
  // in step(), keeping the particles; a checkpoint's parameters must not be swapped for others).
  void reset() override {
    m_model.reset();
    m_coloredImage.clear();  // recoloured from the new start positions
  }
  void restart() override {  // the window's R: an edited count that does not fit stays refused
    syncAllocation();
    reset();
  }

  void step(gl::GpuProfiler& profiler) override {
    syncAllocation();
    syncColors();
    ModelStage::step(profiler);
    m_clock += m_model.params().frameSeconds;
  }

  void render(RenderTarget& target, gl::GpuProfiler& profiler) override {
    m_model.setAspect(double(target.width()) / target.height());
    syncAllocation();
    syncColors();
    std::vector<SwarmMarker> markers;
    const glm::dvec2 toNdc(1.0 / m_model.aspect(), 1.0);
    for (const sim::Attractor& a : m_model.attractorsAt(m_model.time()))
      markers.push_back({glm::vec2(a.pos * toNdc), float(a.strength)});
    const glm::vec3 color = m_view.autoHue ? swarmHue(m_clock / 60.0) : m_view.color;
    m_renderer.render(m_model, m_view, color, markers, target, profiler);
  }

  void input(const Input& in) override {
    if (!in.left) {
      m_model.setMouse(std::nullopt);
      return;
    }
    const glm::dvec2 ndc(2.0 * in.cursor.x / std::max(in.viewport.x, 1) - 1.0,
                         1.0 - 2.0 * in.cursor.y / std::max(in.viewport.y, 1));
    m_model.setMouse(ndc * glm::dvec2(m_model.aspect(), 1.0));
  }

  // A PNG dropped on the window colours the particles by where they start (and restarts them);
  // it is decoded whole first, and a bad one changes nothing.
  std::string dropFile(const std::string& path) override {
    try {
      m_dropped = {path, io::readPng(path)};
    } catch (const Error& e) {
      m_warning = std::string("not loaded: ") + e.what();
      return m_warning;
    }
    m_view.image = path;
    m_view.colorMode = SwarmColorMode::Image;
    m_coloredImage.clear();
    m_imageName.clear();  // the same path may hold a new file: syncColors takes m_dropped
    m_warning.clear();
    return "";
  }

  std::string status() const override {
    return m_warning.empty() ? m_model.status() : m_model.status() + "\n" + m_warning;
  }

  // The model, the hue clock, and the colours an image gave the particles at their start
  // positions (they cannot be sampled again from where the particles are now).
  void visitState(sim::StateVisitor& v) override {
    ModelStage::visitState(v);
    v.value("stage.clock", m_clock);
    bool colored =
        m_view.colorMode == SwarmColorMode::Image && m_renderer.hasColors(m_model) && m_coloredImage == m_view.image;
    v.flag("stage.image_colors", colored);
    if (!colored) return;
    const std::size_t bytes = m_model.count() * sizeof(std::uint32_t);
    if (!v.loading()) {
      v.buffer("stage.colors", const_cast<gl::Buffer&>(m_renderer.colors()), bytes);  // a saver only reads it
      return;
    }
    gl::Buffer colors(bytes);
    v.buffer("stage.colors", colors, bytes);
    m_renderer.adoptColors(m_model, std::move(colors));
    m_coloredImage = m_view.image;
  }

  // The image colours go with the particles when the view shows them.
  std::optional<ExportSource> exportSource() override {
    const bool colored =
        m_view.colorMode == SwarmColorMode::Image && m_renderer.hasColors(m_model) && m_coloredImage == m_view.image;
    return swarmSource(m_model, colored ? &m_renderer.colors() : nullptr);
  }

 private:
  // Count and storage changes (UI, scene) re-allocate; a request that does not fit is refused
  // with the message in the status line, keeping the current particles.
  void syncAllocation() {
    sim::SwarmParams& p = m_model.params();
    if (std::size_t(p.particles) == m_model.count() && p.storage == m_model.storage()) return;
    try {
      m_model.reset();
      m_coloredImage.clear();
      m_warning.clear();
    } catch (const Error& e) {
      m_warning = e.what();
      log::error(m_warning);
      p.particles = int(m_model.count());
      p.storage = m_model.storage();
    }
  }

  // Image colours mark where each particle started: a new image restarts the swarm (as the seed does).
  void syncColors() {
    if (m_view.colorMode != SwarmColorMode::Image) {
      m_otherMode = m_view.colorMode;
      return;
    }
    if (m_coloredImage == m_view.image && m_renderer.hasColors(m_model)) return;
    if ((m_image.rgba.empty() || m_view.image != m_imageName) && !loadImage()) return;
    if (m_coloredImage == m_view.image && m_renderer.hasColors(m_model)) return;  // a refused edit: as it was
    try {
      if (m_model.time() > 0.0) m_model.reset();
      m_renderer.colorFromImage(m_model, m_image);
      m_coloredImage = m_view.image;
    } catch (const Error& e) {
      m_warning = e.what();
      log::error(m_warning);
      m_view.colorMode = m_otherMode;
    }
  }

  // Decodes view.image (or takes what dropFile decoded). A file that fails changes nothing: the
  // view goes back to the image it had (or to its other colour mode) and the status line says
  // why, once.
  bool loadImage() {
    try {
      m_image = m_dropped && m_dropped->first == m_view.image ? std::move(m_dropped->second)
                                                              : loadSwarmImage(m_view.image, "params");
      m_imageName = m_view.image;
      m_dropped.reset();
      m_warning.clear();
      return true;
    } catch (const Error& e) {
      m_dropped.reset();
      m_warning = std::string("not loaded: ") + e.what();
      log::error(m_warning);
      if (m_image.rgba.empty()) {
        m_view.colorMode = m_otherMode;
        return false;
      }
      m_view.image = m_imageName;
      return true;
    }
  }

  SwarmRenderer m_renderer;
  SwarmViewParams m_view;
  std::string m_coloredImage;                                  // image the colour buffer was made from
  io::Image m_image;                                           // view.image decoded, for restarts to recolour
  std::string m_imageName;                                     // the view.image it came from
  SwarmColorMode m_otherMode = SwarmColorMode::Single;         // the mode before image, to go back to
  std::optional<std::pair<std::string, io::Image>> m_dropped;  // decoded by dropFile, for syncColors
  std::string m_warning;
  double m_clock = 0.0;  // frames shown x frame_seconds (not slowed by speed): drives the hue cycle
};

SceneParams parseSwarmParams(const io::Json& params, const std::string& where) {
  return readSceneParams<SwarmSceneParams>(params, where);
}

// A scene in image mode names a file that must load: refused here, like a missing mesh or rules file.
std::unique_ptr<Stage> createSwarmStage(const SceneParams& params, const std::string& where,
                                        gl::ShaderLibrary& shaders) {
  const SwarmSceneParams& p = params.as<SwarmSceneParams>();
  std::optional<io::Image> image;
  if (p.view.colorMode == SwarmColorMode::Image) image = loadSwarmImage(p.view.image, where);
  return std::make_unique<SwarmStage>(p.model, p.view, std::move(image), shaders);
}

}  // namespace

ModelEntry swarmModel() {
  return {"swarm",
          "millions of 2D particles pulled by animated attractors, one following the mouse",
          parseSwarmParams,
          createSwarmStage,
          {{"particles", "the particle count"},
           {"storage", "the precision the state is stored in"},
           {"seed", "the initial positions"},
           {"view.color_mode", "image colours, which restart the swarm"},
           {"view.image", "image colours, which restart the swarm"}}};
}

}  // namespace tidepool
