# cmake -P script behind the integration.install_example test. Inputs (-D):
#   UNIMAP_BUILD_DIR    the unimap build tree to install
#   EXAMPLE_SOURCE_DIR  examples/custom_payload
#   SCENARIO_FILE       a scenario the example payload is simulated in
#   WORK_DIR            scratch folder (recreated): prefix/, build/, simulated data and runs
#   GENERATOR, CXX_COMPILER, BUILD_TYPE  used for the example's build
# Every step must succeed; the first failure ends the test with its name.
cmake_minimum_required(VERSION 3.22)
foreach(var UNIMAP_BUILD_DIR EXAMPLE_SOURCE_DIR WORK_DIR GENERATOR SCENARIO_FILE)
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

# 5. The installed `unimap simulate` plays the example's servo (MotorMotion:
#    oscillating -45..+45 deg, 2 s) from the plugin's own parameters; the
#    recorded encoder reads the servo angle as it is (negative, unwrapped).
set(sim_out "${WORK_DIR}/nodding_sim")
file(WRITE "${WORK_DIR}/nodding.yaml" "plugin: nodding_2d\n")
file(GLOB_RECURSE installed_unimap "${prefix}/bin/unimap")
run_step("simulate the example" "${CMAKE_COMMAND}" -E env "UNIMAP_PLUGIN_PATH=${example_build}"
  ${installed_unimap} simulate --scenario "${SCENARIO_FILE}" --payload "${WORK_DIR}/nodding.yaml"
  --duration-s 4 --out "${sim_out}")
file(STRINGS "${sim_out}/encoder.csv" encoder_lines REGEX "^[-0-9]")
list(LENGTH encoder_lines encoder_count)
set(lowest 1000)
set(highest -1000)
foreach(line ${encoder_lines})
  string(REGEX REPLACE "^[^ ]+ " "" angle "${line}")
  if(angle LESS lowest)
    set(lowest ${angle})
  endif()
  if(angle GREATER highest)
    set(highest ${angle})
  endif()
endforeach()
message(STATUS "nodding encoder: ${encoder_count} samples, ${lowest} .. ${highest} rad")
# -45 and +45 deg are -0.7854 and 0.7854 rad; the scenario's encoder quantises to its counts.
if(encoder_count LESS 100 OR lowest GREATER -0.78 OR lowest LESS -0.79 OR highest LESS 0.78 OR highest GREATER 0.79)
  message(FATAL_ERROR "the simulated servo does not nod -45..+45 deg: ${encoder_count} samples, ${lowest} .. ${highest}")
endif()

# 6. The example maps the whole narrow hallway (simulated with the installed
#    `unimap simulate`, mapped by the installed `unimap run` with the
#    payload's own defaults and nothing else) to the issue's ATE <= 0.15 m.
set(hallway "${WORK_DIR}/nodding_hallway")
set(hallway_run "${WORK_DIR}/nodding_hallway_run")
run_step("simulate the hallway" "${CMAKE_COMMAND}" -E env "UNIMAP_PLUGIN_PATH=${example_build}"
  ${installed_unimap} simulate --scenario "${SCENARIO_FILE}" --payload "${WORK_DIR}/nodding.yaml" --out "${hallway}")
run_step("map the hallway" "${CMAKE_COMMAND}" -E env "UNIMAP_PLUGIN_PATH=${example_build}"
  ${installed_unimap} run --threads 1 --quiet --platform "${WORK_DIR}/nodding.yaml" --data "${hallway}"
  --out "${hallway_run}")
file(READ "${hallway_run}/metrics.json" metrics)
string(JSON ate GET "${metrics}" ate_rmse_m)
message(STATUS "nodding example, narrow hallway: ate_rmse_m ${ate}")
if(ate GREATER 0.15)
  message(FATAL_ERROR "the nodding example maps the narrow hallway to ATE ${ate} m, above 0.15 m")
endif()
