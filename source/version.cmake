# SPDX-License-Identifier: LGPL-2.1-or-later
# Run at every build (the target rsfcycle_version in CMakeLists.txt): write
# OUTPUT from INPUT with the git commit of SOURCE_DIR. OUTPUT is replaced
# only when its text changes, so an unchanged commit recompiles nothing,
# and by a rename, so that builds running at once (ctest -j builds each
# test's target) never see it half written.
execute_process(
  COMMAND git -C ${SOURCE_DIR} describe --always --dirty --abbrev=12
  OUTPUT_VARIABLE COMMIT
  OUTPUT_STRIP_TRAILING_WHITESPACE
  RESULT_VARIABLE result
  ERROR_QUIET)
if(NOT result EQUAL 0 OR COMMIT STREQUAL "")
  set(COMMIT "unknown (not built from a git clone)")
endif()
# a name of this process's own: the shell's process id
execute_process(COMMAND sh -c "echo $$" OUTPUT_VARIABLE pid
  OUTPUT_STRIP_TRAILING_WHITESPACE)
set(temporary ${OUTPUT}.${pid})
configure_file(${INPUT} ${temporary} @ONLY)
file(READ ${temporary} new_text)
set(old_text "")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old_text)
endif()
if(new_text STREQUAL old_text)
  file(REMOVE ${temporary})
else()
  file(RENAME ${temporary} ${OUTPUT})
endif()
