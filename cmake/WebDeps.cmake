# What the browser build (EMSCRIPTEN) takes from Debian's packages without reaching into the
# system's own headers (glibc's would shadow emscripten's): Eigen, nlohmann-json and Boost, header-only,
# through links in the build folder; Dear ImGui 1.86 (the same as libimgui-dev's headers)
# compiled from Debian's source package, which scripts/web.sh unpacks into the build folder.
set(SPRINGLAB_IMGUI_DIR "${CMAKE_BINARY_DIR}/_deps/imgui-1.86" CACHE PATH "Dear ImGui 1.86's sources")
if(NOT EXISTS "${SPRINGLAB_IMGUI_DIR}/imgui.cpp")
  message(FATAL_ERROR "Dear ImGui's sources are not in ${SPRINGLAB_IMGUI_DIR}: scripts/web.sh fetches them")
endif()

set(deps_include "${CMAKE_BINARY_DIR}/_deps/include")
file(MAKE_DIRECTORY "${deps_include}")
foreach(link IN ITEMS /usr/include/eigen3/Eigen /usr/include/nlohmann /usr/include/boost)
  get_filename_component(name "${link}" NAME)
  if(NOT EXISTS "${link}")
    message(FATAL_ERROR "${link} is missing: apt-get install libeigen3-dev nlohmann-json3-dev libboost-dev")
  endif()
  file(CREATE_LINK "${link}" "${deps_include}/${name}" SYMBOLIC)
endforeach()

add_library(Eigen3::Eigen INTERFACE IMPORTED)
target_include_directories(Eigen3::Eigen SYSTEM INTERFACE "${deps_include}")
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE "${deps_include}")
add_library(Boost::headers INTERFACE IMPORTED)
target_include_directories(Boost::headers SYSTEM INTERFACE "${deps_include}")

# Dear ImGui with its GLFW and OpenGL 3 backends (the latter picks OpenGL ES 3 under emscripten).
add_library(imgui STATIC
  ${SPRINGLAB_IMGUI_DIR}/imgui.cpp
  ${SPRINGLAB_IMGUI_DIR}/imgui_draw.cpp
  ${SPRINGLAB_IMGUI_DIR}/imgui_tables.cpp
  ${SPRINGLAB_IMGUI_DIR}/imgui_widgets.cpp
  ${SPRINGLAB_IMGUI_DIR}/backends/imgui_impl_glfw.cpp
  ${SPRINGLAB_IMGUI_DIR}/backends/imgui_impl_opengl3.cpp
)
target_include_directories(imgui SYSTEM PUBLIC "${SPRINGLAB_IMGUI_DIR}")
target_compile_options(imgui PRIVATE -w -sUSE_GLFW=3)
target_link_options(imgui INTERFACE -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2)

# GoogleTest from Debian's sources, for the core's tests in the browser (tests/web).
set(SPRINGLAB_GTEST_DIR /usr/src/googletest/googletest CACHE PATH "GoogleTest's sources")
if(EXISTS "${SPRINGLAB_GTEST_DIR}/src/gtest-all.cc")
  add_library(gtest_web STATIC "${SPRINGLAB_GTEST_DIR}/src/gtest-all.cc")
  target_include_directories(gtest_web SYSTEM PUBLIC "${SPRINGLAB_GTEST_DIR}/include" PRIVATE "${SPRINGLAB_GTEST_DIR}")
  target_compile_options(gtest_web PRIVATE -w)
endif()
