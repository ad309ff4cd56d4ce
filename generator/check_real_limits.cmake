# Every parallel region of the generator makes Real's numeric limits first
# (sg::prepare_real_limits, algebra/real.hpp): Boost 1.74 caches them on first
# use without a lock, and threads that get there together can read a wrong
# epsilon (seen in CI as "inverse iteration lost rank"). Run as a test:
#   cmake -P generator/check_real_limits.cmake
# Fails naming each tbb::parallel_for whose previous line does not call it.
file(GLOB_RECURSE sources "${CMAKE_CURRENT_LIST_DIR}/*.cpp" "${CMAKE_CURRENT_LIST_DIR}/*.hpp")
set(faults "")
foreach(source IN LISTS sources)
  file(STRINGS "${source}" lines)
  set(previous "")
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    if(line MATCHES "tbb::parallel_(for|for_each|invoke|reduce)\\(" AND NOT previous MATCHES "prepare_real_limits\\(\\)")
      file(RELATIVE_PATH name "${CMAKE_CURRENT_LIST_DIR}" "${source}")
      string(APPEND faults "  generator/${name}:${number}: a parallel region without sg::prepare_real_limits() on the line before\n")
    endif()
    if(NOT line MATCHES "^[ \t]*$")
      set(previous "${line}")
    endif()
  endforeach()
endforeach()
if(faults)
  message(FATAL_ERROR "parallel regions that may first use Real's numeric limits together:\n${faults}")
endif()
message(STATUS "every parallel region of the generator prepares Real's numeric limits first")
