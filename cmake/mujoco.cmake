# MuJoCo from PyPI's `mujoco` wheel in .venv/ (scripts/install-deps.sh
# installs the version python/requirements.txt pins): the wheel ships the C
# library (libmujoco.so.X.Y.Z) and its headers (include/mujoco). proxsim links
# that library, so the robot loader (src/robot/mjcf_model.cc), the bench's
# mj_ray peer and `import mujoco` in the Python package's process are one and
# the same MuJoCo, a current one (Debian's libmujoco-dev is 2.2.2 and cannot
# read today's MJCF). Defines the imported target proxsim::mujoco and
# MUJOCO_WHEEL_VERSION.
#
# PROXSIM_MUJOCO_DIR may name another folder holding libmujoco.so.* and
# include/mujoco/mujoco.h (a mujoco package of another environment).

set(proxsim_mujoco_hint "")
file(GLOB proxsim_mujoco_candidates ${CMAKE_SOURCE_DIR}/.venv/lib/python3*/site-packages/mujoco)
if(proxsim_mujoco_candidates)
  list(GET proxsim_mujoco_candidates 0 proxsim_mujoco_hint)
endif()
set(PROXSIM_MUJOCO_DIR "" CACHE PATH
    "Folder of the mujoco Python package (libmujoco.so.* and include/mujoco); empty: .venv's")
set(proxsim_mujoco_dir "${PROXSIM_MUJOCO_DIR}")
if(NOT proxsim_mujoco_dir)
  set(proxsim_mujoco_dir "${proxsim_mujoco_hint}")
endif()

set(proxsim_mujoco_library "")
if(proxsim_mujoco_dir)
  file(GLOB proxsim_mujoco_libraries ${proxsim_mujoco_dir}/libmujoco.so.*)
  if(proxsim_mujoco_libraries)
    list(GET proxsim_mujoco_libraries 0 proxsim_mujoco_library)
  endif()
endif()
if(NOT proxsim_mujoco_library OR NOT EXISTS ${proxsim_mujoco_dir}/include/mujoco/mujoco.h)
  message(FATAL_ERROR
    "MuJoCo not found: proxsim links the C library inside PyPI's `mujoco` wheel, in .venv/ "
    "(looked for libmujoco.so.* and include/mujoco/mujoco.h in "
    "'${CMAKE_SOURCE_DIR}/.venv/lib/python3*/site-packages/mujoco', PROXSIM_MUJOCO_DIR='${PROXSIM_MUJOCO_DIR}'). "
    "Run scripts/install-deps.sh (it creates .venv/ and installs python/requirements.txt), "
    "then configure again; or set PROXSIM_MUJOCO_DIR to a mujoco package's folder.")
endif()

# the version from the header: mjVERSION_HEADER is major·1e6 + minor·1e3 + patch
file(STRINGS ${proxsim_mujoco_dir}/include/mujoco/mujoco.h proxsim_mujoco_version_line
     REGEX "^#define mjVERSION_HEADER [0-9]+")
string(REGEX REPLACE "^#define mjVERSION_HEADER ([0-9]+).*" "\\1" proxsim_mujoco_version_number
       "${proxsim_mujoco_version_line}")
math(EXPR proxsim_mujoco_major "${proxsim_mujoco_version_number} / 1000000")
math(EXPR proxsim_mujoco_minor "(${proxsim_mujoco_version_number} / 1000) % 1000")
math(EXPR proxsim_mujoco_patch "${proxsim_mujoco_version_number} % 1000")
set(MUJOCO_WHEEL_VERSION "${proxsim_mujoco_major}.${proxsim_mujoco_minor}.${proxsim_mujoco_patch}")
if(proxsim_mujoco_major LESS 3)
  message(FATAL_ERROR "MuJoCo ${MUJOCO_WHEEL_VERSION} in '${proxsim_mujoco_dir}' is older than 3.0, which "
                      "today's MJCF needs: run scripts/install-deps.sh to install python/requirements.txt's pin")
endif()

add_library(proxsim::mujoco SHARED IMPORTED)
set_target_properties(proxsim::mujoco PROPERTIES
  IMPORTED_LOCATION ${proxsim_mujoco_library}
  INTERFACE_INCLUDE_DIRECTORIES ${proxsim_mujoco_dir}/include
  # the wheel's header folder is third-party: its warnings are not ours
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${proxsim_mujoco_dir}/include)
message(STATUS "MuJoCo ${MUJOCO_WHEEL_VERSION}: ${proxsim_mujoco_library}")
