// The balls step as a list of passes, and the statistics pass. Each pass binds what its kernel
// reads and writes and ends with the barrier its readers need; stepOnce() only names them.
#include <cmath>
#include <cstddef>

#include "balls/bindings.glsl"
#include "balls/stats_layout.glsl"
#include "sim/balls/balls.h"
#include "sim/balls/balls_kernels.h"

namespace tidepool::balls {
namespace {

// One work group's partial statistics as stats.comp writes them (balls/stats_layout.glsl).
struct GroupStats {
  float kinetic;     // sum, m²/s² per unit mass
  float potential;   // sum
  float overlap;     // sum of overlap / r over contacts
  float contacts;    // sum
  float maxOverlap;  // max, fraction of r
  float maxSpeed;    // max, m/s
  float nonFinite;   // sum, balls
  float outside;     // sum, balls
  float front;       // max, m (< -1e29: no ball near the floor)
  float backHeight;  // max, m (< -1e29: no ball near the back wall)
};
static_assert(sizeof(GroupStats) == BALLS_STATS_VALUES * sizeof(float));
static_assert(offsetof(GroupStats, kinetic) == BALLS_STATS_KINETIC * sizeof(float));
static_assert(offsetof(GroupStats, potential) == BALLS_STATS_POTENTIAL * sizeof(float));
static_assert(offsetof(GroupStats, overlap) == BALLS_STATS_OVERLAP * sizeof(float));
static_assert(offsetof(GroupStats, contacts) == BALLS_STATS_CONTACTS * sizeof(float));
static_assert(offsetof(GroupStats, maxOverlap) == BALLS_STATS_MAX_OVERLAP * sizeof(float));
static_assert(offsetof(GroupStats, maxSpeed) == BALLS_STATS_MAX_SPEED * sizeof(float));
static_assert(offsetof(GroupStats, nonFinite) == BALLS_STATS_NON_FINITE * sizeof(float));
static_assert(offsetof(GroupStats, outside) == BALLS_STATS_OUTSIDE * sizeof(float));
static_assert(offsetof(GroupStats, front) == BALLS_STATS_FRONT * sizeof(float));
static_assert(offsetof(GroupStats, backHeight) == BALLS_STATS_BACK_HEIGHT * sizeof(float));

constexpr std::size_t kVec4 = sizeof(glm::vec4);

gl::GpuProfiler::Scope timed(gl::GpuProfiler* profiler, const char* name) {
  return profiler ? profiler->scope(name) : gl::GpuProfiler::Scope(nullptr);
}

}  // namespace

void Balls::stepOnce(gl::GpuProfiler* profiler) {
  updateWalls();
  rebuildObstacles();
  emitFromTap();
  m_coupling.sync(m_params.obstacles);
  beginLoads();
  // Obstacles are placed where they are when the forces act: at t, or at t + dt for Verlet's
  // forces on the drifted positions.
  const bool verlet = m_params.integrator == Integrator::VelocityVerlet;
  const double forces = verlet ? m_time + m_params.dt : m_time;
  if (verlet) accelerations();                 // allocated on the first Verlet step (then a(x0) is evaluated)
  if (verlet && !m_accValid && m_count > 0) {  // a(x0) for the first drift
    placeObstacles(m_time, nullptr);
    sortByCell(nullptr);
    collide(nullptr, Collide::VerletForces);
  }
  if (m_count > 0) {
    if (verlet) drift(profiler);
    sortByCell(profiler);
  }
  // Neither the drift nor the sort reads the obstacles: the GPU runs them while the bodies wait
  // for the last step's loads.
  m_coupling.move(m_params.dt, -mass(), glm::dvec3(gravity()), water::wallsAt(m_params, forces),
                  water::posesAt(m_params.obstacles, forces));
  placeObstacles(forces, profiler);
  if (m_count > 0) {
    collide(profiler, verlet ? Collide::VerletKick : Collide::Integrate);
    m_accValid = verlet;
    if (m_loadsOn) measureLoads(profiler);
  }
  if (m_loadsOn) m_loads.sum(m_obstacles);
  m_loadsValid = m_loadsOn && m_count > 0;
  m_coupling.requestLoads(m_loadsValid);  // complete: on their way back while the next step sorts
  m_time += m_params.dt;
}

void Balls::step(gl::GpuProfiler& profiler) {
  for (int i = 0; i < m_params.substeps; ++i) stepOnce(&profiler);
  watch();
}

void Balls::rebuildObstacles() {
  if (std::string error; m_obstacles.update(m_params.obstacles, m_radius, error)) m_obstacleError = error;
}

void Balls::placeObstacles(double time, gl::GpuProfiler* profiler) {
  m_obstacles.place(m_params.obstacles, bodies().poses(m_params.obstacles, time), m_params.domainMin,
                    m_params.domainMax, profiler);
}

std::vector<gl::ShaderDefine> Balls::defines(bool verlet) const {
  std::vector<gl::ShaderDefine> d;
  switch (m_params.contact) {
    case Contact::Penalty: d.push_back({"CONTACT_PENALTY", ""}); break;
    case Contact::CudaSample: d.push_back({"CONTACT_CUDA", ""}); break;
    case Contact::SpringDashpot: d.push_back({"CONTACT_SPRING", ""}); break;
  }
  if (verlet)
    d.push_back({"INTEGRATOR_VERLET", ""});
  else if (m_params.integrator == Integrator::ExplicitEuler)
    d.push_back({"INTEGRATOR_EXPLICIT", ""});
  if (m_obstacles.active()) d.push_back({"HAS_OBSTACLE", ""});
  return d;
}

ContactUniforms Balls::contactUniforms() const {
  const Params& q = m_params;
  return {q.dt,       q.penaltyFactor, springPerMass(q), dashpotPerMass(q),
          q.friction, q.cudaSpring,    q.cudaDamping,    q.cudaShear};
}

WallUniforms Balls::wallUniforms() const {
  return {m_wallMin, m_wallMax, m_wallMinVel, m_wallMaxVel, m_params.cudaBoundaryDamping};
}

float Balls::foamDecayPerStep() const {
  return std::pow(m_params.foamDecay, m_params.dt / 0.0005f);  // the seed's decay per 0.5 ms
}

NeighbourUniforms Balls::bindNeighbours(const gl::Window& sources) const {
  m_obstacles.bind();
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_CELL_START);
  return {m_radius, GLuint(sources.first), m_grid->uniforms(), m_obstacles.uniforms()};
}

