// The sanitizer tests' runtime options, compiled in so that every runner (ctest, a shell, a
// debugger) gets them: leaks are findings; the first finding ends the process with a stack.
// Mixed instrumented and uninstrumented code (sanitizer_tests.cmake): std::vector's
// container-overflow annotations hold only where every user of a vector is instrumented, so that
// check is off.
extern "C" const char* __asan_default_options() {
  return "detect_leaks=1:detect_container_overflow=0:strict_string_checks=1:abort_on_error=0";
}
extern "C" const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }
