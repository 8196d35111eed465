// Verlet neighbour lists (issue 20): a lists run finds exactly the grid's contacts. At every step
// of a sloshing block, the state the lists run holds is stepped once more by a grid twin, and
// both results agree to float rounding (the sums over the same contacts run in another order);
// the lists were reused between builds and rebuilt when needed; a list too short for its ball
// falls back to the grid and still agrees; two lists runs are bit-identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/balls/balls.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;

namespace {

class BallsLists : public test::GlTest {};

// A block of water released against a wall: it falls, splashes and slides, so the balls move
// relative to each other (the lists must be rebuilt now and then) but slowly enough to keep them.
Params sloshing(Integrator integrator, Contact contact = Contact::SpringDashpot) {
  Params p;
  p.radius = 0.01f;
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(0.3f, 0.12f, 0.3f);
  p.fill = Fill::Block;
  p.fillMin = glm::vec3(0.0f);
  p.fillMax = glm::vec3(0.12f, 0.12f, 0.16f);
  p.jitter = 0.1f;
  p.contact = contact;
  p.integrator = integrator;
  p.contactTime = 0.004f;
  p.dt = 2e-4f;
  p.substeps = 1;
  p.neighbours = Neighbours::Lists;
  p.skin = 0.05f;  // thin: the lists go stale within a few dozen steps
  return p;
}

struct Mismatch {
  double position = 0, velocity = 0;  // largest differences, m and m/s
  double speed = 0;                   // largest speed, m/s
};

// Names each ball by its index in position w, which every pass carries along and none reads: both
// runs reorder their balls (the grid twin every step, twice in Verlet's first; the lists run at
// its rebuilds).
void nameBalls(Balls& b) {
  std::vector<glm::vec4> x = b.downloadPositions();
  for (std::size_t i = 0; i < x.size(); ++i) x[i].w = float(i);
  b.upload(x, b.downloadVelocities());
}

// One step of `lists` against a grid twin started from the same state.
Mismatch stepBoth(Balls& lists, gl::ShaderLibrary& shaders, const Params& params) {
  Params gp = params;
  gp.neighbours = Neighbours::Grid;
  Balls twin(shaders, gp);
  twin.upload(lists.downloadPositions(), lists.downloadVelocities());
  // Verlet's a(x) was evaluated with the half-step velocity: state too, not recomputable.
  if (params.integrator == Integrator::VelocityVerlet && lists.time() > 0)
    twin.uploadAccelerations(lists.downloadAccelerations());
  lists.stepOnce();
  twin.stepOnce();
  const std::vector<glm::vec4> x = lists.downloadPositions(), v = lists.downloadVelocities();
  const std::vector<glm::vec4> tx = twin.downloadPositions(), tv = twin.downloadVelocities();
  // Both runs may have moved their balls into grid order: find each by its name.
  std::vector<std::size_t> at(x.size(), x.size());
  for (std::size_t i = 0; i < x.size(); ++i) at[std::size_t(x[i].w)] = i;
  Mismatch m;
  for (std::size_t k = 0; k < tx.size(); ++k) {
    const std::size_t i = at[std::size_t(tx[k].w)];
    if (i >= x.size()) {
      ADD_FAILURE() << "ball " << tx[k].w << " is missing from the lists run";
      return {1e9, 1e9, 0};
    }
    m.position = std::max(m.position, double(glm::length(glm::vec3(x[i]) - glm::vec3(tx[k]))));
    m.velocity = std::max(m.velocity, double(glm::length(glm::vec3(v[i]) - glm::vec3(tv[k]))));
    m.speed = std::max(m.speed, double(glm::length(glm::vec3(tv[k]))));
  }
  return m;
}

void expectSameContactsAsTheGrid(gl::ShaderLibrary& shaders, const Params& p, int steps) {
  Balls lists(shaders, p);
  nameBalls(lists);
  ASSERT_TRUE(lists.listsActive());
  ASSERT_GT(lists.count(), 200u);
  for (int s = 0; s < steps; ++s) {
    const Mismatch m = stepBoth(lists, shaders, p);
    // Rounding of sums of a few dozen terms, not a missed contact: one missed contact changes a
    // velocity by about overlap / t_c, millimetres per second and more.
    ASSERT_LT(m.velocity, 1e-5 * std::max(1.0, m.speed)) << "step " << s;
    ASSERT_LT(m.position, 1e-7) << "step " << s;
  }
  const Balls::ListCounts c = lists.listCounts();
  EXPECT_GE(c.steps, std::uint32_t(steps));  // Verlet gates its first a(x) too
  EXPECT_GE(c.rebuilds, 2u) << "the balls moved past the skin: the lists must have been rebuilt";
  EXPECT_LT(c.rebuilds, c.steps) << "lists reused between builds";
}

}  // namespace

