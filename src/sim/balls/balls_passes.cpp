// The balls step as a list of passes, and the statistics pass. Each pass binds what its kernel
// reads and writes and ends with the barrier its readers need; stepOnce() only names them.
#include <cmath>
#include <cstddef>

#include "balls/bindings.glsl"
#include "balls/list_layout.glsl"
#include "balls/stats_layout.glsl"
#include "common/dispatch_gate_layout.glsl"
#include "sim/balls/balls.h"

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
  ensureGrid();  // a live edit of the neighbour search
  // Obstacles are placed where they are when the forces act: at t, or at t + dt for Verlet's
  // forces on the drifted positions.
  const bool verlet = m_params.integrator == Integrator::VelocityVerlet;
  const bool lists = listsActive();
  if (!lists) m_listsStale = true;  // balls reordered meanwhile: the lists' indices are void
  if (verlet) accelerations();      // allocated on the first Verlet step (then a(x0) is evaluated)
  auto neighbours = [&](gl::GpuProfiler* prof) { lists ? gateLists(prof) : sortByCell(prof); };
  if (verlet && !m_accValid && m_count > 0) {  // a(x0) for the first drift
    placeObstacles(m_time, nullptr);
    neighbours(nullptr);
    collide(nullptr, Collide::VerletForces);
  }
  placeObstacles(verlet ? m_time + m_params.dt : m_time, profiler);
  if (m_count > 0) {
    if (verlet) drift(profiler);
    neighbours(profiler);
    collide(profiler, verlet ? Collide::VerletKick : Collide::Integrate);
    m_accValid = verlet;
  }
  m_time += m_params.dt;
}

void Balls::step(double, gl::GpuProfiler& profiler) {
  for (int i = 0; i < m_params.substeps; ++i) stepOnce(&profiler);
  watch();
}

void Balls::rebuildObstacles() {
  if (std::string error; m_obstacles.update(m_params.obstacles, m_radius, error)) m_obstacleError = error;
}

void Balls::placeObstacles(double time, gl::GpuProfiler* profiler) {
  m_obstacles.place(m_params.obstacles, time, m_params.domainMin, m_params.domainMax, profiler);
}

std::vector<gl::ShaderDefine> Balls::defines(bool verlet, bool lists, bool countCells) const {
  std::vector<gl::ShaderDefine> d;
  if (lists) d.push_back({"LISTS", ""});
  if (countCells) d.push_back({"COUNT_CELLS", ""});
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

gl::Program& Balls::useKernel(const char* file, bool verlet, bool lists, bool countCells) {
  gl::Program& p = m_shaders.program({file}, defines(verlet, lists, countCells));
  const Params& q = m_params;
  p.use();
  p.set("uCount", GLuint(m_count));
  p.set("uRadius", m_radius);
  p.set("uDt", q.dt);
  p.set("uGravity", gravity());
  p.set("uDecay", std::exp(-q.damping * q.dt));
  p.set("uPenaltyFactor", q.penaltyFactor);
  p.set("uSpringK1", springPerMass(q));
  p.set("uDashpotG1", dashpotPerMass(q));
  p.set("uFriction", q.friction);
  p.set("uCudaSpring", q.cudaSpring);
  p.set("uCudaDamping", q.cudaDamping);
  p.set("uCudaShear", q.cudaShear);
  p.set("uBoundaryDamping", q.cudaBoundaryDamping);
  p.set("uWallMin", m_wallMin);
  p.set("uWallMax", m_wallMax);
  p.set("uWallMinVel", m_wallMinVel);
  p.set("uWallMaxVel", m_wallMaxVel);
  p.set("uFoamGain", q.foamGain);
  p.set("uFoamDecay", std::pow(q.foamDecay, q.dt / 0.0005f));  // the seed's decay per 0.5 ms
  m_grid->setUniforms(p);
  if (m_obstacles.active()) m_obstacles.bind(p);
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_CELL_START);
  return p;
}

