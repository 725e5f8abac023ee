# A CMake project of its own (a cross build of the firmware, the fuzzers),
# configured and built as a step of this build (ExternalProject):
#
#   include(cmake/minrt_sub_build.cmake)
#   minrt_sub_build(NAME SOURCE_DIR DIR BINARY_DIR DIR
#                   INPUTS FOLDER... CACHE_ARGS -DVAR:TYPE=VALUE... [BYPRODUCTS FILE...])
#
# Rebuilt only when it has to be: when a source file under one of the INPUTS
# folders (repository folders) changes, is added or removed, or when its
# CACHE_ARGS change; a build with nothing changed does not enter it.
# Its own output (configure and build, with their own percentages) goes to
# <build>/logs/NAME-{configure,build}-{out,err}.log, printed only when the
# step fails, so that a build shows one progress sequence, this build's,
# with a line naming each sub-build step as it starts.
include_guard(GLOBAL)
include(ExternalProject)

function(minrt_sub_build name)
  # What a sub-build compiles or reads: sources, headers, linker scripts,
  # CMake files, board files, the scripts its build steps run.
  set(patterns *.c *.cpp *.h *.hpp *.inc *.S *.py *.board CMakeLists.txt *.cmake)
  cmake_parse_arguments(ARG "" "SOURCE_DIR;BINARY_DIR" "INPUTS;CACHE_ARGS;BYPRODUCTS" ${ARGN})
  foreach(_required SOURCE_DIR BINARY_DIR INPUTS)
    if(NOT ARG_${_required})
      message(FATAL_ERROR "minrt_sub_build(${name}): ${_required} not given")
    endif()
  endforeach()
  set(_globs "")
  foreach(_folder IN LISTS ARG_INPUTS)
    foreach(_pattern IN LISTS patterns)
      list(APPEND _globs "${_folder}/${_pattern}")
    endforeach()
  endforeach()
  # CONFIGURE_DEPENDS: a new or removed file re-runs this configure, so the
  # list below is always the current one.
  file(GLOB_RECURSE _inputs CONFIGURE_DEPENDS ${_globs})
  ExternalProject_Add(${name}
    SOURCE_DIR "${ARG_SOURCE_DIR}"
    BINARY_DIR "${ARG_BINARY_DIR}"
    CMAKE_CACHE_ARGS ${ARG_CACHE_ARGS}
    INSTALL_COMMAND ""
    LOG_DIR "${CMAKE_BINARY_DIR}/logs"
    BUILD_BYPRODUCTS ${ARG_BYPRODUCTS}
    LOG_CONFIGURE ON
    LOG_BUILD ON
    LOG_OUTPUT_ON_FAILURE ON)
  ExternalProject_Add_StepDependencies(${name} build ${_inputs})
endfunction()
