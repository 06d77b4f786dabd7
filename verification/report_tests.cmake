# The report and the publication bundle (scripts/report*.py, scripts/bundle.sh) on a hand-made
# results folder (verification/tests/report_fixture: invented numbers in the layout sphv verify
# writes). The real-sweep report is report_script in cli_tests.cmake.
set(_fixture ${CMAKE_SOURCE_DIR}/verification/tests/report_fixture)
set(_py "py=$(bash ${CMAKE_SOURCE_DIR}/scripts/find-python.sh) && $py")
add_test(NAME report_fixture COMMAND bash -c
  "${_py} ${CMAKE_SOURCE_DIR}/scripts/report_test.py ${_fixture} ${CMAKE_BINARY_DIR}/report_fixture --mutants ${_fixture}/kill_matrix.json --dirty")
# pdflatex is not installed by scripts/install-deps.sh (texlive is large): without it the test is skipped, saying so.
add_test(NAME bundle_compiles COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/bundle_test.sh compiles ${_fixture} ${CMAKE_BINARY_DIR}/bundle_compiles)
set_tests_properties(bundle_compiles PROPERTIES SKIP_RETURN_CODE 77)
add_test(NAME bundle_refuses_dirty_tree COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/bundle_test.sh dirty ${_fixture} ${CMAKE_BINARY_DIR}/bundle_dirty)
