#!/usr/bin/env bash
# The README's first command: install dependencies, build, and run the main job on the built-in
# Darlington example: the NASCAR paper's comparison, the Gen-7-like car's minimum-time lap of
# Darlington with tyre and brake temperatures and wear as states, without and with a 500 degC
# front-disc limit, writing out/darlington/{unconstrained.csv,constrained.csv,compare.html} and
# out/darlington.json (two Ipopt solves side by side, 30-50 s on two cores once built).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh --target hotlap  # the program only; scripts/test.sh builds the rest
mkdir -p out
./build/hotlap lap --method ocp --compare-disc-limit-C 500 --track darlington --car gen7 \
  --out out/darlington --json out/darlington.json
