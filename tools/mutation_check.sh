#!/usr/bin/env bash
# Shows that the checks of issue 43, item 6 can fail: for each, a small mutation of the code under
# test (or, where the check is about what the test itself did, of the test's own action), a
# rebuild of the one target the test needs, the one test run, and a table of whether it failed as
# expected and by the check in question (its failure message, MARKER, in the output).
#
#   bash tools/mutation_check.sh BUILD_DIR [NAME ...]   # the mutations named (default: all)
#   bash tools/mutation_check.sh --list                 # their names, cheap ones first
#
# BUILD_DIR is a configured build folder of this checkout (e.g. `cmake -S . -B build-h -G Ninja
# -DCMAKE_BUILD_TYPE=Release`); it is rebuilt with each mutation and once more at the end with
# the files restored (HOTLAP_MUTATION_NO_REBUILD=1: not at the end). Every mutated file is copied
# to a temporary folder first and copied back however the script ends (trap), so the tree is left
# as it was (git diff before and after: the same); the copy back gives the file a new time, so the
# next build compiles it again. Costs (2 cores): yaml_self_alias and sweep_rerun well under a
# minute each once built; stint_* about 1 minute; fe_checkpoint and fe_ensemble_step a few; the
# disc-limit ones several minutes each (optimal-control solves; disc_delta_command runs the
# README's main job).
# Exit status: 0 if every mutation run made its test fail by its check, 1 otherwise.
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD

# name | file | perl substitution (applied with perl -0pi -e) | build target | test | marker
# test: "gtest FILTER" (BUILD_DIR/hotlap_tests) or "pytest NODE" (python/tests, Debian's python3).
mutations=(
  "yaml_self_alias|src/hotlap/common/yaml_reader.cc|s/  if \(depth > kMaxYamlDepth\) \{\n/  if (depth > kMaxYamlDepth) return;  \/\/ MUTATION\n  if (false) {\n/|hotlap_tests|gtest YamlReaderTest.AliasesThatHoldThemselvesOrExplodeAreRefused|an alias that holds itself accepted"
  "sweep_rerun|python/tests/test_sweep.py|s/os\.kill\(pid, signal\.SIGKILL\)/os.kill(pid, 0)  # MUTATION: no kill/|hotlap_python hotlap|pytest test_sweep.py::test_a_worker_killed_during_a_case_leaves_every_case_done|was not run again"
  "stint_last_iterate|src/hotlap/ocp/stint_checkpoint.cc|s/(void StintCheckpoints::WriteStintIterate\(const SolveResult& iterate\) const \{\n)/\$1  if (std::filesystem::exists(dir_ \/ \"stint_iterate.bin\")) return;  \/\/ MUTATION: the first kept\n/|hotlap_tests|gtest StintCommandTest.KilledStintResumesFromItsCheckpoints|more than one interval behind"
  "fe_checkpoint|src/hotlap/fe/checkpoint.cc|s/(\nvoid WriteCheckpointFile\([^)]*\) \{\n)/\$1  if (std::filesystem::exists(path)) return;  \/\/ MUTATION: the first kept\n/|hotlap_tests|gtest FeCommandTest.KilledRunRestartsFromItsLastCheckpointLosingAtMostOneInterval|more than one interval behind the run"
  "fe_ensemble_step|src/hotlap/abs/fe_abs_torque.cc|s/  spin_sum_ \+= dt \* spin;/  spin_sum_ += dt * spin * (1.0 + 1e-2 * (6e-6 \/ dt));  \/\/ MUTATION: a step-dependent sensor gain/|hotlap_tests|gtest FeAbsEnsembleTest.FiguresAgreeAtTheFullAndHalfStepWithinTheirMargins|moved with the step"
  "disc_lap_time|src/hotlap/ocp/disc_limit_comparison.cc|s/limited_options\.front_disc_limit = front_disc_limit;/limited_options.front_disc_limit = front_disc_limit + 150.0;  \/\/ MUTATION/|hotlap_tests|gtest DiscLimitComparisonTest.LimitHoldsBindsAndCostsTime|and from_guess.run.solution.lap_time"
  "disc_delta|src/hotlap/ocp/disc_limit_comparison.cc|s/limited_options\.front_disc_limit = front_disc_limit;/limited_options.front_disc_limit = front_disc_limit + 1000.0;  \/\/ MUTATION/|hotlap_tests|gtest DiscLimitComparisonTest.LimitHoldsBindsAndCostsTime|the limit costs no time"
  "disc_delta_command|src/hotlap/ocp/disc_limit_comparison.cc|s/limited_options\.front_disc_limit = front_disc_limit;/limited_options.front_disc_limit = front_disc_limit + 1000.0;  \/\/ MUTATION/|hotlap_tests|gtest OptimalLapCommandTest.DarlingtonDiscLimitComparisonMeetsTheAcceptance|the limit costs no time"
)

