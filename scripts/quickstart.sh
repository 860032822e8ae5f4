#!/usr/bin/env bash
# The README's first command: install dependencies, build, and run the main job on the built-in
# Darlington example (replay of the example lap through all four tyre and brake models).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p out
./build/hotlap replay --telemetry data/telemetry/darlington_example.csv \
  --out out/darlington_replay.csv --json out/darlington_replay.json --heat-flows
