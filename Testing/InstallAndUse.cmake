# Installs vtkFX into a scratch prefix, builds Examples/Cxx as a separate
# project against it with find_package(vtkFX), and runs the result: what
# another VTK application does with vtkFX.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK=... -DMESH=... -P InstallAndUse.cmake
file(REMOVE_RECURSE "${WORK}")
set(prefix "${WORK}/prefix")
function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}${err}")
  endif ()
  set(last_output "${out}" PARENT_SCOPE)
endfunction ()
run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
# (the build's own generator: the README installs ninja, not necessarily make)
run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Examples/Cxx" -B "${WORK}/example" -G "${GENERATOR}"
  "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}" "-DvtkFX_DIR=${prefix}/lib/cmake/vtkFX"
  -DCMAKE_BUILD_TYPE=Release)
run("${CMAKE_COMMAND}" --build "${WORK}/example")
set(ENV{LD_LIBRARY_PATH} "${prefix}/lib")
run("${WORK}/example/vtkfx-example" "${MESH}" "${WORK}/example.png")
message("${last_output}")
if (NOT last_output MATCHES "passes: lights gbuffer ssao ssao-blur composite")
  message(FATAL_ERROR "the installed pipeline did not run its deferred passes")
endif ()
# The installed Python package imports from the prefix alone.
if (PYTHON)
  file(GLOB package_dirs "${prefix}/lib/python*/dist-packages")
  set(ENV{PYTHONPATH} "${package_dirs}")
  # (no ";" in the code: CMake would split the argument there)
  run("${PYTHON}" -c "m = __import__('vtkfx')\nprint(m.__file__, m.vtkFXPipelinePass().GetClassName())")
  message("${last_output}")
  if (NOT last_output MATCHES "^${prefix}.*vtkFXPipelinePass")
    message(FATAL_ERROR "'import vtkfx' did not load the installed package")
  endif ()
endif ()
