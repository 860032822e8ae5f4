#!/usr/bin/env bash
# The README's second command (and CI's): install dependencies, build, run the whole test suite.
#
#   bash scripts/test.sh                  # the above
#   bash scripts/test.sh --sanitize-fast  # then the sanitizer part (scripts/sanitize.sh --fast:
#                                         # the reader areas' unit tests under ASan + UBSan and a
#                                         # 10-second smoke of every fuzz target), about 7 more
#                                         # minutes on 2 cores; CI runs it with HOTLAP_CI_SANITIZE=1
#   bash scripts/test.sh --sanitize       # instead: everything built with ASan + UBSan and the whole
#                                         # suite under it (scripts/sanitize.sh --full; slow)
# docs/reliability.md.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-}
case "$mode" in
  "" | --sanitize-fast | --sanitize) ;;
  *) echo "test.sh: unknown option '$mode' (--sanitize-fast or --sanitize)" >&2; exit 2 ;;
esac
# --test: also Chromium (report tests), CalculiX (FE check); --fuzz: Clang (sanitizers, fuzzers)
bash scripts/install-deps.sh --test ${mode:+--fuzz}
if [ "$mode" = "--sanitize" ]; then
  exec bash scripts/sanitize.sh --full
fi
bash scripts/build.sh
# install-deps --test put CalculiX in place: its absence is then a failure, not a skip.
export HOTLAP_REQUIRE_CALCULIX=1
(cd build && ctest --output-on-failure --parallel "$(nproc)" --timeout 900)
if [ "$mode" = "--sanitize-fast" ]; then
  bash scripts/sanitize.sh --fast
fi
