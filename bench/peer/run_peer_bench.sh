#!/usr/bin/env bash
# The peer benchmark (docs/f1-peer.md): hotlap's minimum-lap-time solve of the Perantoni-Limebeer
# 2014 F1 car on fastest-lap's 500-point Catalunya, against fastest-lap's figures on this kind of
# 2-core machine: 51 Ipopt iterations, lap 77.791 s, about 22 s wall time as shipped and about
# 11 s with glibc malloc thresholds tuned (data README: shared/data/peer).
#
# Usage: bench/peer/run_peer_bench.sh [BUILD_DIR] [RUNS]   (defaults: build, 3)
# Needs a built `hotlap` (cmake --build BUILD_DIR --target hotlap). Prints, for each run and for
# the median run: the solve wall time (Ipopt, from the JSON summary), the whole command's wall and
# CPU time, Ipopt iterations and the lap time, then the ratios to fastest-lap's figures. Needs
# python3 and /usr/bin/time (GNU time).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${1:-$root/build}"
runs="${2:-3}"
exe="$build/hotlap"
[[ -x "$exe" ]] || { echo "no $exe: build it first (cmake --build $build --target hotlap)" >&2; exit 2; }

peer_lap=77.791
peer_iter=51
peer_shipped_s=22
peer_tuned_s=11

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

results=()
for i in $(seq 1 "$runs"); do
  start=$(date +%s.%N)
  # The command's CPU time (user + system) too: the solve is single-threaded, so on an idle
  # machine its wall time equals its CPU time; on a loaded one the CPU time is the fairer figure.
  /usr/bin/time -f "%U %S" -o "$tmp/run$i.cpu" \
    "$exe" optimise --track catalunya-fl --car f1-2014 --out "$tmp/run$i" \
    --json "$tmp/run$i.json" > "$tmp/run$i.log" 2>&1 || {
    echo "run $i failed:" >&2; cat "$tmp/run$i.log" >&2; exit 1; }
  end=$(date +%s.%N)
  line=$(python3 - "$tmp/run$i.json" "$start" "$end" "$tmp/run$i.cpu" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
wall = float(sys.argv[3]) - float(sys.argv[2])
user, system = (float(x) for x in open(sys.argv[4]).read().split()[-2:])
print(f"{j['solve_time_s']:.3f} {wall:.3f} {j['ipopt_iterations']} {j['lap_time_s']:.4f} "
      f"{j['status']} {user + system:.3f}")
PY
)
  read -r solve wall iters lap status cpu <<< "$line"
  printf 'run %d: solve %.2f s (command %.2f s wall, %.2f s CPU), %d Ipopt iterations, lap %.3f s, %s\n' \
    "$i" "$solve" "$wall" "$cpu" "$iters" "$lap" "$status"
  results+=("$line")
done

printf '%s\n' "${results[@]}" | python3 -c "
import sys, statistics
rows = [l.split() for l in sys.stdin if l.strip()]
rows.sort(key=lambda r: float(r[0]))
m = rows[len(rows) // 2]
solve, wall, iters, lap, cpu = float(m[0]), float(m[1]), int(m[2]), float(m[3]), float(m[5])
load = open('/proc/loadavg').read().split()[0]
peer_lap, peer_iter, shipped, tuned = $peer_lap, $peer_iter, $peer_shipped_s, $peer_tuned_s
print()
print(f'hotlap (median of {len(rows)}): solve wall time {solve:.2f} s, command {wall:.2f} s wall / '
      f'{cpu:.2f} s CPU, {iters} Ipopt iterations, lap {lap:.3f} s (load average now {load})')
print(f'fastest-lap:              {tuned} s tuned / {shipped} s as shipped, {peer_iter} iterations, '
      f'lap {peer_lap:.3f} s')
print(f'lap time difference: {100.0 * (lap - peer_lap) / peer_lap:+.3f} % (acceptance: within 0.5 %)')
print(f'speed-up on the solve: {tuned / solve:.1f}x vs tuned, {shipped / solve:.1f}x vs shipped '
      f'(goal: 5x vs tuned)')
print(f'speed-up on the whole command: {tuned / wall:.1f}x vs tuned, {shipped / wall:.1f}x vs shipped '
      f'(wall); {tuned / cpu:.1f}x vs tuned, {shipped / cpu:.1f}x vs shipped (CPU)')
"
