#!/usr/bin/env bash
# The README's second command (and CI's): install dependencies, build, run the whole test suite,
# the documentation's checks and site (scripts/docs.sh), then its sanitizer part
# (scripts/sanitize.sh --fast: the reader areas' unit tests under ASan + UBSan and a smoke of 10
# CPU seconds of every fuzz target; docs/reliability.md).
#
#   bash scripts/test.sh                 # the above
#   bash scripts/test.sh --no-sanitize   # without the sanitizer part (no Clang needed)
#   bash scripts/test.sh --sanitize      # instead: everything built with ASan + UBSan and the whole
#                                        # suite under it (scripts/sanitize.sh --full; slow)
# Both builds go through ccache (CMakeLists.txt's HOTLAP_CCACHE), so a clean clone of code built
# before on this machine compiles in seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:---sanitize-fast}
case "$mode" in
  --no-sanitize | --sanitize-fast | --sanitize) ;;
  *) echo "test.sh: unknown option '$mode' (--no-sanitize or --sanitize)" >&2; exit 2 ;;
esac
# --test: also Chromium (report tests), CalculiX (FE check); --fuzz: Clang (sanitizers, fuzzers)
fuzz_deps=--fuzz
if [ "$mode" = "--no-sanitize" ]; then fuzz_deps=; fi
bash scripts/install-deps.sh --test $fuzz_deps
if [ "$mode" = "--sanitize" ]; then
  exec bash scripts/sanitize.sh --full
fi
bash scripts/build.sh
# install-deps --test put CalculiX in place: its absence is then a failure, not a skip.
export HOTLAP_REQUIRE_CALCULIX=1
(cd build && ctest --output-on-failure --parallel "$(nproc)" --timeout 900)
# The docs: generated references current, the guides' commands' output, the site (scripts/docs.sh).
bash scripts/docs.sh
if [ "$mode" = "--sanitize-fast" ]; then
  bash scripts/sanitize.sh --fast
fi
