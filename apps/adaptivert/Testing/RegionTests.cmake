# `adaptivert reduce --region / --labels` (AdaptiveRT::Meshing, CGAL Mesh_3): a sphere of 1 in a
# box of 0 meshed by value range (an open end is taken at the data's range + 1), two touching
# labelled cubes as one mesh; refusals.
set(_mesh "${CMAKE_SOURCE_DIR}/tests/data/meshing")
art_expect_test(cli.reduce_region_sphere EXIT 0
  STDOUT "region +0.5:1: 4,224 voxels \\(12.9% of the volume\\) in 1 piece.*boundary on the region's surface.*error +RMS [0-9.e-]+, max [0-9.e-]+ inside the region.*0 inverted, conforming"
  ARGS reduce "${_mesh}/sphere-32.mha" "${_out}/region_sphere.vtu" --region 0.5:1 --tets 3000 --no-whole-box --quiet)
art_expect_test(cli.reduce_region_json EXIT 0
  STDOUT "^\\{\"input\":.*\"region_voxels\":4224,.*\"region\":\\[0.5,2\\].*\"whole_box_tets\":[0-9]+,"
  ARGS reduce "${_mesh}/sphere-32.mha" "${_out}/region_sphere_json.vtu" --region 0.5: --tets 1500 --json --quiet)
art_expect_test(cli.reduce_labels_cubes EXIT 0
  STDOUT "labels +2 \\(1, 2\\), background 0: 4,096 voxels in 2 pieces.*interfaces shared.*conforming"
  ARGS reduce "${_mesh}/cubes-24.mha" "${_out}/labels_cubes.vtu" --labels --tets 2000 --quiet)
art_expect_test(cli.reduce_labels_background EXIT 0 STDOUT "labels +2 \\(0, 2\\), background 1: 11,776 voxels"
  ARGS reduce "${_mesh}/cubes-24.mha" "${_out}/labels_cubes_bg.vtu" --labels --background 1 --tets 2000 --quiet)
art_expect_test(cli.reduce_region_outside EXIT 1
  STDERR "sphere-32.mha: no voxel lies in the region 5:6 \\(the values span 0 .. 1\\)" ONE_LINE_STDERR
  ARGS reduce "${_mesh}/sphere-32.mha" "${_out}/never.vtu" --region 5:6 --tets 3000 --quiet)
art_expect_test(cli.reduce_region_reversed EXIT 2 STDERR "--region 3:1 is empty: its low end is above its high end"
  ONE_LINE_STDERR ARGS reduce "${_mesh}/sphere-32.mha" "${_out}/never.vtu" --region 3:1 --tets 3000)
art_expect_test(cli.reduce_region_and_labels EXIT 2 STDERR "--region and --labels exclude each other" ONE_LINE_STDERR
  ARGS reduce "${_mesh}/cubes-24.mha" "${_out}/never.vtu" --region 1:2 --labels --tets 3000)
art_expect_test(cli.reduce_background_alone EXIT 2 STDERR "--background goes with --region or --labels" ONE_LINE_STDERR
  ARGS reduce "${_mesh}/cubes-24.mha" "${_out}/never.vtu" --background 3 --tets 3000)
# --values: the label mesh carries another volume's values (a ramp x + 2y + 3z over the cubes,
# tests/data/meshing/cubes-24-ramp.mha), fitted inside the labels: 0.15 RMS over the labels'
# voxels (range 0 .. 138; the tets holding few voxels anchored at the values around their
# vertices; anchored at the mean, 5.4), bound 0.5. Dimensions must match; --values goes with
# --labels only.
art_expect_test(cli.reduce_labels_values EXIT 0 STDOUT "\"rms_error\":0\\.[0-4][0-9]*,"
  ARGS reduce "${_mesh}/cubes-24.mha" "${_out}/labels_values.vtu" --labels --tets 2000
  --values "${_mesh}/cubes-24-ramp.mha" --json --quiet)
art_expect_test(cli.reduce_labels_values_size EXIT 1 STDERR "sphere-32.mha: the values to fit have 32 x 32 x 32"
  ONE_LINE_STDERR ARGS reduce "${_mesh}/cubes-24.mha" "${_out}/never.vtu" --labels --tets 2000
  --values "${_mesh}/sphere-32.mha" --quiet)
art_expect_test(cli.reduce_values_region EXIT 2 STDERR "--values goes with --labels" ONE_LINE_STDERR
  ARGS reduce "${_mesh}/sphere-32.mha" "${_out}/never.vtu" --region 0.5:1 --values "${_mesh}/sphere-32.mha" --tets 300)
# A linear ramp (10 z, tests/data/meshing/halves-24-ramp.mha) is fitted exactly inside a region
# of it: RMS 1.6e-5 (bound 1e-3); with the sparse tets anchored at the mean it was 7.4.
art_expect_test(cli.reduce_region_ramp_exact EXIT 0 STDOUT "\"rms_error\":[0-9.]+e-0[4-9],"
  ARGS reduce "${_mesh}/halves-24-ramp.mha" "${_out}/region_ramp.vtu" --region 100:230 --tets 1000 --no-whole-box
  --json --quiet)
# reduce --labels --values, rendered: each label's hue brightening with the values as the closed
# form says (max 0.007 off on 8-bit pixels, bound 0.03), one colour per label under flat, and
# --tf grey-ramp brightening them in their hues.
art_add_python_test(cli.render_label_values_ramp "${CMAKE_CURRENT_LIST_DIR}/label_values_check.py" LABELS image)
