# Precompiled headers (HOTLAP_PCH, docs/validation/build-times.md): the standard and third-party
# headers most sources include, parsed once per target instead of once per source. Every source
# still includes what it uses (a build with -DHOTLAP_PCH=OFF checks that; the Clang build of
# scripts/fuzz.sh is one, for the reader areas), so the list changes speed, never meaning.
#
#   hotlap_precompile_headers(TARGET [HEADER...])  TARGET's own precompiled header: the list below
#                                                   and the extra HEADERs (gtest, CLI11)
#   hotlap_reuse_precompiled_headers(TARGET FROM)   TARGET uses FROM's (same flags: the areas)
#
# ccache caches the compilations that use one when told to ignore the header's fresh time stamps
# and its __DATE__ (CCACHE_SLOPPINESS in CMakeLists.txt's launcher; ccache's manual,
# "Precompiled headers").
option(HOTLAP_PCH "Precompile the third-party headers most sources include" ON)
set(HOTLAP_PCH_HEADERS
  <algorithm> <array> <cmath> <cstdint> <filesystem> <functional> <limits> <map> <memory>
  <optional> <span> <string> <string_view> <utility> <vector>
  <Eigen/Core> <ceres/jet.h> <fmt/format.h> <nlohmann/json.hpp> <yaml-cpp/yaml.h>)

function(hotlap_precompile_headers target)
  if(HOTLAP_PCH)
    target_precompile_headers(${target} PRIVATE ${HOTLAP_PCH_HEADERS} ${ARGN})
  endif()
endfunction()

# Unity builds (HOTLAP_UNITY): a target's sources compiled in batches of HOTLAP_UNITY_BATCH, one
# translation unit each, so the code the headers' inline functions and templates make (CLI11,
# nlohmann::json, fmt, GoogleTest) is generated once per batch, not once per source. A source's
# file-local names must then differ from those of the other sources of its target.
option(HOTLAP_UNITY "Compile each target's sources in batches (unity build)" ON)
set(HOTLAP_UNITY_BATCH 8 CACHE STRING "Sources per unity batch")
function(hotlap_unity_build target)
  if(HOTLAP_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON
      UNITY_BUILD_BATCH_SIZE ${HOTLAP_UNITY_BATCH})
  endif()
endfunction()

function(hotlap_reuse_precompiled_headers target from)
  if(HOTLAP_PCH)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()
