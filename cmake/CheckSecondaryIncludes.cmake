# cmake -DSECONDARY_DIR=<engine/secondary> -P CheckSecondaryIncludes.cmake
# The run-time part of secondary motion (the files directly in engine/secondary) must not
# include the offline part (engine/secondary/offline, engine/secondary/mpi): a viewer or
# renderer that plays capes never pulls in the simulator, exploration or compression.
file(GLOB runtime_files ${SECONDARY_DIR}/*.h ${SECONDARY_DIR}/*.cpp)
if(NOT runtime_files)
  message(FATAL_ERROR "${SECONDARY_DIR}: no run-time sources found")
endif()
set(offenders "")
foreach(file ${runtime_files})
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"secondary/(offline|mpi)/")
  foreach(line ${lines})
    list(APPEND offenders "${file}: ${line}")
  endforeach()
endforeach()
if(offenders)
  list(JOIN offenders "\n" text)
  message(FATAL_ERROR "run-time secondary files include offline ones:\n${text}")
endif()
list(LENGTH runtime_files count)
message(STATUS "${count} run-time secondary files, none includes an offline one")
