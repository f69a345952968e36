# Writes the code version recorded in every result (solver/version.cpp.in -> OUTPUT).
# Run by the `slipfront_version` target on every build, so a rebuild after new commits
# records the new `git describe`; configure_file leaves OUTPUT untouched (and nothing
# recompiles) when the version has not changed.
# Inputs: SOURCE_DIR, INPUT, OUTPUT, PROJECT_VERSION.
execute_process(COMMAND git describe --always --dirty --tags
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE SLIPFRONT_GIT_DESCRIBE OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT SLIPFRONT_GIT_DESCRIBE)
  set(SLIPFRONT_GIT_DESCRIBE "unknown")
endif()
set(SLIPFRONT_VERSION_STRING "${PROJECT_VERSION}+${SLIPFRONT_GIT_DESCRIBE}")
configure_file(${INPUT} ${OUTPUT} @ONLY)
