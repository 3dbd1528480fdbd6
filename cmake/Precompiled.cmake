# Precompiled headers: the standard library, Eigen, GoogleTest, Dear ImGui and pybind11 parsed once
# a target instead of once a file. Eigen's headers alone take about 3 s a file to parse, and CI
# builds about 400 files three times over (native, checking and browser builds). Measured on this
# project's 2-core machine: core/src/methods/euler.cpp 7.4 s -> 5.3 s, loading/scene.cpp 13.2 s ->
# 10.0 s, with byte-identical objects (a precompiled header changes what is parsed, not the code).
# Not CLI11: its header defines validators as objects at namespace scope, so every file that
# included it precompiled built their constructors (the app's files took 7 s each, 247 s more in
# all). clang's checking build gains less: its cost is instantiating templates, not parsing.
# OFF for a build that wants each file to prove its own includes (-DSPRINGLAB_PCH=OFF).
option(SPRINGLAB_PCH "Precompile the headers most files include" ON)

# springlab_precompile(<target> [<header>...]): the common headers plus the target's own.
function(springlab_precompile target)
  if(SPRINGLAB_PCH)
    target_precompile_headers(${target} PRIVATE
      <algorithm> <cmath> <functional> <memory> <optional> <sstream> <string> <vector>
      <Eigen/Dense> ${ARGN})
    # GCC 12 reports its known false positives in <string>'s inlined memcpy (-Warray-bounds,
    # -Wstringop-overflow, -Wstringop-overread, -Wrestrict; GCC bug 105329) once the standard
    # headers come from a precompiled header: the same files built without one are silent.
    # clang's checking build (scripts/sanitize.sh) still checks bounds, at run time.
    target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-array-bounds -Wno-stringop-overflow -Wno-stringop-overread -Wno-restrict>)
  endif()
endfunction()
