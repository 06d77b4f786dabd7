# Command-line behaviour: bad input is refused with one clear "sphv: error:" line and a
# non-zero exit; good input writes its files.
function(sphv_refuses name)
  add_test(NAME cli_refuses_${name} COMMAND sphv ${ARGN})
  set_tests_properties(cli_refuses_${name} PROPERTIES WILL_FAIL TRUE)
  add_test(NAME cli_message_${name} COMMAND sphv ${ARGN})
  set_tests_properties(cli_message_${name} PROPERTIES PASS_REGULAR_EXPRESSION "^sphv: error: [^\n]+\n?$")
endfunction()

sphv_refuses(unknown_case run no_such_case)
sphv_refuses(unknown_parameter run kernel --set nope=1)
sphv_refuses(malformed_setting run kernel --set n)
sphv_refuses(non_integer_n run kernel --set n=ten)
sphv_refuses(zero_n run kernel --set n=0)
sphv_refuses(huge_n run kernel --set n=99999999999)
sphv_refuses(huge_level sweep kernel --levels 16,99999999999)
sphv_refuses(n_beyond_memory run sedov --set dim=3 --set n=10000000)
sphv_refuses(sod2d_mixed_pairing run sod2d --set energy=38)
sphv_refuses(unknown_kernel run sod --set kernel=gaussian)
sphv_refuses(sod2d_kernel run sod2d --set kernel=wendland_c4)
sphv_refuses(sod_kernel_other_forms run sod --set kernel=wendland_c4 --set euler=26)
sphv_refuses(sedov_kernel_other_energy run sedov --set kernel=wendland_c2 --set energy=41)
sphv_refuses(negative_n sweep interpolation --levels 16,-32)
sphv_refuses(negative_h run kernel --set h=-0.1)
sphv_refuses(nan_h run kernel --set h=nan)
sphv_refuses(bad_dim run interpolation --set dim=4)
sphv_refuses(unknown_option run kernel --bogus)
# Options a scheme refuses (sph/schemes/) are bad input too: exit 2, not 3.
sphv_refuses(chapter_conduction run square --set n=16 --set alpha_u=0)
sphv_refuses(chapter_conduction_speed run square --set n=16 --set vsig_u=velocity)
sphv_refuses(gradh_rate53 run sedov --set n=16 --set scheme=gradh_switches --set hmode=rate53)
add_test(NAME cli_scheme_option_exits_2 COMMAND bash -c
         "$<TARGET_FILE:sphv> run sedov --set n=16,scheme=gradh_switches,hmode=rate53 --out ${CMAKE_BINARY_DIR}/cli_rate53 2>/dev/null; test $? -eq 2")

# CMake's `.` matches a newline too, so `.*` spans lines; `(.|\n)*` would match each newline two
# ways and backtrack exponentially in the lines after its last match (minutes on `sphv list`).
add_test(NAME cli_list COMMAND sphv list)
set_tests_properties(cli_list PROPERTIES PASS_REGULAR_EXPRESSION "interpolation.*kernel")
add_test(NAME cli_run_writes_result COMMAND sphv run interpolation --set n=16 --out ${CMAKE_BINARY_DIR}/cli_run)
set_tests_properties(cli_run_writes_result PROPERTIES PASS_REGULAR_EXPRESSION "verdict: ok")
# A kernel chosen at run time (sph/kernel/kernels.hpp), scored against the references.
add_test(NAME cli_run_sod_wendland_c4 COMMAND sphv run sod --set kernel=wendland_c4 --out ${CMAKE_BINARY_DIR}/cli_run_sod_wc4)
set_tests_properties(cli_run_sod_wendland_c4 PROPERTIES PASS_REGULAR_EXPRESSION "L1_rho=.*verdict: ok")
add_test(NAME cli_run_sedov_wendland_c2 COMMAND sphv run sedov --set kernel=wendland_c2 --out ${CMAKE_BINARY_DIR}/cli_run_sedov_wc2)
set_tests_properties(cli_run_sedov_wendland_c2 PROPERTIES PASS_REGULAR_EXPRESSION "L1_rho=.*shock_radius=.*verdict: stable")

