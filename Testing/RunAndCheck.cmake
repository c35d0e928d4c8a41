# Runs one command and checks its exit code and output.
#   cmake -DCOMMAND="prog|arg|arg" -DEXPECT_RESULT=N [-DEXPECT_OUTPUT=regex]
#         [-DEXPECT_FILE=path] -P RunAndCheck.cmake
# ("|" separates arguments, since CTest would split a ";" list.)
string(REPLACE "|" ";" command "${COMMAND}")
if (DEFINED EXPECT_FILE)
  file(REMOVE "${EXPECT_FILE}") # (one left by an earlier run proves nothing)
endif ()
execute_process(COMMAND ${command} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if (NOT rc STREQUAL "${EXPECT_RESULT}")
  message(FATAL_ERROR "exit status '${rc}', expected ${EXPECT_RESULT}")
endif ()
if (DEFINED EXPECT_OUTPUT AND NOT "${out}${err}" MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "output does not match '${EXPECT_OUTPUT}'")
endif ()
if (DEFINED EXPECT_FILE AND NOT EXISTS "${EXPECT_FILE}")
  message(FATAL_ERROR "'${EXPECT_FILE}' was not written")
endif ()
