# Tiers and the catalogue pool (issue 14): a point killed by SIGKILL and one hanging past
# --timeout end as those points' verdicts, the catalogue finishes (exit 1), JUnit names them.
add_test(NAME verify_survives_crash_and_hang COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/test-faults.sh $<TARGET_FILE:sphv> ${CMAKE_BINARY_DIR}/faults)
# Beside other tests: its points run well inside the 8 s and 3 s timeouts (heat_stiff n = 256, the
# slowest, 2.4 s alone), and it waits through a hang most of its time. Started early (COST): the
# longest test of the command.
set_tests_properties(verify_survives_crash_and_hang PROPERTIES COST 60)
sphv_refuses(unknown_tier verify --tier huge --out ${CMAKE_BINARY_DIR}/verify_refused)
sphv_refuses(negative_timeout verify --tier quick --timeout -1 --out ${CMAKE_BINARY_DIR}/verify_refused)
sphv_refuses(negative_sweep_timeout sweep kernel --tier quick --timeout -1 --out ${CMAKE_BINARY_DIR}/verify_refused)
