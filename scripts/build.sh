#!/usr/bin/env bash
# Configures and builds hotlap in build/ (Release). `--target NAME` (repeatable) builds only those
# targets (the quick start builds just the hotlap program); other arguments go to cmake's
# configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
configure=()
targets=()
while [ $# -gt 0 ]; do
  if [ "$1" = "--target" ] && [ $# -ge 2 ]; then
    targets+=(--target "$2")
    shift 2
  else
    configure+=("$1")
    shift
  fi
done
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${configure[@]}" >/dev/null
cmake --build build --parallel "$(nproc)" "${targets[@]}"
