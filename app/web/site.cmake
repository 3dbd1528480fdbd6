# The site's versions, run by the build once springlab.js, .wasm, .data and the icons are in the
# site folder (app/web/CMakeLists.txt), and by the browser tests on files of their own:
#   cmake -DSITE=DIR -DSOURCE=app/web -P app/web/site.cmake
# 1. The assets' version: the SHA-256 (its first 16 hex digits) of the list "NAME SHA-256" of
#    springlab.js, .wasm, .data, the icons and the manifest's template. index.html and the
#    manifest are written from their templates with it: the page asks for springlab.js?v=VERSION.
# 2. The cache's version: the same over every file the site serves (index.html, the manifest and
#    those above as written) and sw.js's template. sw.js is written with it (the cache's name,
#    springlab-VERSION) and with every file and its SHA-256, so sw.js changes with any file of the
#    site and the browser installs the new one, which checks what it fetches against them.
# Files are rewritten only when their text changes.
cmake_minimum_required(VERSION 3.20)
foreach(var SITE SOURCE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "site.cmake: -D${var}=... is missing")
  endif()
endforeach()

# "NAME SHA-256" lines of files, and their SHA-256's first 16 hex digits as `out`.
function(version_of out lines_out)
  set(lines "")
  foreach(pair IN LISTS ARGN)
    string(REPLACE "=" ";" pair "${pair}")
    list(GET pair 0 name)
    list(GET pair 1 file)
    if(NOT EXISTS "${file}")
      message(FATAL_ERROR "site.cmake: ${file} is missing")
    endif()
    file(SHA256 "${file}" hash)
    string(APPEND lines "${name} ${hash}\n")
  endforeach()
  string(SHA256 all "${lines}")
  string(SUBSTRING "${all}" 0 16 all)
  set(${out} "${all}" PARENT_SCOPE)
  set(${lines_out} "${lines}" PARENT_SCOPE)
endfunction()

set(assets springlab.js springlab.wasm springlab.data icon-192.png icon-512.png homework.js acorn.js acorn-walk.js access.js)
set(pairs "")
foreach(f IN LISTS assets)
  list(APPEND pairs "${f}=${SITE}/${f}")
endforeach()
version_of(SPRINGLAB_ASSETS_VERSION unused ${pairs} "manifest.webmanifest.in=${SOURCE}/manifest.webmanifest")
configure_file("${SOURCE}/index.html" "${SITE}/index.html" @ONLY)
configure_file("${SOURCE}/manifest.webmanifest" "${SITE}/manifest.webmanifest" @ONLY)

# The files as the page asks for them, with their SHA-256, for sw.js.
set(served index.html manifest.webmanifest ${assets})
set(pairs "")
set(json "")
foreach(f IN LISTS served)
  list(APPEND pairs "${f}=${SITE}/${f}")
  file(SHA256 "${SITE}/${f}" hash)
  set(url "${f}?v=${SPRINGLAB_ASSETS_VERSION}")
  if(f STREQUAL "index.html")
    set(url "index.html")
  endif()
  if(json)
    string(APPEND json ",\n ")
  endif()
  string(APPEND json "{ \"url\": \"${url}\", \"sha256\": \"${hash}\" }")
endforeach()
set(SPRINGLAB_SITE_FILES "[\n ${json}\n]")
version_of(SPRINGLAB_CACHE_VERSION unused ${pairs} "sw.js.in=${SOURCE}/sw.js")
configure_file("${SOURCE}/sw.js" "${SITE}/sw.js" @ONLY)
message(STATUS "site.cmake: cache springlab-${SPRINGLAB_CACHE_VERSION}, assets ?v=${SPRINGLAB_ASSETS_VERSION}")
