#!/usr/bin/env bash
# Installs every build and test dependency of hotlap from Debian's packages (bookworm).
# Idempotent: safe to run any number of times. Needs root (or sudo) and the Debian archive.
#
#   bash scripts/install-deps.sh          # what building and running hotlap needs
#   bash scripts/install-deps.sh --test   # also what the test suite needs (scripts/test.sh)
#   bash scripts/install-deps.sh --fuzz   # also Clang, libFuzzer, libomp: the fuzzers and the
#                                         # sanitizer build (scripts/fuzz.sh, sanitize.sh)
set -euo pipefail

with_tests=0
with_fuzz=0
for arg in "$@"; do
  case "$arg" in
    --test) with_tests=1 ;;
    --fuzz) with_fuzz=1 ;;
    *) echo "install-deps: unknown option '$arg' (options: --test, --fuzz)" >&2; exit 2 ;;
  esac
done

packages=(
  build-essential cmake ninja-build pkg-config git
  ccache                 # compiler cache: a clean clone of code built before compiles in seconds
  libeigen3-dev          # linear algebra: small fixed-size systems, Cholesky convection matrices
  libceres-dev           # least squares and Jet automatic differentiation (fitting, model AD)
  coinor-libipopt-dev    # Ipopt: the optimal-control lap's sparse nonlinear programme
  libyaml-cpp-dev        # parameter files
  libpugixml-dev         # XML input (fastest-lap circuits and car): a kept library, not a hand-written parser
  libcli11-dev           # command-line parsing
  libfmt-dev             # formatted terminal output
  nlohmann-json3-dev     # --json summaries
  libjs-chart.js         # Chart.js, embedded in the binary at build time so HTML reports work offline
  libgtest-dev libgmock-dev  # unit tests
  libbenchmark-dev       # benchmarks in bench/
  libmumps-headers-dev   # dmumps_c.h: ocp_bench counts MUMPS factorisations (Ipopt's linear solver)
  python3 time           # bench/peer/run_peer_bench.sh: JSON parsing, GNU time for CPU seconds
  pybind11-dev python3-dev python3-numpy  # the Python module `hotlap` (python/, docs/python.md)
  python3-distributed python3-yaml  # hotlap sweep: dask.distributed, YAML case tables (docs/sweeps.md)
)
if [ "$with_tests" -eq 1 ]; then
  packages+=(
    chromium             # headless browser: the tests check that HTML reports render without errors
    calculix-ccx         # CalculiX: implicit reference for the FE solver's pressed-block test
    python3-pytest       # the Python package's tests (python/tests)
    python3-matplotlib   # examples/python's tyre-curve plot, run by the tests
    mkdocs mkdocs-material  # the docs site, built with --strict so a broken link fails (scripts/docs.sh)
    doxygen              # the C++ API reference from the headers (Doxyfile)
    python3-nbclient python3-nbformat python3-ipykernel  # runs the notebook tutorials (tools/run_notebooks.py)
  )
fi
if [ "$with_fuzz" -eq 1 ]; then
  packages+=(
    clang libclang-rt-14-dev  # libFuzzer and the sanitizers' runtimes (scripts/fuzz.sh, sanitize.sh)
    libomp-dev                # OpenMP for Clang (the FE area in the fuzzing build)
  )
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
