# Writes the page's service worker (web/service_worker.js) into the build with this build's
# version: the first 16 hex digits of a SHA-256 over the files the page loads (their names and
# contents), and the list of those files. Any change to any of them is a new version, which
# browsers that visited before fetch at their next visit.
#   cmake -DDIR=<build/web> -DTEMPLATE=<web/service_worker.js> -DFILES=a,b,c -P service_worker_version.cmake
string(REPLACE "," ";" files "${FILES}")
set(digests "")
set(quoted "")
foreach(f ${files})
  if(NOT EXISTS "${DIR}/${f}")
    message(FATAL_ERROR "service worker: ${DIR}/${f} is missing")
  endif()
  file(SHA256 "${DIR}/${f}" digest)
  string(APPEND digests "${f} ${digest}\n")
  list(APPEND quoted "'${f}'")
endforeach()
file(READ "${TEMPLATE}" text)
string(APPEND digests "${text}")  # the worker's own code is part of the version too
string(SHA256 version "${digests}")
string(SUBSTRING "${version}" 0 16 version)
list(JOIN quoted ", " quoted)
string(REPLACE "@SWARMLAB_WEB_VERSION@" "${version}" text "${text}")
string(REPLACE "@SWARMLAB_WEB_FILES@" "${quoted}" text "${text}")
set(out "${DIR}/service_worker.js")
set(old "")
if(EXISTS "${out}")
  file(READ "${out}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${out}" "${text}")
  message(STATUS "service worker: version ${version}")
endif()
