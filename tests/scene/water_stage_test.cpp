// The water stage runs balls or fluid and switches between them keeping the particle set (the
// window's "Water model" choice, or the M key).
#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>
#include <regex>

#include "render/orbit_camera.h"
#include "render/target.h"
#include "scene/scene.h"
#include "scene/stage.h"
#include "support/gl_test.h"
#include "support/null_visitor.h"

using namespace tidepool;

namespace {

class WaterStage : public test::GlTest {};

// The first number of the status line: the particle count ("5000 balls + ...", "5000 particles + ...").
long countOf(const Stage& stage) {
  std::smatch m;
  const std::string status = stage.status();
  return std::regex_search(status, m, std::regex(R"((\d+) (balls|particles))")) ? std::stol(m[1]) : -1;
}

bool isFluid(const Stage& stage) { return stage.status().find("particles") != std::string::npos; }

// Sets the "water_model" choice as the UI would.
struct ChooseModel : test::NullVisitor {
  int index = 0;
  void choiceIndex(const ParamInfo& info, int& value, std::span<const char* const>) override {
    if (std::string(info.key) == "water_model") value = index;
  }
};

std::unique_ptr<Stage> small(gl::ShaderLibrary& shaders, const char* model) {
  const std::string params = std::string(model) == "balls"
                                 ? R"({"particles": {"radius": 0.02, "domain_max": [0.4, 0.2, 0.4], "fill": "block",
                                       "fill_max": [0.2, 0.2, 0.2]}})"
                                 : R"({"particles": {"spacing": 0.04, "domain_max": [0.4, 0.2, 0.4], "fill": "block",
                                       "fill_max": [0.2, 0.2, 0.2]}})";
  Scene s = parseScene(
      io::parseJson(std::string(R"({"model": ")") + model + R"(", "params": )" + params + "}", "w.json"), "w.json");
  return createStage(s, shaders);
}

double probe(const ProbeReadings& r, const std::string& column) {
  for (std::size_t i = 0; i < r.columns.size(); ++i)
    if (r.columns[i] == column) return r.values[i];
  return NAN;
}

// A tank 0.4 × 0.2 × 0.4 m of `model` (fluid of d = 0.02, or balls of r = 0.01; 20 ms a frame),
// water in the corner up to `fillMax`, one dynamic obstacle (`obstacle`, JSON) with its body
// probe, seen from −y by a camera 0.6 m from `target`, rendered once at 64 × 32; `camera` is that
// camera, to cast the same rays as the stage.
struct SideView {
  std::unique_ptr<Stage> stage;
  OrbitCamera camera;
};
SideView sideView(gl::ShaderLibrary& shaders, const std::string& fillMax, const std::string& obstacle, glm::vec3 target,
                  const std::string& model = "fluid") {
  const bool balls = model == "balls";
  const std::string at =
      "[" + std::to_string(target.x) + ", " + std::to_string(target.y) + ", " + std::to_string(target.z) + "]";
  const std::string scene =
      R"({"model": ")" + model + R"(", "params": {"particles": {)" +
      (balls ? R"("radius": 0.01)" : R"("spacing": 0.02)") +
      R"(, "domain_max": [0.4, 0.2, 0.4], "fill": "block", "fill_max": )" + fillMax + R"(}, "engine": )" +
      (balls ? R"({"dt": 0.0005, "substeps": 40})" : R"({"dt": 0.002, "substeps": 10})") + R"(, "obstacles": [)" +
      obstacle + R"(], "probes": [{"kind": "body", "obstacle": 0}], "view": {"camera": {"target": )" + at +
      R"(, "distance": 0.6, "yaw": -1.5707963, "pitch": 0}}}})";
  SideView v{createStage(parseScene(io::parseJson(scene, "w.json"), "w.json"), shaders), {}};
  gl::GpuProfiler profiler;
  RenderTarget frame(64, 32);
  v.stage->render(frame, profiler);
  v.camera.params().target = target;
  v.camera.params().distance = 0.6f;
  v.camera.params().yaw = -1.5707963f;
  v.camera.params().pitch = 0.0f;
  return v;
}

}  // namespace

TEST_F(WaterStage, SwitchingBetweenBallsAndFluidKeepsTheParticles) {
  for (const char* start : {"balls", "fluid"}) {
    SCOPED_TRACE(start);
    std::unique_ptr<Stage> stage = small(shaders(), start);
    gl::GpuProfiler profiler;
    for (int i = 0; i < 3; ++i) stage->step(profiler);
    const long before = countOf(*stage);
    ASSERT_GT(before, 0);
    const bool wasFluid = isFluid(*stage);
    EXPECT_EQ(wasFluid, std::string(start) == "fluid");
    EXPECT_EQ(stage->running(), start);                  // as the window's title says it
    stage->key('M');                                     // the next step switches
    for (int i = 0; i < 10; ++i) stage->step(profiler);  // and the other model runs on with them
    EXPECT_NE(isFluid(*stage), wasFluid) << stage->status();
    EXPECT_EQ(stage->running(), wasFluid ? "balls" : "fluid");
    EXPECT_EQ(countOf(*stage), before) << stage->status();
    ChooseModel back;  // and back through the UI's choice
    back.index = wasFluid ? 1 : 0;
    stage->visitParams(back);
    stage->step(profiler);
    EXPECT_EQ(isFluid(*stage), wasFluid) << stage->status();
    EXPECT_EQ(countOf(*stage), before);
    EXPECT_FALSE(stage->divergence().has_value());
  }
}

