# Run by ctest after the tests of tridem_tests are discovered (tests/CMakeLists.txt): those
# that run the OpenMP solver, on every core, get RUN_SERIAL.
foreach(name IN LISTS tridem_cpu_tests)
  if(name MATCHES "openmp|OpenMP|ThreadChoice|CpuParity")
    set_tests_properties("${name}" PROPERTIES RUN_SERIAL TRUE)
  endif()
endforeach()
