#!/usr/bin/env bash
# The README's second command (and CI's): install dependencies, build, run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --test  # --test: also Chromium (report tests), CalculiX (FE check)
bash scripts/build.sh
cd build
# install-deps --test put CalculiX in place: its absence is then a failure, not a skip.
export HOTLAP_REQUIRE_CALCULIX=1
ctest --output-on-failure --parallel "$(nproc)" --timeout 900
