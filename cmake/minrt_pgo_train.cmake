# Build step of MINRT_PGO (host/pgo/CMakeLists.txt): renders the training
# scenes with the instrumented minrt-pgo-train into a fresh PROFILE_DIR, then
# writes STAMP. PROFILE_DIR must be the directory minrt-pgo-train was
# compiled with (-fprofile-generate=DIR), which is where it writes. Run as
#   cmake -DTRAINER=EXE -DPROFILE_DIR=DIR -DSTAMP=FILE -DSLD_SCENES=LIST -DUNITS=LIST -P minrt_pgo_train.cmake
# The old profile is removed first: GCC adds counts to an existing .gcda,
# and the profile must be the same on every build.
foreach(var TRAINER PROFILE_DIR STAMP SLD_SCENES UNITS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "minrt_pgo_train.cmake: ${var} not given")
  endif()
endforeach()
file(REMOVE_RECURSE ${PROFILE_DIR})
file(MAKE_DIRECTORY ${PROFILE_DIR})
set(out ${PROFILE_DIR}/out)
file(MAKE_DIRECTORY ${out})

function(train)
  execute_process(COMMAND ${TRAINER} --threads 1 ${ARGN} RESULT_VARIABLE status ERROR_VARIABLE errors
                  OUTPUT_QUIET)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "minrt-pgo-train ${ARGN} failed (${status}): ${errors}")
  endif()
endfunction()

# min-rt SLD: the exact double mode (the default) at 128x128, and float with
# the portable shims (the board's arithmetic) at 64x64.
foreach(scene IN LISTS SLD_SCENES)
  train(--size 128x128 -o ${out}/sld.ppm ${scene})
  train(--size 64x64 --precision float --shims portable -o ${out}/sld.ppm ${scene})
endforeach()
file(REMOVE_RECURSE ${out})
# One profile per unit (GCC names it after the object, with '#' for '/'):
# without it that unit would quietly be compiled as if untrained.
foreach(unit IN LISTS UNITS)
  get_filename_component(name ${unit} NAME)
  file(GLOB found "${PROFILE_DIR}/*#${name}.gcda")
  list(LENGTH found count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "minrt_pgo_train.cmake: ${count} profiles for ${name} in ${PROFILE_DIR}")
  endif()
endforeach()
file(TOUCH ${STAMP})