void Balls::drift(gl::GpuProfiler* profiler) {
  auto scope = timed(profiler, "balls.drift");
  const gl::Kernel<DriftUniforms> drift(m_shaders, "balls/drift.comp", {BALLS_POS_OUT, BALLS_VEL_OUT, BALLS_ACC},
                                        defines(false));
  const Params& q = m_params;
  for (const gl::Window& w : gl::windows(m_count, kVec4)) {
    gl::bindWindow(m_pos[m_posIndex], BALLS_POS_OUT, w, kVec4);
    gl::bindWindow(m_vel[m_velIndex], BALLS_VEL_OUT, w, kVec4);
    gl::bindWindow(m_acc, BALLS_ACC, w, kVec4);
    drift.dispatchThreads(w.count, {.first = GLuint(w.first),
                                    .count = GLuint(w.end()),
                                    .dt = q.dt,
                                    .radius = m_radius,
                                    .foamGain = q.foamGain,
                                    .foamDecay = foamDecayPerStep(),
                                    .walls = wallUniforms()});
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void Balls::sortByCell(gl::GpuProfiler* profiler) {
  const int p = m_posIndex, v = m_velIndex;
  if (!(m_countedAhead == countKey())) {
    auto scope = timed(profiler, "balls.count");
    m_grid->countParticles(m_pos[p], m_count);
  }
  m_countedAhead = {};
  {
    auto scope = timed(profiler, "balls.scan");
    m_grid->scanCells();
  }
  planReachWindows();  // balls over one storage block: the collide's windows, read back after the reorder
  auto scope = timed(profiler, "balls.reorder");
  m_grid->setStable(m_params.deterministic);  // may change while running
  m_grid->reorder(m_pos[p], {{&m_pos[p], &m_pos[1 - p]}, {&m_vel[v], &m_vel[1 - v]}},
                  m_trackOrder ? &permutation() : nullptr);
}

void Balls::collide(gl::GpuProfiler* profiler, Collide what) {
  auto scope = timed(profiler, "balls.collide");
  const bool verlet = what != Collide::Integrate;
  const int p = m_posIndex, v = m_velIndex;
  // Euler writes the next step's positions and counts them into its grid on the way: the next
  // sortByCell starts at the scan (velocity Verlet's positions move again before they are sorted).
  const bool countCells = !verlet;
  m_countedAhead = {};                            // set again below when this pass counts
  if (countCells) m_grid->prepareCount(m_count);  // its fill binds and runs a kernel of its own: first
  // Read back before the kernel's bindings: one window of all balls when they fit one block.
  m_windows = reachWindows();
  const gl::Kernel<CollideUniforms> collide(
      m_shaders, "balls/collide.comp",
      {BALLS_POS_IN, BALLS_VEL_IN, BALLS_VEL_OUT, BALLS_STEP_OUT, BALLS_NEXT_CELL_COUNT, BALLS_NEXT_INDEX_IN_CELL,
       BALLS_NEXT_PARTICLE_CELL, BALLS_CELL_START},
      defines(verlet));
  const Params& q = m_params;
  CollideUniforms u{.gravity = gravity(),
                    .decay = std::exp(-q.damping * q.dt),
                    .foamGain = q.foamGain,
                    .foamDecay = foamDecayPerStep(),
                    .kick = what == Collide::VerletKick ? 0.5f : 0.0f,
                    .contact = contactUniforms(),
                    .walls = wallUniforms(),
                    .neighbours = {}};  // per window, below
  // The cell-ordered copies in, the others out; a window at a time when they pass one storage block.
  const gl::Buffer &posIn = m_pos[1 - p], &velIn = m_vel[1 - v], &velOut = m_vel[v];
  const gl::Buffer& stepOut = verlet ? m_acc : m_pos[p];
  if (verlet) m_posIndex = 1 - p;  // positions stay in cell order; velocities come back to v
  if (countCells) {                // the counts for the next step's grid, at the positions written here
    m_grid->cellCount().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_NEXT_CELL_COUNT);
    m_grid->indexInCell().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_NEXT_INDEX_IN_CELL);
    m_grid->particleCell().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_NEXT_PARTICLE_CELL);
  }
  for (const ReachWindow& w : m_windows) {
    gl::bindWindow(posIn, BALLS_POS_IN, w.sources, kVec4);
    gl::bindWindow(velIn, BALLS_VEL_IN, w.sources, kVec4);
    gl::bindWindow(velOut, BALLS_VEL_OUT, w.balls, kVec4);
    gl::bindWindow(stepOut, BALLS_STEP_OUT, w.balls, kVec4);
    u.first = GLuint(w.balls.first);
    u.count = GLuint(w.balls.end());
    u.neighbours = bindNeighbours(w.sources);
    collide.dispatchThreads(w.balls.count, u);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (countCells) m_countedAhead = countKey();
}

