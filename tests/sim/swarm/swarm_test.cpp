// The swarm model on the GPU against the CPU reference (animated attractors, every integrator),
// walls, particle count, fp16 storage error and the size limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/packing.hpp>
#include <random>

#include "reference/swarm_reference.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::sim;

namespace {

using SwarmTest = test::GlTest;

std::vector<SwarmParticle> randomParticles(std::size_t n, unsigned seed, float speed = 0.0f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<SwarmParticle> out(n);
  for (auto& p : out) p = {{u(rng), u(rng)}, {speed * u(rng), speed * u(rng)}};
  return out;
}

double maxPosGap(const std::vector<SwarmParticle>& a, const std::vector<test::RefParticle>& b) {
  double gap = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) gap = std::max(gap, glm::length(glm::dvec2(a[i].pos) - b[i].pos));
  return gap;
}

}  // namespace

// The full law (gravity, eps, friction, aspect 16:9, bounce) with the moving "orbit" attractors:
// forces at intermediate times must use the attractors at those times. A reference that holds
// the attractors at the start of each step lands far outside the tolerance.
TEST_F(SwarmTest, AnimatedPresetMatchesCpuReferenceForEveryIntegrator) {
  constexpr int kSteps = 30;
  constexpr float kDt = 1.0f / 60.0f;
  const std::vector<SwarmParticle> start = randomParticles(2048, 7, 0.3f);
  for (Integrator integrator :
       {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4}) {
    SCOPED_TRACE(kIntegratorNames[int(integrator)]);
    SwarmParams params;
    params.integrator = integrator;
    params.friction = 0.5f;
    Swarm gpu(shaders(), params);
    gpu.setAspect(16.0 / 9.0);
    gpu.upload(start);
    test::SwarmReference cpu{params, 16.0 / 9.0, {}, test::toReference(start)};
    test::SwarmReference frozen = cpu;  // attractors held at the step's start time
    for (int n = 0; n < kSteps; ++n) {
      gpu.step(kDt);
      cpu.step(kDt);
      const double t = frozen.time;
      frozen.params.preset = Preset::None;
      frozen.extra = presetAttractors(Preset::Orbit, t);
      frozen.step(kDt);
    }
    const std::vector<SwarmParticle> got = gpu.download();
    const double gap = maxPosGap(got, cpu.particles);
    std::vector<SwarmParticle> frozenAsGpu;
    for (const auto& p : frozen.particles) frozenAsGpu.push_back({glm::vec2(p.pos), glm::vec2(p.vel)});
    const double frozenGap = maxPosGap(frozenAsGpu, cpu.particles);
    std::printf("%s: max |x_gpu - x_ref| = %.3g; with attractors frozen per step: %.3g\n",
                kIntegratorNames[int(integrator)], gap, frozenGap);
    EXPECT_LT(gap, 2e-5) << "GPU step differs from the CPU reference beyond fp32 round-off";
    if (integrator == Integrator::Verlet || integrator == Integrator::Rk4)
      EXPECT_GT(frozenGap, 20 * gap) << "the test must be able to tell when attractors are evaluated";
  }
}

TEST_F(SwarmTest, BounceKeepsEveryParticleInsideAndTheCountNeverChanges) {
  SwarmParams params;
  params.particles = 20000;
  params.preset = Preset::CentralRepulsive;
  params.friction = 0.0f;
  params.epsilon = 0.001f;  // strong kicks near the centre: particles cross walls fast
  Swarm swarm(shaders(), params);
  swarm.setAspect(2.0);
  swarm.setExtraAttractors({{{0.3, 0.2}, -8.0}, {{-0.5, -0.4}, 9.0}});
  const std::size_t bytes = swarm.state().size();
  for (int n = 0; n < 200; ++n) swarm.step(1.0 / 30.0);
  std::vector<SwarmParticle> got = swarm.download();
  ASSERT_EQ(got.size(), 20000u);
  EXPECT_EQ(swarm.count(), 20000u);
  EXPECT_EQ(swarm.state().size(), bytes);
  std::size_t outside = 0, fast = 0;
  for (const auto& p : got) {
    outside += !(std::abs(p.pos.x) <= 1.0f && std::abs(p.pos.y) <= 1.0f);  // NaN counts as outside
    fast += glm::length(p.vel) > 1.0f;
  }
  EXPECT_EQ(outside, 0u);
  EXPECT_GT(fast, 1000u) << "the test must drive particles into the walls";

  swarm.params().bounce = false;  // free flight: particles leave the box but none is lost
  for (int n = 0; n < 100; ++n) swarm.step(1.0 / 30.0);
  got = swarm.download();
  std::size_t finite = 0, gone = 0;
  for (const auto& p : got) {
    finite += std::isfinite(p.pos.x) && std::isfinite(p.pos.y);
    gone += std::abs(p.pos.x) > 1.0f || std::abs(p.pos.y) > 1.0f;
  }
  EXPECT_EQ(finite, 20000u);
  EXPECT_GT(gone, 0u);
  EXPECT_EQ(swarm.count(), 20000u);
}