if [ "${1:-}" = "--list" ]; then
  for m in "${mutations[@]}"; do echo "${m%%|*}"; done
  exit 0
fi
if [ $# -lt 1 ] || [ ! -f "$1/build.ninja" ]; then
  echo "usage: bash tools/mutation_check.sh BUILD_DIR [NAME ...] (a configured Ninja build folder)" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
shift
wanted=("$@")

saved=$(mktemp -d "${TMPDIR:-/tmp}/hotlap-mutation.XXXXXX")
restore() {
  local f
  for f in "$saved"/files/*; do
    [ -e "$f" ] || continue
    # Not cp -p: the restored file gets a new time, so the next build compiles it again.
    cp "$f" "$root/$(cat "$f.path")"
    rm -f "$f" "$f.path"
  done
}
trap 'restore; rm -rf "$saved"' EXIT
trap 'exit 130' INT TERM
mkdir -p "$saved/files"

rows=()
status=0
targets_built=()
for m in "${mutations[@]}"; do
  IFS='|' read -r name file expr target test marker <<<"$m"
  if [ ${#wanted[@]} -gt 0 ] && [[ ! " ${wanted[*]} " =~ " $name " ]]; then continue; fi
  echo "== $name: $file"
  key=$(echo "$file" | tr / _)
  cp "$root/$file" "$saved/files/$key"
  echo "$file" >"$saved/files/$key.path"
  perl -0pi -e "$expr" "$root/$file"
  if cmp -s "$root/$file" "$saved/files/$key"; then
    rows+=("$name|$file|did not apply|no")
    status=1
    restore
    continue
  fi
  git --no-pager diff --no-color -U0 -- "$file" | sed -n '/^@@/,$p' | grep '^[-+]' || true
  targets_built+=($target)
  log=$saved/$name.log
  if ! cmake --build "$build" --target $target >"$log" 2>&1; then
    rows+=("$name|$file|did not build ($log kept)|no")
    cp "$log" "${TMPDIR:-/tmp}/hotlap-mutation-$name.build.log"
    status=1
    restore
    continue
  fi
  kind=${test%% *}
  what=${test#* }
  rc=0
  if [ "$kind" = gtest ]; then
    (cd "$build" && ./hotlap_tests --gtest_filter="$what" --gtest_brief=1) >"$log" 2>&1 || rc=$?
  else
    (cd "$root/python/tests" && PYTHONPATH="$build/python" HOTLAP_BINARY="$build/hotlap" \
      HOTLAP_DATA_DIR="$root/data" MPLBACKEND=Agg /usr/bin/python3 -m pytest -q \
      -p no:cacheprovider "$what") >"$log" 2>&1 || rc=$?
  fi
  restore
  if [ "$rc" -ne 0 ] && grep -qF -- "$marker" "$log"; then
    rows+=("$name|$file|yes (exit $rc; '$marker')|yes")
  elif [ "$rc" -ne 0 ]; then
    rows+=("$name|$file|failed, but not by its check (no '$marker'; log: ${TMPDIR:-/tmp}/hotlap-mutation-$name.log)|no")
    cp "$log" "${TMPDIR:-/tmp}/hotlap-mutation-$name.log"
    status=1
  else
    rows+=("$name|$file|no: the test passed|no")
    cp "$log" "${TMPDIR:-/tmp}/hotlap-mutation-$name.log"
    status=1
  fi
  grep -E '^\[  FAILED  \]|Failure|Expected|Which is|assert|Error' "$log" | head -8 | sed 's/^/    /'
done

restore
if [ ${#targets_built[@]} -gt 0 ] && [ -z "${HOTLAP_MUTATION_NO_REBUILD:-}" ]; then
  echo "== rebuilding with the files restored"
  # shellcheck disable=SC2046
  cmake --build "$build" $(printf -- '--target %s ' $(printf '%s\n' "${targets_built[@]}" | sort -u)) \
    >/dev/null || status=1
fi

echo
printf '%-20s | %-44s | %s\n' check mutation "failed as expected"
printf '%-20s-+-%-44s-+-%s\n' -------------------- -------------------------------------------- ------------------
for r in "${rows[@]}"; do
  IFS='|' read -r name file result ok <<<"$r"
  printf '%-20s | %-44s | %s\n' "$name" "$file" "$result"
done
exit $status
