# Unity builds: a target's files compiled a folder at a time, a few files to a translation unit.
# With the precompiled headers (Precompiled.cmake) a file still parsed its own project headers
# (about 2 s each in the app) and instantiated the same Eigen, JSON and CLI11 templates as its
# neighbours; a unit of files from one folder does both once. Files of one folder share their
# headers, so that is where the saving is.
# Every build uses it (normal, checking, browser): CI builds the tree three times over. OFF
# (-DSPRINGLAB_UNITY=OFF) compiles each file alone, so that a change to one file rebuilds only
# that file; with -DSPRINGLAB_PCH=OFF too, each file proves its own includes.
option(SPRINGLAB_UNITY "Compile each folder's files a few to a translation unit (unity build)" ON)

# springlab_unity(<target> <files a unit>): the target's sources grouped by folder, at most
# <files a unit> to a group; a source marked SKIP_UNITY_BUILD_INCLUSION stays alone.
function(springlab_unity target size)
  if(NOT SPRINGLAB_UNITY)
    return()
  endif()
  get_target_property(sources ${target} SOURCES)
  get_target_property(root ${target} SOURCE_DIR)
  # First each folder's files, then each folder split evenly into ceil(n / size) units.
  set(keys "")
  foreach(source IN LISTS sources)
    get_source_file_property(skip ${source} SKIP_UNITY_BUILD_INCLUSION)
    if(skip OR NOT source MATCHES "\\.cpp$")
      continue()
    endif()
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${root} OUTPUT_VARIABLE path)
    cmake_path(GET path PARENT_PATH folder)
    cmake_path(RELATIVE_PATH folder BASE_DIRECTORY ${root})
    string(MAKE_C_IDENTIFIER "u_${folder}" key)
    list(APPEND keys ${key})
    list(APPEND files_${key} ${path})
  endforeach()
  list(REMOVE_DUPLICATES keys)
  foreach(key IN LISTS keys)
    list(LENGTH files_${key} n)
    math(EXPR units "(${n} + ${size} - 1) / ${size}")
    set(index 0)
    foreach(path IN LISTS files_${key})
      math(EXPR unit "${index} * ${units} / ${n}")
      math(EXPR index "${index} + 1")
      set_source_files_properties(${path} TARGET_DIRECTORY ${target} PROPERTIES UNITY_GROUP ${key}_${unit})
    endforeach()
  endforeach()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  # GCC takes a .cpp included by a unit for a header, and a class there with a member of a type
  # from an anonymous namespace for one that every includer would see differently
  # (-Wsubobject-linkage); in a unit the file is included exactly once.
  target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-subobject-linkage>)
endfunction()
