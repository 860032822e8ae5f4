// Where this build's source tree and programs are, for the shipped data's fallback
// (common/data_path.cc), the tests, the benchmarks and the fuzzers. Force-included (-include) by
// those targets; the values are defined in generated sources of the build folder
// (cmake/HotlapBuildPaths.cmake), so that no compile command carries the path of one checkout and
// a compiler cache (ccache, CMakeLists.txt's HOTLAP_CCACHE) serves every clone of the same code.
#pragma once

namespace hotlap_build {
extern const char kSourceDir[];       // the source tree (PROJECT_SOURCE_DIR)
extern const char kBinary[];          // the hotlap program (tests only)
extern const char kMakeExampleLog[];  // tools/make_example_log (tests only)
}  // namespace hotlap_build

#define HOTLAP_SOURCE_DIR (::hotlap_build::kSourceDir)
#define HOTLAP_BINARY (::hotlap_build::kBinary)
#define HOTLAP_MAKE_EXAMPLE_LOG (::hotlap_build::kMakeExampleLog)
