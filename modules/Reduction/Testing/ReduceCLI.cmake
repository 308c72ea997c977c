# CLI checks of `adaptivert reduce`, through the same harness as tests/cli (ARGS joined by '|').
file(MAKE_DIRECTORY "${ART_TEST_OUTPUT}")
function(art_reduce_cli_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "ONE_LINE_STDERR" "EXIT;STDOUT;STDERR" "ARGS")
  string(REPLACE ";" "|" _args "${arg_ARGS}")
  add_test(NAME cli.${name} COMMAND ${CMAKE_COMMAND}
    "-DCMD=$<TARGET_FILE:adaptivert>" "-DARGS=${_args}" "-DEXIT=${arg_EXIT}"
    "-DSTDOUT=${arg_STDOUT}" "-DSTDERR=${arg_STDERR}" "-DONE_LINE=${arg_ONE_LINE_STDERR}"
    -P "${CMAKE_SOURCE_DIR}/tests/cli/expect.cmake")
  set_tests_properties(cli.${name} PROPERTIES LABELS unit)
endfunction()
set(_ct "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha")
set(_out "${ART_TEST_OUTPUT}")
art_reduce_cli_test(reduce_help EXIT 0 STDOUT "examples:.*adaptivert reduce" ARGS reduce --help)
art_reduce_cli_test(reduce_default_ct EXIT 0
  STDOUT "tets +[45],[0-9][0-9][0-9] \\([0-9,]+ vertices.*error +RMS [0-9.]+, max [0-9.]+ data units.*quality +min dihedral.*time +[0-9.]+ s"
  ARGS reduce "${_ct}" "${_out}/reduce_ct.vtu" --tets 5000)
art_reduce_cli_test(reduce_json EXIT 0 STDOUT "^\\{\"input\":.*\"tets\":8[0-9][0-9],.*\"rms_error\":"
  ARGS reduce --json --quiet "${_ct}" "${_out}/reduce_ct_json.vtu" --tets 0.1%)
art_reduce_cli_test(reduce_levels EXIT 0 STDOUT "level .*reduce_lv_500.vtu.*level .*reduce_lv_2000.vtu.*output .*reduce_lv.vtu"
  ARGS reduce "${_ct}" "${_out}/reduce_lv.vtu" --tets 4000 --levels 500,2000)
art_reduce_cli_test(reduce_edge_split EXIT 0
  STDOUT "tets +[23],[0-9][0-9][0-9] \\([0-9,]+ vertices.*error +RMS [0-9.]+, max [0-9.]+ data units"
  ARGS reduce "${_ct}" "${_out}/reduce_edge.vtu" --tets 3000 --refinement edge)
art_reduce_cli_test(reduce_bad_refinement EXIT 2 STDERR "--refinement is bisection or edge, got 'red'" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.vtu" --tets 100 --refinement red)
art_reduce_cli_test(reduce_error_bound EXIT 0 STDOUT "error +RMS [0-9.]+.*\\(([0-2]\\.[0-9]+|3\\.000)% /"
  ARGS reduce "${_ct}" "${_out}/reduce_err.vtu" --max-error 3%)
art_reduce_cli_test(reduce_tf EXIT 0
  STDOUT "error +RMS [0-9.]+, max [0-9.]+ data units.*weighted +RMS [0-9.]+, max [0-9.]+ data units \\(opacity-weighted error of --tf ct-skin-bone\\)"
  ARGS reduce "${_ct}" "${_out}/reduce_tf.vtu" --tets 5000 --tf ct-skin-bone)
art_reduce_cli_test(reduce_tf_json EXIT 0 STDOUT "\"weighted\":true,\"weighted_rms_error\":[0-9.e+-]+,\"weighted_max_error\""
  ARGS reduce --json --quiet "${_ct}" "${_out}/reduce_tf_json.vtu" --tets 2000 --tf ct-bone)
art_reduce_cli_test(reduce_bad_tf EXIT 1 STDERR "unknown transfer-function preset 'nope'" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.vtu" --tets 100 --tf nope)
art_reduce_cli_test(reduce_no_target EXIT 2 STDERR "give --tets N or --max-error E" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.vtu")
art_reduce_cli_test(reduce_bad_budget EXIT 2 STDERR "--tets wants a positive number" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.vtu" --tets lots)
art_reduce_cli_test(reduce_budget_out_of_range EXIT 2 STDERR "--tets '1e300' is beyond any mesh" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.vtu" --tets 1e300)
art_reduce_cli_test(reduce_bad_output EXIT 2 STDERR "output must be a .vtu" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.png" --tets 100)
# The extension in any case, as the mesh writer takes it (OUT.VTU was a usage error; probe12).
art_reduce_cli_test(reduce_upper_case_vtu EXIT 0 STDOUT "output +[^ ]*/UPPER.VTU: "
  ARGS reduce "${_ct}" "${_out}/UPPER.VTU" --tets 100)
art_reduce_cli_test(reduce_missing_file EXIT 1 STDERR "nonexistent.mha: no such file" ONE_LINE_STDERR
  ARGS reduce "${CMAKE_SOURCE_DIR}/tests/data/bad/nonexistent.mha" "${_out}/x.vtu" --tets 100)
art_reduce_cli_test(reduce_surface_input EXIT 1 STDERR "am_underworks.ply: " ONE_LINE_STDERR
  ARGS reduce "${CMAKE_SOURCE_DIR}/data/am_underworks.ply" "${_out}/x.vtu" --tets 100)
