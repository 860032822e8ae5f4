# Sanitizer and fuzzing builds (docs/reliability.md), after Ceres' cmake/EnableSanitizer.cmake.
#
#   HOTLAP_SANITIZE=ON  every target compiled and linked with AddressSanitizer and
#                       UndefinedBehaviorSanitizer (GCC or Clang): -fsanitize=address,undefined,
#                       frame pointers kept, undefined behaviour fatal (no recovery), so a test
#                       that meets any of it fails.
#   HOTLAP_FUZZ=ON      (Clang only) the same, plus libFuzzer's coverage instrumentation of every
#                       target (-fsanitize=fuzzer-no-link) and the libFuzzer targets of fuzz/,
#                       linked with -fsanitize=fuzzer. Implies HOTLAP_SANITIZE.
option(HOTLAP_SANITIZE "Build everything with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(HOTLAP_FUZZ "Build the libFuzzer targets of fuzz/ (Clang; implies HOTLAP_SANITIZE)" OFF)

if(HOTLAP_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "HOTLAP_FUZZ needs Clang (libFuzzer): configure with "
      "-DCMAKE_CXX_COMPILER=clang++ (scripts/fuzz.sh does)")
  endif()
  set(HOTLAP_SANITIZE ON CACHE BOOL "" FORCE)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(HOTLAP_SANITIZE)
  set(hotlap_sanitize_flags -fsanitize=address,undefined -fno-sanitize-recover=undefined
    -fno-omit-frame-pointer)
  add_compile_options(${hotlap_sanitize_flags})
  add_link_options(-fsanitize=address,undefined)
  # Eigen 3.4 switches to its hand-made aligned allocator when __SANITIZE_ADDRESS__ is defined,
  # while Debian's Ceres (not sanitized) was built with the plain malloc one; the linker keeps one
  # copy of each Eigen function both instantiate, so a block could be allocated one way and freed
  # the other. ASan's malloc is 16-byte aligned (docs/validation/reliability.md), which is all
  # Eigen asks of it: every object then uses malloc and free.
  add_compile_definitions(EIGEN_MALLOC_ALREADY_ALIGNED=1)
endif()
