# Writes OUT, the header with the build's version, at every build (rewriting it only when it
# changes): the commit, and for a tree with uncommitted changes a hash of them, so that runs
# of an ensemble made by different sources never pass for the same build.
#   cmake -DSRC=<source dir> -DOUT=<header> -P program_version.cmake
execute_process(COMMAND git -C "${SRC}" rev-parse --short=12 HEAD
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET
                RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT commit)
  set(version "unknown")
else()
  execute_process(COMMAND git -C "${SRC}" diff HEAD OUTPUT_VARIABLE changes ERROR_QUIET)
  if(changes)
    string(SHA1 changes_hash "${changes}")
    string(SUBSTRING "${changes_hash}" 0 8 changes_hash)
    set(version "${commit}-dirty-${changes_hash}")
  else()
    set(version "${commit}")
  endif()
endif()
set(text "#pragma once\n// Written at build time by app/ensemble/program_version.cmake.\n#define SWARMLAB_VERSION \"${version}\"\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
