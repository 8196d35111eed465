// Mesh obstacles: the voxelised cube equals the analytic box fill on the same lattice, an
// icosphere fills like the analytic sphere, shells hug the surface, rows through the mesh's own
// edges count right, bad meshes are refused with the reason, and a ball dropped on a mesh
// obstacle (solid or shell) never gets inside it.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "base/error.h"
#include "sim/balls/balls.h"
#include "sim/water/mesh_solid.h"
#include "sim/water/obstacle_pose.h"
#include "sim/water/water_init.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;
using namespace tidepool::water;

namespace {

io::TriangleMesh icosphere(int subdivisions) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  io::TriangleMesh m;
  m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (glm::vec3& v : m.vertices) v = glm::normalize(v);
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<unsigned, unsigned>, unsigned> middle;
    auto mid = [&](unsigned a, unsigned b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      if (auto it = middle.find(key); it != middle.end()) return it->second;
      m.vertices.push_back(glm::normalize(m.vertices[a] + m.vertices[b]));
      return middle[key] = unsigned(m.vertices.size() - 1);
    };
    std::vector<glm::uvec3> next;
    for (const glm::uvec3& f : m.triangles) {
      const unsigned a = mid(f.x, f.y), b = mid(f.y, f.z), c = mid(f.z, f.x);
      next.insert(next.end(), {{f.x, a, c}, {f.y, b, a}, {f.z, c, b}, {a, b, c}});
    }
    m.triangles = next;
  }
  return m;
}

io::TriangleMesh cubeMesh() { return io::readObj(io::findMesh("cube")); }

float surfaceDistance(const io::TriangleMesh& m, glm::vec3 q) {
  float best = 1e30f;
  for (const glm::uvec3& t : m.triangles)
    best = std::min(best, pointTriangleDistance(q, m.vertices[t.x], m.vertices[t.y], m.vertices[t.z]));
  return best;
}

ObstacleParams shape(Shape kind, glm::vec3 centre, glm::vec3 size) {
  ObstacleParams o;
  o.shape = kind;
  o.centre = centre;
  o.size = size;
  return o;
}

ObstacleParams meshShape(const std::string& mesh, glm::vec3 centre, glm::vec3 size) {
  ObstacleParams o = shape(Shape::Mesh, centre, size);
  o.mesh = mesh;
  return o;
}

Params meshObstacle(const std::string& mesh, glm::vec3 centre, glm::vec3 size, float r) {
  Params p;
  p.radius = r;
  p.obstacles = {meshShape(mesh, centre, size)};
  return p;
}

// Obstacle k's mesh where the model placed it.
io::TriangleMesh placedMesh(const Balls& b, std::size_t k) {
  io::TriangleMesh m = *b.obstacles().body(k).mesh;
  for (glm::vec3& v : m.vertices) v = b.obstacles().pose(k).place(v);
  return m;
}

class MeshObstacle : public test::GlTest {};

}  // namespace

TEST(MeshVoxels, CubeMeshFillsLikeTheAnalyticBoxOnTheSameLattice) {
  for (const float r : {0.01f, 0.0137f}) {
    SCOPED_TRACE(r);
    const glm::vec3 c(0.43f, 0.52f, 0.37f), s(0.11f);
    const std::vector<glm::vec4> analytic = Obstacle(shape(Shape::Box, c, s), r).particles();
    const MeshSolid solid(placeMesh(cubeMesh(), c, s, glm::mat3(1.0f)));
    const std::vector<glm::vec3> voxels = meshLatticePoints(solid, r, false);
    // Lattice points lie on the x faces (the lattice starts r outside them): those may go either
    // way in float arithmetic. Every point clearly inside is in both, none clearly outside is.
    std::size_t clearlyInside = 0, possiblyInside = 0;
    for (const glm::vec3& q : hcpLattice(c - s - r, c + s + r, r)) {
      const glm::vec3 d = glm::abs(q - c);
      clearlyInside += glm::all(glm::lessThan(d, s - 1e-5f));
      possiblyInside += glm::all(glm::lessThanEqual(d, s + 1e-5f));
    }
    ASSERT_GT(clearlyInside, 300u);
    EXPECT_GE(voxels.size(), clearlyInside);
    EXPECT_LE(voxels.size(), possiblyInside);
    EXPECT_GE(analytic.size(), clearlyInside);
    EXPECT_LE(analytic.size(), possiblyInside);
    for (const glm::vec3& q : voxels) EXPECT_TRUE(glm::all(glm::lessThanEqual(glm::abs(q - c), s + 1e-5f)));
    std::printf("r = %g: cube mesh %zu, analytic box %zu, clearly inside %zu, on the faces %zu\n", r, voxels.size(),
                analytic.size(), clearlyInside, possiblyInside - clearlyInside);
  }
}