# A sweep writes sweep.json, and the report script turns it into a page with figures.
# heat: every row verifies on these levels, so the report's convergence figure has a panel (it shows
# verified claims only).
add_test(NAME cli_sweep_writes_sweep COMMAND sphv sweep heat --levels 16,24,32 --out ${CMAKE_BINARY_DIR}/cli_sweep/heat/default)
set_tests_properties(cli_sweep_writes_sweep PROPERTIES FIXTURES_SETUP sweep_output PASS_REGULAR_EXPRESSION "heat +default +spatial_gauss ")
# (scripts/report_test.py: no warnings, every href and src resolves, a figure per claimed error.)
add_test(NAME report_script COMMAND bash -c
  "py=$(bash ${CMAKE_SOURCE_DIR}/scripts/find-python.sh) && $py ${CMAKE_SOURCE_DIR}/scripts/report_test.py ${CMAKE_BINARY_DIR}/cli_sweep ${CMAKE_BINARY_DIR}/reports_ctest")
set_tests_properties(report_script PROPERTIES FIXTURES_REQUIRED sweep_output)

# Sweeps at scale (issue 9): resumable after a kill; the MPI sweep matches the serial one.
add_test(NAME sweep_resumes_after_kill COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/test-resume.sh $<TARGET_FILE:sphv> ${CMAKE_BINARY_DIR}/resume)
# Beside other tests (load only slows the points, which leaves the kill more room), started early.
set_tests_properties(sweep_resumes_after_kill PROPERTIES COST 20)
add_test(NAME sweep_parallel_matches_serial COMMAND bash -c
  "rm -rf par ser && $<TARGET_FILE:sphv> sweep interpolation --vary dim=1,2 --jobs 2 --out par >/dev/null && $<TARGET_FILE:sphv> sweep interpolation --vary dim=1,2 --jobs 1 --out ser >/dev/null && py=$(bash ${CMAKE_SOURCE_DIR}/scripts/find-python.sh) && $py ${CMAKE_SOURCE_DIR}/scripts/compare-sweeps.py par ser"
  WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
set_tests_properties(sweep_parallel_matches_serial PROPERTIES PASS_REGULAR_EXPRESSION "points identical")
# Each point's provenance (threads, date) is its own, not that of the parent writing sweep.json:
# the parent runs on more threads (--threads 5) than --jobs 2 gives a point (one each, or every
# core for the longest one) on a machine of fewer than five cores.
add_test(NAME sweep_keeps_point_provenance COMMAND bash -c
  "rm -rf prov && $<TARGET_FILE:sphv> --threads 5 sweep interpolation --levels 16,32 --jobs 2 --out prov >/dev/null && py=$(bash ${CMAKE_SOURCE_DIR}/scripts/find-python.sh) && $py ${CMAKE_SOURCE_DIR}/verification/tests/sweep_provenance.py prov 5 ${CMAKE_SOURCE_DIR}"
  WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
# Never stale: a point is reused only by the build (executable bytes, flags) that produced it.
add_test(NAME sweep_never_reuses_another_build COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/test-never-stale.sh $<TARGET_FILE:sphv> ${CMAKE_BINARY_DIR}/never_stale)
find_program(MPIEXEC_BIN NAMES mpirun mpiexec)
if(MPI_CXX_FOUND AND MPIEXEC_BIN)
  add_test(NAME sweep_mpi_matches_serial COMMAND bash -c
    "rm -rf mpi ser1 && ${MPIEXEC_BIN} --oversubscribe -n 2 $<TARGET_FILE:sphv> --threads 1 sweep interpolation --vary dim=1,2 --out mpi >/dev/null && $<TARGET_FILE:sphv> --threads 1 sweep interpolation --vary dim=1,2 --jobs 1 --out ser1 >/dev/null && py=$(bash ${CMAKE_SOURCE_DIR}/scripts/find-python.sh) && $py ${CMAKE_SOURCE_DIR}/scripts/compare-sweeps.py mpi ser1"
    WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  # OpenMPI refuses root unless told; CI runs as root.
  set_tests_properties(sweep_mpi_matches_serial PROPERTIES PASS_REGULAR_EXPRESSION "points identical"
    ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1")
endif()

# sphv gravity: bad input gives one error line and a non-zero exit (inputs written at configure time).
set(_gdir ${CMAKE_BINARY_DIR}/gravity_cli)
file(WRITE ${_gdir}/ok.csv "x,y,z,m\n0,0,0,1\n1,0,0,1\n0,1,0,0.5\n")
file(WRITE ${_gdir}/empty.csv "")
file(WRITE ${_gdir}/header_only.csv "x,y,z,m\n")
file(WRITE ${_gdir}/negative_mass.csv "x,y,z,m\n0,0,0,1\n1,0,0,-1\n")
file(WRITE ${_gdir}/malformed.csv "x,y,z,m\n0,0,zero,1\n")
file(WRITE ${_gdir}/short_row.csv "x,y,z,m\n0,0,1\n")
file(WRITE ${_gdir}/no_mass_column.csv "x,y,z\n0,0,0\n")
foreach(_case theta_zero theta_negative empty header_only negative_mass malformed short_row no_mass_column missing_file bad_multipole)
  set(_in ${_gdir}/ok.csv)
  set(_extra "")
  if(_case STREQUAL "theta_zero")
    set(_extra --theta 0)
  elseif(_case STREQUAL "theta_negative")
    set(_extra --theta -0.5)
  elseif(_case STREQUAL "missing_file")
    set(_in ${_gdir}/does_not_exist.csv)
  elseif(_case STREQUAL "bad_multipole")
    set(_extra --multipole octupole)
  else()
    set(_in ${_gdir}/${_case}.csv)
  endif()
  sphv_refuses(gravity_${_case} gravity --input ${_in} --out ${_gdir}/out_${_case}.csv ${_extra})
endforeach()
sphv_refuses(bench_output_is_a_file bench --sizes 1000 --threads 1 --out ${_gdir}/ok.csv)
# sphv gravity's exit codes: 2 for bad input, 3 for an output it cannot write; one error line each.
function(sphv_gravity_exits name code)
  string(JOIN " " _args ${ARGN})
  add_test(NAME cli_gravity_exits_${name} COMMAND bash -c
    "$<TARGET_FILE:sphv> gravity ${_args} 2> ${_gdir}/err_${name}.txt; s=$?; cat ${_gdir}/err_${name}.txt; test $s -eq ${code} && test $(wc -l < ${_gdir}/err_${name}.txt) -eq 1 && echo PASS")
  set_tests_properties(cli_gravity_exits_${name} PROPERTIES PASS_REGULAR_EXPRESSION "PASS")
endfunction()
sphv_gravity_exits(theta_zero 2 --input ${_gdir}/ok.csv --out ${_gdir}/out_exits.csv --theta 0)
sphv_gravity_exits(missing_file 2 --input ${_gdir}/does_not_exist.csv --out ${_gdir}/out_exits.csv)
sphv_gravity_exits(negative_mass 2 --input ${_gdir}/negative_mass.csv --out ${_gdir}/out_exits.csv)
sphv_gravity_exits(unwritable_output 3 --input ${_gdir}/ok.csv --out ${_gdir}/ok.csv/out.csv)
add_test(NAME cli_gravity_ok COMMAND sphv gravity --input ${_gdir}/ok.csv --out ${_gdir}/out_ok.csv --theta 0.7 --multipole mono --softening 0.1)
set_tests_properties(cli_gravity_ok PROPERTIES PASS_REGULAR_EXPRESSION "relative force error.*99% ")

# The pair loops' instruction-set copies are vector code, as their speed needs (a branch GCC does
# not remove leaves a copy scalar with every result unchanged): verification/tests/pair_loops_vectorised.py.
add_test(NAME pair_loops_vectorised COMMAND bash -c
  "py=$(bash ${CMAKE_SOURCE_DIR}/scripts/find-python.sh) && $py ${CMAKE_SOURCE_DIR}/verification/tests/pair_loops_vectorised.py $<TARGET_FILE:sphv>")
set_tests_properties(pair_loops_vectorised PROPERTIES SKIP_RETURN_CODE 77)
