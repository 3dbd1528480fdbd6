# Compiler flags shared by every target.
#
# Floating point: no -ffast-math, and no FMA contraction (-ffp-contract=off), so that a result
# does not depend on which instructions the compiler happened to fuse: the same scene gives the
# same bits with SSE2 or AVX2 code and with any thread count. -fno-math-errno and
# -fno-trapping-math change no value: they let sqrt vectorise and let the spring loop select
# with a compare instead of a branch (springlab never unmasks floating-point traps).
add_compile_options(-Wall -Wextra -Wpedantic -ffp-contract=off -fno-math-errno -fno-trapping-math)
# simd.hpp passes 32-byte vectors between inline functions; GCC notes that their ABI changed in
# GCC 4.6 whenever AVX is off, which concerns no code here.
add_compile_options($<$<CXX_COMPILER_ID:GNU>:-Wno-psabi>)

# AVX2 doubles the width of the vectorised spring loops. Only used when the build machine has it
# (the binary is meant for the machine it is built on, as scripts/ build it).
include(CheckCXXSourceRuns)
if(EMSCRIPTEN)
  # WebAssembly's 128-bit SIMD (every current browser has it): f64x4 becomes two f64x2. Exceptions
  # as WebAssembly's own (the loaders' InputError), not emulated through JavaScript, which would
  # slow every call that might throw.
  set(SPRINGLAB_HAVE_AVX2 OFF)
  add_compile_options(-msimd128 -fwasm-exceptions)
  add_link_options(-fwasm-exceptions)
elseif(NOT DEFINED SPRINGLAB_HAVE_AVX2)
  check_cxx_source_runs("int main() { return __builtin_cpu_supports(\"avx2\") ? 0 : 1; }"
                        SPRINGLAB_HAVE_AVX2)
endif()
option(SPRINGLAB_AVX2 "Compile with -mavx2 (no FMA, see above)" ${SPRINGLAB_HAVE_AVX2})
if(SPRINGLAB_AVX2)
  add_compile_options(-mavx2)
endif()

# The sanitizer build (scripts/sanitize.sh) is a checking build: asserts on (-UNDEBUG), line
# numbers in the reports (-g1), and -O1, the sanitizers' advice, which also builds several times
# faster than -O3 (core/CMakeLists.txt then leaves out its -O3).
option(SPRINGLAB_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
# Which: address (with undefined, the default) or thread (ThreadSanitizer: scripts/stress.sh).
set(SPRINGLAB_SANITIZER "address" CACHE STRING "With SPRINGLAB_SANITIZE: address or thread")
if(SPRINGLAB_SANITIZE)
  add_compile_options(-O1 -g1 -UNDEBUG)
  # At -O1 clang does not vectorise the `omp simd` loops, and would say so at every one.
  add_compile_options($<$<CXX_COMPILER_ID:Clang>:-Wno-pass-failed>)
  add_compile_definitions(SPRINGLAB_SANITIZE)  # for the few tests that bound a time
  if(SPRINGLAB_SANITIZER STREQUAL "thread")
    add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
    add_link_options(-fsanitize=thread)
  else()
    add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
    add_link_options(-fsanitize=address,undefined)
  endif()
endif()
