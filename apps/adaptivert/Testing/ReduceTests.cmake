# `adaptivert reduce`: budgets, levels, weighting, refinement, outputs and refusals.

# reduce said the same in other words ('extract a component first', with no way to do it).
art_expect_test(cli.reduce_components EXIT 1
  STDERR "rgb-3x3x3.vti: the scalars 'rgb' have 3 components; one is needed \\(choose with --array rgb:magnitude"
  ONE_LINE_STDERR ARGS reduce "${_bad}/rgb-3x3x3.vti" "${ART_TEST_OUTPUT}/never.vtu" --tets 10)
art_expect_test(cli.reduce_vector_component EXIT 0 STDOUT "output .*rgb-green.vtu"
  ARGS reduce "${_bad}/rgb-3x3x3.vti" "${ART_TEST_OUTPUT}/rgb-green.vtu" --array rgb:1 --tets 10)
art_expect_test(cli.bad_array_name EXIT 1 STDERR "ct-head-128.mha: has no point array 'nope' \\(it has: MetaImage\\)"
  ONE_LINE_STDERR ARGS reduce "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" "${ART_TEST_OUTPUT}/never.vtu" --tets 100 --array nope)
# reduce on a constant volume stops at the coarse mesh, exact: it said "no finer tets than the voxels
# allow" of a 5 x 5 x 5 volume reduced to 48 tets.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/constant-5.mha"
  "ObjectType = Image\nNDims = 3\nDimSize = 5 5 5\nElementType = MET_UCHAR\nElementSpacing = 1 1 1\n"
  "ElementDataFile = LOCAL\nAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA")
art_expect_test(cli.reduce_constant_is_exact EXIT 0
  STDOUT "output .*constant-5.vtu: [0-9]+ tets.*\\(tet budget not reached: the fit is exact, no tet has an error left to refine\\)"
  ARGS reduce "${CMAKE_CURRENT_BINARY_DIR}/constant-5.mha" "${ART_TEST_OUTPUT}/constant-5.vtu" --tets 300)
# reduce --max-error alone stops at one tet per voxel (125 here), not at the finest tets the voxels
# allow (320): it said "no finer tets than the voxels allow" there, and --tets N goes further.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/random-5.mha"
  "ObjectType = Image\nNDims = 3\nDimSize = 5 5 5\nElementType = MET_UCHAR\nElementSpacing = 1 1 1\n"
  "ElementDataFile = LOCAL\nHSRELTPUSCTAPIRHGWPRRPMUEHUEQMXAVYCFYSBJYAIPTXMWZNMXZSOELDBEPGIVNYUJNQMSLRSNSHKVAITVWFWKRSSDWUGUSIJDCPUPCLZCNEAJNYNDBTTYBMWSK")
art_expect_test(cli.reduce_error_bound_at_voxel_count EXIT 0
  STDOUT "output .*random-5.vtu: 1[2-9][0-9] tets.*\\(error bound not reached by one tet per voxel, where an error bound alone stops; --tets N lets it go on\\)"
  ARGS reduce "${CMAKE_CURRENT_BINARY_DIR}/random-5.mha" "${ART_TEST_OUTPUT}/random-5.vtu" --max-error 0)
# reduce takes its output with -o as render does ('unknown option -o' before), or after the input.
art_expect_test(cli.reduce_output_option EXIT 0 STDOUT "output .*constant-5-o.vtu: "
  ARGS reduce "${CMAKE_CURRENT_BINARY_DIR}/constant-5.mha" -o "${ART_TEST_OUTPUT}/constant-5-o.vtu" --tets 300)
art_expect_test(cli.reduce_output_twice EXIT 2 STDERR "give the output once: after the input or with -o" ONE_LINE_STDERR
  ARGS reduce "${CMAKE_CURRENT_BINARY_DIR}/constant-5.mha" "${ART_TEST_OUTPUT}/a.vtu" -o "${ART_TEST_OUTPUT}/b.vtu" --tets 300)
# reduce --levels: a level the run never meets is said, not dropped without a word.
art_expect_test(cli.reduce_level_above_target EXIT 2 STDERR "--levels: 2000 tets is not below --tets 1000" ONE_LINE_STDERR
  ARGS reduce "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" "${ART_TEST_OUTPUT}/never.vtu" --tets 1000 --levels 100,2000)