void Balls::drift(gl::GpuProfiler* profiler) {
  auto scope = timed(profiler, "balls.drift");
  m_countedAhead = {};  // it moves the balls
  const bool lists = listsActive();
  gl::Program& p = useKernel("balls/drift.comp", false, lists);
  if (lists) bindLists(p);
  for (const gl::Window& w : gl::windows(m_count, kVec4)) {
    gl::bindWindow(m_pos[m_posIndex], BALLS_POS_OUT, w, kVec4);
    gl::bindWindow(m_vel[m_velIndex], BALLS_VEL_OUT, w, kVec4);
    gl::bindWindow(m_acc, BALLS_ACC, w, kVec4);
    p.set("uFirst", GLuint(w.first));
    p.set("uCount", GLuint(w.end()));
    p.dispatchThreads(w.count);
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
  m_grid->setReorderMode(m_params.gridReorder);  // may change while running
  m_grid->setStable(m_params.deterministic);
  m_grid->reorder(m_pos[p], {{&m_pos[p], &m_pos[1 - p]}, {&m_vel[v], &m_vel[1 - v]}},
                  m_trackOrder ? &permutation() : nullptr);
}

void Balls::collide(gl::GpuProfiler* profiler, Collide what) {
  auto scope = timed(profiler, "balls.collide");
  const bool verlet = what != Collide::Integrate;
  const int p = m_posIndex, v = m_velIndex;
  const bool lists = listsActive();
  const bool countCells = countsInCollide(what);
  m_countedAhead = {};                            // set again below when this pass counts
  if (countCells) m_grid->prepareCount(m_count);  // its fill binds and runs a kernel of its own: first
  // Read back before the kernel's bindings: one window of all balls when they fit one block.
  const std::vector<ReachWindow> windows = lists ? std::vector<ReachWindow>{} : reachWindows();
  m_collideWindows = lists ? 1 : windows.size();
  gl::Program& collide = useKernel("balls/collide.comp", verlet, lists, countCells);
  if (lists) {  // the balls in place: read the current buffers, write the others
    bindLists(collide);
    m_pos[p].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_IN);
    m_vel[v].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VEL_IN);
    m_vel[1 - v].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VEL_OUT);
    m_velIndex = 1 - v;
    if (verlet) {
      collide.set("uKick", what == Collide::VerletKick ? 0.5f : 0.0f);
      m_acc.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_ACC);
    } else {
      m_pos[1 - p].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_OUT);
      m_posIndex = 1 - p;
    }
    collide.set("uFirst", 0u);  // lists fit one storage block (listCapacity())
    collide.set("uSourceFirst", 0u);
    collide.dispatchThreads(m_count);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    return;
  }
  // The cell-ordered copies in, the others out; a window at a time when they pass one storage block.
  const gl::Buffer &posIn = m_pos[1 - p], &velIn = m_vel[1 - v], &velOut = m_vel[v];
  const gl::Buffer& stepOut = verlet ? m_acc : m_pos[p];
  if (verlet) {
    collide.set("uKick", what == Collide::VerletKick ? 0.5f : 0.0f);
    m_posIndex = 1 - p;  // positions stay in cell order; velocities come back to v
  }
  if (countCells) {  // the counts for the next step's grid, at the positions written here
    m_grid->cellCount().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_NEXT_CELL_COUNT);
    m_grid->indexInCell().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_NEXT_INDEX_IN_CELL);
    m_grid->particleCell().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_NEXT_PARTICLE_CELL);
  }
  for (const ReachWindow& w : windows) {
    gl::bindWindow(posIn, BALLS_POS_IN, w.sources, kVec4);
    gl::bindWindow(velIn, BALLS_VEL_IN, w.sources, kVec4);
    gl::bindWindow(velOut, BALLS_VEL_OUT, w.balls, kVec4);
    gl::bindWindow(stepOut, verlet ? BALLS_ACC : BALLS_POS_OUT, w.balls, kVec4);
    collide.set("uFirst", GLuint(w.balls.first));
    collide.set("uCount", GLuint(w.balls.end()));
    collide.set("uSourceFirst", GLuint(w.sources.first));
    collide.dispatchThreads(w.balls.count);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (countCells) m_countedAhead = countKey();
}

// The collide counts the balls into the next step's grid when it writes their positions in
// place (Euler) and has two storage blocks to spare (no obstacle, no lists).
bool Balls::countsInCollide(Collide what) const {
  return m_countInCollide && what == Collide::Integrate && !listsActive() && !m_obstacles.active();
}

Balls::CountKey Balls::countKey() const { return {m_count, m_posIndex, m_grid.get(), true}; }

void Balls::bindLists(gl::Program& program) const {
  m_lists.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_LISTS);
  program.set("uListStride", GLuint(m_capacity));
  program.set("uListCapacity", GLuint(m_listColumns - BALLS_LIST_FIRST));
  program.set("uControl", GLuint(m_listColumns * m_capacity));
}

