# Installs the python component into a scratch prefix and imports it from
# there with an isolated interpreter (no PYTHONPATH, no user site), checking
# that the module and the pds libraries it loads all come from the prefix.
# cmake -DBINARY_DIR=... -DWORK_DIR=... -DPYTHON=... -DPACKAGE_DIR=... -P check_install.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --component python --prefix ${prefix}
  RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "cmake --install --component python failed")
endif()
set(site ${prefix}/${PACKAGE_DIR})
set(code [=[
import sys
sys.path.insert(0, sys.argv[1])
import pds
prefix = sys.argv[1]
assert pds.__file__.startswith(prefix), pds.__file__
assert len(pds.generate("bridson", radius=0.1)) > 10
libs = [l.split()[-1] for l in open("/proc/self/maps") if "libpds_" in l]
assert libs and all(l.startswith(prefix) for l in libs), libs
print("imported from", prefix)
]=])
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=PYTHONPATH --unset=LD_LIBRARY_PATH
    ${PYTHON} -I -c "${code}" ${site}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "importing the installed pds failed:\n${out}${err}")
endif()
message(STATUS "${out}")
