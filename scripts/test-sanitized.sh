#!/usr/bin/env bash
# The test suite under AddressSanitizer + UndefinedBehaviorSanitizer, with LeakSanitizer checking
# every process at exit: builds build-asan/ (TIDEPOOL_SANITIZE=ON) and runs its
# tests. The `tidepool` the CLI tests spawn is build-asan/tidepool, sanitized too, and inherits
# the options below. Leaks inside the GL driver stack are suppressed in tests/sanitizers/lsan.supp
# (each entry names its library); ours never are.
# Usage: scripts/test-sanitized.sh [ctest arguments]
#   no arguments  the selection CI runs (below: every parser, the grid, determinism, GPU limits,
#                 checkpoints, bad input and drops, soak's judge, one step test per model), which
#                 fits CI's time with the sanitized build (Debug at -O1 -g1: the build is most of it)
#   -R .          everything (about three times the normal suite's time); -R Swarm: one area
# Left out (docs/RELIABILITY.md, "Sanitizers"): the build checks (Layers.*, Build.*: they test
# compilers and linkers, not our code at run time) and the soak tests (label soak: RSS under ASan
# measures its quarantine, not our memory; they run in the normal suite).
set -euo pipefail
cd "$(dirname "$0")/.."
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f build-asan/CMakeCache.txt ]; then
  cmake -S . -B build-asan "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
    -DTIDEPOOL_SANITIZE=ON
fi
cmake --build build-asan -j "$(nproc)"

# Distinct exit codes, so that a finding in a spawned `tidepool` fails a test that expects 1 or 2.
# allocator_may_return_null: a test asks the driver for a terabyte (GL_OUT_OF_MEMORY must come
# back as an error, as it does when malloc returns null, not as an ASan abort).
export ASAN_OPTIONS="allocator_may_return_null=1:detect_leaks=1:exitcode=86:halt_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:detect_invalid_pointer_pairs=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:exitcode=87"
export LSAN_OPTIONS="exitcode=88:suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
# Mesa's llvmpipe driver (swrast_dri.so) holds blocks in its globals until exit, but EGL's teardown
# unloads it first: LSan then reports them from "<unknown module>" (tests/sanitizers/lsan.supp).
# Loaded from the start, it stays, and those blocks stay reachable; nothing of ours is hidden.
driver=/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so
if [ -f "$driver" ]; then
  export LD_PRELOAD="$driver${LD_PRELOAD:+:$LD_PRELOAD}"
  ASAN_OPTIONS+=":verify_asan_link_order=0"  # the driver precedes the ASan runtime; it defines no malloc
fi
cd build-asan
# The step tests of each model (tests/sim/<model>/<model>_step_test.cpp, tests/sim/swarm/swarm_test.cpp)
# and BallsView's debug views (tests/render/balls_debug_views_test.cpp) and the water's looks
# (tests/render/water_look_test.cpp), by name: their suites hold the model's slower tests too.
steps='BallsTest\.(GpuStepEquals|AccelerationsAndOrder|NothingIsLost|PistonPushes|SpinningObstacle|TooManyBalls|TapEmits|ObstacleEdited|CountingInTheCollide)'
steps+='|FluidTest\.(OneSolverIteration|IterationsViscosity|LoadsOnTheWalls)|LifeTest\.(BinnedForces|FrictionAlone|PushBrush|VerletIsSecondOrder)'
steps+='|RipplesTest\.(GpuMatchesCpu|TotalHeightIsConserved|CourantAboveTheLimit|MovingSpherePushes)'
steps+='|SwarmTest\.(AnimatedPreset|BounceKeeps|Fp16StorageErrorAgainstFp32|TooLargeRequests|ResetScatters)'
probes='Probes\.|^Loads\.|RigidBody\.|HeaveReference\.|LoadsTest\.(TheBalls|ForceProbesRead|ProbesOfAnObstacleAdded)|BoundaryLoadsTest\.|ProbesTest\.(GaugesEqual|TheBodyProbe|AGaugeReads|PressuresEqual)|Validate\.(SceneProbes|ProbesTheScene|APressureProbe)|BallsLoads\.OneSteps|BallsLoads\.Measuring'
debugViews='BallsViewTest\.(GridCellsCompaction|GridCellsOverlay|ScreenNormalsFace)|WaterLookTest\.|WaterCausticsTest\.'
selection=(-R "Grid|Determinism|DomainEdges|ParticleMemory|GpuLimits|BadInput|Checkpoint|InputLimits|BadDrop|Hostile|Fuzz|SoakJudge|SoakCli|Json|Obj|Png|ParamJson|SceneFile|LifeRules|$steps|SwarmStages|Export|Video|Surface|Resolution|FramePacer|$probes|$debugViews|KeyBindings|Indicators")
[ $# -gt 0 ] && selection=("$@")
ctest --output-on-failure --no-tests=error -j "$(nproc)" -E '^(Layers|Build)\.' -LE soak "${selection[@]}"
