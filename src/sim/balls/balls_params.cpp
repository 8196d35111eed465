#include "sim/balls/balls_params.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/error.h"

namespace tidepool::balls {

void visit(ParamVisitor& v, Params& p) {
  if (v.beginGroup({"particles", "Particles", "count, size and initial state (re-creates the particles)"})) {
    v.real({"radius", "Radius", "r, m"}, p.radius, 1e-4f, 0.5f);
    visitFill(v, p);
    v.integer({"lattice_count", "Lattice count", "particles"}, p.latticeCount, 1, 1 << 30);
    v.flag({"lattice_scaling", "Lattice scaling", "r = 1/G and gravity x 64/G as the CUDA sample"}, p.latticeScaling);
    v.endGroup();
  }
  if (v.beginGroup({"engine", "Engine", "time step, contact law, integrator"})) {
    v.choice({"contact", "Contact", "penalty (the seed's), spring-dashpot (linear DEM) or cuda-sample"}, p.contact,
             kContactNames);
    v.choice({"integrator", "Integrator", "explicit Euler, symplectic Euler or velocity Verlet"}, p.integrator,
             kIntegratorNames);
    v.real({"dt", "Time step", "s"}, p.dt, 1e-6f, 1.0f);
    v.integer({"substeps", "Substeps", "steps per frame"}, p.substeps, 1, 1000);
    v.vector({"gravity", "Gravity", "m/s^2"}, p.gravity, -1000.0f, 1000.0f);
    v.real({"damping", "Damping", "1/s, frame-rate independent"}, p.damping, 0.0f, 1000.0f);
    v.flag({"deterministic", "Deterministic", "bit-identical runs: the grid orders each cell's balls by index"},
           p.deterministic);
    v.real({"contact_time", "Contact time", "t_c of spring-dashpot, s"}, p.contactTime, 1e-6f, 10.0f);
    v.real({"restitution", "Restitution", "e of spring-dashpot"}, p.restitution, 0.01f, 1.0f);
    v.real({"friction", "Friction", "tangential Coulomb coefficient (spring-dashpot)"}, p.friction, 0.0f, 2.0f);
    v.real({"penalty_factor", "Penalty factor", "seed: 0.96"}, p.penaltyFactor, 0.0f, 2.0f);
    v.real({"cuda_spring", "CUDA spring", "per-step velocity change per overlap"}, p.cudaSpring, 0.0f, 2.0f);
    v.real({"cuda_damping", "CUDA damping", "per step"}, p.cudaDamping, 0.0f, 1.0f);
    v.real({"cuda_shear", "CUDA shear", "per step"}, p.cudaShear, 0.0f, 1.0f);
    v.real({"cuda_boundary_damping", "CUDA wall factor", "velocity factor at walls"}, p.cudaBoundaryDamping, -1.0f,
           1.0f);
    v.real({"foam_gain", "Foam gain", "per m of travel"}, p.foamGain, 0.0f, 1000.0f);
    v.real({"foam_decay", "Foam decay", "factor per 0.5 ms"}, p.foamDecay, 0.5f, 1.0f);
    v.endGroup();
  }
  if (v.beginGroup({"walls", "Walls", "piston and domain rotation"})) {
    visitWalls(v, p);
    v.endGroup();
  }
  if (v.beginGroup({"tap", "Tap", "emits balls over time"})) {
    visitTap(v, p);
    v.endGroup();
  }
  visitObstacles(v, p);
}

void visitFill(ParamVisitor& v, Params& p) {
  v.vector({"domain_min", "Domain min", "m"}, p.domainMin, -100.0f, 100.0f);
  v.vector({"domain_max", "Domain max", "m"}, p.domainMax, -100.0f, 100.0f);
  v.choice({"fill", "Fill", "block, slab, random, lattice (benchmark) or none"}, p.fill, kFillNames);
  v.vector({"fill_min", "Fill min", "block / random region, m"}, p.fillMin, -100.0f, 100.0f);
  v.vector({"fill_max", "Fill max", "block / random region, m"}, p.fillMax, -100.0f, 100.0f);
  v.real({"slab_height", "Slab height", "m"}, p.slabHeight, 0.0f, 100.0f);
  v.integer({"random_count", "Random count", "particles"}, p.randomCount, 1, 1 << 30);
  v.real({"jitter", "Jitter", "initial noise, fraction of r"}, p.jitter, 0.0f, 0.5f);
  v.real({"resolution", "Resolution",
          "refines the scene: spacing / R, counts x R^3, dt / R (1: as the scene sets it; re-creates the particles)"},
         p.resolution, 0.05f, 64.0f);
  v.integer({"max_particles", "Max particles", "refuse larger requests (0: as many as the GPU holds)"}, p.maxParticles,
            0, 1 << 30);
}

void visitWalls(ParamVisitor& v, Params& p) {
  v.integer({"piston_axis", "Piston axis", "0 none, 1 x, 2 y, 3 z: that axis' max wall moves"}, p.pistonAxis, 0, 3);
  v.real({"piston_travel", "Piston travel", "fraction of the domain"}, p.pistonTravel, 0.0f, 0.9f);
  v.real({"piston_period", "Piston period", "s"}, p.pistonPeriod, 0.01f, 1000.0f);
  v.real({"rotation", "Rotation", "degrees about x (gravity follows)"}, p.rotation, -360.0f, 360.0f);
  v.real({"rotation_rate", "Rotation rate", "degrees per s"}, p.rotationRate, -3600.0f, 3600.0f);
  v.real({"contraction", "Contraction", "the top wall (z) at this fraction of the domain's height"}, p.contraction,
         0.2f, 1.0f);
  if (v.action({"reset_domain", "Reset domain", "rotation 0, contraction 1; stops the rotation and the piston"}))
    resetDomain(p);
}

void resetDomain(Params& p) {
  p.rotation = 0.0f;
  p.rotationRate = 0.0f;
  p.contraction = 1.0f;
  p.pistonAxis = 0;
}

void visitTap(ParamVisitor& v, Params& p) {
  v.flag({"enabled", "Enabled", ""}, p.tap);
  v.vector({"position", "Position", "nozzle centre, m"}, p.tapPosition, -100.0f, 100.0f);
  v.vector({"direction", "Direction", "of the jet"}, p.tapDirection, -1.0f, 1.0f);
  v.real({"speed", "Speed", "m/s"}, p.tapSpeed, 0.0f, 100.0f);
  v.real({"radius", "Nozzle radius", "m"}, p.tapRadius, 0.0f, 10.0f);
  v.integer({"max", "Max balls", "the tap stops after adding this many"}, p.tapMax, 0, 1 << 26);
}

void visitObstacles(ParamVisitor& v, Params& p) {
  v.list(
      {"obstacles", "Obstacles", "fixed particles from shapes; added, removed, moved and turned while running"},
      p.obstacles, kMaxObstacles, [](ParamVisitor& v, ObstacleParams& o) { visit(v, o); },
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
}

namespace {
std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}
}  // namespace

void refine(Params& p, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    throw Error("resolution: the factor must be positive, not " + number(factor));
  Params q = p;
  const double resolution = double(p.resolution) * factor;
  // A count the scene uses past 2^30 is refused; one it does not use (random_count with a block
  // fill) is scaled too, for a later switch, but held at the limit.
  auto scaleCount = [&](int& n, bool used, const char* key) {
    const double scaled = std::round(double(n) * factor * factor * factor);
    if (used && scaled > double(1 << 30))
      throw Error("resolution " + number(resolution) + " asks for " + number(scaled) + " particles in " + key +
                  " (at most 2^30 = 1073741824): lower the resolution");
    n = n > 0 ? int(std::clamp(scaled, 1.0, double(1 << 30))) : 0;
  };
  scaleCount(q.randomCount, p.fill == Fill::Random, "particles.random_count");
  scaleCount(q.latticeCount, p.fill == Fill::Lattice, "particles.lattice_count");
  scaleCount(q.tapMax, p.tap, "tap.max");
  const double frame = double(p.dt) * p.substeps;
  const long substeps = std::max(1L, std::lround(double(p.substeps) * factor));
  if (substeps > 1000)
    throw Error("resolution " + number(resolution) + " needs " + std::to_string(substeps) +
                " substeps per frame (engine.substeps allows 1000): lower the resolution or raise engine.dt");
  q.substeps = int(substeps);
  q.dt = float(frame / double(substeps));
  q.radius = float(double(p.radius) / factor);
  q.contactTime = float(double(p.contactTime) / factor);
  q.resolution = float(resolution);
  p = q;
}

bool sameBody(const ObstacleParams& a, const ObstacleParams& b) {
  return a.shape == b.shape && a.shell == b.shell && a.size == b.size && (a.shape != Shape::Mesh || a.mesh == b.mesh);
}

}  // namespace tidepool::balls
