// What the deferred balls renderer draws and how: the look (a scene's "view" group), the camera
// of one frame, and the batches of spheres it reads straight from simulation SSBOs.
#pragma once

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "base/param.h"
#include "gl/buffer.h"

namespace tidepool::gl {
class Texture2D;
}

namespace tidepool {

enum class BallsMode { Balls, Water };
inline constexpr std::array<const char*, 2> kBallsModeNames = {"balls", "water"};
// What the compose shows: the picture, or one G-buffer channel (normals: world axes; screen_normals:
// view axes, x right, y up, z towards the eye).
enum class BallsDebug { Final, Local, Normals, Thickness, Depth, ScreenNormals };
inline constexpr std::array<const char*, 6> kBallsDebugNames = {"final",     "local", "normals",
                                                                "thickness", "depth", "screen_normals"};

// Who draws the sphere impostors: the shader cores (src/render/balls_splat.h), or the raster units
// where the balls' arrays pass one storage block (they are drawn a window at a time) and for the
// tests and `bench render`, which hold the two against each other. Not a scene parameter.
enum class BallsRaster { Compute, Fragment };
inline constexpr std::array<const char*, 2> kBallsRasterNames = {"compute", "fragment"};

// The grid cells debug overlay (src/render/balls_grid_cells.h): off, the non-empty cells coloured
// by their number of balls, or the non-empty cells all alike.
enum class GridCellsMode { Hidden, Population, NonEmpty };
inline constexpr std::array<const char*, 3> kGridCellsModeNames = {"hidden", "population", "non_empty"};

// Presets of the look (applyLook): the seed's flat blue water over a dark background, clear
// water over a tiled floor under a sky (the default), and deeper, greener ocean water there.
enum class WaterLook { Seed, Clear, Ocean };
inline constexpr std::array<const char*, 3> kWaterLookNames = {"seed", "clear", "ocean"};

struct BallsViewParams {
  BallsMode mode = BallsMode::Balls;
  BallsRaster raster = BallsRaster::Compute;  // not read from scenes (see BallsRaster)
  BallsDebug debug = BallsDebug::Final;
  bool debugUnblurred = false;                      // water: the debug views show the G-buffer before the blur
  GridCellsMode gridCells = GridCellsMode::Hidden;  // the neighbour grid's non-empty cells as wire cubes
  float gridCellsFull = 3.0f;                       // balls per cell at the population ramp's red end
  // The fields a look sets start as the clear look's (render/balls_view.cpp, kLooks).
  WaterLook look = WaterLook::Clear;           // the preset the fields below started from
  bool environment = true;                     // a sky, the sun and a tiled floor (off: the background)
  float refractionIndex = 1.33f;               // water's, bending what is seen through it (1: straight)
  glm::vec3 skyColor{0.30f, 0.50f, 0.85f};     // linear RGB at the zenith (the horizon: background)
  float floorTiles = 5.0f;                     // tiles across the domain box's shorter side
  float glass = 0.04f;                         // the box's side walls' reflectance at normal incidence
  float caustics = 1.0f;                       // the sunlight the water focuses on the floor (0: none, 1: all)
  glm::vec3 waterColor{0.45f, 0.78f, 0.88f};   // linear RGB: balls' albedo, water's tint
  float absorption = 6.0f;                     // 1/m: thickness 1/absorption transmits waterColor
  float scattering = 0.35f;                    // water: how much of the absorbed light it sends back, tinted
  float spray = 1.0f;                          // water: how white a lone ball (a droplet) is drawn
  float blurRadius = 4.0f;                     // blur kernel radius, in on-screen ball radii
  int blurIterations = 2;                      // times the blur's row and column passes run
  float depthThreshold = 12.0f;                // ball radii: no blur across larger depth steps between pixels
  bool foam = true;                            // white water from the per-ball foam
  float fresnelF0 = 0.02f;                     // reflectance at normal incidence (water)
  float specular = 1.0f;                       // key-light highlight strength
  glm::vec3 lightDirection{0.5f, 0.3f, 1.0f};  // world (z up), towards the key light; any length
  glm::vec3 obstacleColor{0.55f, 0.55f, 0.58f};
  glm::vec3 background{0.80f, 0.85f, 0.90f};  // linear RGB (with the environment: the sky's horizon)
  bool showBox = true;
  bool showObstacle = true;
  bool obstacleBalls = false;  // the obstacle's fixed balls too (they stick out of its mesh by up to r)