TEST_F(BallsLists, SymplecticEulerFindsTheGridsContactsAtEveryStep) {
  expectSameContactsAsTheGrid(shaders(), sloshing(Integrator::SymplecticEuler), 160);
}

TEST_F(BallsLists, VelocityVerletFindsTheGridsContactsAtEveryStep) {
  expectSameContactsAsTheGrid(shaders(), sloshing(Integrator::VelocityVerlet), 120);
}

TEST_F(BallsLists, TheCudaSampleLawFindsTheGridsContacts) {
  Params p = sloshing(Integrator::SymplecticEuler, Contact::CudaSample);
  p.dt = 0.5f;  // the sample's per-step law (bench-lattice's units)
  p.gravity = glm::vec3(0.0f, 0.0f, -0.0003f);
  p.domainMin = glm::vec3(-1.0f);
  p.domainMax = glm::vec3(1.0f);
  p.fill = Fill::Lattice;
  p.latticeCount = 4096;
  p.skin = 0.3f;  // the lattice falls as one for a while, then collapses
  expectSameContactsAsTheGrid(shaders(), p, 120);
}

TEST_F(BallsLists, BallsWithMoreNeighboursThanTheListHoldsWalkTheGrid) {
  Params p = sloshing(Integrator::SymplecticEuler);
  p.listCapacity = 4;  // a block holds up to ~18 neighbours within 2.3 r
  Balls lists(shaders(), p);
  nameBalls(lists);
  for (int s = 0; s < 20; ++s) {
    const Mismatch m = stepBoth(lists, shaders(), p);
    ASSERT_LT(m.velocity, 1e-5 * std::max(1.0, m.speed)) << "step " << s;
  }
  const Balls::ListCounts c = lists.listCounts();
  EXPECT_GT(c.overflow, 0u);
  EXPECT_EQ(c.rebuilds, c.steps) << "while lists overflow, every step rebuilds";
}

TEST_F(BallsLists, TwoRunsAreBitIdentical) {
  const Params p = sloshing(Integrator::SymplecticEuler);
  Balls a(shaders(), p), b(shaders(), p);
  for (int s = 0; s < 100; ++s) {
    a.stepOnce();
    b.stepOnce();
  }
  EXPECT_EQ(a.downloadPositions(), b.downloadPositions());
  EXPECT_EQ(a.downloadVelocities(), b.downloadVelocities());
}

TEST_F(BallsLists, ObstaclesUseTheGrid) {
  Params p = sloshing(Integrator::SymplecticEuler);
  ObstacleParams o;
  o.shape = Shape::Sphere;
  o.centre = glm::vec3(0.2f, 0.06f, 0.05f);
  o.size = glm::vec3(0.04f);
  p.obstacles.push_back(o);
  Balls b(shaders(), p);
  EXPECT_FALSE(b.listsActive());
  for (int s = 0; s < 5; ++s) b.stepOnce();
  EXPECT_EQ(b.listCounts().steps, 0u);
}

TEST_F(BallsLists, LiveEditsOfTheSearchAndTheIntegratorKeepFindingTheGridsContacts) {
  Params p = sloshing(Integrator::SymplecticEuler);
  Balls lists(shaders(), p);
  nameBalls(lists);
  auto check = [&](int steps, const char* what) {
    for (int s = 0; s < steps; ++s) {
      const Mismatch m = stepBoth(lists, shaders(), lists.params());
      ASSERT_LT(m.velocity, 1e-5 * std::max(1.0, m.speed)) << what << ", step " << s;
    }
  };
  check(10, "symplectic Euler");
  lists.params().integrator = Integrator::ExplicitEuler;  // the gated section stays the same
  check(10, "explicit Euler");
  lists.params().deterministic = false;  // fewer passes in the section: recorded again
  lists.params().integrator = Integrator::SymplecticEuler;
  for (int s = 0; s < 10; ++s) lists.stepOnce();
  lists.params().deterministic = true;
  lists.params().neighbours = Neighbours::Grid;  // back to the grid and again to lists (new cells)
  for (int s = 0; s < 5; ++s) lists.stepOnce();
  EXPECT_FALSE(lists.listsActive());
  lists.params().neighbours = Neighbours::Lists;
  lists.params().skin = 0.5f;
  lists.stepOnce();
  EXPECT_TRUE(lists.listsActive());
  check(10, "lists again, skin 0.5 r");
}
