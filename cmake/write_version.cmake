# cmake -DGIT=... -DSOURCE_DIR=... -DPROJECT_VERSION=... -DINPUT=... -DOUTPUT=...
#   -P write_version.cmake
# Writes OUTPUT from INPUT (common/version.cc.in) with the checkout's
# `git describe`, at every build, and touches it only when that changed, so
# that an unchanged checkout relinks nothing.
set(AG_GIT_DESCRIBE "no git")
if(GIT)
  execute_process(
    COMMAND ${GIT} describe --always --dirty --tags
    WORKING_DIRECTORY ${SOURCE_DIR}
    OUTPUT_VARIABLE describe
    RESULT_VARIABLE status
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(status EQUAL 0)
    set(AG_GIT_DESCRIBE ${describe})
  endif()
endif()
configure_file(${INPUT} ${OUTPUT} @ONLY)
