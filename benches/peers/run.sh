#!/usr/bin/env bash
# The peer harness of issue 47: our generated PGA f32 and CGA f64 products against klein
# (hand-written SSE PGA, f32) and GATL (C++17 templates, CGA f64; also ga-benchmark's inverse
# kinematics, gatl_ik.hpp), on one input file, checked element by element, in a table graded
# against the issue's targets.
#
#   benches/peers/run.sh KLEIN_DIR GATL_DIR [ROUNDS]
#
# KLEIN_DIR: a checkout of https://github.com/jeremyong/klein (headers in public/klein);
# GATL_DIR: a checkout of https://github.com/laffernandes/gatl (headers in cpp/include/gatl).
# Either may be `-` to leave that peer out. Nothing of either is kept in this repository.
# Flags: ours at the x86-64 baseline (no -C target-cpu; `cargo build --release`), klein with
# g++ -O3 -DNDEBUG -std=c++17 -msse4.1 (klein needs SSE4.1), GATL with g++ -O3 -DNDEBUG
# -std=c++17 at the baseline. ROUNDS (default 5) runs of ours, klein and GATL, alternating;
# the table gives medians over the rounds. Everything is built and written under target/peers
# (our side under $CARGO_TARGET_DIR when it is set).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
klein="${1:?usage: run.sh KLEIN_DIR GATL_DIR [ROUNDS]}"
gatl="${2:?usage: run.sh KLEIN_DIR GATL_DIR [ROUNDS]}"
rounds="${3:-5}"
out="$root/target/peers"
mkdir -p "$out"
rm -f "$out"/*.times "$out"/*.out
cxx=(g++ -O3 -DNDEBUG -std=c++17)
describe() { git -C "$1" describe --tags --always 2>/dev/null || echo unknown; }

peers=()
if [ "$klein" != - ]; then
  [ -f "$klein/public/klein/klein.hpp" ] || { echo "no klein headers under $klein/public" >&2; exit 2; }
  echo "klein $(describe "$klein") ($(git -C "$klein" rev-parse HEAD 2>/dev/null || echo '?')): -msse4.1"
  "${cxx[@]}" -msse4.1 -I"$klein/public" "$here/klein.cpp" -o "$out/klein-peer"
  peers+=(klein)
fi
if [ "$gatl" != - ]; then
  [ -f "$gatl/cpp/include/gatl/ga3c.hpp" ] || { echo "no GATL headers under $gatl/cpp/include" >&2; exit 2; }
  echo "GATL $(describe "$gatl") ($(git -C "$gatl" rev-parse HEAD 2>/dev/null || echo '?')): baseline"
  # The operation set in one object per left grade (gatl_ops.cpp): one translation unit for
  # all of it needs many GiB of compiler memory. Objects are rebuilt only when a source changed.
  objs=()
  for g in 0 1 2 3 4 5; do
    o="$out/gatl_ops$g.o"
    if [ ! -f "$o" ] || [ -n "$(find "$here" -name 'gatl_*' -newer "$o")" ] || [ "$here/peer_io.hpp" -nt "$o" ]; then
      "${cxx[@]}" -I"$gatl/cpp/include" -DGATL_OPS_LEFT=$g -c "$here/gatl_ops.cpp" -o "$o"
    fi
    objs+=("$o")
  done
  "${cxx[@]}" -I"$gatl/cpp/include" "$here/gatl.cpp" "${objs[@]}" -o "$out/gatl-peer"
  peers+=(gatl)
fi
echo "g++: $(g++ -dumpfullversion); rustc: $(rustc --version)"

(cd "$root" && cargo build --release -p benches --example peer_ops)
ours="${CARGO_TARGET_DIR:-$root/target}/release/examples/peer_ops"
"$ours" gen "$out/input.bin"
for r in $(seq 1 "$rounds"); do
  "$ours" run "$out/input.bin" "$out/ours.$r"
  for p in "${peers[@]}"; do "$out/$p-peer" "$out/input.bin" "$out/$p.$r"; done
done
# Every round writes the same outputs; the report compares the last round's.
for side in ours "${peers[@]}"; do mv "$out/$side.$rounds.out" "$out/$side.out"; rm -f "$out/$side".*.out; done
"$ours" report "$out" "$rounds"
