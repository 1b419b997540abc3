# Helpers for payload plugins, used in-tree and by out-of-tree projects after
# find_package(unimap).
#
#   unimap_add_payload_plugin(<name> SOURCES <src>... [LINK_LIBRARIES <lib>...] [NO_INSTALL])
#     Builds the MODULE library libunimap_payload_<name>.so (target
#     unimap_payload_<name>) that the unimap plugin loader finds by <name>.
#
#   unimap_add_conformance_test(<name> [PLUGIN_TARGET <target>])
#     Builds <name>_conformance, runs the unimap payload conformance suite
#     against the plugin, and registers every case with ctest.
include_guard(GLOBAL)
include(GNUInstallDirs)

set(_UNIMAP_HELPERS_DIR "${CMAKE_CURRENT_LIST_DIR}")

function(unimap_add_payload_plugin name)
  cmake_parse_arguments(ARG "NO_INSTALL" "" "SOURCES;LINK_LIBRARIES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "unimap_add_payload_plugin(${name}): SOURCES is required")
  endif()
  set(target unimap_payload_${name})
  add_library(${target} MODULE ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE unimap::sdk ${ARG_LINK_LIBRARIES})
  set_target_properties(${target} PROPERTIES
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    PREFIX "lib"
    OUTPUT_NAME "unimap_payload_${name}"
    INSTALL_RPATH "$ORIGIN/../..")
  if(DEFINED UNIMAP_PLUGIN_BUILD_DIR)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${UNIMAP_PLUGIN_BUILD_DIR}")
  endif()
  if(NOT ARG_NO_INSTALL)
    if(DEFINED UNIMAP_PLUGIN_INSTALL_DIR)
      set(dest "${UNIMAP_PLUGIN_INSTALL_DIR}")
    else()
      set(dest "${CMAKE_INSTALL_LIBDIR}/unimap/plugins")
    endif()
    install(TARGETS ${target} LIBRARY DESTINATION "${dest}")
  endif()
endfunction()

function(unimap_add_conformance_test name)
  cmake_parse_arguments(ARG "" "PLUGIN_TARGET" "" ${ARGN})
  if(NOT ARG_PLUGIN_TARGET)
    set(ARG_PLUGIN_TARGET unimap_payload_${name})
  endif()
  if(NOT TARGET ${ARG_PLUGIN_TARGET})
    message(FATAL_ERROR "unimap_add_conformance_test(${name}): no target ${ARG_PLUGIN_TARGET}")
  endif()
  include(GoogleTest)
  set(main_src "${CMAKE_CURRENT_BINARY_DIR}/${name}_conformance_main.cpp")
  configure_file("${_UNIMAP_HELPERS_DIR}/conformance_main.cpp.in" "${main_src}" COPYONLY)
  add_executable(${name}_conformance "${main_src}")
  target_link_libraries(${name}_conformance PRIVATE unimap::conformance)
  target_compile_definitions(${name}_conformance PRIVATE
    "UNIMAP_CONFORMANCE_PLUGIN=\"$<TARGET_FILE:${ARG_PLUGIN_TARGET}>\"")
  add_dependencies(${name}_conformance ${ARG_PLUGIN_TARGET})
  # NO_PRETTY_VALUES: the suite names each case after its plugin; without it
  # ctest names would end in "# GetParam() = <path>". The emptied variable
  # keeps a caller's UNIMAP_CONFORMANCE_PLUGINS from redirecting the run.
  gtest_discover_tests(${name}_conformance TEST_PREFIX "conformance.${name}." DISCOVERY_TIMEOUT 60
                       NO_PRETTY_VALUES PROPERTIES ENVIRONMENT "UNIMAP_CONFORMANCE_PLUGINS=")
endfunction()
