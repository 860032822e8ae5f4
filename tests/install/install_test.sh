#!/usr/bin/env bash
# The installed package, as a user sees it: install the build into a fresh prefix, build
# examples/cpp against that prefix only (find_package(hotlap)), run both programs on the installed
# data, check that the tyre-only program links no solver, and compile every installed header in
# one translation unit against the installed targets (no header needs one left out).
#   install_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1
build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
fail() { echo "install test: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
config=$(find "$prefix" -name hotlapConfig.cmake | head -1)
[ -n "$config" ] || fail "no hotlapConfig.cmake under $prefix"
# No installed text file (CMake package, headers, Python files) may point back into the source
# or build tree. The libraries are left out (-I): they hold the source tree's path on purpose,
# as DataDir()'s fallback while that tree exists (common/data_path.h), and a byte search of them
# also matches that path where the linker happens to lay another string right after it.
if grep -rlIF -e "$src/" -e "$build/" "$prefix/lib" "$prefix/include" >/dev/null 2>&1; then
  fail "installed files name the source or build tree: $(grep -rlIF -e "$src/" -e "$build/" "$prefix/lib" "$prefix/include" | head -3)"
fi
[ -f "$prefix/share/hotlap/data/cars/gen7/car.yaml" ] || fail "the car data is not installed"
[ -x "$prefix/bin/hotlap" ] || fail "the hotlap program is not installed"
[ ! -e "$prefix/include/hotlap/report/assets.h" ] || fail "an internal header is installed"

cmake -S "$src/examples/cpp" -B "$work/examples" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; fail "examples/cpp does not configure against the install"; }
cmake --build "$work/examples" >"$work/build.log" 2>&1 ||
  { cat "$work/build.log"; fail "examples/cpp does not build against the install"; }

# The tyre-only program links no solver (Ceres, Ipopt, MUMPS).
if readelf -d "$work/examples/tyre_curve" | grep -Ei "ceres|ipopt|mumps|glog"; then
  fail "tyre_curve links a solver library"
fi

# Both run on the installed data.
export HOTLAP_DATA_DIR="$prefix/share/hotlap/data"
"$work/examples/tyre_curve" >"$work/tyre.txt" || fail "tyre_curve failed"
grep -q "^12," "$work/tyre.txt" || fail "tyre_curve printed no 12 deg row"
"$work/examples/qss_lap" >"$work/qss.txt" || fail "qss_lap failed"
grep -q "^lap 3: " "$work/qss.txt" || fail "qss_lap printed no third lap"
"$prefix/bin/hotlap" track info --track darlington >/dev/null || fail "installed hotlap failed"
# The installed Python package, when the build has it.
if [ -d "$build/python/hotlap" ]; then
  PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c \
    "import hotlap; assert hotlap.__file__.startswith('$prefix'); assert hotlap.load_car('gen7').name == 'gen7'" ||
    fail "the installed Python package does not import"
  # Without HOTLAP_DATA_DIR it finds the data installed beside it (<prefix>/share/hotlap/data),
  # wherever --prefix put it, not the source tree's nor the configured prefix's.
  env -u HOTLAP_DATA_DIR PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c \
    "import hotlap, os; d = os.path.realpath(str(hotlap.data_dir())); assert d == os.path.realpath('$prefix/share/hotlap/data'), d" ||
    fail "the installed Python package does not find the installed data by itself"
fi

# Every installed header in one translation unit, against the installed targets.
mkdir -p "$work/headers"
(cd "$prefix/include" && find hotlap -name '*.h' | sort | sed 's/.*/#include "&"/') \
  >"$work/headers/all.cc"
cat >"$work/headers/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.22)
project(hotlap_headers LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
find_package(hotlap REQUIRED)
add_library(all_headers OBJECT all.cc)
target_link_libraries(all_headers PRIVATE hotlap::hotlap)
CMAKE
cmake -S "$work/headers" -B "$work/headers/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
  >/dev/null 2>&1 || fail "the header check does not configure"
cmake --build "$work/headers/build" >"$work/headers.log" 2>&1 ||
  { cat "$work/headers.log"; fail "the installed headers do not compile together"; }
echo "install test: $(find "$prefix/include" -name '*.h' | wc -l) headers, $(ls "$prefix/lib"/*.a | wc -l) libraries; examples built and ran"
