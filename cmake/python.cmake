# The Python package (included by CMakeLists.txt): `proxsim` in
# ${CMAKE_BINARY_DIR}/python/proxsim, importable with
# PYTHONPATH=build/<preset>/python by Debian's /usr/bin/python3 (pybind11-dev,
# python3-dev, python3-numpy; scripts/install-deps.sh installs them). The
# package's .py files are copied next to the compiled core at every build.
# Tests: tests/python through pytest (python3-pytest), as one CTest test.

# .venv/ (scripts/install-deps.sh) is Debian's Python with PyPI's pinned
# packages (python/requirements.txt: mujoco, gymnasium, xacro, rosbags) over it;
# without it, Debian's Python alone.
if(EXISTS ${CMAKE_SOURCE_DIR}/.venv/bin/python3)
  set(proxsim_default_python ${CMAKE_SOURCE_DIR}/.venv/bin/python3)
else()
  set(proxsim_default_python /usr/bin/python3)
endif()
set(Python_EXECUTABLE ${proxsim_default_python} CACHE FILEPATH "Debian's Python (in .venv/ with PyPI's pinned packages), for which pybind11-dev and python3-numpy are installed")
set(PYBIND11_FINDPYTHON ON)
find_package(Python COMPONENTS Interpreter Development.Module REQUIRED)
find_package(pybind11 CONFIG REQUIRED)

# The sanitizer pass runs no Python test (the interpreter is not ours to
# judge): its preset leaves the module out (PROXSIM_BUILD_PYTHON_MODULE OFF).
if(PROXSIM_BUILD_PYTHON_MODULE)
  set(python_package_dir ${CMAKE_BINARY_DIR}/python/proxsim)
  # pybind11 links the module with -flto unless told otherwise: over its three
  # binding files (the modules it links are not LTO objects) that bought nothing
  # but a serial LTRANS pass at every link and lto-wrapper's warning about it
  set(CMAKE_INTERPROCEDURAL_OPTIMIZATION OFF)
  pybind11_add_module(proxsim_python MODULE python/bindings/module.cc python/bindings/robot_state.cc
                      python/bindings/vec_walk_env.cc)
  set_target_properties(proxsim_python PROPERTIES OUTPUT_NAME _core LIBRARY_OUTPUT_DIRECTORY ${python_package_dir})
  target_link_libraries(proxsim_python PRIVATE proxsim_lib)
  target_compile_options(proxsim_python PRIVATE -Wall -Wextra)

  file(GLOB python_sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/python/proxsim/*.py)
  set(python_copies "")
  foreach(source ${python_sources})
    get_filename_component(name ${source} NAME)
    add_custom_command(OUTPUT ${python_package_dir}/${name}
                       COMMAND ${CMAKE_COMMAND} -E copy_if_different ${source} ${python_package_dir}/${name}
                       DEPENDS ${source} VERBATIM)
    list(APPEND python_copies ${python_package_dir}/${name})
  endforeach()
  add_custom_target(proxsim_python_package ALL DEPENDS ${python_copies})
  add_dependencies(proxsim_python proxsim_python_package)
  # `proxsim bench` drives the paper run from Python too (bench/python_loop.py)
  target_compile_definitions(proxsim_bench PRIVATE PROXSIM_PYTHON_DIR="${CMAKE_BINARY_DIR}/python")
  add_dependencies(proxsim proxsim_python)
endif()

# `proxsim export --ros2` runs the bag writer from the source tree with this
# Python (the venv's, where rosbags is): set on its one source file, so that
# nothing else recompiles when the interpreter changes.
set_source_files_properties(${CMAKE_SOURCE_DIR}/src/report/ros2_export.cc PROPERTIES COMPILE_DEFINITIONS
  "PROXSIM_PYTHON_PROGRAM=\"${Python_EXECUTABLE}\";PROXSIM_ROS2_BAG_WRITER=\"${CMAKE_SOURCE_DIR}/python/proxsim/ros2_bag.py\"")

if(PROXSIM_BUILD_TESTS AND PROXSIM_BUILD_PYTHON_MODULE)
  set(python_test_environment
      "PYTHONPATH=${CMAKE_BINARY_DIR}/python"
      "PROXSIM_BINARY=$<TARGET_FILE:proxsim>"
      "PROXSIM_SOURCE_DIR=${CMAKE_SOURCE_DIR}")
  # Under the sanitizers the interpreter must load ASan's runtime first, and
  # the C++ runtime with it (ASan's throw interceptor needs the real
  # __cxa_throw at start, which python3 itself does not link); the
  # interpreter's own allocations are not ours to judge, so no leak checking.
  if(CMAKE_CXX_FLAGS MATCHES "sanitize=address")
    execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so
                    OUTPUT_VARIABLE asan_runtime OUTPUT_STRIP_TRAILING_WHITESPACE)
    execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libstdc++.so.6
                    OUTPUT_VARIABLE cxx_runtime OUTPUT_STRIP_TRAILING_WHITESPACE)
    list(APPEND python_test_environment "LD_PRELOAD=${asan_runtime}:${cxx_runtime}"
         "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1")
  endif()
  add_test(NAME python_package
           COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${CMAKE_SOURCE_DIR}/tests/python)
  # label rays too: its walks read Embree's hits (the release-isa-sse42 preset runs it again)
  set_tests_properties(python_package PROPERTIES ENVIRONMENT "${python_test_environment}" TIMEOUT 600
                       LABELS "python;rays")
endif()
