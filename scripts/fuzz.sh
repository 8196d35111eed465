#!/usr/bin/env bash
# Fuzzes one parser for a set time with libFuzzer, ASan and UBSan (clang from Debian):
#
#   scripts/fuzz.sh <parser> <seconds> [libFuzzer options...]
#   scripts/fuzz.sh obj 600                  # ten minutes of OBJ meshes
#   scripts/fuzz.sh scene 60 -jobs=2         # anything after the time goes to libFuzzer
#
# Parsers: scene rules share obj png checkpoint (tests/fuzz/CMakeLists.txt says what each calls). Builds
# build-fuzz/ (clang, TIDEPOOL_FUZZ=ON, no test suite) when needed. Starts from the seed corpus
# tests/fuzz/corpus/<parser>/ and keeps what it finds new in build-fuzz/corpus/<parser>/; a crash,
# leak, UB report, timeout or out-of-memory input is written to build-fuzz/findings/<parser>/ and
# stops the run (exit status non-zero). Replay one with: build-fuzz/tests/fuzz/<parser>_fuzz FILE
# and add it to tests/fuzz/regressions/<parser>/ with its fix (ctest replays that folder).
set -euo pipefail
cd "$(dirname "$0")/.."
parsers="scene rules share obj png checkpoint"
if [[ $# -lt 2 || " $parsers " != *" $1 "* || ! $2 =~ ^[0-9]+$ ]]; then
  echo "usage: scripts/fuzz.sh <parser> <seconds> [libFuzzer options...]  (parsers: $parsers)" >&2
  exit 2
fi
parser=$1 seconds=$2
shift 2
if ! command -v clang++ >/dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  echo "scripts/fuzz.sh needs clang with libFuzzer: apt-get install clang libclang-rt-14-dev" >&2
  exit 1
fi
build=${TIDEPOOL_FUZZ_BUILD:-build-fuzz}
if [[ ! -f $build/build.ninja ]]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTIDEPOOL_FUZZ=ON \
    -DTIDEPOOL_BUILD_TESTS=OFF ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER}
fi
cmake --build "$build" --target "${parser}_fuzz"
mkdir -p "$build/corpus/$parser" "$build/findings/$parser"
dict=()
[[ $parser == scene || $parser == rules ]] && dict=(-dict=tests/fuzz/json.dict)
# One process (the machine is shared); 10 s per input is a hang; 2 GiB is the memory ceiling.
exec "$build/tests/fuzz/${parser}_fuzz" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix="$build/findings/$parser/" "${dict[@]}" "$@" \
  "$build/corpus/$parser" "tests/fuzz/corpus/$parser"
