# The report and the publication bundle (scripts/report*.py, scripts/bundle.sh) on a hand-made
# results folder (verification/tests/report_fixture: invented numbers in the layout sphv verify
# writes). The real-sweep report is report_script in cli_tests.cmake.
set(_fixture ${CMAKE_SOURCE_DIR}/verification/tests/report_fixture)
set(_py "py=$(bash ${CMAKE_SOURCE_DIR}/scripts/find-python.sh) && $py")
add_test(NAME report_fixture COMMAND bash -c
  "${_py} ${CMAKE_SOURCE_DIR}/scripts/report_test.py ${_fixture} ${CMAKE_BINARY_DIR}/report_fixture --mutants ${_fixture}/kill_matrix.json --dirty")
# pdflatex and pdffonts come from scripts/install-deps.sh --tex, which the test command (scripts/test.sh)
# runs: on a machine without them (ctest run by hand) the test is skipped, saying so.
add_test(NAME bundle_compiles COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/bundle_test.sh compiles ${_fixture} ${CMAKE_BINARY_DIR}/bundle_compiles)
set_tests_properties(bundle_compiles PROPERTIES SKIP_RETURN_CODE 77)
# The bundle copied into an empty folder outside any checkout rebuilds itself (reproduce.sh, stub build).
add_test(NAME bundle_reproduce_from_copy COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/bundle_test.sh reproduce ${_fixture} ${CMAKE_BINARY_DIR}/bundle_reproduce)
add_test(NAME bundle_refuses_dirty_tree COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/bundle_test.sh dirty ${_fixture} ${CMAKE_BINARY_DIR}/bundle_dirty)
# Every mutant of the kill matrix (verification/mutants, scripts/mutants.sh) still applies to the
# tree, with the tool mutants.py applies it with: a change to a patched line must carry the mutant
# along (two density mutants had stopped applying, unnoticed until a mutant run).
add_test(NAME mutants_apply COMMAND bash -c
  "for p in ${CMAKE_SOURCE_DIR}/verification/mutants/*.patch; do patch -p1 --dry-run --batch --silent -d ${CMAKE_SOURCE_DIR} -i \"$p\" > /dev/null || { echo \"mutant does not apply: $p\"; exit 1; }; done")
# The report and bundle tests (8-15 s each) are defined last: started first, they do not leave one
# core idle at the end of the run.
set_tests_properties(report_fixture bundle_compiles bundle_reproduce_from_copy bundle_refuses_dirty_tree PROPERTIES COST 30)
