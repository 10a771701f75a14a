# The Slurm job-array test (included by CMakeLists.txt after python.cmake):
# tests/slurm starts munged, one slurmctld and one slurmd on localhost from
# files of its own (Debian's slurm-wlm and munge, scripts/install-deps.sh),
# runs a study as an array of 3 slices and merges them. Label `slurm`; it
# fails, never skips, when the daemons cannot start. Within 2 minutes.
if(PROXSIM_BUILD_TESTS)
  add_test(NAME slurm_job_array
           COMMAND ${Python_EXECUTABLE} -m pytest -q -s -p no:cacheprovider ${CMAKE_SOURCE_DIR}/tests/slurm)
  set_tests_properties(slurm_job_array PROPERTIES
    ENVIRONMENT "PROXSIM_BINARY=$<TARGET_FILE:proxsim>;PROXSIM_SOURCE_DIR=${CMAKE_SOURCE_DIR}"
    LABELS "slurm;python" TIMEOUT 120)
endif()