art_expect_test(cli.reduce_level_not_reached EXIT 0 STDERR "level_probe.vtu: level 900000 not written: the reduction stopped at"
  STDOUT "levels_not_written\":\\[900000\\]" ONE_LINE_STDERR
  ARGS reduce "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" "${ART_TEST_OUTPUT}/level_probe.vtu" --max-error 5%
    --levels 100,900000 --json --quiet)
art_expect_test(cli.reduce_huge_values EXIT 1
  STDERR "huge-4x4x4.vti: the scalars' range -8e\\+299 .. 9.32051e\\+299 reaches beyond 1e150 in magnitude: .*overflow to infinity"
  ONE_LINE_STDERR ARGS reduce "${_bad}/huge-4x4x4.vti" "${ART_TEST_OUTPUT}/never.vtu" --tets 20)
art_expect_test(cli.reduce_help EXIT 0 STDOUT "examples:.*adaptivert reduce" ARGS reduce --help)
art_expect_test(cli.reduce_default_ct EXIT 0
  STDOUT "tets +[45],[0-9][0-9][0-9] \\([0-9.]+% of the voxel count\\), [0-9,]+ vertices \\([0-9.]+% of the voxels\\).*error +RMS [0-9.]+, max [0-9.]+ data units.*quality +min dihedral.*time +[0-9.]+ s"
  ARGS reduce "${_ct}" "${_out}/reduce_ct.vtu" --tets 5000)
art_expect_test(cli.reduce_json EXIT 0 STDOUT "^\\{\"input\":.*\"tets\":8[0-9][0-9],.*\"rms_error\":"
  ARGS reduce --json --quiet "${_ct}" "${_out}/reduce_ct_json.vtu" --tets 0.1%)
art_expect_test(cli.reduce_levels EXIT 0 STDOUT "level .*reduce_lv_500.vtu.*level .*reduce_lv_2000.vtu.*output .*reduce_lv.vtu"
  ARGS reduce "${_ct}" "${_out}/reduce_lv.vtu" --tets 4000 --levels 500,2000)
art_expect_test(cli.reduce_edge_split EXIT 0
  STDOUT "tets +[23],[0-9][0-9][0-9] \\([0-9.]+% of the voxel count\\), [0-9,]+ vertices.*error +RMS [0-9.]+, max [0-9.]+ data units"
  ARGS reduce "${_ct}" "${_out}/reduce_edge.vtu" --tets 3000 --refinement edge)
