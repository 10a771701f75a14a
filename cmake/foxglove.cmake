# The MCAP exporter for Foxglove (included by CMakeLists.txt after viewer.cmake,
# whose node and npm it uses; docs/foxglove.md):
#  - proxsim_foxglove (built by default): `npm ci` in foxglove/ when its
#    package-lock.json changed (a stamp file in node_modules): @mcap/core,
#    @mcap/nodejs and @foxglove/schemas, at the versions the lock pins. The
#    exporter runs from the source tree with node; nothing is bundled.
#  - proxsim_report learns where node and the exporter are (PROXSIM_NODE_PROGRAM,
#    PROXSIM_MCAP_EXPORTER), for ExportMcap(); the tests where the read-back
#    check is (PROXSIM_MCAP_READBACK).

find_program(PROXSIM_NODE node REQUIRED)
find_program(PROXSIM_NPM npm REQUIRED)
set(foxglove_dir ${CMAKE_SOURCE_DIR}/foxglove)
set(foxglove_npm_stamp ${foxglove_dir}/node_modules/.proxsim-npm-ci.stamp)
add_custom_command(
  OUTPUT ${foxglove_npm_stamp}
  COMMAND ${PROXSIM_NPM} ci --no-audit --no-fund --loglevel=error
  COMMAND ${CMAKE_COMMAND} -E touch ${foxglove_npm_stamp}
  DEPENDS ${foxglove_dir}/package-lock.json ${foxglove_dir}/package.json
  WORKING_DIRECTORY ${foxglove_dir}
  COMMENT "Installing the MCAP exporter's npm packages (npm ci)"
  VERBATIM)
add_custom_target(proxsim_foxglove ALL DEPENDS ${foxglove_npm_stamp})
add_dependencies(proxsim proxsim_foxglove)

target_compile_definitions(proxsim_report PUBLIC
  PROXSIM_NODE_PROGRAM="${PROXSIM_NODE}"
  PROXSIM_MCAP_EXPORTER="${foxglove_dir}/src/export_mcap.mjs")
if(PROXSIM_BUILD_TESTS)
  target_compile_definitions(proxsim_tests PRIVATE
    PROXSIM_MCAP_READBACK="${CMAKE_SOURCE_DIR}/tests/foxglove/mcap_readback.mjs")
endif()
