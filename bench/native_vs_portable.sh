#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The portable build (baseline x86-64, kernels chosen at run time) against a build for this
# machine's CPU (-DIFSFX_NATIVE=ON, -march=native), in one run: chaos_game_bench, steal_bench and
# bench/vs-flam3.sh of each, the two builds alternating round by round so that the load of a
# shared machine falls on both alike; the best of the rounds is kept. Prints per benchmark both
# figures and the portable build's speed relative to the native one (1.00 = as fast; the issue
# allows no kernel to lose more than 5%, i.e. no ratio below 0.95).
#   bash tools/build.sh native   (→ build/native; the portable one: bash tools/build.sh release)
#   bench/native_vs_portable.sh [PORTABLE_BUILD] [NATIVE_BUILD] [ROUNDS]
# (defaults build/release, build/native, 3)
set -euo pipefail
cd "$(dirname "$0")/.."
portable=${1:-build/release} native=${2:-build/native} rounds=${3:-3}
for dir in "$portable" "$native"; do
  for program in bench/chaos_game_bench bench/steal_bench cli/ifsfx; do
    [ -x "$dir/$program" ] || { echo "native_vs_portable: no $dir/$program (build it first)" >&2; exit 2; }
  done
done
command -v python3 >/dev/null || { echo "native_vs_portable: needs python3" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flam3=0
command -v flam3-render >/dev/null && flam3=1

# Lines "KIND NAME REAL CPU UNIT": Google Benchmark's times (ms; lower is better; CPU: of the
# benchmark's main thread, less disturbed by other processes than wall time on a shared machine),
# or vs-flam3's rate ("-" and Mpts per whole-process CPU-second; higher is better).
for round in $(seq "$rounds"); do
  for kind in portable native; do
    dir=$portable
    [ "$kind" = native ] && dir=$native
    for program in chaos_game_bench steal_bench; do
      "$dir/bench/$program" --benchmark_format=json 2>/dev/null |
        python3 -c 'import json, sys
for b in json.load(sys.stdin)["benchmarks"]:
    print(sys.argv[1], b["name"], b["real_time"], b["cpu_time"], b["time_unit"])' "$kind" \
          >>"$work/results"
    done
    if ((flam3)); then
      bash bench/vs-flam3.sh "$dir/cli/ifsfx" |
        awk -v kind="$kind" '/Mpts per CPU-second/ { print kind, "vs-flam3:" $1, "-", $3, "Mpts" }' \
          >>"$work/results"
    fi
    echo "round $round: $kind done" >&2
  done
done

# Per benchmark the best of the rounds of each build, and the portable build's speed relative to
# the native one from wall time and from CPU time.
python3 - "$work/results" <<'PY'
import sys
best = {}
order = []
for line in open(sys.argv[1]):
    kind, name, real, cpu, unit = line.split()
    if name not in order:
        order.append(name)
    rate = unit == "Mpts"
    real = None if real == "-" else float(real)
    cpu = float(cpu)
    old = best.get((kind, name))
    if old is None:
        best[kind, name] = [real, cpu, unit]
    else:
        pick = max if rate else min
        if real is not None:
            old[0] = pick(old[0], real)
        old[1] = pick(old[1], cpu)
print(f"{'benchmark (best of the rounds)':44} {'portable':>19} {'native':>19} {'speed':>13}")
print(f"{'':44} {'wall':>9} {'CPU':>9} {'wall':>9} {'CPU':>9} {'wall':>6} {'CPU':>6}")
for name in order:
    p, q = best.get(("portable", name)), best.get(("native", name))
    if p is None or q is None:
        continue
    rate = p[2] == "Mpts"
    f = lambda v: "-" if v is None else f"{v:.1f}"
    speed = lambda a, b: "-" if a is None or b is None else f"{(a / b if rate else b / a):.3f}"
    print(f"{name:44} {f(p[0]):>9} {f(p[1]):>9} {f(q[0]):>9} {f(q[1]):>9} "
          f"{speed(p[0], q[0]):>6} {speed(p[1], q[1]):>6}")
print("times in ms (vs-flam3: Mpts per CPU-second); speed: portable relative to native, > 1 when "
      "the portable build is faster")
PY
