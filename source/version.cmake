# Run at every build (the target rsfcycle_version in CMakeLists.txt): write
# OUTPUT from INPUT with the git commit of SOURCE_DIR. configure_file()
# rewrites OUTPUT only when its text changes, so an unchanged commit
# recompiles nothing.
execute_process(
  COMMAND git -C ${SOURCE_DIR} describe --always --dirty --abbrev=12
  OUTPUT_VARIABLE COMMIT
  OUTPUT_STRIP_TRAILING_WHITESPACE
  RESULT_VARIABLE result
  ERROR_QUIET)
if(NOT result EQUAL 0 OR COMMIT STREQUAL "")
  set(COMMIT "unknown (not built from a git clone)")
endif()
configure_file(${INPUT} ${OUTPUT} @ONLY)