art_expect_test(cli.reduce_bad_refinement EXIT 2 STDERR "--refinement is bisection, edge or anisotropic, got 'red'" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.vtu" --tets 100 --refinement red)
art_expect_test(cli.reduce_error_bound EXIT 0 STDOUT "error +RMS [0-9.]+.*\\(([0-2]\\.[0-9]+|3\\.000)% /"
  ARGS reduce "${_ct}" "${_out}/reduce_err.vtu" --max-error 3%)
art_expect_test(cli.reduce_tf EXIT 0
  STDOUT "error +RMS [0-9.]+, max [0-9.]+ data units.*weighted +RMS [0-9.]+, max [0-9.]+ data units \\(opacity-weighted error of --tf ct-skin-bone\\)"
  ARGS reduce "${_ct}" "${_out}/reduce_tf.vtu" --tets 5000 --tf ct-skin-bone)
art_expect_test(cli.reduce_tf_json EXIT 0 STDOUT "\"weighted\":true,\"weighted_rms_error\":[0-9.e+-]+,\"weighted_max_error\""
  ARGS reduce --json --quiet "${_ct}" "${_out}/reduce_tf_json.vtu" --tets 2000 --tf ct-bone)
# --tf that is neither a preset nor a file is a usage error, said before the volume is read.
art_expect_test(cli.reduce_bad_tf EXIT 2 ONE_LINE_STDERR
  STDERR "--tf expects a transfer-function preset \\(auto, .*\\) or a file, got 'nope': no preset has that name and no file of that name exists"
  ARGS reduce "${_ct}" "${_out}/x.vtu" --tets 100 --tf nope)
art_expect_test(cli.reduce_no_target EXIT 2 STDERR "give --tets N or --max-error E" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.vtu")
art_expect_test(cli.reduce_bad_budget EXIT 2 STDERR "--tets wants a positive number" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.vtu" --tets lots)
art_expect_test(cli.reduce_budget_out_of_range EXIT 2 STDERR "--tets '1e300' is beyond any mesh" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.vtu" --tets 1e300)
art_expect_test(cli.reduce_bad_output EXIT 2 STDERR "output must be a .vtu" ONE_LINE_STDERR
  ARGS reduce "${_ct}" "${_out}/x.png" --tets 100)
# The extension in any case, as the mesh writer takes it (OUT.VTU was a usage error).
art_expect_test(cli.reduce_upper_case_vtu EXIT 0 STDOUT "output +[^ ]*/UPPER.VTU: "
  ARGS reduce "${_ct}" "${_out}/UPPER.VTU" --tets 100)
art_expect_test(cli.reduce_missing_file EXIT 1 STDERR "nonexistent.mha: no such file" ONE_LINE_STDERR
  ARGS reduce "${CMAKE_SOURCE_DIR}/tests/data/bad/nonexistent.mha" "${_out}/x.vtu" --tets 100)
art_expect_test(cli.reduce_surface_input EXIT 1 STDERR "am_underworks.ply: " ONE_LINE_STDERR
  ARGS reduce "${CMAKE_SOURCE_DIR}/data/am_underworks.ply" "${_out}/x.vtu" --tets 100)
# reduce: 650^3 voxels weighted by --tf need ~7.7 GB more (28 bytes a voxel for the opacity
# weights) than the cap leaves beside the volume and its samples (1.4 GB; 275 MB read).
set(_w "${ART_TEST_OUTPUT}/reduce-memory")
add_test(NAME reduce.memory_check COMMAND bash "${_mem}" "${_w}" "650 650 650" MET_UCHAR 274625000
  "big.mhd: reducing this volume of 650 x 650 x 650 = 274625000 voxels weighted by a transfer function's opacity needs about 7.69 GB more, more than the .* GB of memory available; crop or resample it first"
  "${_w}/big.vtu" -- "$<TARGET_FILE:adaptivert>" reduce "${_w}/big.mhd" -o "${_w}/big.vtu" --tets 1000 --tf ct-skin-bone)
set_tests_properties(reduce.memory_check PROPERTIES LABELS "unit" TIMEOUT 120)
# A budget at or past the full-resolution mesh (5 tets per voxel cell) makes that mesh, exact,
# without refining towards it (60M tets on 8.7M voxels ran half an hour before it was killed).
art_expect_test(cli.reduce_past_full_resolution EXIT 0
  STDOUT "output .*full-res.vtu: 40 tets, 27 vertices, RMS 0 "
  STDERR "--tets 1000 is at least the 40 tets of the full-resolution mesh \\(5 per voxel cell\\), the finest the voxels allow: that mesh is made, exact, without reducing"
  ARGS reduce "${_bad}/rgb-3x3x3.vti" "${_out}/full-res.vtu" --array rgb:1 --tets 1000 -q)
art_expect_test(cli.render_past_full_resolution EXIT 0
  STDOUT "note +--tets 1000 is at least the 40 tets .*mesh +full-resolution tets \\(5 per voxel cell\\): 40 tets"
  ARGS render "${_bad}/rgb-3x3x3.vti" -o "${_out}/full-res.png" --array rgb:1 --tets 1000 --size 16x16 --no-error -q)
art_expect_test(cli.reduce_tets_hexadecimal EXIT 2 STDERR "--tets wants a positive number or a percentage, got '0x10'"
  ONE_LINE_STDERR ARGS reduce "${_ct}" "${ART_TEST_OUTPUT}/never.vtu" --tets 0x10)
# --refinement anisotropic: MMG3D to the Hessian metric, the budget met within 5%, levels not nested.
art_expect_test(cli.reduce_anisotropic EXIT 0
  STDOUT "level .*reduce_aniso_1000.vtu: (9[5-9][0-9]|1,0[0-4][0-9]) tets.*output .*reduce_aniso.vtu: (2,8[5-9][0-9]|2,9[0-9][0-9]|3,0[0-9][0-9]|3,1[0-4][0-9]) tets.*levels +not nested \\(each remeshed by MMG3D"
  ARGS reduce "${_ct}" "${_out}/reduce_aniso.vtu" --tets 3000 --levels 1000 --refinement anisotropic -q)
art_expect_test(cli.reduce_anisotropic_json EXIT 0 STDOUT "\"refinement\":\"anisotropic\",\"levels_nested\":false"
  ARGS reduce --json --quiet "${_ct}" "${_out}/reduce_aniso_json.vtu" --tets 1500 --refinement anisotropic --tf ct-bone)
art_expect_test(cli.reduce_anisotropic_relocate_json EXIT 0 STDOUT "\"levels_nested\":false,\"vertices_relocated\":true"
  ARGS reduce --json --quiet "${_ct}" "${_out}/reduce_aniso_reloc.vtu" --tets 1500 --refinement anisotropic --relocate)
# Nested bisection levels were said to have their "vertices relocated at each level".
art_expect_test(cli.reduce_levels_nested_plain EXIT 0 STDOUT "levels +nested.time +[0-9]"
  ARGS reduce "${_ct}" "${_out}/reduce_nested.vtu" --tets 2000 --levels 1000)
# render's default refinement without MMG falls back to bisection and says so.
art_expect_test(cli.render_default_without_mmg EXIT 0
  STDERR "note: reducing with bisection: anisotropic refinement needs MMG \\(cannot load /nonexistent/libmmg3d.so.5"
  STDOUT "least-squares reduction, vertices relocated, RMS"
  PROGRAM "${CMAKE_COMMAND}" ARGS -E env ART_MMG_LIBRARY=/nonexistent/libmmg3d.so.5 "$<TARGET_FILE:adaptivert>"
  render "${_ct}" -o "${_out}/no-mmg.png" --size 16x16 --tets 1000 --plain-reduction --no-error)
# A missing or broken MMG is one line naming the library and the way out; the other refinements
# do not need it.
art_expect_test(cli.reduce_anisotropic_without_mmg EXIT 1 ONE_LINE_STDERR
  STDERR "ct-head-128.mha: anisotropic refinement needs MMG \\(libmmg3d 5.8\\): cannot load /nonexistent/libmmg3d.so.5: .*set ART_MMG_LIBRARY to its path"
  PROGRAM "${CMAKE_COMMAND}" ARGS -E env ART_MMG_LIBRARY=/nonexistent/libmmg3d.so.5 "$<TARGET_FILE:adaptivert>"
  reduce "${_ct}" "${_out}/x.vtu" --tets 1000 --refinement anisotropic -q)
art_expect_test(cli.reduce_anisotropic_broken_mmg EXIT 1 ONE_LINE_STDERR
  STDERR "anisotropic refinement needs MMG \\(libmmg3d 5.8\\): cannot load .*README.md: .*"
  PROGRAM "${CMAKE_COMMAND}" ARGS -E env "ART_MMG_LIBRARY=${CMAKE_SOURCE_DIR}/data/README.md" "$<TARGET_FILE:adaptivert>"
  reduce "${_ct}" "${_out}/x.vtu" --tets 1000 --refinement anisotropic -q)
art_expect_test(cli.reduce_anisotropic_not_mmg EXIT 1 ONE_LINE_STDERR
  STDERR "anisotropic refinement needs MMG \\(libmmg3d 5.8\\): .*libAdaptiveRTCore[^ ]* is not MMG 5's libmmg3d \\(it has no MMG3D_Init_mesh\\)"
  PROGRAM "${CMAKE_COMMAND}" ARGS -E env "ART_MMG_LIBRARY=$<TARGET_FILE:AdaptiveRT::Core>" "$<TARGET_FILE:adaptivert>"
  reduce "${_ct}" "${_out}/x.vtu" --tets 1000 --refinement anisotropic -q)
art_expect_test(cli.reduce_bisection_without_mmg EXIT 0 STDOUT "output .*reduce_no_mmg.vtu: "
  PROGRAM "${CMAKE_COMMAND}" ARGS -E env ART_MMG_LIBRARY=/nonexistent/libmmg3d.so.5 "$<TARGET_FILE:adaptivert>"
  reduce "${_ct}" "${_out}/reduce_no_mmg.vtu" --tets 1000 -q)
