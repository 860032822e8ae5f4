#!/usr/bin/env bash
# Builds (if needed) and runs hotlap's libFuzzer targets (fuzz/, docs/reliability.md).
#
#   bash scripts/fuzz.sh [TARGET|all] [SECONDS]   # default: all, 60 CPU seconds each (CPU time, not
#                                                 # wall time: a loaded machine makes a run take
#                                                 # longer, not do less or report a false hang)
#   bash scripts/fuzz.sh --list                   # the targets
#   bash scripts/fuzz.sh --summary                # fuzz/budget.tsv per target (runs, minutes, ...)
#   bash scripts/fuzz.sh --budget [TARGET|all]     # each target until the goal of
#                                                 # docs/reliability.md: 10^7 executions or one
#                                                 # CPU-hour in all (fuzz/budget.tsv's runs count),
#                                                 # whichever comes first; at nice 19 (its session's
#                                                 # too, see below), so it can run beside other
#                                                 # work for as long as it takes
#                                                 # (Ctrl-C in its terminal, or --stop, stops it, the
#                                                 # runs so far counted)
#   bash scripts/fuzz.sh --stop                   # stops a --budget run (a stop file, then SIGINT
#                                                 # to the fuzzers) so that every running chunk
#                                                 # is counted (never SIGSTOP a fuzzer: it times
#                                                 # the pause as a hang)
#
# TARGET is a name of fuzz/ without "_fuzz" (tir, telemetry_csv, ...). Targets run one after the
# other (HOTLAP_FUZZ_JOBS=N: N at a time). Each grows its corpus in fuzz/corpus/TARGET (not in
# git), starting from the seeds of the shipped data (made afresh in build-fuzz/seeds/TARGET);
# what it finds (crash-*, leak-*, timeout-*, oom-*) goes to fuzz/findings/TARGET/ (not in git).
# One line per run is appended to fuzz/stats.tsv (time, target, seconds, executions, corpus
# files, outcome, CPU seconds); --budget's runs go to fuzz/budget.tsv instead, which is in git:
# the budget's record outlives the checkout it ran in (corpora do not; an eighth column, where
# there is one, is the number of runs a line stands for: 1 otherwise). Exits 1 if any target
# found something. Needs clang (scripts/install-deps.sh --fuzz).
#
# Environment: HOTLAP_FUZZ_BUILD (build folder, default build-fuzz), HOTLAP_FUZZ_NO_BUILD=1 (run
# what is built), HOTLAP_FUZZ_ARGS (more libFuzzer options, e.g. "-max_len=4096"),
# HOTLAP_FUZZ_GOAL_RUNS and HOTLAP_FUZZ_GOAL_CPU_S (--budget's goal, default 10^7 and 3600),
# HOTLAP_FUZZ_CHUNK_S (--budget's CPU seconds a recorded run, default 600), TMPDIR (where each
# run's temporary folder goes: the targets write every input to a file there, as the readers take
# paths; default /dev/shm where it is writable, a tmpfs, else /tmp).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=${HOTLAP_FUZZ_BUILD:-build-fuzz}
jobs=${HOTLAP_FUZZ_JOBS:-1}
# Each input is written to a file before it is read: on a tmpfs that costs no disk (measured on
# this machine's ext4, tyre_yaml: 1,250 executions per CPU second in /dev/shm against 1,070 in
# /tmp, and the fuzzer at 100% of a core against 92%).
tmp_root=${TMPDIR:-}
if [ -z "$tmp_root" ]; then
  if [ -d /dev/shm ] && [ -w /dev/shm ]; then tmp_root=/dev/shm; else tmp_root=/tmp; fi
fi

targets_all=(telemetry_csv motec_csv motec_channel_map rig_csv car_yaml tyre_yaml compound_yaml
  brake_yaml abs_yaml tir track_yaml tum_csv fastest_lap_xml fe_config fe_checkpoint)

if [ "${1:-}" = "--list" ]; then
  printf '%s\n' "${targets_all[@]}"
  exit 0