// A left drag that starts on a dynamic body pulls it with the mouse (balls and fluid): from the
// side, the cursor moved up 6 pixels lifts the point picked on the box off the floor to the
// mouse's point at the depth where it was picked (within 5 mm), and the camera stays put.
// Released, a left drag turns the camera again.
TEST_F(WaterStage, ALeftDragOnABodyPullsItAndElsewhereTurnsTheCamera) {
  for (const char* model : {"fluid", "balls"}) {
    SCOPED_TRACE(model);
    SideView side = sideView(shaders(), "[0.1, 0.2, 0.1]",
                             R"({"shape": "box", "size": [0.04, 0.04, 0.03], "centre": [0.28, 0.1, 0.045],
                               "dynamic": true, "density": 800})",
                             {0.28f, 0.1f, 0.045f}, model);
    Stage* stage = side.stage.get();
    const OrbitCamera& camera = side.camera;
    gl::GpuProfiler profiler;
    // The body's pose from its probe: where the point `own` (from the pose's origin) is in the world.
    auto placed = [&](glm::dvec3 own) {
      const ProbeReadings r = stage->probes();
      const glm::dquat q(probe(r, "body0_qw"), probe(r, "body0_qx"), probe(r, "body0_qy"), probe(r, "body0_qz"));
      return glm::dvec3(probe(r, "body0_x_m"), probe(r, "body0_y_m"), probe(r, "body0_z_m")) + q * own;
    };
    const glm::dvec3 origin = placed(glm::dvec3(0.0));
    const std::optional<glm::mat4> view = stage->indicators().view;
    ASSERT_TRUE(view);
    Input in;
    in.viewport = {64, 32};
    in.cursor = {32, 16};
    in.left = true;
    stage->input(in);  // picked: a point of the box's face, on this ray
    auto ray = [&](double depth) {
      return glm::dvec3(camera.rayOrigin(in.cursor, in.viewport)) +
             depth * glm::dvec3(camera.rayDirection(in.cursor, in.viewport));
    };
    std::vector<glm::dvec3> picked;  // where it may be: the face is 0.56 m away, its particles' spheres up to 0.58
    for (double depth = 0.55; depth <= 0.6; depth += 0.001) picked.push_back(ray(depth));
    in.cursor = {32, 10};
    in.cursorDelta = {0, -6};
    for (int i = 0; i < 40; ++i) {
      stage->input(in);
      in.cursorDelta = {0, 0};
      stage->step(profiler);
    }
    // The point picked, carried by the body, against the new ray's point at the same depth; the pull
    // leaves it g dt τ = 2 mm below it.
    double closest = 1e30, lift = 0;
    for (std::size_t i = 0; i < picked.size(); ++i) {
      const glm::dvec3 held = placed(picked[i] - origin), want = ray(0.55 + 0.001 * double(i));
      if (glm::distance(held, want) < closest) {
        closest = glm::distance(held, want);
        lift = held.z - picked[i].z;
      }
    }
    std::printf("the picked point %.4f m from the mouse's at its depth, lifted %.4f m\n", closest, lift);
    EXPECT_LT(closest, 0.005);
    EXPECT_GT(lift, 0.08) << "not lifted";
    EXPECT_EQ(stage->indicators().view, view) << "the drag turned the camera";
    // Released; a drag from empty space turns the camera.
    in.left = false;
    stage->input(in);
    in.cursor = {2, 2};
    in.left = true;
    stage->input(in);
    in.cursor = {12, 2};
    in.cursorDelta = {10, 0};
    stage->input(in);
    EXPECT_NE(stage->indicators().view, view);
  }
}

// A hinged body dragged turns about its hinge: a plank hinged about y through its centre, seen
// along the axis, picked 4 pixels right of it and pulled 4 pixels up, turns until the point picked
// points at the mouse's (45°, within 3°), its centre still on the axis (within 1 mm).
TEST_F(WaterStage, ADraggedHingedBodyTurnsAboutItsHinge) {
  SideView side = sideView(shaders(), "[0.06, 0.2, 0.06]",
                           R"({"shape": "box", "size": [0.08, 0.03, 0.01], "centre": [0.2, 0.1, 0.2],
                               "dynamic": true, "density": 800, "hinge": {"axis": [0, 1, 0]}})",
                           {0.2f, 0.1f, 0.2f});
  Stage* stage = side.stage.get();
  const OrbitCamera& camera = side.camera;
  gl::GpuProfiler profiler;
  Input in;
  in.viewport = {64, 32};
  in.cursor = {36, 16};
  in.left = true;
  // Where the rays meet the plane of the axis (y = 0.1): the pick and the target, about.
  auto onPlane = [&] {
    const glm::vec3 o = camera.rayOrigin(in.cursor, in.viewport), d = camera.rayDirection(in.cursor, in.viewport);
    return o + d * ((0.1f - o.y) / d.y);
  };
  const glm::vec3 picked = onPlane();
  stage->input(in);
  in.cursor = {36, 12};
  for (int i = 0; i < 40; ++i) {
    stage->input(in);
    stage->step(profiler);
  }
  const glm::vec3 pulled = onPlane();
  const ProbeReadings r = stage->probes();
  const double turned = glm::degrees(-2.0 * std::atan2(probe(r, "body0_qy"), probe(r, "body0_qw")));
  const double want = glm::degrees(std::atan2(pulled.z - 0.2, picked.x - 0.2));
  std::printf("turned %.2f degrees up, the mouse's point %.2f degrees above the axis\n", turned, want);
  EXPECT_NEAR(turned, want, 3.0);
  EXPECT_NEAR(probe(r, "body0_x_m"), 0.2, 1e-3);
  EXPECT_NEAR(probe(r, "body0_z_m"), 0.2, 1e-3);
}