// The gate kernel judges the displacements the last step left (balls/list_gate.comp) and opens
// or closes the gated section: the grid at the current positions, the balls gathered into its
// order in the spare buffers and copied back (so that the current buffers stay current whether
// the gate opened or not), and the lists. The first time, and after the balls or the section's
// passes changed, the section runs unconditionally and is recorded; after a restore it is noted
// without running, so the saved lists stay in use.
void Balls::gateLists(gl::GpuProfiler* profiler) {
  auto scope = timed(profiler, "balls.lists");
  const int p = m_posIndex, v = m_velIndex;
  const bool verlet = m_params.integrator == Integrator::VelocityVerlet;
  const std::size_t bytes = m_count * sizeof(glm::vec4);
  m_grid->setReorderMode(m_params.gridReorder);
  m_grid->setStable(m_params.deterministic);
  const GateKey key = gateKey();
  if (!(key == m_gateKey)) {  // other passes in the section: record it again
    m_gate.forget();
    m_listsStale = true;
    m_gateKey = key;
  }
  if (verlet && m_accScratch.size() < accelerations().size()) m_accScratch = gl::Buffer(m_acc.size());
  permutation();
  auto section = [&] {
    m_grid->countParticles(m_pos[p], m_count);
    m_grid->scanCells();
    std::vector<grid::ReorderArray> arrays{{&m_pos[p], &m_pos[1 - p]}, {&m_vel[v], &m_vel[1 - v]}};
    if (verlet) arrays.push_back({&m_acc, &m_accScratch});  // a(x) follows its ball
    m_grid->reorder(m_pos[p], arrays, &m_permutation);
    m_ops.copy(m_pos[1 - p], m_pos[p], bytes);
    m_ops.copy(m_vel[1 - v], m_vel[v], bytes);
    if (verlet) m_ops.copy(m_accScratch, m_acc, bytes);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    buildLists();
  };
  const bool record = m_listsStale && !m_gate.recorded();
  if (!record && !m_gate.recorded()) m_gate.note(section);  // before the gate is in use: it uses other programs
  gl::Program& gate = m_shaders.program({"balls/list_gate.comp"});
  gate.use();
  bindLists(gate);
  gate.set("uSkin", m_params.skin * m_radius);
  if (record) {
    gate.set("uForce", 1u);
    gate.set("uGateDispatches", 0u);
    m_lists.bindBase(GL_SHADER_STORAGE_BUFFER, DISPATCH_GATE_GROUPS);  // not read: no dispatch recorded yet
    m_lists.bindBase(GL_SHADER_STORAGE_BUFFER, DISPATCH_GATE_ARGS);
    gate.dispatch({1, 1, 1});
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    bindLists(gate);
    m_gate.record(section);
  } else {
    gate.set("uForce", m_listsStale ? 1u : 0u);
    gate.set("uGateDispatches", GLuint(m_gate.dispatches()));
    m_gate.recordedGroups().bindBase(GL_SHADER_STORAGE_BUFFER, DISPATCH_GATE_GROUPS);
    m_gate.arguments().bindBase(GL_SHADER_STORAGE_BUFFER, DISPATCH_GATE_ARGS);
    gate.dispatch({1, 1, 1});
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    m_gate.replay(section);
  }
  m_listsStale = false;
}

Balls::GateKey Balls::gateKey() const {
  return {m_count, m_params.integrator == Integrator::VelocityVerlet, m_params.deterministic, m_params.gridReorder};
}

void Balls::buildLists() {
  gl::Program& build = m_shaders.program({"balls/list_build.comp"});
  build.use();
  m_grid->setUniforms(build);
  bindLists(build);
  build.set("uCount", GLuint(m_count));
  build.set("uListReach", (2.0f + m_params.skin) * m_radius);
  m_pos[m_posIndex].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_IN);
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_CELL_START);
  build.dispatchThreads(m_count);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

Stats Balls::stats() {
  Stats st;
  st.time = m_time;
  st.count = m_count;
  if (m_count == 0) return st;
  // The stats pass needs the balls in cell order: sort copies into the scratch buffers, leaving
  // the state (and Verlet's accelerations, which follow its order) untouched.
  const int p = m_posIndex, v = m_velIndex;
  m_countedAhead = {};  // the reorder below ranks over the slots
  m_grid->build(m_pos[p], m_count);
  planReachWindows();
  m_grid->reorder(m_pos[p], {{&m_pos[p], &m_pos[1 - p]}, {&m_vel[v], &m_vel[1 - v]}});
  const std::vector<ReachWindow> windows = reachWindows();  // before the kernel's bindings
  gl::Program& prog = useKernel("balls/stats.comp", false);
  prog.set("uDomainMin", m_params.domainMin);
  constexpr std::size_t kGroupBytes = sizeof(GroupStats);
  for (const ReachWindow& w : windows) {  // the partials of each window's groups from its first group on
    gl::bindWindow(m_pos[1 - p], BALLS_POS_IN, w.sources, kVec4);
    gl::bindWindow(m_vel[1 - v], BALLS_VEL_IN, w.sources, kVec4);
    const std::size_t firstGroup = w.balls.first / BALLS_GROUP_SIZE;
    const std::size_t groups = (w.balls.count + BALLS_GROUP_SIZE - 1) / BALLS_GROUP_SIZE;
    m_stats.bindRange(GL_SHADER_STORAGE_BUFFER, BALLS_STATS, firstGroup * kGroupBytes, groups * kGroupBytes);
    prog.set("uFirst", GLuint(w.balls.first));
    prog.set("uCount", GLuint(w.balls.end()));
    prog.set("uSourceFirst", GLuint(w.sources.first));
    prog.dispatchThreads(w.balls.count);
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
