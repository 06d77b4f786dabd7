# Read by ctest after the Catch2 tests are discovered (CMakeLists.txt): the square's gate runs its
# nine variants' quick levels, about 80 s on the tests' build, four times the next longest test.
# Started first, it runs beside the others; started in its place among the gates (COST 10 like
# them), it was the last test running, alone, for its last minute.
set_tests_properties("gate: square" PROPERTIES COST 100)