// The collide's inputs are still the cell-ordered copies (Verlet's positions are the state now,
// its velocities the half step's): the loads are what the collide's accelerations were. The walls'
// from every ball (a probe on a wall), the obstacles' from every obstacle particle, a window of
// balls at a time.
void Balls::measureLoads(gl::GpuProfiler* profiler) {
  auto scope = timed(profiler, "balls.loads");
  const bool verlet = m_params.integrator == Integrator::VelocityVerlet;
  const gl::Buffer &posIn = verlet ? m_pos[m_posIndex] : m_pos[1 - m_posIndex], &velIn = m_vel[1 - m_velIndex];
  if (m_loads.walls()) {
    const gl::Kernel<LoadsUniforms> walls(m_shaders, "balls/loads.comp", {BALLS_POS_IN, BALLS_VEL_IN, BALLS_LOADS},
                                          defines(false));
    for (const ReachWindow& w : m_windows) {
      gl::bindWindow(posIn, BALLS_POS_IN, w.balls, kVec4);
      gl::bindWindow(velIn, BALLS_VEL_IN, w.balls, kVec4);
      m_loads.bindWallGroups(BALLS_LOADS, w.balls.first / BALLS_GROUP_SIZE,
                             (w.balls.count + BALLS_GROUP_SIZE - 1) / BALLS_GROUP_SIZE);
      walls.dispatchThreads(w.balls.count, {.first = GLuint(w.balls.first),
                                            .count = GLuint(w.balls.end()),
                                            .radius = m_radius,
                                            .sourceFirst = GLuint(w.balls.first),
                                            .contact = contactUniforms(),
                                            .walls = wallUniforms()});
    }
  }
  if (m_loads.obstacles()) {
    const gl::Kernel<ObstacleLoadsUniforms> obstacles(
        m_shaders, "balls/obstacle_loads.comp",
        {BALLS_POS_IN, BALLS_VEL_IN, BALLS_CELL_START, BALLS_OBSTACLE_PLACED, BALLS_SHARES, BALLS_MOMENTS},
        defines(false));
    m_obstacles.bind();
    m_obstacles.placed().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_OBSTACLE_PLACED);
    m_loads.bindShares(BALLS_SHARES, BALLS_MOMENTS);
    m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_CELL_START);
    for (const ReachWindow& w : m_windows) {  // each adds its balls' part, in the grid's order
      gl::bindWindow(posIn, BALLS_POS_IN, w.sources, kVec4);
      gl::bindWindow(velIn, BALLS_VEL_IN, w.sources, kVec4);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);  // the last window's shares
      obstacles.dispatchThreads(m_obstacles.particles(), {.first = GLuint(w.balls.first),
                                                          .count = GLuint(w.balls.end()),
                                                          .radius = m_radius,
                                                          .sourceFirst = GLuint(w.sources.first),
                                                          .particles = GLuint(m_obstacles.particles()),
                                                          .add = GLuint(w.balls.first > 0),
                                                          .contact = contactUniforms(),
                                                          .grid = m_grid->uniforms()});
    }
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

