# Run by ctest after the tests of tridem_tests are discovered (tests/CMakeLists.txt).
# Every test gets a timeout, so that a test that hangs fails by its name instead of holding
# a ctest slot until CI's own limit (LiveView.PreparesBeforeTheFirstStep once waited forever
# for a frame under the sanitizers): 600 s, ten times the slowest test under ASan on a busy
# 2-core machine (50 s). Those that run the OpenMP solver, on every core, get RUN_SERIAL.
# The longest physics validations (tens of thousands of steps: 27-45 s in Release, 130-210
# s under ASan at -O1) get the label `long`: the sanitizer suite leaves them out
# (scripts/run-sanitizers.sh), since shorter tests take the same code paths (bodies, bonds)
# there; Release runs them.
foreach(name IN LISTS tridem_cpu_tests)
  set_tests_properties("${name}" PROPERTIES TIMEOUT 600)
  if(name MATCHES "openmp|OpenMP|ThreadChoice|CpuParity")
    set_tests_properties("${name}" PROPERTIES RUN_SERIAL TRUE)
  endif()
  if(name MATCHES "^AngleOfRepose\\.|^BrazilianDisc\\.PeakForce|^BiaxialExample\\.|^NotchedBeam\\.|^BondedSpecimen\\.CompressionToFailure")
    set_tests_properties("${name}" PROPERTIES LABELS long)
  endif()
endforeach()
