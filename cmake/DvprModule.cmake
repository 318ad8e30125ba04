# dvpr_module(<target> DEPS <targets...> [DEFINITIONS <name=value...>])
# One static library per folder, built from the .cpp files directly in it
# (subfolders are libraries of their own; main.cpp is excluded), so adding a
# file needs no CMake edit. DEPS are the modules and packages it may use: the
# direction written in docs/architecture.md, which scripts/check_layers.py
# checks against the includes. DEFINITIONS are private compile definitions
# (given here so both variants below get them). Every module also joins the
# umbrella target dvpr_all (benchmarks).
#
# With DVPR_ARCH=dispatch (cmake/DvprArch.cmake) every module has a twin,
# <target>${DVPR_FAST_SUFFIX}, compiled for ${DVPR_FAST_ARCH} and linked only
# to the twins of its modules, so a fast executable holds no generic code and
# the generic one no fast code (Eigen's and std's templates are instantiated in
# both; one binary must not mix them).
function(dvpr_module target)
  cmake_parse_arguments(ARG "" "" "DEPS;DEFINITIONS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  list(FILTER sources EXCLUDE REGEX ".*/main\\.cpp$")
  _dvpr_add_library(${target} "${sources}" "${ARG_DEPS}" "" "${ARG_DEFINITIONS}")
  target_link_libraries(dvpr_all INTERFACE ${target})
  if(DVPR_DISPATCH)
    dvpr_fast_variants(fast_deps ${ARG_DEPS})
    _dvpr_add_library(${target}${DVPR_FAST_SUFFIX} "${sources}" "${fast_deps}" "${DVPR_FAST_FLAGS}"
                      "${ARG_DEFINITIONS}")
    target_link_libraries(dvpr_all${DVPR_FAST_SUFFIX} INTERFACE ${target}${DVPR_FAST_SUFFIX})
  endif()
  set_property(GLOBAL APPEND PROPERTY DVPR_MODULES ${target})
endfunction()

function(_dvpr_add_library target sources deps flags definitions)
  if(sources)
    add_library(${target} STATIC ${sources})
    target_link_libraries(${target} PUBLIC dvpr_includes ${deps})
    target_compile_options(${target} PRIVATE ${flags})
    target_compile_definitions(${target} PRIVATE ${definitions})
  else()
    add_library(${target} INTERFACE)
    target_link_libraries(${target} INTERFACE dvpr_includes ${deps})
  endif()
endfunction()

# dvpr_fast_variants(<out> <targets...>): each module replaced by its fast twin;
# packages and interface-only helpers stay as they are. A module not yet defined
# is an error: its twin would be missed silently.
function(dvpr_fast_variants out)
  get_property(modules GLOBAL PROPERTY DVPR_MODULES)
  set(result)
  foreach(t ${ARGN})
    if(t IN_LIST modules)
      list(APPEND result ${t}${DVPR_FAST_SUFFIX})
    elseif(t MATCHES "^dvpr_" AND NOT t IN_LIST DVPR_SHARED_TARGETS)
      message(FATAL_ERROR "dvpr_fast_variants: ${t} is not a module defined before its users")
    else()
      list(APPEND result ${t})
    endif()
  endforeach()
  set(${out} ${result} PARENT_SCOPE)
endfunction()

# dvpr_executable(<name> SOURCES <files...> LIBS <targets...> [DEFINITIONS <name=value...>]
#                 [OUTPUT_DIR <dir>])
# One executable; with DVPR_ARCH=dispatch also <name>-${DVPR_FAST_ARCH} beside it,
# built from the fast twins. The generic one calls dvpr::ExecFastestVariant
# (experiments/arch/dispatch.h) first: on a CPU that runs the fast variant it
# replaces itself with it.
function(dvpr_executable name)
  cmake_parse_arguments(ARG "" "OUTPUT_DIR" "SOURCES;LIBS;DEFINITIONS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} dvpr_arch)
  target_compile_definitions(${name} PRIVATE ${ARG_DEFINITIONS})
  if(ARG_OUTPUT_DIR)
    set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIR})
  endif()
  if(DVPR_DISPATCH)
    set(fast ${name}-${DVPR_FAST_ARCH})
    target_compile_definitions(${name} PRIVATE DVPR_FAST_EXECUTABLE="${fast}")
    dvpr_fast_variants(fast_libs ${ARG_LIBS} dvpr_arch)
    add_executable(${fast} ${ARG_SOURCES})
    target_link_libraries(${fast} PRIVATE ${fast_libs})
    target_compile_options(${fast} PRIVATE ${DVPR_FAST_FLAGS})
    target_compile_definitions(${fast} PRIVATE ${ARG_DEFINITIONS})
    if(ARG_OUTPUT_DIR)
      set_target_properties(${fast} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIR})
    endif()
    add_dependencies(${name} ${fast})  # building one builds both
  endif()
endfunction()
