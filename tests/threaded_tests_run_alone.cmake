# Run by ctest after the tests of tridem_tests are discovered (tests/CMakeLists.txt): those
# that run the OpenMP solver, on every core, get RUN_SERIAL. The longest physics
# validations (tens of thousands of steps: 27-45 s in Release, 130-210 s under ASan at -O1)
# get the label `long`: the sanitizer suite leaves them out (scripts/run-sanitizers.sh),
# since shorter tests take the same code paths (bodies, bonds) there; Release runs them.
foreach(name IN LISTS tridem_cpu_tests)
  if(name MATCHES "openmp|OpenMP|ThreadChoice|CpuParity")
    set_tests_properties("${name}" PROPERTIES RUN_SERIAL TRUE)
  endif()
  if(name MATCHES "^AngleOfRepose\\.|^BrazilianDisc\\.PeakForce|^BiaxialExample\\.|^NotchedBeam\\.|^BondedSpecimen\\.CompressionToFailure")
    set_tests_properties("${name}" PROPERTIES LABELS long)
  endif()
endforeach()
