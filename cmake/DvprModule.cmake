# dvpr_module(<target> DEPS <targets...>)
# One static library per folder, built from the .cpp files directly in it
# (subfolders are libraries of their own; main.cpp is excluded), so adding a
# file needs no CMake edit. DEPS are the modules and packages it may use: the
# direction written in docs/architecture.md, which scripts/check_layers.py
# checks against the includes. Every module also joins the umbrella target
# dvpr_all (benchmarks).
function(dvpr_module target)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
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
