# dvpr_module(<target> [PUBLIC <targets...>] [PRIVATE <targets...>] [DEFINITIONS <name=value...>])
# One static library per folder, built from the .cpp files directly in it
# (subfolders are libraries of their own; main.cpp is excluded), so adding a
# file needs no CMake edit. PUBLIC and PRIVATE together are the modules and
# packages it may use, exactly its row of docs/architecture.md; PUBLIC only
# those its headers include (their users need them too), PRIVATE the rest.
# scripts/check_layers.py checks both against the includes. DEFINITIONS are private compile definitions
# (given here so both variants below get them). Every module also joins the
# umbrella target dvpr_all (benchmarks).
#
# With DVPR_ARCH=dispatch (cmake/DvprArch.cmake) every module has a twin,
# <target>${DVPR_FAST_SUFFIX}, compiled for ${DVPR_FAST_ARCH} and linked only
# to the twins of its modules, so a fast executable holds no generic code and
# the generic one no fast code (Eigen's and std's templates are instantiated in
# both; one binary must not mix them).
function(dvpr_module target)
  cmake_parse_arguments(ARG "" "" "PUBLIC;PRIVATE;DEPS;DEFINITIONS" ${ARGN})
  list(APPEND ARG_PUBLIC ${ARG_DEPS})  # DEPS: the earlier name of PUBLIC
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "dvpr_module(${target}): unexpected ${ARG_UNPARSED_ARGUMENTS} (PUBLIC, PRIVATE, DEFINITIONS)")
  endif()
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  list(FILTER sources EXCLUDE REGEX ".*/main\\.cpp$")
  _dvpr_add_library(${target} "${sources}" "${ARG_PUBLIC}" "${ARG_PRIVATE}" "" "${ARG_DEFINITIONS}")
  target_link_libraries(dvpr_all INTERFACE ${target})
  if(DVPR_DISPATCH)
    dvpr_fast_variants(fast_public ${ARG_PUBLIC})
    dvpr_fast_variants(fast_private ${ARG_PRIVATE})
    _dvpr_add_library(${target}${DVPR_FAST_SUFFIX} "${sources}" "${fast_public}" "${fast_private}"
                      "${DVPR_FAST_FLAGS}" "${ARG_DEFINITIONS}")
    target_link_libraries(dvpr_all${DVPR_FAST_SUFFIX} INTERFACE ${target}${DVPR_FAST_SUFFIX})
  endif()
  set_property(GLOBAL APPEND PROPERTY DVPR_MODULES ${target})
endfunction()

function(_dvpr_add_library target sources public private flags definitions)
  if(sources)
    add_library(${target} STATIC ${sources})
    target_link_libraries(${target} PUBLIC dvpr_includes ${public} PRIVATE ${private})
    target_compile_options(${target} PRIVATE ${flags})
    target_compile_definitions(${target} PRIVATE ${definitions})
    if(DVPR_FUZZ AND target IN_LIST DVPR_FUZZ_COVERED)  # tests/fuzz/fuzz_flags.cmake
      target_compile_options(${target} PRIVATE ${DVPR_FUZZ_COVERAGE_FLAGS})
      target_link_libraries(${target} PUBLIC dvpr_fuzz_coverage)
    endif()
  else()
    if(private)  # a library of headers only has no sources of its own to use them
      message(FATAL_ERROR "${target}: PRIVATE ${private} in a module without .cpp files")
    endif()
    add_library(${target} INTERFACE)
    target_link_libraries(${target} INTERFACE dvpr_includes ${public})
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
