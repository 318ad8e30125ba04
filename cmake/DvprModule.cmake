# dvpr_module(<target> DEPS <targets...>)
# One static library per top-level folder, built from every .cpp below it
# (main.cpp excluded), so adding a file needs no CMake edit. The module joins
# the umbrella target dvpr_all that tests, benchmarks and the dvpr command link.
function(dvpr_module target)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  list(FILTER sources EXCLUDE REGEX ".*/main\\.cpp$")
  if(sources)
    add_library(${target} STATIC ${sources})
    target_link_libraries(${target} PUBLIC dvpr_includes ${ARG_DEPS})
  else()
    add_library(${target} INTERFACE)
    target_link_libraries(${target} INTERFACE dvpr_includes ${ARG_DEPS})
  endif()
  target_link_libraries(dvpr_all INTERFACE ${target})
endfunction()
