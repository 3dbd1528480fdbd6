# The installed package works from outside the source tree: installs the build into a fresh
# prefix, configures examples/consumer against that prefix alone, builds and runs it on the
# spring scene, and checks what it prints against the installed command line and the physics.
# cmake -DBUILD=<build dir> -DSOURCE=<source dir> -DWORK=<scratch dir> -P consumer_test.cmake
file(REMOVE_RECURSE ${WORK})
function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGV}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/prefix)
foreach(f lib/libspringlab_core.a include/springlab/simulation.hpp include/springlab/version.hpp
          lib/cmake/springlab/springlabConfig.cmake lib/cmake/springlab/springlabConfigVersion.cmake
          share/doc/springlab/LICENSE)
  if(NOT EXISTS ${WORK}/prefix/${f})
    message(FATAL_ERROR "the install lacks ${f}")
  endif()
endforeach()
# Only the prefix: CMAKE_FIND_USE_PACKAGE_REGISTRY off, so that nothing finds the build tree.
run(${CMAKE_COMMAND} -S ${SOURCE}/examples/consumer -B ${WORK}/consumer -G Ninja -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run(${CMAKE_COMMAND} --build ${WORK}/consumer)
run(${WORK}/consumer/consumer ${SOURCE}/assets/scenes/spring.json)
set(consumer "${out}")
message(STATUS "consumer printed:\n${consumer}")
# The library gives what the installed command line gives (the same steps of the same code), and
# RK4 keeps the spring's 12.5 J (its energy error, (h w)^6 / 72 a step, is below the 6 digits).
foreach(method symplectic-euler rk4)
  string(REGEX MATCH "${method}: energy total ([^ ]+) J after 120 steps \\(initially 12.5 J\\)" line "${consumer}")
  if(NOT line)
    message(FATAL_ERROR "no line for ${method} as expected in:\n${consumer}")
  endif()
  set(library "${CMAKE_MATCH_1}")
  run(${WORK}/prefix/bin/springlab run ${SOURCE}/assets/scenes/spring.json --method ${method} --steps 120 --substeps 1)
  string(REGEX MATCH "total ([^ ]+) J" line "${out}")
  if(NOT library STREQUAL CMAKE_MATCH_1)
    message(FATAL_ERROR "${method}: the library gives ${library} J, springlab run ${CMAKE_MATCH_1} J")
  endif()
endforeach()
string(REGEX MATCH "rk4: energy total ([^ ]+) J" line "${consumer}")
if(NOT CMAKE_MATCH_1 STREQUAL "12.5")
  message(FATAL_ERROR "RK4 ends at ${CMAKE_MATCH_1} J, not 12.5 J")
endif()
