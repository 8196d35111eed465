// OBJ meshes: every face form, fan triangulation, negative indices, one-line errors naming file
// and line, the closedness check, and the meshes shipped in assets/meshes.
#include <gtest/gtest.h>

#include "base/error.h"
#include "io/assets.h"
#include "io/obj.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

// The message of the Error that parsing `text` throws, or "" if it parses.
std::string parseError(const std::string& text) {
  try {
    io::parseObj(text, "t.obj");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

const char* kCube =
    "v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";

}  // namespace

TEST(Obj, EveryFaceFormCommentsAndIgnoredLines) {
  const io::TriangleMesh m = io::parseObj(
      "# a comment line\n"
      "o thing\r\n"
      "v 0 0 0\n"
      "v 1 0 0   # trailing comment\n"
      "v 0 1 0\n"
      "v +1 1 0.5 1.0\n"  // a sign and an optional w
      "vt 0 0\nvn 0 0 1\ns off\ng group\nusemtl stone\n"
      "\n"
      "f 1 2 3\n"
      "f 1/1 2/1 3/1\n"
      "f 1/1/1 2/1/1 3/1/1\n"
      "f 1//1 2//1 3//1\n"
      "f -4 -3 -2\n"
      "f\t2 4 3\n",
      "t.obj");
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.vertices[3], glm::vec3(1.0f, 1.0f, 0.5f));
  ASSERT_EQ(m.triangles.size(), 6u);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(m.triangles[k], glm::uvec3(0, 1, 2)) << "face " << k;
  EXPECT_EQ(m.triangles[5], glm::uvec3(1, 3, 2));
  EXPECT_EQ(m.boundsMin(), glm::vec3(0.0f));
  EXPECT_EQ(m.boundsMax(), glm::vec3(1.0f, 1.0f, 0.5f));
}

TEST(Obj, PolygonsAreFanTriangulatedAndDegenerateCornersDropped) {
  const io::TriangleMesh m =
      io::parseObj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0.5 0\nf 1 2 3 4 5\nf 1 1 2\n", "t.obj");
  ASSERT_EQ(m.triangles.size(), 3u) << "a pentagon makes three triangles; 'f 1 1 2' has no area";
  EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
  EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
  EXPECT_EQ(m.triangles[2], glm::uvec3(0, 3, 4));
}

TEST(Obj, ErrorsNameFileAndLine) {
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(parseError("v 0 0 0\nv 1 x 0\n"), "t.obj:2: bad number 'x' in vertex");
  EXPECT_EQ(parseError("v 0 0 0\nv 1 0\n"), "t.obj:2: a vertex needs x y z ('v 0 1 0')");
  EXPECT_EQ(parseError("v 1e999 0 0\n"), "t.obj:1: bad number '1e999' in vertex");
  EXPECT_EQ(parseError("v 0 nan 0\n"), "t.obj:1: bad number 'nan' in vertex");
  EXPECT_EQ(parseError(three + "f 1 2 9\n"), "t.obj:4: vertex index 9 out of range (3 defined so far)");
  EXPECT_EQ(parseError(three + "f 1 2 -4\n"), "t.obj:4: vertex index -4 out of range (3 defined so far)");
  EXPECT_EQ(parseError(three + "f 0 1 2\n"), "t.obj:4: vertex index 0 out of range (3 defined so far)");
  EXPECT_EQ(parseError("f 1 2 3\n" + three), "t.obj:1: vertex index 1 out of range (0 defined so far)");
  EXPECT_EQ(parseError(three + "f 1 2\n"), "t.obj:4: a face needs at least 3 vertices ('f 1 2 3')");
  EXPECT_EQ(parseError(three + "f 1 two 3\n"), "t.obj:4: bad index 'two' in face");
  EXPECT_EQ(parseError(three + "f 1/x 2 3\n"), "t.obj:4: bad index 'x' in face");
  EXPECT_EQ(parseError(three + "f 1/1/1/1 2 3\n"), "t.obj:4: bad face corner '1/1/1/1' (v, v/vt, v/vt/vn or v//vn)");
  EXPECT_EQ(parseError(three), "t.obj: no triangles (an OBJ mesh needs 'f' lines)");
  EXPECT_EQ(parseError("# empty\n"), "t.obj: no triangles (an OBJ mesh needs 'f' lines)");
  try {
    io::readObj("/nonexistent/mesh.obj");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "file not found: '/nonexistent/mesh.obj'");
  }
  test::TempDir dir;
  dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n");
  try {
    io::readObj(dir / "bad.obj");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "bad.obj").string() + ":4: vertex index 4 out of range (3 defined so far)");
  }
}

TEST(Obj, ClosedMeshesShareEveryEdgeBetweenTwoTriangles) {
  io::TriangleMesh cube = io::parseObj(kCube, "cube.obj");
  ASSERT_EQ(cube.triangles.size(), 12u);
  io::EdgeCheck check = io::checkClosed(cube);
  EXPECT_TRUE(check.closed()) << check.describe();
  EXPECT_EQ(check.edges, 18u) << "12 cube edges and 6 face diagonals";
  EXPECT_EQ(check.describe(), "closed (18 edges, each shared by two triangles)");

  io::TriangleMesh holed = cube;
  holed.triangles.pop_back();  // half of the +x face gone: a triangular hole
  check = io::checkClosed(holed);
  EXPECT_FALSE(check.closed());
  EXPECT_EQ(check.boundaryEdges, 3u);
  EXPECT_EQ(check.nonManifoldEdges, 0u);
  EXPECT_EQ(
      check.describe().rfind("not closed: 3 edges belong to one triangle only (a hole); the first at vertices ", 0), 0u)
      << check.describe();

  io::TriangleMesh fin = cube;
  fin.vertices.emplace_back(0.0f, 0.0f, 3.0f);
  fin.triangles.emplace_back(4, 5, 8);  // a fin on the edge 5-6 of the top face
  check = io::checkClosed(fin);
  EXPECT_EQ(check.nonManifoldEdges, 1u);
  EXPECT_EQ(check.boundaryEdges, 2u);
  EXPECT_NE(check.describe().find("1 edges are shared by three or more triangles"), std::string::npos);

  // Vertices repeated at one position (a texture seam) still close the surface.
  io::TriangleMesh seam = cube;
  seam.vertices.push_back(seam.vertices[0]);
  seam.triangles[0].x = 8;
  EXPECT_TRUE(io::checkClosed(seam).closed()) << io::checkClosed(seam).describe();
}

TEST(Obj, ShippedMeshesAreClosedAndFoundByName) {
  for (const char* name : {"cube", "torus", "blob", "paddle-wheel"}) {
    SCOPED_TRACE(name);
    const std::filesystem::path path = io::findMesh(name);
    EXPECT_EQ(path, io::findAssetDir() / "meshes" / (std::string(name) + ".obj"));
    const io::TriangleMesh m = io::readObj(path);
    EXPECT_GE(m.triangles.size(), 12u);
    EXPECT_TRUE(io::checkClosed(m).closed()) << io::checkClosed(m).describe();
  }
  EXPECT_EQ(io::findMesh("torus.obj"), io::findAssetDir() / "meshes" / "torus.obj");
  EXPECT_EQ(io::findMesh("/any/absolute.obj"), "/any/absolute.obj") << "absolute paths are taken as given";
  try {
    io::findMesh("teapot");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(
        std::string(e.what()).rfind("mesh 'teapot' not found: neither a file nor a name in assets/meshes (known: ", 0),
        0u)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("blob, cube, paddle-wheel, torus"), std::string::npos) << e.what();
  }
}
