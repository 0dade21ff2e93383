# The ctest docs.doxygen: runs Doxygen on the public headers and fails on any warning (an
# undocumented public type, function, member or enum value, or a broken Doxygen command),
# printing every one.
#   cmake -DDOXYGEN=... -DDOXYFILE=... -DWARNINGS=... -P check_doxygen.cmake
file(REMOVE ${WARNINGS})
get_filename_component(directory ${DOXYFILE} DIRECTORY)
execute_process(COMMAND ${DOXYGEN} ${DOXYFILE} WORKING_DIRECTORY ${directory} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "doxygen ${DOXYFILE} failed (exit ${status})")
endif()
set(lines "")
if(EXISTS ${WARNINGS})
  file(STRINGS ${WARNINGS} lines)
endif()
list(LENGTH lines count)
if(count GREATER 0)
  list(JOIN lines "\n" text)
  message("${text}")
  message(FATAL_ERROR "${count} Doxygen warning line(s) on the public headers, listed above (also in ${WARNINGS})")
endif()
message(STATUS "Doxygen: no warnings on the public headers (${directory}/html/index.html)")