// fp16 storage rounds position and velocity to 11 significant bits after every step. Measured
// here against fp32 storage from the same start (values representable in both):
// after one step the gap is one half-precision rounding (<= 2^-11 |x| per coordinate); after
// a second of the seed's settings it stays a small fraction of the box.
TEST_F(SwarmTest, Fp16StorageErrorAgainstFp32IsMeasuredAndBounded) {
  std::vector<SwarmParticle> start = randomParticles(4096, 11, 0.2f);
  for (auto& p : start) {  // start from values exact in fp16, so only the stepping differs
    p.pos = glm::unpackHalf2x16(glm::packHalf2x16(p.pos));
    p.vel = glm::unpackHalf2x16(glm::packHalf2x16(p.vel));
  }
  SwarmParams params;  // seed defaults: orbit preset, symplectic Euler, bounce
  Swarm wide(shaders(), params);
  params.storage = Storage::Fp16;
  Swarm half(shaders(), params);
  for (Swarm* s : {&wide, &half}) {
    s->setAspect(16.0 / 9.0);
    s->upload(start);
  }
  EXPECT_EQ(half.state().size(), wide.state().size() / 2) << "fp16 halves the state";
  auto gaps = [&] {
    const auto a = wide.download(), b = half.download();
    std::vector<double> d;
    for (std::size_t i = 0; i < a.size(); ++i) d.push_back(glm::length(glm::dvec2(a[i].pos - b[i].pos)));
    std::sort(d.begin(), d.end());
    return std::pair{d[d.size() / 2], d.back()};  // median, max (NDC units)
  };
  constexpr double kDt = 1.0 / 120.0;
  test::SwarmReference exact{params, 16.0 / 9.0, {}, test::toReference(start)};  // fp32 vs double, for scale
  wide.step(kDt);
  half.step(kDt);
  exact.step(kDt);
  const auto [median1, max1] = gaps();
  for (int n = 1; n < 120; ++n) {
    wide.step(kDt);
    half.step(kDt);
    exact.step(kDt);
  }
  const auto [median120, max120] = gaps();
  std::vector<double> wideGap;
  const auto wideEnd = wide.download();
  for (std::size_t i = 0; i < wideEnd.size(); ++i)
    wideGap.push_back(glm::length(glm::dvec2(wideEnd[i].pos) - exact.particles[i].pos));
  std::sort(wideGap.begin(), wideGap.end());
  std::printf(
      "fp16 vs fp32 position gap (NDC): 1 step median %.3g max %.3g; 120 steps (1 s) median %.3g max %.3g "
      "(fp32 vs double: median %.3g)\n",
      median1, max1, median120, max120, wideGap[wideGap.size() / 2]);
  RecordProperty("fp16_gap_1s_median", std::to_string(median120));
  RecordProperty("fp16_gap_1s_max", std::to_string(max120));
  EXPECT_LE(max1, std::sqrt(2.0) * std::ldexp(1.0, -11)) << "one step: one fp16 rounding per coordinate";
  EXPECT_LE(wideGap[wideGap.size() / 2], 1e-4) << "fp32 storage stays near the double reference";
  EXPECT_LE(median120, 5e-3) << "after 1 s, typical drift must stay under ~3 pixels at 1080p (1 px = 1.9e-3)";
}

TEST_F(SwarmTest, TooLargeRequestsFailBeforeAllocatingWithOneLine) {
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  const std::size_t fits = std::size_t(maxBlock) / 16;
  EXPECT_NO_THROW(checkSwarmFits(fits, Storage::Fp32));
  try {
    checkSwarmFits(fits + 1, Storage::Fp32);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos);
    EXPECT_NE(what.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), std::string::npos) << what;
    EXPECT_NE(what.find("fp16"), std::string::npos) << "suggests the smaller storage: " << what;
  }
  EXPECT_NO_THROW(checkSwarmFits(fits + 1, Storage::Fp16));
  SwarmParams params;
  params.particles = int(std::min<std::size_t>(fits + 1, kMaxSwarmParticles));
  if (std::size_t(params.particles) > fits) EXPECT_THROW(Swarm(shaders(), params), Error);
}

TEST_F(SwarmTest, ResetScattersUniformlyAtRestAndIsReproducible) {
  SwarmParams params;
  params.particles = 10000;
  params.storage = Storage::Fp16;
  Swarm swarm(shaders(), params);
  const auto a = swarm.download();
  swarm.step(0.01);
  swarm.reset();
  EXPECT_EQ(swarm.time(), 0.0);
  const auto b = swarm.download();
  int quadrant[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].pos, b[i].pos);
    ASSERT_EQ(b[i].vel, glm::vec2(0.0f));
    ASSERT_LE(std::abs(b[i].pos.x), 1.0f);
    ASSERT_LE(std::abs(b[i].pos.y), 1.0f);
    ++quadrant[(b[i].pos.x > 0) + 2 * (b[i].pos.y > 0)];
  }
  for (int q : quadrant) EXPECT_NEAR(q, 2500, 200);  // 4 sigma of a binomial(10000, 1/4)
}
