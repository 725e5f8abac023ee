# One scene of sld/ordinary: minrt --size 128x128 (double, libm shims) must
# exit 0, print nothing on stderr, and print an image whose sha256 is the one
# SUMS lists for the scene's file name (the original program's output).
#   cmake -DMINRT=EXE -DSCENE=FILE.sld -DSUMS=reference.sha256 -DWORK=DIR -P check_ordinary_scene.cmake
foreach(var MINRT SCENE SUMS WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_ordinary_scene.cmake: ${var} not given")
  endif()
endforeach()
get_filename_component(name "${SCENE}" NAME)
file(STRINGS "${SUMS}" lines REGEX "^[0-9a-f]+  ${name}$")
list(LENGTH lines count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "${SUMS}: ${count} lines for ${name}, expected 1")
endif()
string(REGEX REPLACE "^([0-9a-f]+)  .*$" "\\1" expected "${lines}")

file(MAKE_DIRECTORY "${WORK}")
set(image "${WORK}/${name}.ppm")
file(REMOVE "${image}")
execute_process(COMMAND "${MINRT}" --size 128x128 "${SCENE}" OUTPUT_FILE "${image}"
                ERROR_VARIABLE errors RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "minrt ${name} exited with ${status}: ${errors}")
endif()
if(NOT errors STREQUAL "")
  message(FATAL_ERROR "minrt ${name} printed on stderr (an ordinary scene must read without warnings): ${errors}")
endif()
file(SHA256 "${image}" actual)
if(NOT actual STREQUAL expected)
  message(FATAL_ERROR "${name}: image sha256 ${actual}, the original's is ${expected} (image kept at ${image})")
endif()
file(REMOVE "${image}")
message(STATUS "${name}: same bytes as the original (${actual})")
