# SPDX-License-Identifier: MIT
# Runs COMMAND (a ;-list) and checks its exit code, its output and a file it should write.
#   -DCOMMAND=...            command line
#   -DEXPECT_CODE=n          required exit code
#   -DEXPECT_OUTPUT=regex    optional: stdout+stderr must match
#   -DEXPECT_FILE=path       optional: must exist afterwards (removed before the run)
#   -DUNSET_DISPLAY=ON       optional: run without DISPLAY and WAYLAND_DISPLAY
if(EXPECT_FILE)
  file(REMOVE "${EXPECT_FILE}")
endif()
if(UNSET_DISPLAY)
  unset(ENV{DISPLAY})
  unset(ENV{WAYLAND_DISPLAY})
endif()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 100)
message("${out}${err}")
if(NOT "${code}" STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}")
endif()
if(EXPECT_OUTPUT AND NOT "${out}${err}" MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "output does not match '${EXPECT_OUTPUT}'")
endif()
if(EXPECT_FILE AND NOT EXISTS "${EXPECT_FILE}")
  message(FATAL_ERROR "${EXPECT_FILE} was not written")
endif()
