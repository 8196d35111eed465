// The original's domain controls on the balls: a static contraction lowers the top wall to
// min.z + contraction·height (the walls' z ≤ contraction − r in the unit cube), a ball above it
// is pushed below it on the GPU, and "Reset domain" brings rotation 0 and contraction 1 back.
#include <gtest/gtest.h>

#include "scene/balls_stage.h"
#include "scene/scene.h"
#include "sim/balls/balls.h"
#include "sim/water/water_frame.h"
#include "support/balls_fixtures.h"
#include "support/gl_test.h"
#include "support/null_visitor.h"

using namespace tidepool;
using namespace tidepool::balls;
using namespace tidepool::water;

namespace {
using BallsTest = test::GlTest;

// Presses the "Reset domain" button, as the panel does, and sees the contraction slider's range.
class PressReset final : public test::NullVisitor {
 public:
  bool action(const ParamInfo& info) override { return std::string(info.key) == "reset_domain"; }
  void real(const ParamInfo& info, float& value, float min, float max) override {
    if (std::string(info.key) == "contraction") range = {min, max, value};
  }
  glm::vec3 range{0.0f};
};
}  // namespace

TEST(BallsDomainWalls, ContractionLowersOnlyTheTopWall) {
  Params p = test::emptyBox(0.01f, glm::vec3(1.0f));
  p.contraction = 0.4f;
  Walls w = wallsAt(p, 0.0);
  EXPECT_EQ(w.min, glm::vec3(0.0f));
  EXPECT_EQ(w.max, glm::vec3(1.0f, 1.0f, 0.4f));
  p.domainMin = {-1.0f, -1.0f, -2.0f};
  p.domainMax = {1.0f, 1.0f, 2.0f};
  EXPECT_FLOAT_EQ(wallsAt(p, 0.0).max.z, -2.0f + 0.4f * 4.0f) << "a fraction of the domain's height";
  // With the piston on z the lower of the two holds the wall (and it stands still while it does).
  p = test::emptyBox(0.01f, glm::vec3(1.0f));
  p.pistonAxis = 3;
  p.pistonTravel = 0.8f;
  p.pistonPeriod = 4.0f;
  p.contraction = 0.5f;
  w = wallsAt(p, 1.0);  // the piston at 0.6
  EXPECT_FLOAT_EQ(w.max.z, 0.5f);
  EXPECT_EQ(w.maxVel.z, 0.0f);
  w = wallsAt(p, 2.0);  // the piston at 0.2, under the contraction
  EXPECT_NEAR(w.max.z, 0.2f, 1e-6f);
  p.contraction = 1.0f;
  EXPECT_NEAR(wallsAt(p, 1.0).max.z, 0.6f, 1e-6f) << "contraction 1 leaves the piston as it was";
}

TEST(BallsDomainWalls, ResetDomainRestoresRotationAndContraction) {
  Params p;
  p.rotation = 30.0f;
  p.rotationRate = 22.9f;
  p.contraction = 0.35f;
  p.pistonAxis = 3;
  PressReset press;
  visit(press, p);  // the walls group's button, through the one declaration
  const Params defaults;
  EXPECT_EQ(p.rotation, 0.0f);
  EXPECT_EQ(p.contraction, 1.0f);
  EXPECT_EQ(p.rotationRate, 0.0f);
  EXPECT_EQ(p.pistonAxis, 0);
  EXPECT_EQ(domainRotation(p, 12.0), 0.0f) << "the domain stays upright";
  EXPECT_EQ(wallsAt(p, 5.0).max, defaults.domainMax);
  EXPECT_EQ(press.range, glm::vec3(0.2f, 1.0f, 0.35f)) << "the original's slider: 0.2-1";
}

// A ball resting above the contracted wall: the step clamps it to the wall and the wall's
// contact (the spring-dashpot's and the seed's penalty) pushes it down, below contraction − r
// (no gravity), never letting it back above the wall.
TEST_F(BallsTest, ABallAboveTheContractedWallIsPushedBelowIt) {
  for (Contact contact : {Contact::SpringDashpot, Contact::Penalty}) {
    Params p = test::emptyBox(0.02f, glm::vec3(1.0f));
    p.contact = contact;
    p.gravity = glm::vec3(0.0f);
    p.substeps = 1;
    p.dt = 5e-4f;
    p.contraction = 0.5f;
    Balls b(shaders(), p);
    b.upload({glm::vec4(0.3f, 0.6f, 0.8f, 1.0f)}, {glm::vec4(0.0f)});
    EXPECT_FLOAT_EQ(b.wallMax().z, 0.5f);
    b.stepOnce();
    EXPECT_LE(b.downloadPositions()[0].z, 0.5f) << "clamped into the box at once";
    const float upper = 0.5f - p.radius;
    const char* law = kContactNames[std::size_t(contact)];
    int below = -1;  // the first step that leaves the ball under contraction - r
    for (int n = 1; n <= 200 && below < 0; ++n) {
      b.stepOnce();
      const glm::vec4 x = b.downloadPositions()[0], v = b.downloadVelocities()[0];
      ASSERT_LE(x.z, 0.5f) << law << ", step " << n << ": never above the wall";
      EXPECT_FLOAT_EQ(x.x, 0.3f) << "the other axes untouched";
      EXPECT_FLOAT_EQ(x.y, 0.6f);
      if (x.z < upper) {
        below = n;
        EXPECT_LT(v.z, 0.0f) << law << ": pushed down by the wall";
      }
    }
    EXPECT_GT(below, 0) << law << ": the wall pushes the ball below contraction - r within 0.1 s";
    // Contraction back to 1: the wall returns to the top and the ball is free to go on.
    b.params().contraction = 1.0f;
    b.stepOnce();
    EXPECT_FLOAT_EQ(b.wallMax().z, 1.0f);
  }
}

// The shipped scene with both of the original's animations: the box turns (90 degrees per s)
// and the top wall follows the original's Contract curve, 0.2 + 0.8 (0.5 + 0.5 cos(pi t)).
TEST(BallsDomainWalls, TheDomainAnimationSceneRotatesAndContracts) {
  const Params p = ballsParams(loadScene(resolveScenePath("domain-animation")));
  const double pi = 3.14159265358979;
  EXPECT_NEAR(domainRotation(p, 1.0), pi / 2, 1e-5);
  for (double t : {0.0, 0.3, 0.6, 1.0, 1.7}) {
    const double expected = 0.2 + 0.8 * (0.5 + 0.5 * std::cos(pi * t));
    EXPECT_NEAR(wallsAt(p, t).max.z, expected, 1e-5) << "t = " << t;
  }
}
