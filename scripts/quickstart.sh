#!/usr/bin/env bash
# The README's first command: install dependencies, build, and run the main job on the built-in
# Darlington example: the Gen-7-like car round Darlington (quasi-steady-state lap) with the tyre
# and brake thermal and wear models, writing out/darlington/{lap.csv,lap.html} and
# out/darlington.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p out
./build/hotlap lap --method qss --track darlington --car gen7 --out out/darlington \
  --json out/darlington.json
