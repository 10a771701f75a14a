# The report's build and tests (included by CMakeLists.txt).
#  - proxsim_viewer (built by default): `npm ci` in viewer/ when package-lock.json
#    changed (a stamp file in node_modules), then esbuild bundles three.js, uPlot
#    and the viewer into ONE script, ${CMAKE_BINARY_DIR}/viewer/viewer.js.
#  - proxsim_report learns where the bundle and report/make_report.py are
#    (PROXSIM_VIEWER_BUNDLE, PROXSIM_REPORT_SCRIPT), for MakeReport().
#  - tests: the report's Python unit tests, and the viewer's end-to-end test in
#    Debian's chromium (skipped, exit 77, only when /usr/bin/chromium is missing).

find_program(PROXSIM_NODE node REQUIRED)
find_program(PROXSIM_NPM npm REQUIRED)

set(viewer_dir ${CMAKE_SOURCE_DIR}/viewer)
set(viewer_bundle ${CMAKE_BINARY_DIR}/viewer/viewer.js)
set(viewer_npm_stamp ${viewer_dir}/node_modules/.proxsim-npm-ci.stamp)

add_custom_command(
  OUTPUT ${viewer_npm_stamp}
  COMMAND ${PROXSIM_NPM} ci --no-audit --no-fund --loglevel=error
  COMMAND ${CMAKE_COMMAND} -E touch ${viewer_npm_stamp}
  DEPENDS ${viewer_dir}/package-lock.json ${viewer_dir}/package.json
  WORKING_DIRECTORY ${viewer_dir}
  COMMENT "Installing the viewer's npm packages (npm ci)"
  VERBATIM)

file(GLOB viewer_sources CONFIGURE_DEPENDS ${viewer_dir}/src/*.js ${viewer_dir}/src/*.css)
add_custom_command(
  OUTPUT ${viewer_bundle}
  COMMAND ${PROXSIM_NODE} build.mjs --outfile ${viewer_bundle}
  DEPENDS ${viewer_npm_stamp} ${viewer_sources} ${viewer_dir}/build.mjs
  WORKING_DIRECTORY ${viewer_dir}
  COMMENT "Bundling the replay viewer (esbuild)"
  VERBATIM)
add_custom_target(proxsim_viewer ALL DEPENDS ${viewer_bundle})

target_compile_definitions(proxsim_report PUBLIC
  PROXSIM_VIEWER_BUNDLE="${viewer_bundle}"
  PROXSIM_REPORT_SCRIPT="${CMAKE_SOURCE_DIR}/report/make_report.py")
add_dependencies(proxsim proxsim_viewer)

if(PROXSIM_BUILD_TESTS)
  set(report_python /usr/bin/python3)   # Debian's, which has python3-matplotlib
  add_test(NAME report_unit
           COMMAND ${report_python} -m unittest discover -s ${CMAKE_SOURCE_DIR}/tests/report -v)
  set_tests_properties(report_unit PROPERTIES LABELS python)

  # The browser test opens the report of real runs: the default paper run
  # (walking robot), the world-mounted sensor demo (no robot), the
  # circumvent example (the path walked and the strategy's events), the
  # stairs course (the robot shown climbs to the 0.6 m landing) and the H1's.
  # `proxsim run` draws the report itself.
  set(e2e_scenario_walk "")
  set(e2e_scenario_no_robot ${CMAKE_SOURCE_DIR}/data/scenarios/world_sensors_demo.yaml)
  set(e2e_scenario_circumvent ${CMAKE_SOURCE_DIR}/data/scenarios/circumvent_obstacle.yaml)
  set(e2e_scenario_stairs ${CMAKE_SOURCE_DIR}/data/scenarios/stairs_walk.yaml)
  set(e2e_options_stairs --climb-m 0.55)
  set(e2e_scenario_collision ${CMAKE_SOURCE_DIR}/data/scenarios/paper_no_stop_rule.yaml)
  set(e2e_scenario_multizone ${CMAKE_SOURCE_DIR}/data/scenarios/multizone_shins.yaml)
  set(e2e_scenario_moving ${CMAKE_SOURCE_DIR}/data/scenarios/person_crossing.yaml)
  set(e2e_kinds walk no_robot circumvent stairs collision multizone moving)
  # and the Unitree H1's example (its meshes drawn), when the H1's description (Unitree's,
  # not part of this repository) is beside the repository in ../shared/robots
  if(EXISTS ${CMAKE_SOURCE_DIR}/../shared/robots/h1_description/urdf/h1.urdf)
    set(e2e_scenario_h1 ${CMAKE_SOURCE_DIR}/data/scenarios/h1_dining_room.yaml)
    list(APPEND e2e_kinds h1)
  endif()
  foreach(kind ${e2e_kinds})
    set(run_dir ${CMAKE_BINARY_DIR}/viewer_e2e/${kind})
    add_test(NAME viewer_e2e_${kind}_run
             COMMAND $<TARGET_FILE:proxsim> run ${e2e_scenario_${kind}} --out ${run_dir})
    add_test(NAME viewer_e2e_${kind}
             COMMAND ${PROXSIM_NODE} ${CMAKE_SOURCE_DIR}/tests/viewer_e2e/viewer_e2e.mjs ${run_dir}
                     --viewer-dir ${viewer_dir} ${e2e_options_${kind}})
    # label browser, the run too: it exists for the browser test only
    set_tests_properties(viewer_e2e_${kind}_run PROPERTIES FIXTURES_SETUP e2e_${kind}_run TIMEOUT 180
      LABELS browser)
    set_tests_properties(viewer_e2e_${kind} PROPERTIES
      FIXTURES_REQUIRED e2e_${kind}_run SKIP_RETURN_CODE 77 TIMEOUT 240
      RESOURCE_LOCK chromium LABELS browser)
  endforeach()
endif()
