# The three ways a project uses pds, each configured, built and run from
# scratch: cmake -DMODE=... -DSOURCE_DIR=... -DBINARY_DIR=... -DWORK_DIR=... -P
#   shared-full   install the already-built (shared, every component) pds;
#                 find_package(pds) and link pds::pds
#   static-core   build pds static with only the core, install it;
#                 find_package(pds COMPONENTS core) with every third-party
#                 package search disabled
#   subdirectory  add_subdirectory(pds) with only the core
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
include(ProcessorCount)
ProcessorCount(jobs)

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGV}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()

set(launcher "")
if(COMPILER_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${COMPILER_LAUNCHER})
endif()

if(MODE STREQUAL "shared-full")
  run(${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${prefix})
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${WORK_DIR}/build
      -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
elseif(MODE STREQUAL "static-core")
  # Position-independent like the main (shared) build, so that the same
  # compile commands come from ccache instead of two minutes of compiling.
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/pds -DCMAKE_BUILD_TYPE=Release ${launcher}
      -DCMAKE_POSITION_INDEPENDENT_CODE=ON -DBUILD_SHARED_LIBS=OFF -DPDS_WITH_CGAL=OFF -DPDS_WITH_MESH=OFF -DPDS_WITH_PLOT=OFF -DPDS_WITH_RENDER=OFF
      -DPDS_BUILD_APPS=OFF -DPDS_BUILD_TESTS=OFF -DPDS_BUILD_BENCH=OFF -DPDS_BUILD_PYTHON=OFF)
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/pds -j ${jobs})
  run(${CMAKE_COMMAND} --install ${WORK_DIR}/pds --prefix ${prefix})
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/core -B ${WORK_DIR}/build
      -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
elseif(MODE STREQUAL "subdirectory")
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/subdirectory -B ${WORK_DIR}/build
      -DPDS_SOURCE_DIR=${SOURCE_DIR} -DCMAKE_BUILD_TYPE=Release ${launcher})
else()
  message(FATAL_ERROR "MODE must be shared-full, static-core or subdirectory, got '${MODE}'")
endif()
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build -j ${jobs})
run(${WORK_DIR}/build/consumer)
