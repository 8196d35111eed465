// The obstacle mesher (render/obstacle_mesh.h) on shapes with known surfaces: closed and
// consistently wound, on the balls' outer surface, normals outward, no inner surface for a hollow
// shell. CPU only.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "render/obstacle_mesh.h"
#include "sim/water/water_init.h"

using namespace tidepool;

namespace {

constexpr float kRadius = 0.01f;

water::ObstacleParams sphereObstacle() {  // built about the origin, its own frame
  water::ObstacleParams o;
  o.shape = water::Shape::Sphere;
  o.size = glm::vec3(0.1f);
  return o;
}

}  // namespace

TEST(ObstacleMesh, NoBallsNoTriangles) { EXPECT_TRUE(ballUnionMesh({}, 0.01f).empty()); }

TEST(ObstacleMesh, SphereIsClosedOnTheBallsSurfaceWithOutwardNormals) {
  const float r = kRadius;
  const std::vector<MeshVertex> mesh = ballUnionMesh(water::Obstacle(sphereObstacle(), r).particles(), r);
  ASSERT_GT(mesh.size(), 300u);
  ASSERT_EQ(mesh.size() % 3, 0u);
  // Closed and consistently wound: each edge as often one way as the other (surface nets can
  // give an edge four quads where two parts of the surface touch).
  std::map<std::pair<std::tuple<float, float, float>, std::tuple<float, float, float>>, int> edges;
  const auto key = [](const glm::vec4& v) { return std::tuple(v.x, v.y, v.z); };
  for (std::size_t t = 0; t < mesh.size(); t += 3)
    for (int k = 0; k < 3; ++k) ++edges[{key(mesh[t + k].position), key(mesh[t + (k + 1) % 3].position)}];
  for (const auto& [edge, count] : edges) {
    const auto reverse = edges.find({edge.second, edge.first});
    ASSERT_TRUE(reverse != edges.end()) << "an open edge";
    ASSERT_EQ(reverse->second, count) << "an edge wound more often one way";
  }
  // The lattice's outermost centres lie up to a ball inside 0.1 m, their balls' tops at 0.1 + r:
  // the smoothed surface runs between the two (over the tops, through the dimples between).
  double mean = 0, meanFacing = 0;
  for (const MeshVertex& v : mesh) {
    const glm::vec3 out = glm::vec3(v.position);
    const float distance = glm::length(out);
    EXPECT_GT(distance, 0.1f + r - 2.0f * r);
    EXPECT_LT(distance, 0.1f + r + 0.5f * r);
    const float facing = glm::dot(glm::vec3(v.normal), out / distance);
    EXPECT_GT(facing, 0.0f) << "normal outward";
    meanFacing += facing;
    mean += distance;
  }
  EXPECT_GT(mean / double(mesh.size()), 0.1 - 0.5 * r);
  EXPECT_LT(mean / double(mesh.size()), 0.1 + r);
  EXPECT_GT(meanFacing / double(mesh.size()), 0.95) << "mean";
}

TEST(ObstacleMesh, AClosedHollowHasOnlyItsOuterSurface) {
  // Balls 1.5 r apart on a sphere of radius 0.1 m (a Fibonacci lattice): a closed skin around an
  // empty inside, which must not be meshed.
  const float r = 0.01f;
  const int count = 560;
  std::vector<glm::vec4> skin;
  for (int i = 0; i < count; ++i) {
    const float z = 1.0f - 2.0f * (float(i) + 0.5f) / float(count), ring = std::sqrt(1.0f - z * z);
    const float angle = 2.399963f * float(i);  // golden angle
    skin.emplace_back(0.1f * ring * std::cos(angle), 0.1f * ring * std::sin(angle), 0.1f * z, 0.0f);
  }
  const std::vector<MeshVertex> mesh = ballUnionMesh(skin, r);
  ASSERT_FALSE(mesh.empty());
  for (const MeshVertex& v : mesh) ASSERT_GT(glm::length(glm::vec3(v.position)), 0.1f) << "a vertex inside";
}
