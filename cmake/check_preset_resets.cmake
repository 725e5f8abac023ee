# Checks that configuring with PRESET sets every project setting (MINRT_*
# cache entry other than a found program or library), so that
# `cmake --preset PRESET`, which scripts/setup.sh runs, undoes any -D given
# to that folder before. Run as
#   cmake -DPRESETS=CMakePresets.json -DPRESET=host-release -DCACHE=<build>/CMakeCache.txt \
#         -P cmake/check_preset_resets.cmake
# Fails naming each setting the preset leaves as it was.
cmake_minimum_required(VERSION 3.20)
foreach(var PRESETS PRESET CACHE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_preset_resets.cmake: ${var} not given")
  endif()
endforeach()

file(READ "${PRESETS}" json)
string(JSON count LENGTH "${json}" configurePresets)
math(EXPR last "${count} - 1")

# The names the preset sets, its own and those of the presets it inherits.
set(names "")
set(pending "${PRESET}")
while(pending)
  list(POP_FRONT pending wanted)
  set(found FALSE)
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" configurePresets ${i} name)
    if(NOT name STREQUAL wanted)
      continue()
    endif()
    set(found TRUE)
    string(JSON vars ERROR_VARIABLE none GET "${json}" configurePresets ${i} cacheVariables)
    if(NOT none)
      string(JSON nvars LENGTH "${vars}")
      math(EXPR vlast "${nvars} - 1")
      foreach(j RANGE ${vlast})
        string(JSON var MEMBER "${vars}" ${j})
        list(APPEND names "${var}")
      endforeach()
    endif()
    string(JSON parents ERROR_VARIABLE none GET "${json}" configurePresets ${i} inherits)
    if(NOT none)
      list(APPEND pending ${parents})  # a name, or a JSON array of names
    endif()
  endforeach()
  if(NOT found)
    message(FATAL_ERROR "${PRESETS}: no configure preset '${wanted}'")
  endif()
endwhile()
# An "inherits" array arrives as its JSON text: keep the bare names.
string(REGEX REPLACE "[][\" ]" "" names "${names}")
string(REPLACE "," ";" names "${names}")

# The project's CMake text: a MINRT_* entry it never names is a leftover of
# an older source tree in the same build folder, not a setting.
get_filename_component(source_dir "${PRESETS}" DIRECTORY)
file(GLOB cmake_files "${source_dir}/CMakeLists.txt" "${source_dir}/cmake/*.cmake" "${source_dir}/*/CMakeLists.txt"
     "${source_dir}/*/*/CMakeLists.txt")
set(cmake_text "")
foreach(f IN LISTS cmake_files)
  file(READ "${f}" text)
  string(APPEND cmake_text "${text}")
endforeach()

# The cache: each entry follows its help text; find_program/find_library
# results say "Path to a program." / "Path to a library.".
file(STRINGS "${CACHE}" lines)
set(help "")
set(missing "")
set(checked 0)
foreach(line IN LISTS lines)
  if(line MATCHES "^//(.*)$")
    set(help "${CMAKE_MATCH_1}")
    continue()
  endif()
  if(line MATCHES "^(MINRT_[A-Z0-9_]+):(BOOL|STRING|PATH|FILEPATH)=")
    set(var "${CMAKE_MATCH_1}")
    string(FIND "${cmake_text}" "${var}" named)
    if(named GREATER -1 AND NOT help MATCHES "^Path to a (program|library|file)\\.$")
      math(EXPR checked "${checked} + 1")
      if(NOT var IN_LIST names)
        list(APPEND missing "${var}")
      endif()
    endif()
  endif()
  set(help "")
endforeach()
if(checked EQUAL 0)
  message(FATAL_ERROR "${CACHE}: no MINRT_* settings found")
endif()
if(missing)
  string(REPLACE ";" ", " missing "${missing}")
  message(FATAL_ERROR "${PRESETS}: preset '${PRESET}' does not set ${missing}: a -D given once would stay "
                      "in the build folder; add the default to the 'defaults' preset (docs/building.md)")
endif()
message(STATUS "preset '${PRESET}' sets all ${checked} MINRT_* settings of ${CACHE}")
