# Renders INPUT with vtkfx-render through vtkFX (--effects none) and with
# --plain-vtk, then requires PSNR >= MIN_PSNR between them, and checks that
# the --stats JSON names the passes that ran and the G-buffer's size.
#   cmake -DRENDER=... -DCOMPARE=... -DINPUT=... -DOUT=dir -DMIN_PSNR=50 -P CompareRenders.cmake
get_filename_component(name "${INPUT}" NAME_WE)
string(REPLACE ":" "_" name "${name}")
set(fx "${OUT}/${name}-vtkfx.png")
set(vtk "${OUT}/${name}-vtk.png")
set(stats "${OUT}/${name}-stats.json")
file(REMOVE "${fx}" "${vtk}" "${stats}") # (an earlier run's files prove nothing)
execute_process(COMMAND "${RENDER}" "${INPUT}" --size 400x300 --effects none --frames 3
  --out "${fx}" --stats "${stats}" RESULT_VARIABLE rc)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "vtkfx-render failed (${rc})")
endif ()
execute_process(COMMAND "${RENDER}" "${INPUT}" --size 400x300 --plain-vtk --out "${vtk}"
  RESULT_VARIABLE rc)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "vtkfx-render --plain-vtk failed (${rc})")
endif ()
execute_process(COMMAND "${COMPARE}" "${fx}" "${vtk}" --min-psnr "${MIN_PSNR}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message("${INPUT}: ${out}")
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "vtkFX and plain VTK differ: ${out}")
endif ()
file(READ "${stats}" json)
message("${json}")
if (NOT json MATCHES "\"passes_ran\": \\[\"lights\", \"gbuffer\", \"composite\"")
  message(FATAL_ERROR "stats do not list the deferred passes")
endif ()
if (NOT json MATCHES "\"gbuffer_bytes_per_pixel\": [1-9][0-9]*")
  message(FATAL_ERROR "stats lack the G-buffer size")
endif ()