TEST(MeshVoxels, RowsThroughEdgesAndVerticesCountEachCrossingOnce) {
  // The cube [-1, 1]^3: rows along x at y, z on its face diagonals (y = z), edges and corners.
  // A row on the boundary is decided as if shifted by (+ε, +ε²) in (y, z): rows on the low faces
  // are inside, rows on the high faces outside; never a lone crossing that inverts the row.
  const MeshSolid solid(cubeMesh());
  for (float y : {-1.0f, -0.5f, 0.0f, 0.25f, 0.999f})
    for (float z : {-1.0f, -0.5f, 0.0f, 0.25f, 0.999f}) {
      SCOPED_TRACE(testing::Message() << "y " << y << " z " << z);
      EXPECT_TRUE(solid.inside({0.0f, y, z}));
      EXPECT_TRUE(solid.inside({-1.0f, y, z}));
      EXPECT_TRUE(solid.inside({1.0f, y, z}));
      EXPECT_FALSE(solid.inside({1.001f, y, z}));
      EXPECT_FALSE(solid.inside({-1.001f, y, z}));
      EXPECT_FALSE(solid.inside({0.0f, 1.0f, z}));
      EXPECT_FALSE(solid.inside({0.0f, y, 1.0f}));
    }
  EXPECT_FALSE(solid.inside({0.0f, 1.001f, 0.0f}));
  EXPECT_FALSE(solid.inside({0.0f, 0.0f, -1.001f}));
  // The cube turned 45° about z: rows through its vertical edges and in the planes of its lids.
  const MeshSolid turned(placeMesh(cubeMesh(), glm::vec3(0.0f), glm::vec3(1.0f), orientationMatrix({0, 0, 45})));
  const float h = std::sqrt(2.0f);
  EXPECT_TRUE(turned.inside({0.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(turned.inside({0.0f, h * 0.999f, 0.5f}));
  EXPECT_FALSE(turned.inside({0.0f, h * 1.001f, 0.5f}));
  EXPECT_TRUE(turned.inside({0.5f * h, 0.0f, -1.0f}));
  EXPECT_FALSE(turned.inside({0.5f * h, -h * 0.999f, 0.0f})) << "near the edge at y = -√2, but beside it";
  EXPECT_FALSE(turned.inside({0.5f * h, 0.0f, 1.0f}));
}

TEST(MeshVoxels, IcosphereFillsLikeTheAnalyticSphere) {
  const float r = 0.01f, radius = 0.15f;
  const glm::vec3 c(0.5f, 0.45f, 0.4f);
  const std::size_t analytic = Obstacle(shape(Shape::Sphere, c, glm::vec3(radius)), r).particles().size();
  const io::TriangleMesh ico = icosphere(3);  // 1280 faces, vertices on the sphere
  const std::size_t voxels =
      meshLatticePoints(MeshSolid(placeMesh(ico, c, glm::vec3(radius), glm::mat3(1.0f))), r, false).size();
  // HCP: one ball per 4√2 r³ of volume.
  const double ideal = 4.0 / 3.0 * 3.14159265 * std::pow(radius, 3) / (4.0 * std::sqrt(2.0) * std::pow(r, 3));
  std::printf("icosphere %zu, analytic sphere %zu, volume / cell %.0f\n", voxels, analytic, ideal);
  // The README's "within 0.4%": 2482 points against 2490 (0.32% fewer). The icosphere's flat faces
  // lie inside its sphere (0.86% less volume); few lattice points fall in the sliver between them.
  EXPECT_NEAR(double(voxels) / double(analytic), 1.0, 0.004);
  EXPECT_NEAR(double(voxels) / ideal, 1.0, 0.04);
}

TEST(MeshVoxels, ShellPointsHugTheSurfaceAndCoverTheSolidsOuterLayer) {
  const float r = 0.01f;
  const glm::vec3 c(0.5f, 0.5f, 0.3f);
  const io::TriangleMesh torus = placeMesh(io::readObj(io::findMesh("torus")), c, glm::vec3(0.2f), glm::mat3(1.0f));
  const MeshSolid solid(torus);
  const std::vector<glm::vec3> shell = meshLatticePoints(solid, r, true);
  const std::vector<glm::vec3> fill = meshLatticePoints(solid, r, false);
  ASSERT_GT(shell.size(), 200u);
  for (const glm::vec3& q : shell) ASSERT_LE(surfaceDistance(torus, q), kShellHalfWidth * r * 1.0001f);
  // The solid's lattice points within r of the surface are all in the shell (the same lattice).
  std::size_t outer = 0;
  for (const glm::vec3& q : fill) {
    if (surfaceDistance(torus, q) > r) continue;
    ++outer;
    float nearest = 1e30f;
    for (const glm::vec3& s : shell) nearest = std::min(nearest, glm::length(s - q));
    ASSERT_LT(nearest, 1e-5f) << "solid point " << q.x << " " << q.y << " " << q.z << " missing from the shell";
  }
  EXPECT_GT(outer, 100u);
  // The torus (major 0.2/1.4·1, tube 0.2/1.4·0.4) fills to its volume 2π²Rρ² at one ball per 4√2 r³.
  const double major = 0.2 / 1.4, tube = 0.4 * 0.2 / 1.4;
  const double ideal = 2 * 9.8696 * major * tube * tube / (4 * std::sqrt(2.0) * r * r * r);
  EXPECT_NEAR(double(fill.size()) / ideal, 1.0, 0.05) << fill.size() << " vs " << ideal;
}

TEST(MeshVoxels, OrientationTurnsTheBodyAboutItsCentre) {
  // The particles are built once in the obstacle's own frame; its pose turns them (and its mesh).
  const float r = 0.01f;
  ObstacleParams o = meshShape("torus", glm::vec3(0.5f), glm::vec3(0.2f));
  o.orientation = glm::vec3(90.0f, 0.0f, 0.0f);  // ring upright in the xz plane
  const Obstacle torus(o, r);
  const ObstaclePose pose = obstaclePose(o, 0.0);
  const std::vector<glm::vec4> points = torus.particles();
  ASSERT_GT(points.size(), 500u);
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& v : torus.mesh()->vertices) {
    lo = glm::min(lo, pose.place(v) - 0.5f);
    hi = glm::max(hi, pose.place(v) - 0.5f);
  }
  EXPECT_NEAR(hi.x, 0.2f, 1e-4f);
  EXPECT_NEAR(hi.z, 0.2f, 1e-4f);
  EXPECT_NEAR(hi.y, 0.2f * 0.4f / 1.4f, 1e-3f);
  EXPECT_NEAR(lo.z, -0.2f, 1e-4f);
  for (const glm::vec4& q : points) {
    // Distance from the tube's centre circle (radius 0.2/1.4 in the xz plane about the centre).
    const glm::vec3 d = pose.place(glm::vec3(q)) - 0.5f;
    const float ring = glm::length(glm::vec2(glm::length(glm::vec2(d.x, d.z)) - 0.2f / 1.4f, d.y));
    ASSERT_LE(ring, 0.4f * 0.2f / 1.4f + 1e-4f);
  }
  // Analytic shapes turn too: a box of half extents (0.2, 0.05, 0.1) turned 90° about z.
  ObstacleParams box = shape(Shape::Box, glm::vec3(0.5f), glm::vec3(0.2f, 0.05f, 0.1f));
  box.orientation = glm::vec3(0.0f, 0.0f, 90.0f);
  const Obstacle turnedBox(box, r);
  const ObstaclePose turned = obstaclePose(box, 0.0);
  EXPECT_TRUE(turnedBox.inside(turned.toBody(glm::vec3(0.5f, 0.68f, 0.5f))));
  EXPECT_FALSE(turnedBox.inside(turned.toBody(glm::vec3(0.68f, 0.5f, 0.5f))));
  for (const glm::vec4& q : turnedBox.particles())
    ASSERT_LE(std::abs(turned.place(glm::vec3(q)).x - 0.5f), 0.05f + 1e-4f);
}

TEST(MeshVoxels, BadMeshesAreRefusedWithTheReason) {
  auto error = [](const Params& p) {
    try {
      Obstacle o(p.obstacles[0], p.radius);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error(meshObstacle("/nonexistent/m.obj", glm::vec3(0.5f), glm::vec3(0.1f), 0.01f)),
            "file not found: '/nonexistent/m.obj'");
  EXPECT_EQ(error(meshObstacle("nosuchmesh", glm::vec3(0.5f), glm::vec3(0.1f), 0.01f))
                .rfind("mesh 'nosuchmesh' not found: neither a file nor a name in assets/meshes", 0),
            0u);
  test::TempDir dir;
  dir.write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");  // no lid
  Params open = meshObstacle((dir / "open.obj").string(), glm::vec3(0.5f), glm::vec3(0.1f), 0.01f);
  EXPECT_EQ(error(open),
            "mesh '" + open.obstacles[0].mesh +
                "' is not closed: 3 edges belong to one triangle only (a hole); the first at vertices 2-3: "
                "a solid fill needs a closed mesh; fix the mesh or make the obstacle a shell");
  open.obstacles[0].shell = true;
  EXPECT_EQ(error(open), "") << "a shell needs no closed mesh";
  EXPECT_GT(Obstacle(open.obstacles[0], open.radius).particles().size(), 50u);
}

TEST_F(MeshObstacle, BallsDroppedOnItNeverGetInside) {
  for (const bool shell : {false, true}) {
    for (const char* mesh : {"cube", "torus", "blob"}) {
      SCOPED_TRACE(testing::Message() << mesh << (shell ? " shell" : " solid"));
      Params p = meshObstacle(mesh, glm::vec3(0.3f, 0.3f, 0.15f), glm::vec3(0.12f), 0.01f);
      p.obstacles[0].shell = shell;
      p.domainMax = glm::vec3(0.6f);
      p.fill = Fill::None;
      p.dt = 2e-4f;
      p.contactTime = 0.004f;  // 20 steps a contact
      p.restitution = 0.3f;
      p.friction = 0.5f;  // without it they slide off the lattice's bumps
      Balls b(shaders(), p);
      ASSERT_GT(b.obstacleCount(), 100u);
      const MeshSolid solid(placedMesh(b, 0));
      std::vector<glm::vec4> pos, vel;
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {  // over the top, from 0.2 m: 2 m/s at impact, 0.4 mm a step
          pos.emplace_back(0.3f + 0.06f * float(i - 1), 0.3f + 0.06f * float(j - 1), 0.47f, 1.0f);
          vel.emplace_back(0.0f);
        }
      b.upload(pos, vel);
      std::size_t touched = 0;
      for (int n = 0; n < 2000; ++n) {  // 0.4 s
        b.stepOnce();
        for (const glm::vec4& q : b.downloadPositions()) {
          ASSERT_FALSE(solid.inside(glm::vec3(q))) << "step " << n << ": a ball at " << q.x << " " << q.y << " " << q.z;
          if (n == 1999 && surfaceDistance(solid.mesh(), glm::vec3(q)) < 4.0f * p.radius) ++touched;
        }
      }
      if (std::string(mesh) == "cube") EXPECT_EQ(touched, 9u) << "all nine rest on the cube's top face";
      for (const glm::vec4& q : b.downloadPositions()) EXPECT_GT(q.z, 0.0f);
    }
  }
}

TEST_F(MeshObstacle, EditingTheMeshWhileRunningRebuildsItOrRefusesTheEdit) {
  Params p;
  p.fill = Fill::None;
  p.domainMax = glm::vec3(0.6f);
  Balls b(shaders(), p);
  EXPECT_EQ(b.obstacles().size(), 0u);
  b.params().obstacles = {meshShape("cube", glm::vec3(0.3f), glm::vec3(0.1f))};  // added
  b.stepOnce();
  ASSERT_EQ(b.obstacles().size(), 1u);
  ASSERT_NE(b.obstacles().body(0).mesh, nullptr);
  EXPECT_EQ(b.obstacles().body(0).mesh->triangles.size(), 12u);
  const std::size_t cube = b.obstacleCount();
  const unsigned id = b.obstacles().body(0).id;
  EXPECT_GT(cube, 500u);
  b.params().obstacles[0].mesh = "no-such-mesh";  // refused: the cube stays
  b.stepOnce();
  EXPECT_EQ(b.obstacleCount(), cube);
  EXPECT_EQ(b.obstacles().body(0).id, id);
  EXPECT_EQ(b.params().obstacles[0].mesh, "cube") << "the refused edit is undone";
  EXPECT_EQ(b.obstacleError().rfind("obstacles[0] not changed: mesh 'no-such-mesh' not found", 0), 0u)
      << b.obstacleError();
  b.params().obstacles[0].orientation = glm::vec3(0.0f, 0.0f, 45.0f);  // turned: placed, not rebuilt
  b.stepOnce();
  EXPECT_EQ(b.obstacles().body(0).id, id);
  EXPECT_EQ(b.obstacleCount(), cube);
  EXPECT_NEAR(placedMesh(b, 0).boundsMax().x, 0.3f + 0.1f * std::sqrt(2.0f), 1e-4f);
  b.params().obstacles[0].centre = glm::vec3(0.25f, 0.3f, 0.3f);  // moved
  b.stepOnce();
  EXPECT_NEAR(placedMesh(b, 0).boundsMax().x, 0.25f + 0.1f * std::sqrt(2.0f), 1e-4f);
  b.params().obstacles[0].mesh = "torus";  // reshaped: rebuilt, and the error is gone
  b.stepOnce();
  EXPECT_TRUE(b.obstacleError().empty());
  EXPECT_NE(b.obstacles().body(0).id, id);
  b.params().obstacles.clear();  // removed
  b.stepOnce();
  EXPECT_EQ(b.obstacleCount(), 0u);
  EXPECT_EQ(b.obstacles().size(), 0u);
}
