cmake_minimum_required(VERSION 3.22)
# The generator's folders and what each may include (cmake -P check_layering.cmake,
# run by ctest as "generator layering"). Static libraries would link a wrong-way
# call silently, so the direction of dependencies is checked here, by include.
# Keep this in step with the libraries in CMakeLists.txt.
set(allowed_base base)
set(allowed_algebra base algebra)
set(allowed_common base algebra common)
set(allowed_curve base algebra common curve)
set(allowed_quad base algebra common curve quad)
set(allowed_triangle base algebra common curve triangle)  # curve: a crease curve
set(allowed_cli base algebra common curve quad triangle cli)

set(violations "")
foreach(folder base algebra common curve quad triangle cli)
  file(GLOB sources "${CMAKE_CURRENT_LIST_DIR}/${folder}/*.hpp" "${CMAKE_CURRENT_LIST_DIR}/${folder}/*.cpp")
  foreach(source ${sources})
    file(STRINGS "${source}" includes REGEX "^#include \"[a-z_]+/")
    foreach(line ${includes})
      string(REGEX REPLACE "^#include \"([a-z_]+)/.*" "\\1" used "${line}")
      if(line STREQUAL "#include \"stencil_runtime/binary_format.hpp\"")
        continue()  # the binary formats, defined once for the runtime and the generator
      endif()
      if(NOT used IN_LIST allowed_${folder})
        file(RELATIVE_PATH name "${CMAKE_CURRENT_LIST_DIR}" "${source}")
        string(APPEND violations "  ${name}: ${line} (${folder}/ may include only: ${allowed_${folder}})\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "generator layering violated:\n${violations}")
endif()
message(STATUS "generator layering holds")