fi
# --summary: fuzz/budget.tsv added up per target, as the Markdown rows of docs/reliability.md.
if [ "${1:-}" = "--summary" ]; then
  awk -F'\t' '/^#/ { next } { runs[$2] += $4; secs[$2] += $3; corpus[$2] = $5; n[$2] += ($8 == "" ? 1 : $8)
      cpu[$2] += ($7 == "" ? $3 : $7)
      if ($6 ~ /^FOUND/) found[$2]++ }
    END { for (t in runs) printf "| %s | %d | %.1f | %.1f | %d | %d | %d |\n", t, runs[t],
      secs[t] / 60, cpu[t] / 60, n[t], found[t], corpus[t] }' fuzz/budget.tsv | sort
  exit 0
fi
# --stop: asks a --budget run to stop (a stop file it looks for before each chunk and target),
# then ends the running fuzzers by SIGINT, so that each chunk is recorded as "stopped", and waits
# for the run to end.
if [ "${1:-}" = "--stop" ]; then
  mkdir -p "$build"
  touch "$build/budget.stop"
  pkill -INT -f "_fuzz fuzz/corpus" || true
  # The budget run (its shell's PID in budget.pid while it runs).
  budget_running() {
    local pid
    pid=$(cat "$build/budget.pid" 2>/dev/null) && [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null
  }
  for _ in $(seq 60); do
    if ! budget_running; then break; fi
    sleep 1
  done
  if budget_running; then
    echo "fuzz: --stop: a budget run is still there after 60 s" >&2
    exit 1
  fi
  echo "fuzz: stopped; the chunks are in fuzz/budget.tsv"
  exit 0
fi
# --budget: what each target has left of the goal (10^7 executions, 3600 CPU seconds).
budget=0
goal_runs=${HOTLAP_FUZZ_GOAL_RUNS:-10000000}
goal_cpu=${HOTLAP_FUZZ_GOAL_CPU_S:-3600}
chunk_cpu=${HOTLAP_FUZZ_CHUNK_S:-600}
stats=fuzz/stats.tsv
if [ "${1:-}" = "--budget" ]; then
  budget=1
  stats=fuzz/budget.tsv
  shift
  rm -f "$build/budget.stop"  # a stop asked of an earlier run
fi
# --budget runs at nice 19 in a session of its own. Linux groups a session's processes for the
# scheduler (autogroups): a nice value counts only within the group, so a fuzzer at nice 19 in
# the session of a terminal still took half the machine from a build started in another (seen
# 2026-11-27: two niced fuzzers at 50% of a core each beside cc1plus). The group's own nice value
# (/proc/PID/autogroup) is what yields to other sessions; it is set for the budget's session
# only. Ctrl-C here still stops the run (--stop), since the new session has no terminal.
if [ "$budget" -eq 1 ] && [ -z "${HOTLAP_FUZZ_OWN_SESSION:-}" ] && command -v setsid >/dev/null &&
  [ -e /proc/self/autogroup ]; then
  HOTLAP_FUZZ_OWN_SESSION=1 setsid --wait bash "$0" --budget "$@" &
  child=$!
  trap 'bash "$0" --stop; wait "$child"; exit $?' INT TERM
  wait "$child"
  exit $?
fi
if [ -n "${HOTLAP_FUZZ_OWN_SESSION:-}" ]; then
  echo 19 2>/dev/null >"/proc/$$/autogroup" || true
fi
if [ "$budget" -eq 1 ]; then
  mkdir -p "$build"
  echo $$ >"$build/budget.pid"
  trap 'rm -f "$build/budget.pid"' EXIT
fi
which=${1:-all}
seconds=${2:-60}
if [ "$which" = "all" ] || [ "$which" = "--configure" ]; then
  targets=("${targets_all[@]}")
else
  if [[ ! " ${targets_all[*]} " =~ " ${which} " ]]; then
    echo "fuzz.sh: unknown target '$which'; targets: ${targets_all[*]}" >&2
    exit 2
  fi
  targets=("$which")
fi

# Build: Clang with HOTLAP_FUZZ=ON (libFuzzer coverage, ASan, UBSan), -O1 with line tables for the
# sanitizers' stack traces and assertions left on (an assertion that fires is a finding too).
# The same build holds scripts/sanitize.sh --fast's unit tests of the reader areas. Without the
# precompiled header (HOTLAP_PCH, cmake/HotlapPrecompiledHeaders.cmake): this build also checks
# that every source of those areas includes what it uses.
configure() {
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" -DCMAKE_CXX_COMPILER=clang++ \
    -DHOTLAP_FUZZ=ON -DHOTLAP_BUILD_TESTS=ON "-DHOTLAP_TEST_AREAS=common;logs;tyre;brake;track;vehicle" \
    -DHOTLAP_BUILD_BENCH=OFF -DHOTLAP_BUILD_PYTHON=OFF -DHOTLAP_PCH=OFF >/dev/null
}
if [ "$which" = "--configure" ]; then
  configure
  exit 0
fi
if [ ! -f "$build/build.ninja" ]; then configure; fi
build_targets=()
for t in "${targets[@]}"; do build_targets+=(--target "${t}_fuzz"); done
if [ -z "${HOTLAP_FUZZ_NO_BUILD:-}" ]; then
  cmake --build "$build" --parallel "$(nproc)" "${build_targets[@]}"
fi

# The seeds of each target: shipped files it reads (a long CSV cut to its first lines, so inputs
# stay small and runs fast), plus fuzz/seeds/TARGET where the data has no such file.
seeds_of() {
  case "$1" in
    telemetry_csv) echo "head:data/telemetry/darlington_example.csv"
      echo "head:tests/data/motec/darlington_i2_equivalent.csv" ;;
    motec_csv) echo "head:tests/data/motec/darlington_i2.csv" ;;
    motec_channel_map) echo data/motec_channels.yaml ;;
    car_yaml) echo data/cars/gen7/car.yaml data/cars/f1-2014/car.yaml ;;
    tyre_yaml) echo data/cars/gen7/tyres/f?.yaml data/cars/gen7/tyres/r?.yaml data/tyres/*.yaml \
      data/abs/tyre_235_75r15_brush.yaml ;;
    compound_yaml) echo data/cars/gen7/tyres/compound.yaml ;;
    brake_yaml) echo data/cars/gen7/brakes/*.yaml data/abs/brake.yaml ;;
    abs_yaml) echo data/abs/paper.yaml ;;
    tir) echo data/cars/gen7/tyres/*.tir tests/data/tir/*/*.tir ;;
    track_yaml) echo data/tracks/darlington.yaml ;;
    tum_csv) echo data/tracks/*.csv ;;
    fastest_lap_xml) echo data/tracks/catalunya-fl.xml ;;
    fe_config) echo data/fe/*.yaml ;;
  esac
}
dict_of() {
  case "$1" in
    *_csv) echo fuzz/dicts/csv.dict ;;
    *_yaml | motec_channel_map | fe_config) echo fuzz/dicts/yaml.dict ;;
    tir) echo fuzz/dicts/tir.dict ;;
    *_xml) echo fuzz/dicts/xml.dict ;;
  esac
}

run_one() {
  local t=$1
  local seeds=$build/seeds/$t corpus=fuzz/corpus/$t findings=fuzz/findings/$t
  rm -rf "$seeds"
  mkdir -p "$seeds" "$corpus" "$findings"
  local s
  for s in $(seeds_of "$t"); do
    if [[ $s == head:* ]]; then
      head -n 40 "${s#head:}" >"$seeds/$(basename "${s#head:}")"
    else
      cp "$s" "$seeds/"
    fi
  done
  if [ -d "fuzz/seeds/$t" ]; then cp fuzz/seeds/"$t"/* "$seeds/"; fi
  if [ "$t" = fe_checkpoint ]; then
    local seed_tmp
    seed_tmp=$(mktemp -d "$tmp_root/hotlap-fuzz-seeds.XXXXXX")
    TMPDIR=$seed_tmp HOTLAP_FUZZ_WRITE_SEEDS=$seeds "$build/fuzz/${t}_fuzz"
    rm -rf "$seed_tmp"
  fi
  local dict
  dict=$(dict_of "$t")
  local log=$build/logs/$t.log
  mkdir -p "$build/logs"
  # --budget runs the target in chunks of HOTLAP_FUZZ_CHUNK_S CPU seconds (default 600), each
  # recorded as it ends, until the goal: a run stopped any way loses at most one chunk.
  while :; do
    # A run of SECONDS CPU seconds (RLIMIT_CPU: SIGXCPU ends it), not libFuzzer's
    # -max_total_time, which is wall time: the same work however loaded the machine is.
    local rc=0 limits=(-max_total_time=0) cpu_limit=$seconds
    local prefix=(prlimit --cpu="$seconds:$((seconds + 30))" --)
    if [ "$budget" -eq 1 ] && [ -e "$build/budget.stop" ]; then return 0; fi
    if [ "$budget" -eq 1 ]; then
      local done_runs done_cpu
      read -r done_runs done_cpu < <(awk -F'\t' -v t="$t" '$2 == t { r += $4; c += ($7 == "" ? $3 : $7) }
        END { printf "%d %d\n", r, c }' "$stats" 2>/dev/null || echo "0 0")
      if [ "${done_runs:-0}" -ge "$goal_runs" ] || [ "${done_cpu:-0}" -ge "$goal_cpu" ]; then
        echo "fuzz: $t: goal reached (${done_runs:-0} executions, ${done_cpu:-0} CPU s)"
        return 0
      fi
      # The rest of the goal: -runs for the executions, RLIMIT_CPU (SIGXCPU) for the CPU time.
      limits=(-runs=$((goal_runs - ${done_runs:-0})) -max_total_time=0)
      cpu_limit=$((goal_cpu - ${done_cpu:-0}))
      if [ "$cpu_limit" -gt "$chunk_cpu" ]; then cpu_limit=$chunk_cpu; fi
      prefix=(nice -n 19 prlimit --cpu=$cpu_limit:$((cpu_limit + 30)) --)
    fi
    local started_wall
    started_wall=$(date +%s)
    # This shell's own and its waited-for children's CPU ticks (utime, stime, cutime, cstime).
    local me=$BASHPID started_cpu
    started_cpu=$(awk '{ print $14 + $15 + $16 + $17 }' "/proc/$me/stat")
    # The run's own temporary folder, removed here however the run ended (a fuzzer ended by its
    # CPU limit or a crash does not remove its own).
    local run_tmp
    run_tmp=$(mktemp -d "$tmp_root/hotlap-fuzz-$t.XXXXXX")
    # -timeout: an input that takes 10 s is a hang. Leaks are findings (ASan's leak checker).
    # The group's stderr is closed to the shell's own report of the run's end by its CPU limit
    # ("CPU time limit exceeded"): the expected end, judged below from the exit status.
    {
      TMPDIR=$run_tmp ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
        UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1} \
        "${prefix[@]}" "$build/fuzz/${t}_fuzz" "$corpus" "$seeds" ${dict:+-dict=$dict} \
        "${limits[@]}" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$findings/" ${HOTLAP_FUZZ_ARGS:-} >"$log" 2>&1 || rc=$?
    } 2>/dev/null
    # A run that ended of itself (exit 0) has removed its own temporary folder (fuzz_input.cc):
    # one left behind is a finding (the fuzzers left theirs until 2026-11-27).
    local left_behind=""
    if [ "$rc" -eq 0 ]; then
      left_behind=$(find "$run_tmp" -mindepth 1 -maxdepth 1 -name 'hotlap-fuzz-*' | head -1)
    fi
    rm -rf "$run_tmp"
    # CPU seconds of the fuzzer (children of this shell, in clock ticks).
    local cpu_seconds
    cpu_seconds=$(awk -v s="$started_cpu" -v hz="$(getconf CLK_TCK)" \
      '{ printf "%.0f", ($14 + $15 + $16 + $17 - s) / hz }' "/proc/$me/stat")
    # The CPU limit reached (SIGXCPU, exit 152, which only the limit sends; or SIGKILL at the
    # hard limit, 137, with the CPU time to show for it): the run or chunk ended, not a finding.
    # (The CPU time counted here can fall short of the limit's: 591 s for a 600 s chunk, twice on
    # 2026-11-27, which then counted as findings.)
    if [ "$rc" -eq 152 ] || { [ "$rc" -eq 137 ] && [ "$cpu_seconds" -ge $((cpu_limit - 5)) ]; }; then
      rc=0
    fi
    local runs
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    # Killed by its CPU limit, libFuzzer prints no final stats: its last status line's count.
    if [ -z "$runs" ]; then runs=$(sed -n 's/^#\([0-9][0-9]*\)[[:space:]].*/\1/p' "$log" | tail -1); fi
    local files
    files=$(find "$corpus" -type f | wc -l)
    local outcome=ok
    # Stopped by hand (SIGINT: libFuzzer's interrupted_exitcode, 72): counted, not a finding.
    if [ "$rc" -eq 72 ]; then outcome=stopped; fi
    if [ "$rc" -ne 0 ] && [ "$rc" -ne 72 ]; then outcome="FOUND (exit $rc; $log)"; fi
    # libFuzzer's -timeout is wall-clock: a fuzzer starved by other work (a build, a CI run on
    # both cores, the smokes' parallel jobs) reports an input that took 1 CPU-second as a 10 s
    # hang (twice on 2026-11-27, both at the start of a CI run). Replay it: under 5 CPU-seconds
    # it was the starvation, recorded as such (the input kept as starved-*), and the target goes
    # on; a hang is judged by CPU time, in a smoke as in the budget.
    if [ "$rc" -ne 0 ] && grep -q "ERROR: libFuzzer: timeout" "$log"; then
      local unit
      unit=$(sed -n 's/.*Test unit written to \(.*timeout-[0-9a-f]*\).*/\1/p' "$log" | tail -1)
      if [ -n "$unit" ] && [ -f "$unit" ]; then
        local before_replay replay_rc=0 replay_cpu
        before_replay=$(awk '{ print $16 + $17 }' "/proc/$me/stat")
        prlimit --cpu=30:35 -- "$build/fuzz/${t}_fuzz" "$unit" >"$log.replay" 2>&1 || replay_rc=$?
        replay_cpu=$(awk -v s="$before_replay" -v hz="$(getconf CLK_TCK)" \
          '{ printf "%.1f", ($16 + $17 - s) / hz }' "/proc/$me/stat")
        if [ "$replay_rc" -eq 0 ] && awk -v c="$replay_cpu" 'BEGIN { exit !(c < 5) }'; then
          mv "$unit" "$(dirname "$unit")/starved-${unit##*/timeout-}"
          outcome="starved (a wall-clock timeout under load; the input replays in $replay_cpu CPU s)"
          rc=0
        fi
      fi
    fi
    if [ -n "$left_behind" ]; then
      outcome="FOUND (left its temporary folder $(basename "$left_behind") behind)"
      rc=1
    fi
    local wall=$(($(date +%s) - started_wall))
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$t" "$wall" "${runs:-?}" \
      "$files" "$outcome" "$cpu_seconds" >>"$stats"
    echo "fuzz: $t: ${runs:-?} executions in $wall s ($cpu_seconds CPU s), corpus $files files: $outcome"
    if [ "$outcome" = stopped ]; then return 0; fi
    if [ "$rc" -ne 0 ]; then
      grep -m 3 -E "ERROR|SUMMARY|runtime error|terminate called" "$log" || true
      return 1
    fi
    if [ "$budget" -eq 0 ]; then return 0; fi
  done
}

status=0
# --stop asked for (--budget): no other target is started.
stopping() { [ "$budget" -eq 1 ] && [ -e "$build/budget.stop" ]; }
if [ "$jobs" -le 1 ]; then
  for t in "${targets[@]}"; do
    if stopping; then break; fi
    run_one "$t" || status=1
  done
else
  running=0
  for t in "${targets[@]}"; do
    if stopping; then break; fi
    run_one "$t" &
    running=$((running + 1))
    if [ "$running" -ge "$jobs" ]; then
      wait -n || status=1
      running=$((running - 1))
    fi
  done
  while [ "$running" -gt 0 ]; do
    wait -n || status=1
    running=$((running - 1))
  done
fi
exit $status
