// Balls scenes: the obstacle list loads item by item, and what is wrong in it is reported in one
// line naming the item by index.
#include <gtest/gtest.h>

#include "scene/balls_stage.h"
#include "scene/scene.h"
#include "support/error_of.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class BallsSceneObstacles : public test::GlTest {
 protected:
  // The error of loading a balls scene whose params are `params` and building its stage ("" if none).
  std::string errorOf(const std::string& params) {
    return test::errorOf([&] {
      Scene s = parseScene(io::parseJson(R"({"model": "balls", "params": )" + params + "}", "s.json"), "s.json");
      s.file = "s.json";
      createStage(s, shaders());
    });
  }
};

constexpr const char* kSmall = R"("particles": {"fill": "none", "radius": 0.02})";

std::string withObstacles(const std::string& list) {
  return std::string("{") + kSmall + ", \"obstacles\": " + list + "}";
}

}  // namespace

TEST_F(BallsSceneObstacles, ObstacleListLoadsEveryItem) {
  Scene s = parseScene(io::parseJson(R"({"model": "balls", "params": )" + withObstacles(R"([{"shape": "cup"},
          {"shape": "helix", "spin": 2, "spin_axis": [1, 0, 0]},
          {"shape": "box", "path": {"kind": "circle", "amplitude": [0.1, 0.2, 0], "period": 3, "phase": 90}}])") +
                                         "}",
                                     "s.json"),
                       "s.json");
  const balls::Params p = ballsParams(s);
  ASSERT_EQ(p.obstacles.size(), 3u);
  EXPECT_EQ(p.obstacles[0].shape, water::Shape::Cup);
  EXPECT_EQ(p.obstacles[1].spinAxis, glm::vec3(1, 0, 0));
  EXPECT_EQ(p.obstacles[2].path.kind, water::PathKind::Circle);
  EXPECT_FLOAT_EQ(p.obstacles[2].path.phase, 90.0f);
  EXPECT_EQ(p.obstacles[2].centre, water::ObstacleParams{}.centre) << "absent keys keep the defaults";
  EXPECT_EQ(errorOf(withObstacles("[]")), "");
}

TEST_F(BallsSceneObstacles, BadObstacleListsAreOneLineErrorsNamingTheItem) {
  EXPECT_EQ(errorOf(withObstacles(R"([{}, {}, {"size": [500, 0.1, 0.1]}])")),
            "s.json: params.obstacles[2].size[0] = 500 is out of range [0, 100]");
  EXPECT_EQ(errorOf(withObstacles(R"([{}, {"path": {"kind": "zigzag"}}])")),
            "s.json: params.obstacles[1].path.kind = 'zigzag' is not one of: none, oscillate, circle");
  EXPECT_EQ(errorOf(withObstacles(R"([{"path": {"period": 0}}])")),
            "s.json: params.obstacles[0].path.period = 0 is out of range [0.01, 1000]");
  EXPECT_EQ(
      errorOf(withObstacles(R"([{"centr": [0, 0, 0]}])"))
          .rfind("s.json: params.obstacles[0].centr: unknown key (known here: shape, mesh, shell, size, centre", 0),
      0u);
  EXPECT_EQ(errorOf(withObstacles(R"({"shape": "cup"})")),
            "s.json: params.obstacles: expected an array [{...}, ...], got object");
  EXPECT_EQ(errorOf(withObstacles(R"(["cup"])")), "s.json: params.obstacles[0]: expected an object {...}, got \"cup\"");
  std::string many = "[{}";
  for (int i = 0; i < 16; ++i) many += ", {}";
  EXPECT_EQ(errorOf(withObstacles(many + "]")), "s.json: params.obstacles: 17 items, at most 16");
  EXPECT_EQ(errorOf(withObstacles(R"([{}, {"shape": "mesh", "mesh": "nosuchmesh"}])"))
                .rfind("s.json: params: obstacles[1]: mesh 'nosuchmesh' not found", 0),
            0u);
  // The single obstacle of older scenes is now the list.
  EXPECT_EQ(errorOf(std::string("{") + kSmall + R"(, "obstacle": {"shape": "cup"}})")
                .rfind("s.json: params.obstacle: unknown key (known here: particles, engine, walls, tap, obstacles", 0),
            0u);
}
