#include "sim/water/setup.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.h"
#include "base/number_text.h"

namespace tidepool::water {

float volumePerParticle(float radius, Packing packing) {
  const float cube = std::pow(2.0f * radius, 3.0f);
  return packing == Packing::Hcp ? cube / std::sqrt(2.0f) : cube;
}

Setup switched(const Setup& from, Packing fromPacking, const Setup& own, Packing ownPacking) {
  const float hcpOverCubic = std::pow(2.0f, 1.0f / 6.0f);  // r_hcp / r_cubic at equal particles per volume
  Setup s = from;
  s.dt = own.dt;
  s.substeps = own.substeps;
  s.damping = own.damping;
  if (fromPacking == Packing::Cubic && ownPacking == Packing::Hcp) s.radius = from.radius * hcpOverCubic;
  if (fromPacking == Packing::Hcp && ownPacking == Packing::Cubic) s.radius = from.radius / hcpOverCubic;
  return s;
}

void visitFill(ParamVisitor& v, Setup& s) {
  v.vector({"domain_min", "Domain min", "m"}, s.domainMin, -100.0f, 100.0f);
  v.vector({"domain_max", "Domain max", "m"}, s.domainMax, -100.0f, 100.0f);
  v.choice({"fill", "Fill", "block, slab, random, lattice (benchmark) or none"}, s.fill, kFillNames);
  v.vector({"fill_min", "Fill min", "block / random region, m"}, s.fillMin, -100.0f, 100.0f);
  v.vector({"fill_max", "Fill max", "block / random region, m"}, s.fillMax, -100.0f, 100.0f);
  v.real({"slab_height", "Slab height", "m"}, s.slabHeight, 0.0f, 100.0f);
  v.integer({"random_count", "Random count", "particles"}, s.randomCount, 1, 1 << 30);
  v.real({"jitter", "Jitter", "initial noise, fraction of r"}, s.jitter, 0.0f, 0.5f);
  v.real({"resolution", "Resolution",
          "refines the scene: spacing / R, counts x R^3, dt / R (1: as the scene sets it; re-creates the particles)"},
         s.resolution, 0.05f, 64.0f);
  v.integer({"max_particles", "Max particles", "refuse larger requests (0: as many as the GPU holds)"}, s.maxParticles,
            0, 1 << 30);
}

void visitEngine(ParamVisitor& v, Setup& s, float maxDt) {
  v.real({"dt", "Time step", "s"}, s.dt, 1e-6f, maxDt);
  v.integer({"substeps", "Substeps", "steps per frame"}, s.substeps, 1, 1000);
  v.vector({"gravity", "Gravity", "m/s^2"}, s.gravity, -1000.0f, 1000.0f);
  v.real({"damping", "Damping", "1/s, frame-rate independent"}, s.damping, 0.0f, 1000.0f);
}

void visitFoam(ParamVisitor& v, Setup& s) {
  v.real({"foam_gain", "Foam gain", "per m of travel"}, s.foamGain, 0.0f, 1000.0f);
  v.real({"foam_decay", "Foam decay", "factor per 0.5 ms"}, s.foamDecay, 0.5f, 1.0f);
}

void visitWalls(ParamVisitor& v, Setup& s) {
  v.integer({"piston_axis", "Piston axis", "0 none, 1 x, 2 y, 3 z: that axis' max wall moves"}, s.pistonAxis, 0, 3);
  v.real({"piston_travel", "Piston travel", "fraction of the domain"}, s.pistonTravel, 0.0f, 0.9f);
  v.real({"piston_period", "Piston period", "s"}, s.pistonPeriod, 0.01f, 1000.0f);
  v.real({"rotation", "Rotation", "degrees about x (gravity follows)"}, s.rotation, -360.0f, 360.0f);
  v.real({"rotation_rate", "Rotation rate", "degrees per s"}, s.rotationRate, -3600.0f, 3600.0f);
  v.real({"contraction", "Contraction", "the top wall (z) at this fraction of the domain's height"}, s.contraction,
         0.2f, 1.0f);
  if (v.action({"reset_domain", "Reset domain", "rotation 0, contraction 1; stops the rotation and the piston"}))
    resetDomain(s);
}

void resetDomain(Setup& s) {
  s.rotation = 0.0f;
  s.rotationRate = 0.0f;
  s.contraction = 1.0f;
  s.pistonAxis = 0;
}

void visitTap(ParamVisitor& v, Setup& s) {
  v.flag({"enabled", "Enabled", ""}, s.tap);
  v.vector({"position", "Position", "nozzle centre, m"}, s.tapPosition, -100.0f, 100.0f);
  v.vector({"direction", "Direction", "of the jet"}, s.tapDirection, -1.0f, 1.0f);
  v.real({"speed", "Speed", "m/s"}, s.tapSpeed, 0.0f, 100.0f);
  v.real({"radius", "Nozzle radius", "m"}, s.tapRadius, 0.0f, 10.0f);
  v.integer({"max", "Max balls", "the tap stops after adding this many"}, s.tapMax, 0, 1 << 26);
}

void visitObstacles(ParamVisitor& v, Setup& s) {
  v.list(
      {"obstacles", "Obstacles", "fixed particles from shapes; added, removed, moved and turned while running"},
      s.obstacles, kMaxObstacles, [](ParamVisitor& v, ObstacleParams& o) { visit(v, o); },
      [](std::size_t i, const ObstacleParams& o) {
        return std::to_string(i) + ": " +
               (o.shape == Shape::Mesh ? "mesh " + o.mesh : std::string(kShapeNames[std::size_t(o.shape)]));
      });
}

void visit(ParamVisitor& v, ObstacleParams& o) {
  v.choice({"shape", "Shape", "none, sphere, box, capsule, cup, helix or mesh (rebuilt when edited)"}, o.shape,
           kShapeNames);
  v.text({"mesh", "Mesh", "mesh shape: OBJ file in assets/meshes (torus, cube, blob) or a path"}, o.mesh);
  v.flag({"shell", "Shell only", "surface shell instead of a solid fill (open meshes need it)"}, o.shell);
  v.vector({"size", "Size",
            "half extents (box; mesh: its bounds fit inside, aspect kept), radius x and height z (others), m"},
           o.size, 0.0f, 100.0f);
  v.vector({"centre", "Centre", "m (moves it while running)"}, o.centre, -100.0f, 100.0f);
  v.vector({"orientation", "Orientation", "degrees about x, then y, then z (about the centre)"}, o.orientation, -360.0f,
           360.0f);
  v.real({"spin", "Spin", "rad/s about the spin axis through the centre"}, o.spin, -100.0f, 100.0f);
  v.vector({"spin_axis", "Spin axis", "direction (any length; zero: no spin)"}, o.spinAxis, -1.0f, 1.0f);
  if (v.beginGroup({"path", "Path", "periodic translation of the centre"})) {
    v.choice({"kind", "Kind", "none; oscillate: centre + amplitude sin; circle: (a.x cos, a.y sin, a.z sin)"},
             o.path.kind, kPathNames);
    v.vector({"amplitude", "Amplitude", "m"}, o.path.amplitude, -10.0f, 10.0f);
    v.real({"period", "Period", "s"}, o.path.period, 0.01f, 1000.0f);
    v.real({"phase", "Phase", "degrees at t = 0"}, o.path.phase, -360.0f, 360.0f);
    v.endGroup();
  }
  v.flag({"dynamic", "Dynamic",
          "a rigid body the water, gravity and contacts move, starting at rest at its centre; spin and path "
          "unused"},
         o.dynamic);
  v.real({"density", "Density", "kg/m^3 of a dynamic obstacle (water: 1000)"}, o.density, 1.0f, 100000.0f);
  if (v.beginGroup({"hinge", "Hinge", "a dynamic obstacle that only turns about an axis fixed in the world"})) {
    v.vector({"axis", "Axis", "direction (any length; zero: no hinge, it moves freely)"}, o.hingeAxis, -1.0f, 1.0f);
    v.vector({"at", "At", "the axis passes through the centre plus this, m"}, o.hingeAt, -100.0f, 100.0f);
    v.endGroup();
  }
}

bool sameBody(const ObstacleParams& a, const ObstacleParams& b) {
  return a.shape == b.shape && a.shell == b.shell && a.size == b.size && (a.shape != Shape::Mesh || a.mesh == b.mesh);
}

namespace {}  // namespace

void refine(Setup& s, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    throw Error("resolution: the factor must be positive, not " + numberText(factor));
  Setup q = s;
  const double resolution = double(s.resolution) * factor;
  // A count the scene uses past 2^30 is refused; one it does not use (random_count with a block
  // fill) is scaled too, for a later switch, but held at the limit.
  auto scaleCount = [&](int& n, bool used, const char* key) {
    const double scaled = std::round(double(n) * factor * factor * factor);
    if (used && scaled > double(1 << 30))
      throw Error("resolution " + numberText(resolution) + " asks for " + numberText(scaled) + " particles in " + key +
                  " (at most 2^30 = 1073741824): lower the resolution");
    n = n > 0 ? int(std::clamp(scaled, 1.0, double(1 << 30))) : 0;
  };
  scaleCount(q.randomCount, s.fill == Fill::Random, "particles.random_count");
  scaleCount(q.latticeCount, s.fill == Fill::Lattice, "particles.lattice_count");
  scaleCount(q.tapMax, s.tap, "tap.max");
  const double frame = double(s.dt) * s.substeps;
  const long substeps = std::max(1L, std::lround(double(s.substeps) * factor));
  if (substeps > 1000)
    throw Error("resolution " + numberText(resolution) + " needs " + std::to_string(substeps) +
                " substeps per frame (engine.substeps allows 1000): lower the resolution or raise engine.dt");
  q.substeps = int(substeps);
  q.dt = float(frame / double(substeps));
  q.radius = float(double(s.radius) / factor);
  q.resolution = float(resolution);
  s = q;
}

}  // namespace tidepool::water