Balls::CountKey Balls::countKey() const { return {m_pos[m_posIndex].version(), m_count, m_grid.get()}; }

Stats Balls::stats() {
  Stats st;
  st.time = m_time;
  st.count = m_count;
  if (m_count == 0) return st;
  // The stats pass needs the balls in cell order: sort copies into the scratch buffers, leaving
  // the state (and Verlet's accelerations, which follow its order) untouched.
  const int p = m_posIndex, v = m_velIndex;
  m_countedAhead = {};  // the reorder below ranks over the grid's slots
  m_grid->build(m_pos[p], m_count);
  planReachWindows();
  m_grid->reorder(m_pos[p], {{&m_pos[p], &m_pos[1 - p]}, {&m_vel[v], &m_vel[1 - v]}});
  const std::vector<ReachWindow> windows = reachWindows();  // before the kernel's bindings
  const gl::Kernel<StatsUniforms> kernel(m_shaders, "balls/stats.comp",
                                         {BALLS_POS_IN, BALLS_VEL_IN, BALLS_STATS, BALLS_CELL_START}, defines(false));
  constexpr std::size_t kGroupBytes = sizeof(GroupStats);
  for (const ReachWindow& w : windows) {  // the partials of each window's groups from its first group on
    gl::bindWindow(m_pos[1 - p], BALLS_POS_IN, w.sources, kVec4);
    gl::bindWindow(m_vel[1 - v], BALLS_VEL_IN, w.sources, kVec4);
    const std::size_t firstGroup = w.balls.first / BALLS_GROUP_SIZE;
    const std::size_t groups = (w.balls.count + BALLS_GROUP_SIZE - 1) / BALLS_GROUP_SIZE;
    m_stats.bindRange(GL_SHADER_STORAGE_BUFFER, BALLS_STATS, firstGroup * kGroupBytes, groups * kGroupBytes);
    kernel.dispatchThreads(w.balls.count, {.first = GLuint(w.balls.first),
                                           .count = GLuint(w.balls.end()),
                                           .gravity = gravity(),
                                           .domainMin = m_params.domainMin,
                                           .wallMin = m_wallMin,
                                           .wallMax = m_wallMax,
                                           .neighbours = bindNeighbours(w.sources)});
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const std::size_t groups = (m_count + BALLS_GROUP_SIZE - 1) / BALLS_GROUP_SIZE;
  double front = -1e30, height = -1e30;
  double contacts = 0, overlapSum = 0;
  for (const GroupStats& g : m_stats.read<GroupStats>(groups)) {
    front = std::max(front, double(g.front));
    height = std::max(height, double(g.backHeight));
    st.kinetic += g.kinetic;
    st.potential += g.potential;
    overlapSum += g.overlap;
    contacts += g.contacts;
    st.maxOverlap = std::max(st.maxOverlap, double(g.maxOverlap));
    st.maxSpeed = std::max(st.maxSpeed, double(g.maxSpeed));
    st.nonFinite += std::size_t(g.nonFinite);
    st.outside += std::size_t(g.outside);
  }
  st.meanOverlap = contacts > 0 ? overlapSum / contacts : 0.0;
  st.front = front > -1e29 ? front : std::nan("");
  st.backHeight = height > -1e29 ? height : std::nan("");
  st.contactsPerBall = contacts / double(m_count);
  return st;
}

}  // namespace tidepool::balls
