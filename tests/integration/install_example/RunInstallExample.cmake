# cmake -P script behind the integration.install_example test. Inputs (-D):
#   UNIMAP_BUILD_DIR    the unimap build tree to install
#   EXAMPLE_SOURCE_DIR  examples/custom_payload
#   WORK_DIR            scratch folder (recreated): prefix/ and build/
#   GENERATOR, CXX_COMPILER, BUILD_TYPE  used for the example's build
# Every step must succeed; the first failure ends the test with its name.
cmake_minimum_required(VERSION 3.22)
foreach(var UNIMAP_BUILD_DIR EXAMPLE_SOURCE_DIR WORK_DIR GENERATOR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "RunInstallExample.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()
set(prefix "${WORK_DIR}/prefix")
set(example_build "${WORK_DIR}/build")

# run_step(<name> <command>...): runs the command, fails the test if it fails.
function(run_step name)
  list(JOIN ARGN " " command_line)
  message(STATUS "=== ${name}: ${command_line}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "step '${name}' failed (${rc})")
  endif()
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# 1. The install must reflect the current sources: bring the tree up to date
#    (a no-op right after a build), then install it to the scratch prefix.
run_step("build unimap" "${CMAKE_COMMAND}" --build "${UNIMAP_BUILD_DIR}")
run_step("install unimap" "${CMAKE_COMMAND}" --install "${UNIMAP_BUILD_DIR}" --prefix "${prefix}")
foreach(installed unimapConfig.cmake UnimapPluginHelpers.cmake conformance_main.cpp.in
                  PayloadConformance.hpp)
  file(GLOB_RECURSE found "${prefix}/*/${installed}")
  if(NOT found)
    message(FATAL_ERROR "the install lacks ${installed}")
  endif()
endforeach()

# 2. The example as a third party builds it: only the installed package.
run_step("configure example" "${CMAKE_COMMAND}" -S "${EXAMPLE_SOURCE_DIR}" -B "${example_build}"
  -G "${GENERATOR}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
  "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run_step("build example" "${CMAKE_COMMAND}" --build "${example_build}" --parallel 2)

# 3. Its conformance tests (registered by unimap_add_conformance_test).
run_step("test example" "${CMAKE_COMMAND}" -E env --unset=UNIMAP_CONFORMANCE_PLUGINS
  --unset=UNIMAP_PLUGIN_PATH
  "${CMAKE_CTEST_COMMAND}" --test-dir "${example_build}" --output-on-failure --no-tests=error)

# 4. The installed in-tree plugins through the installed suite.
file(GLOB_RECURSE installed_plugins "${prefix}/*/unimap/plugins/libunimap_payload_*.so")
if(NOT installed_plugins)
  message(FATAL_ERROR "no libunimap_payload_*.so under ${prefix}")
endif()
set(plugin_args "")
foreach(plugin ${installed_plugins})
  list(APPEND plugin_args "--plugin=${plugin}")
endforeach()
run_step("installed plugins" "${CMAKE_COMMAND}" -E env --unset=UNIMAP_CONFORMANCE_PLUGINS
  "${example_build}/nodding_2d_conformance" ${plugin_args} --gtest_brief=1)
