# Writes the git commit of the source tree into a header, at build time:
#   cmake -DSOURCE_DIR=<repository> -DOUTPUT=<header> -P BilayerGitCommit.cmake
# The header defines BILAYER_GIT_COMMIT: the short hash of HEAD, with
# "-dirty" when tracked files have uncommitted changes, or "unknown" when
# SOURCE_DIR is not the top of a git checkout or git is missing. The file
# is rewritten only when its content changes, so that a build after no new
# commit recompiles nothing. Git is only read (no lock taken, the index
# left as it is).

if(NOT SOURCE_DIR OR NOT OUTPUT)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=DIR -DOUTPUT=FILE -P BilayerGitCommit.cmake")
endif()

set(_commit unknown)
find_program(GIT_EXECUTABLE git)
if(GIT_EXECUTABLE)
  set(ENV{GIT_OPTIONAL_LOCKS} 0)
  execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse --show-toplevel
    WORKING_DIRECTORY "${SOURCE_DIR}"
    OUTPUT_VARIABLE _top OUTPUT_STRIP_TRAILING_WHITESPACE
    RESULT_VARIABLE _rc ERROR_QUIET)
  get_filename_component(_top "${_top}" REALPATH)
  get_filename_component(_source "${SOURCE_DIR}" REALPATH)
  # Only the source tree's own repository (not one it was unpacked into).
  if(_rc EQUAL 0 AND _top STREQUAL _source)
    execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse --short HEAD
      WORKING_DIRECTORY "${SOURCE_DIR}"
      OUTPUT_VARIABLE _hash OUTPUT_STRIP_TRAILING_WHITESPACE
      RESULT_VARIABLE _rc ERROR_QUIET)
    if(_rc EQUAL 0 AND _hash MATCHES "^[0-9a-f]+$")
      set(_commit "${_hash}")
      execute_process(COMMAND "${GIT_EXECUTABLE}" status --porcelain
        --untracked-files=no
        WORKING_DIRECTORY "${SOURCE_DIR}"
        OUTPUT_VARIABLE _status RESULT_VARIABLE _rc ERROR_QUIET)
      if(NOT _rc EQUAL 0 OR NOT _status STREQUAL "")
        string(APPEND _commit "-dirty")
      endif()
    endif()
  endif()
endif()

set(_content
  "// Generated at build time by cmake/BilayerGitCommit.cmake: do not edit.\n#define BILAYER_GIT_COMMIT \"${_commit}\"\n")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" _old)
else()
  set(_old "")
endif()
if(NOT _old STREQUAL _content)
  file(WRITE "${OUTPUT}" "${_content}")
endif()
