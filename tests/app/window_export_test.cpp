// The window's export logic without a window: Start captures the state as frame 0, stepped
// frames count (paused ones do not), every K-th is written, Stop writes what is in flight; a
// folder that cannot be made, a write that fails midway and a model without particles are
// messages for the panel that stop the export, never exceptions, and the simulation runs on.
// (Ripples export as VTK only; blank has nothing to export.)
#include "app/window_export.h"

#include <gtest/gtest.h>

#include <fstream>

#include "scene/scene.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class WindowExportLogic : public test::GlTest {};

const std::string kLife = std::string(TIDEPOOL_TEST_DATA) + "/soak/life.json";

std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_F(WindowExportLogic, ExportsEveryKthSteppedFrameFromStart) {
  test::TempDir dir;
  const Scene scene = loadScene(kLife);
  auto stage = createStage(scene, shaders());
  gl::GpuProfiler profiler;
  WindowExport exports(shaders());
  exports.settings() = {io::ExportFormat::Vtk, 2, (dir / "out").string()};
  const WindowExport::Message started = exports.start(*stage);
  EXPECT_FALSE(started.error) << started.text;
  ASSERT_TRUE(exports.running());
  const auto frame = [&](bool step) {
    if (step) stage->step(profiler);
    const auto m = exports.afterFrame(*stage, step);
    EXPECT_FALSE(m) << m->text;
  };
  for (int i = 0; i < 3; ++i) frame(true);
  frame(false);  // paused: no frame counted
  frame(false);
  for (int i = 0; i < 2; ++i) frame(true);
  EXPECT_EQ(exports.frame(), 5);
  const WindowExport::Message stopped = exports.stop();
  EXPECT_FALSE(stopped.error) << stopped.text;
  EXPECT_FALSE(exports.running());
  EXPECT_EQ(exports.written(), 3);  // frames 0, 2, 4
  const std::string pvd = readText(dir / "out/particles.pvd");
  for (const char* f : {"frame_00000.vtp", "frame_00002.vtp", "frame_00004.vtp"}) {
    EXPECT_NE(pvd.find(f), std::string::npos) << pvd;
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  }
  EXPECT_EQ(pvd.find("frame_00003"), std::string::npos) << pvd;
  const std::size_t last = pvd.rfind("timestep=\"");
  ASSERT_NE(last, std::string::npos);
  EXPECT_NEAR(std::stod(pvd.substr(last + 10)), 4 / 40.0, 1e-6) << pvd;  // frame 4: 4 steps of 1/40 s
}

TEST_F(WindowExportLogic, FailuresStopTheExportWithAMessageAndTheRunGoesOn) {
  test::TempDir dir;
  dir.write("file", "x");
  auto stage = createStage(loadScene(kLife), shaders());
  gl::GpuProfiler profiler;
  WindowExport exports(shaders());
  exports.settings().folder = (dir / "file/out").string();
  WindowExport::Message m = exports.start(*stage);
  EXPECT_TRUE(m.error);
  EXPECT_NE(m.text.find("cannot create export folder"), std::string::npos) << m.text;
  EXPECT_FALSE(exports.running());

  // The folder is replaced by a file after the start: the next write fails, naming its file.
  exports.settings().folder = (dir / "out").string();
  m = exports.start(*stage);
  ASSERT_FALSE(m.error) << m.text;
  std::filesystem::remove_all(dir / "out");
  dir.write("out", "not a folder");
  std::optional<WindowExport::Message> failed;
  for (int i = 0; i < 4 && !failed; ++i) {
    stage->step(profiler);
    failed = exports.afterFrame(*stage, true);
  }
  ASSERT_TRUE(failed);
  EXPECT_TRUE(failed->error);
  EXPECT_NE(failed->text.find("cannot write '" + (dir / "out/frame_00000.vtp").string() + "'"), std::string::npos)
      << failed->text;
  EXPECT_FALSE(exports.running());
  stage->step(profiler);  // the simulation runs on
  EXPECT_FALSE(stage->divergence());

  auto ripples = createStage(loadScene(std::string(TIDEPOOL_TEST_DATA) + "/soak/ripples.json"), shaders());
  exports.settings() = {io::ExportFormat::Ply, 1, (dir / "ripples").string()};
  m = exports.start(*ripples);
  EXPECT_TRUE(m.error);
  EXPECT_NE(m.text.find("has no particles: --export ply"), std::string::npos) << m.text;
  auto blank = createStage(parseScene(io::parseJson(R"({"model": "blank"})", "b.json"), "b.json"), shaders());
  exports.settings().format = io::ExportFormat::Vtk;
  m = exports.start(*blank);
  EXPECT_TRUE(m.error);
  EXPECT_NE(m.text.find("has no particles"), std::string::npos) << m.text;
  EXPECT_FALSE(exports.running());
}

// The panel's "water surface": every K-th stepped frame is meshed and written as a surface file
// (a closed PLY with faces), the grid is checked at Start, and a model without water refuses.
TEST_F(WindowExportLogic, TheWaterSurfaceIsMeshedEveryKthFrame) {
  test::TempDir dir;
  auto stage = createStage(loadScene(std::string(TIDEPOOL_TEST_DATA) + "/soak/balls.json"), shaders());
  gl::GpuProfiler profiler;
  WindowExport exports(shaders());
  exports.settings() = {io::ExportFormat::Ply, 2, (dir / "out").string(), true, {.resolution = 32}};
  const WindowExport::Message started = exports.start(*stage);
  ASSERT_FALSE(started.error) << started.text;
  for (int i = 0; i < 4; ++i) {
    stage->step(profiler);
    const auto m = exports.afterFrame(*stage, true);
    ASSERT_FALSE(m) << m->text;
  }
  const WindowExport::Message stopped = exports.stop();
  ASSERT_FALSE(stopped.error) << stopped.text;
  EXPECT_EQ(exports.written(), 3);  // frames 0, 2, 4
  for (const char* f : {"surface_00000.ply", "surface_00002.ply", "surface_00004.ply"}) {
    const std::string ply = readText(dir / "out" / f);
    ASSERT_NE(ply.find("element face"), std::string::npos) << f;
    EXPECT_EQ(ply.find("element face 0\n"), std::string::npos) << f << ": an empty mesh";
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out/frame_00000.ply")) << "particles were not asked for";

  exports.settings().surfaceParams.resolution = 1;  // out of range: refused at Start, nothing written
  WindowExport::Message m = exports.start(*stage);
  EXPECT_TRUE(m.error);
  EXPECT_NE(m.text.find("resolution"), std::string::npos) << m.text;
  EXPECT_FALSE(exports.running());
  auto life = createStage(loadScene(kLife), shaders());
  exports.settings().surfaceParams.resolution = 32;
  m = exports.start(*life);
  EXPECT_TRUE(m.error);
  EXPECT_NE(m.text.find("has no water"), std::string::npos) << m.text;
}