  // Towards the sun (the key light), world, unit; straight up when lightDirection is zero.
  glm::vec3 sunWorld() const {
    return glm::length(lightDirection) > 0.0f ? glm::normalize(lightDirection) : glm::vec3(0.0f, 0.0f, 1.0f);
  }
};
void visit(ParamVisitor& v, BallsViewParams& p);
// Sets the fields a look decides (the surroundings, the caustics, the water's colour, absorption,
// refraction, Fresnel and highlight, the background); the others stay.
void applyLook(BallsViewParams& p, WaterLook look);

// One frame's camera: view and projection matrices (glm::perspective or glm::ortho, symmetric),
// image size and the depth range (m). Only what lies in front of the eye (view depth > 0) is
// drawn, even where an orthographic near plane lies behind it.
struct BallsCamera {
  glm::mat4 view{1.0f}, proj{1.0f};
  int width = 1, height = 1;
  float near = 0.1f, far = 10.0f;
  static BallsCamera perspective(glm::mat4 view, float fovYRadians, int width, int height, float near, float far);
  static BallsCamera orthographic(glm::mat4 view, float halfHeight, int width, int height, float near, float far);
  static BallsCamera of(glm::mat4 view, glm::mat4 proj, int width, int height);  // near, far from proj
  bool isOrthographic() const { return proj[3][3] == 1.0f; }  // glm::ortho's last row is (0, 0, 0, 1)
  glm::vec3 towardsLight(glm::vec3 world) const;              // view space, unit (straight up when world is zero)
};

// Spheres of one radius whose centres are vec4s in an SSBO (w unused), optionally with foam in
// the w of a velocity SSBO; `model` maps their frame to the world.
struct SphereBatch {
  const gl::Buffer* positions = nullptr;
  const gl::Buffer* velocities = nullptr;  // null: no foam
  std::size_t count = 0;
  float radius = 0.01f;  // m
  glm::mat4 model{1.0f};
};

// Triangles whose vertices are MeshVertex records (src/render/obstacle_mesh.h) in an SSBO.
struct MeshBatch {
  const gl::Buffer* vertices = nullptr;
  std::size_t count = 0;  // vertices, three per triangle
  glm::mat4 model{1.0f};  // rigid
  // The vertices' bounds in the mesh's own frame; empty (min > max): unknown, the whole window.
  glm::vec3 boundsMin{1.0f}, boundsMax{-1.0f};
};

// Window pixels from the bottom left, max exclusive.
struct WindowRect {
  glm::ivec2 min{0}, max{0};
};

// The obstacles' depth for the passes after the scene pass: the target's DEPTH32F, cleared and
// drawn inside `rect` only (balls_view.h, meshesWindowRect); outside it the scene is at the far
// plane whatever the texture holds.
struct SceneDepth {
  const gl::Texture2D* texture = nullptr;  // null: nothing opaque was drawn
  WindowRect rect;
};

// Everything in a frame: the water balls, the obstacles (as balls and/or meshes) and the domain box.
struct BallsScene {
  SphereBatch water;
  SphereBatch obstacle;                   // all obstacles' fixed balls, drawn; count 0: none
  SphereBatch cover;                      // all obstacles' balls, drawn or not: the caustics' floor under them
  std::vector<MeshBatch> obstacleMeshes;  // one per obstacle, placed by its model matrix
  glm::vec3 boxMin{0.0f}, boxMax{1.0f};
  glm::mat4 boxModel{1.0f};
};

}  // namespace tidepool
