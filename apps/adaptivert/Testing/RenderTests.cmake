# `adaptivert render`: volumes, tet meshes and triangle scenes to images; baselines and bad options.

art_expect_test(cli.bad_components EXIT 1
  STDERR "rgb-3x3x3.vti: the scalars 'rgb' have 3 components; one is needed \\(choose with --array rgb:magnitude or rgb:0 .. rgb:2"
  ONE_LINE_STDERR ARGS render "${_bad}/rgb-3x3x3.vti" -o "${ART_TEST_OUTPUT}/never.png")
# A vector's magnitude or one component renders and reduces (what VTK's mappers draw with VectorMode).
art_expect_test(cli.render_vector_magnitude EXIT 0 STDOUT "full-resolution tets.*output"
  ARGS render "${_bad}/rgb-3x3x3.vti" -o "${ART_TEST_OUTPUT}/rgb-magnitude.png" --array rgb:magnitude --size 16x16 --no-error)
art_expect_test(cli.bad_vector_component EXIT 1 STDERR "rgb-3x3x3.vti: array 'rgb' has 3 components \\(0 .. 2\\), not a component 3"
  ONE_LINE_STDERR ARGS render "${_bad}/rgb-3x3x3.vti" -o "${ART_TEST_OUTPUT}/never.png" --array rgb:3)
# Face colours (a PLY's red, green, blue on its faces) were dropped: the cube rendered grey. It
# renders as the same cube with the colours on corners of each face's own (tests/data/colours).
art_render_baseline_test(image.surface_face_colours BASELINE surface-face-colours.png MIN_PSNR 40 MIN_SSIM 0.98
  ARGS "${CMAKE_SOURCE_DIR}/tests/data/colours/face-colours.ply" --size 96x96 --azimuth 30 --elevation 25)
# The same cube as an OBJ coloured by materials (usemtl, Kd in two .mtl libraries) was grey too.
art_render_baseline_test(image.surface_obj_material_colours BASELINE surface-face-colours.png MIN_PSNR 40 MIN_SSIM 0.98
  ARGS "${CMAKE_SOURCE_DIR}/tests/data/colours/cube.obj" --size 96x96 --azimuth 30 --elevation 25)
# render says the same of its reduction (it said "no finer tets than the voxels allow").
art_expect_test(cli.render_constant_is_exact EXIT 0
  STDOUT "mesh .*; tet budget not reached: the fit is exact, no tet has an error left to refine\\): [0-9]+ tets"
  ARGS render "${CMAKE_CURRENT_BINARY_DIR}/constant-5.mha" -o "${ART_TEST_OUTPUT}/constant-5.png" --size 8x8 --tets 300 --no-error
  --refinement bisection)
# A NaN angle is a usage error (it crashed the voxel reference); an infinite one a run-time error.
art_expect_test(cli.render_nan_azimuth EXIT 2 STDERR "option '--azimuth' expects a number, got 'nan'" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${ART_TEST_OUTPUT}/never.png" --size 20x20 --azimuth nan)
art_expect_test(cli.render_inf_elevation EXIT 1 STDERR "camera azimuth and elevation must be finite" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/am_underworks.ply" -o "${ART_TEST_OUTPUT}/never.png" --size 20x20 --elevation inf)
# render: the reduction options on a tet mesh are a usage error, as another kind's options are; a
# mesh renders as it is, and --tets 500 drew all of its tets without a word.
art_expect_test(cli.render_mesh_reduction_option EXIT 2 ONE_LINE_STDERR
  STDERR "--tets does not apply to a mesh \\(it reduces or casts a voxel volume; a tet mesh renders as it is\\)"
  ARGS render "${CMAKE_SOURCE_DIR}/tests/data/mixed/hex-and-triangle.vtu" -o "${ART_TEST_OUTPUT}/never.png" --tets 500)
# A scene whose every triangle is degenerate says why it has nothing to render.
art_expect_test(cli.render_degenerate_scene EXIT 1
  STDERR "degenerate.ply: has no triangles to render: all 2 polygons have zero area" ONE_LINE_STDERR
  ARGS render "${_bad}/degenerate.ply" -o "${ART_TEST_OUTPUT}/never.png")
# A flat scene (a floor plan in z = 0) is seen from above by default (it was edge-on from the
# front: background only); turned edge-on, the image is background only and render says why.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/floor.obj" "v 0 0 0\nv 4 0 0\nv 4 3 0\nv 0 3 0\nf 1 2 3 4\n")
art_expect_test(cli.render_flat_scene_edge_on EXIT 0
  STDOUT "note +no surface is in view: the scene is flat in z and seen edge-on \\(the default view, without --azimuth and --elevation, looks at it face on\\)"
  ARGS render "${CMAKE_CURRENT_BINARY_DIR}/floor.obj" -o "${ART_TEST_OUTPUT}/floor.png" --size 32x32 --elevation 90 --quiet)
art_expect_test(cli.render_flat_scene_from_above EXIT 0 STDOUT "\"covered_pixels\":[1-9]"
  ARGS render "${CMAKE_CURRENT_BINARY_DIR}/floor.obj" -o "${ART_TEST_OUTPUT}/floor-above.png" --size 32x32 --json)
# A camera placed straight above the floor (view direction along z, the default view-up) traced
# NaN rays: one flat colour over all 1024 pixels. The 4 x 3 floor seen from 10 above its centre
# with the 30 degree view angle covers 24 x 18 pixels (2 / (10 tan 15 deg) of the half-width).
art_expect_test(cli.render_camera_straight_above EXIT 0 STDOUT "\"covered_pixels\":432[,}]"
  ARGS render "${CMAKE_CURRENT_BINARY_DIR}/floor.obj" -o "${ART_TEST_OUTPUT}/floor-top.png" --size 32x32
  --camera-position 2,1.5,10 --focal-point 2,1.5,0 --json --quiet)
# --zoom on a perspective view of a scene was undone by the view angle set after framing: the
# same pixels at any zoom. The default frame fits the floor to 85% of the image (560 pixels); at
# 0.5 it covers about a quarter of them.
art_expect_test(cli.render_surface_zoom EXIT 0 STDOUT "\"covered_pixels\":120[,}]"
  ARGS render "${CMAKE_CURRENT_BINARY_DIR}/floor.obj" -o "${ART_TEST_OUTPUT}/floor-zoom.png" --size 32x32
  --zoom 0.5 --json --quiet)
art_expect_test(cli.render_surface_zoom_camera_position EXIT 0 STDOUT "\"covered_pixels\":96[,}]"
  ARGS render "${CMAKE_CURRENT_BINARY_DIR}/floor.obj" -o "${ART_TEST_OUTPUT}/floor-zoom-cp.png" --size 32x32
  --camera-position 2,1.5,10 --focal-point 2,1.5,0 --zoom 0.5 --json --quiet)
# A tet mesh clipped through grid points (ParaView's Clip with its default plane through the
# centre: vtkTableBasedClipDataSet leaves flat pieces on the plane) was refused by render and the
# mapper alike ('a face of tet 0 is shared by 5 tets'). The flat pieces are left out, the 160 tets
# of the kept half stay.
art_expect_test(cli.render_clipped_through_grid_points EXIT 0
  STDOUT "flat tets \\(no volume, as a clip through grid points leaves\\) were left out.*mesh +tet mesh: 160 tets"
  ARGS render "${CMAKE_SOURCE_DIR}/tests/data/clipped/half-box.vtu" -o "${ART_TEST_OUTPUT}/half-box.png" --size 32x32 --no-error)
art_expect_test(cli.render_missing_output_folder_first EXIT 1 STDERR "x.png: folder '.*no-such-folder' does not exist"
  ONE_LINE_STDERR ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${ART_TEST_OUTPUT}/no-such-folder/x.png"
  --size 16x16 --tets 2000)
art_expect_test(cli.render_output_is_folder_first EXIT 1 STDERR "is a directory, expected a file name"
  ONE_LINE_STDERR ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${CMAKE_CURRENT_BINARY_DIR}/folder.png"
  --size 16x16 --tets 2000)
# A render no ray of which meets the data (zoomed far out, or clipped away) wrote a blank image
# with "PSNR inf dB" and no word; it says so, as render does of a surface out of view.
art_expect_test(cli.render_no_ray_meets_the_data EXIT 0
  STDOUT "note +no ray meets the data .*background only"
  ARGS render "${_tetdata}/two-tets.vtu" -o "${ART_TEST_OUTPUT}/no-ray.png"
  --size 16x16 --clip 1e308,0,0,1,0,0)
# Values whose squares overflow or vanish are one line saying how to rescale them: render of a
# volume or a mesh of 1e-310 crashed (SIGSEGV in the transfer function's table, its range's inverse
# inf), and reduce of values of 1e300 wrote a 108-tet mesh with 'RMS inf'.
art_expect_test(cli.render_denormal_values EXIT 1
  STDERR "denormal-4x4x4.vti: the scalars' range 1e-310 .. 2.73205e-310 lies below 1e-150 in magnitude: .* rescale them first"
  ONE_LINE_STDERR ARGS render "${_bad}/denormal-4x4x4.vti" -o "${ART_TEST_OUTPUT}/never.png" --size 16x16 --reference)
art_expect_test(cli.render_denormal_mesh EXIT 1
  STDERR "denormal-tet.vtu: the scalars' range 1e-310 .. 4e-310 lies below 1e-150 in magnitude"
  ONE_LINE_STDERR ARGS render "${_bad}/denormal-tet.vtu" -o "${ART_TEST_OUTPUT}/never.png" --size 16x16)
# A NaN cell scalar (a masked or failed cell of a simulation) is named as a cell; it was averaged
# to its corners and reported as '4 points have a NaN ...' of a mesh with no point data. info
# counts such values beside the array's range, which leaves them out.
art_expect_test(cli.render_nan_cell EXIT 1
  STDERR "nan-cell.vtu: cell array 'pressure' holds NaN or infinite values in 1 cell \\(the first: cell 1\\)"
  ONE_LINE_STDERR ARGS render "${_bad}/nan-cell.vtu" -o "${ART_TEST_OUTPUT}/never.png" --size 16x16)
# CLI: the CT head at full-resolution tets against a committed baseline (PSNR >= 40 dB, SSIM >=
# 0.98: thread scheduling cannot change the image, so only compiler/libm differences remain).
art_render_baseline_test(cli.render_tets_ct_head BASELINE tets-ct-head-160.png MIN_PSNR 40 MIN_SSIM 0.98
  ARGS "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" --size 160x160 --azimuth 30 --elevation 10 --no-error)
art_expect_test(cli.render_tets_bad_integrator EXIT 2 STDERR "--integrator expects exact or trapezoid" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --integrator simpson)
# --clip cuts the mesh's rays and the voxel reference's alike (24.0 dB on this cutaway of two planes, framed to the
# head; 10.9 dB with the reference left whole); a plane past the head leaves nothing; a bad plane is refused.
art_expect_test(cli.render_tets_clip EXIT 0 STDOUT "error        PSNR 2[3-6]\\.[0-9]+ dB"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/clip.png" --size 64x64 --tets 3000 --plain-reduction
  --no-relocate "--clip=122,122,80,-1,0,0;0,0,60,0,0,1")
art_expect_test(cli.render_tets_clip_all EXIT 0 STDOUT "ERT 0.99: .* 0.0 tets/ray"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/clip-all.png" --size 32x32 --tets 500 --plain-reduction
  --clip 0,0,1000,0,0,1 --no-error)
art_expect_test(cli.render_tets_clip_bad EXIT 2 STDERR "--clip expects X,Y,Z,NX,NY,NZ \\(a point and a non-zero normal\\)" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --clip 1,2,3,0,0,0)
# A mesh whose tets keep their own points (as some exporters write them) renders as the same mesh
# with shared points: the preset's unit distance counts the merged points (20.5 dB apart before).
art_render_baseline_test(cli.render_tets_own_points BASELINE tets-box-shared-points.png MIN_PSNR 40 MIN_SSIM 0.98
  ARGS "${CMAKE_SOURCE_DIR}/tests/data/duplicates/box-own-points.vtu" --size 48x48 --azimuth 30 --elevation 20 --no-error)
art_expect_test(cli.render_tets_mesh_vector_magnitude EXIT 0 STDOUT "render .*tets/ray"
  ARGS render "${_vec}" -o "${_tmp}/vec.png" --size 32x32 --array velocity:magnitude --no-error)
art_expect_test(cli.render_tets_mesh_vector_whole EXIT 1 ONE_LINE_STDERR
  STDERR "point array 'velocity' has 3 components; rendering needs one \\(choose with --array velocity:magnitude or velocity:0 \\.\\. velocity:2, or another array\\)"
  ARGS render "${_vec}" -o "${_tmp}/vec.png" --size 32x32 --array velocity)
# --tets and --max-error take percentages as in `reduce`: 1% of the 884,736 voxels is 8,847 tets
# (bisection meets a budget to a few tets).
art_expect_test(cli.render_tets_percent_budget EXIT 0 STDOUT "least-squares reduction.*: 88[0-9][0-9] tets"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/pct.png" --size 32x32 --tets 1% --plain-reduction --no-error
  --refinement bisection)
# A transfer function for other data draws nothing: a note says so (exit 0, the image is written).
art_expect_test(cli.render_tets_tf_outside_range EXIT 0
  STDOUT "note         the transfer function is transparent over the data's range -1024 .. 2697 \\(its control points span 5000 .. 6000\\)"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/far.png" --size 16x16 --tets 500 --plain-reduction
  --no-error --tf "${_tetdata}/far-tf.txt")
# Opacity per too long a unit distance leaves the image all but clear: a note says so.
art_expect_test(cli.render_tets_all_but_clear EXIT 0
  STDOUT "note         the image is all but clear \\(opacity at most 0\\.000[0-9]+\\): the transfer function's opacity applies per 100000 world units"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/clear.png" --size 32x32 --tets 500 --plain-reduction
  --unit-distance 100000)
# Reductions are anisotropic and relocate by default, but not under iso-surfaces (where the
# lattice measured better) unless asked for.
art_expect_test(cli.render_tets_iso_keeps_lattice EXIT 0
  STDOUT "mesh +adaptive tets \\(opacity-weighted least-squares reduction, anisotropic \\(MMG3D\\), RMS"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/iso-lattice.png" --size 16x16 --tets 300 --iso 300 --no-error)
art_expect_test(cli.render_tets_iso_relocate EXIT 0
  STDOUT "mesh +adaptive tets \\(opacity-weighted least-squares reduction, anisotropic \\(MMG3D\\), vertices relocated"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/iso-reloc.png" --size 16x16 --tets 300 --iso 300 --relocate --no-error)
art_expect_test(cli.render_tets_relocates_by_default EXIT 0
  STDOUT "mesh +adaptive tets \\(opacity-weighted least-squares reduction, anisotropic \\(MMG3D\\), vertices relocated"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/reloc-default.png" --size 16x16 --tets 300 --no-error)
art_expect_test(cli.render_tets_relocate EXIT 0 STDOUT "least-squares reduction, vertices relocated, RMS error"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/reloc.png" --size 16x16 --tets 100 --plain-reduction
  --relocate --refinement bisection --no-error)
# --relocate given relocates a fine anisotropic mesh too (it was dropped without a word).
art_expect_test(cli.render_tets_fine_anisotropic_relocate EXIT 0
  STDOUT "least-squares reduction, anisotropic \\(MMG3D\\), vertices relocated, RMS error"
  ARGS render "${CMAKE_SOURCE_DIR}/tests/data/synthetic/brain-like.vti" -o "${_tmp}/fine-aniso-reloc.png" --size 16x16
  --tets 10% --plain-reduction --relocate --no-error)
# An anisotropic mesh whose tets hold fewer than 20 voxels each keeps MMG's vertices (relocation
# there fitted the voxel centres, not the field between them) and says so.
art_expect_test(cli.render_tets_fine_anisotropic_not_relocated EXIT 0
  STDOUT "least-squares reduction, anisotropic \\(MMG3D\\), RMS error"
  ARGS render "${CMAKE_SOURCE_DIR}/tests/data/synthetic/brain-like.vti" -o "${_tmp}/fine-aniso.png" --size 16x16
  --tets 10% --plain-reduction --no-error)
art_expect_test(cli.render_tets_bad_ert EXIT 2 STDERR "--ert expects an opacity in \\(0, 1\\], got '2'" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --ert 2)
art_expect_test(cli.render_option_of_another_kind EXIT 2 STDERR "--tets does not apply to a surface" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/am_underworks.ply" -o "${_tmp}/x.png" --tets 1000)
art_expect_test(cli.render_bad_zoom EXIT 2 STDERR "--zoom expects a positive factor, got '0'" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --zoom 0)
art_expect_test(cli.bad_threads EXIT 2 STDERR "--threads expects 0 \\(all cores\\) or a count up to 4096, got '-3'"
  ONE_LINE_STDERR ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --threads -3)
art_expect_test(cli.render_tets_bad_unit_distance EXIT 2 STDERR "--unit-distance expects a positive length, got '-1'"
  ONE_LINE_STDERR ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --unit-distance -1)
art_expect_test(cli.render_tets_edge_refinement EXIT 0 STDOUT "least-squares reduction.*: 30[0-9][0-9] tets"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/edge.png" --size 32x32 --tets 3000 --refinement edge --no-error)
# Maximum intensity reduces with the values clamped to the voxels' range (no bright overshoot).
art_expect_test(cli.render_tets_mip_clamped EXIT 0
  STDOUT "reduction, anisotropic \\(MMG3D\\), vertices relocated, clamped to the voxel range.*: (2[89]|3[01])[0-9][0-9] tets"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/mip.png" --size 32x32 --tets 3000 --mip --no-error)
# A ParaView preset (its "Export" JSON: diverging colours, opacity points) as --tf.
art_expect_test(cli.render_tets_paraview_preset EXIT 0 STDOUT "output .*pv.png"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/pv.png" --size 32x32 --tets 3000 --no-error
  --tf "${_tetdata}/paraview-preset.json")
# Parallel pieces and multiblock files (tests/data/pieces, made by make_pieces.py) read as the one
# mesh: 320 tets, 125 vertices once the points repeated at piece boundaries are merged.
foreach(_f pieces.pvtu blocks.vtm)
  art_expect_test(cli.render_mesh_${_f} EXIT 0 STDOUT "tet mesh: 320 tets, 125 vertices"
    ARGS render "${CMAKE_SOURCE_DIR}/tests/data/pieces/${_f}" -o "${_tmp}/${_f}.png" --size 32x32 --no-error)
endforeach()
art_expect_test(cli.render_mesh_empty_vtm EXIT 1 STDERR "empty.vtm: holds no data sets in its blocks" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/tests/data/pieces/empty.vtm" -o "${_tmp}/x.png" --size 32x32)
art_expect_test(cli.render_tets_bad_refinement EXIT 2 STDERR "--refinement is bisection, edge or anisotropic, got 'red-green'" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --tets 3000 --refinement red-green)
art_expect_test(cli.render_tets_iso_nan EXIT 2 STDERR "--iso expects numbers separated by commas, got 'nan'"
  ONE_LINE_STDERR ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --iso nan)
art_expect_test(cli.render_tets_unknown_preset EXIT 2 ONE_LINE_STDERR
  STDERR "--tf expects a transfer-function preset .* got 'rainbow': no preset has that name and no file of that name exists"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --tf rainbow)
# Control points 1e-310 apart gave Locate's table an infinite scale: a crash (SIGSEGV) on a mesh.
art_expect_test(cli.render_tf_denormal_span EXIT 1 ONE_LINE_STDERR
  STDERR "denormal-span-tf.txt: transfer function's control points span 0 .. 1e-310, too close together"
  ARGS render "${_tetdata}/two-tets.vtu" -o "${_tmp}/x.png" --tf "${_tetdata}/denormal-span-tf.txt")
art_expect_test(cli.render_tets_bad_tf_file EXIT 1 STDERR "bad-tf.txt: line 1: expected 'scalar r g b opacity'" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/x.png" --tf "${_tetdata}/bad-tf.txt")
art_expect_test(cli.render_tets_mesh_without_scalars EXIT 1 STDERR "no-scalars.vtu: mesh has no point or cell scalars" ONE_LINE_STDERR
  ARGS render "${_tetdata}/no-scalars.vtu" -o "${_tmp}/x.png")
# Iso-surfaces get error figures too: the voxel reference composites them (PSNR of 2 digits or more).
art_expect_test(cli.render_tets_iso_error EXIT 0 STDOUT "error +PSNR [1-9][0-9]\\.[0-9]+ dB"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/iso.png" --size 96x80 --tets 20000 --iso 300)
art_expect_test(cli.render_tets_mesh EXIT 0 STDOUT "tet mesh: 2 tets, 5 vertices.*output"
  ARGS render "${_tetdata}/two-tets.vtu" -o "${_tmp}/two-tets.png" --size 64x48 --tf grey-ramp)
# The surface tracer on the embedded am_underworks level, from inside it, opaque with shadows and
# transparent (all-hits attenuation), against committed baselines. Threshold: PSNR >= 40 dB and
# SSIM >= 0.98 (renders are deterministic; the slack covers other compilers' maths).
set(_art_cam --camera-position 640,640,-545 --focal-point 1500,640,-600 --view-angle 70 --size 200x150)
art_render_baseline_test(image.surface_underworks_opaque BASELINE surface-underworks-opaque.png
  MIN_PSNR 40 MIN_SSIM 0.98 ARGS "${CMAKE_SOURCE_DIR}/data/am_underworks.ply" ${_art_cam})
art_render_baseline_test(image.surface_underworks_transparent BASELINE surface-underworks-transparent.png
  MIN_PSNR 40 MIN_SSIM 0.98 ARGS "${CMAKE_SOURCE_DIR}/data/am_underworks.ply" ${_art_cam} --opacity 0.4)
# A scene 2.5e7 units from the origin (survey coordinates; tests/data/far-sphere.vtk, double
# points) renders like the same sphere at the origin (the baseline): the store traces in float.
art_render_baseline_test(image.surface_far_from_origin BASELINE surface-far-sphere.png
  MIN_PSNR 40 MIN_SSIM 0.98 ARGS "${CMAKE_SOURCE_DIR}/tests/data/far-sphere.vtk" --size 96x96)
# Bad options to the surface renderer: one line, exit 2.
art_expect_test(cli.render_surface_bad_opacity EXIT 2 STDERR "--opacity expects a value in" ONE_LINE_STDERR
  ARGS render "${CMAKE_SOURCE_DIR}/data/am_underworks.ply" -o "${ART_TEST_OUTPUT}/bad.png" --opacity 2)
add_test(NAME render.mesh_cache COMMAND bash "${CMAKE_CURRENT_LIST_DIR}/mesh_cache_check.sh"
  "$<TARGET_FILE:adaptivert>" "${CMAKE_SOURCE_DIR}" "${ART_TEST_OUTPUT}/mesh-cache")
set_tests_properties(render.mesh_cache PROPERTIES LABELS "unit" TIMEOUT 300)
# Work too large for the memory available is refused up front (memory_refusal_check.sh: a sparse
# volume, an 8 GB address-space cap, exit 1, the message, nothing written).
# render: full-resolution tets of 450^3 voxels (453 million, ~72 GB; under TetMesh's 2^29 limit, so
# TetMesh::CheckFullResolutionFits is what refuses; 91 MB read).
set(_w "${ART_TEST_OUTPUT}/full-tets-memory")
add_test(NAME render.full_tets_memory COMMAND bash "${_mem}" "${_w}" "450 450 450" MET_UCHAR 91125000
  "big.mhd: full-resolution tets of this volume (452594245) need about 72.4 GB, more than the .* GB of memory available; reduce it first (--tets N"
  "${_w}/big.png" -- "$<TARGET_FILE:adaptivert>" render "${_w}/big.mhd" -o "${_w}/big.png" --size 32x32)
set_tests_properties(render.full_tets_memory PROPERTIES LABELS "unit" TIMEOUT 120)
# A mesh renders without scoring itself (it computed its own exact render and printed "PSNR inf
# dB" or a figure of how it is drawn, not of what it models); --error names the reference: the
# source volume's voxels, an image of the same size, or 'exact'.
art_expect_test(cli.render_mesh_no_self_reference EXIT 0 STDOUT "crossed per thread output"
  ARGS render "${_tetdata}/two-tets.vtu" -o "${_tmp}/two-tets-noref.png" --size 32x24 --tf grey-ramp)
art_expect_test(cli.render_mesh_error_volume_mesh EXIT 0 STDOUT "output .*mesh-err.vtu"
  ARGS reduce "${_ct}" "${_tmp}/mesh-err.vtu" --tets 3000 --quiet)
set_tests_properties(cli.render_mesh_error_volume_mesh PROPERTIES FIXTURES_SETUP render_mesh_err)
art_expect_test(cli.render_mesh_error_volume EXIT 0
  STDOUT "reference +voxel ray caster on .*ct-head-128.mha.*error +PSNR [1-9][0-9]\\.[0-9]+ dB.*object: PSNR [1-9][0-9]\\.[0-9]+ dB"
  ARGS render "${_tmp}/mesh-err.vtu" -o "${_tmp}/mesh-err.png" --size 32x32 --error "${_ct}")
set_tests_properties(cli.render_mesh_error_volume PROPERTIES FIXTURES_REQUIRED render_mesh_err)
art_expect_test(cli.render_mesh_error_exact EXIT 0 STDOUT "reference +exact rule on the mesh.*error +PSNR"
  ARGS render "${_tetdata}/two-tets.vtu" -o "${_tmp}/two-tets-exact.png" --size 32x24 --tf grey-ramp --ert 0.5 --error exact)
art_expect_test(cli.render_mesh_error_image_size EXIT 1 ONE_LINE_STDERR
  STDERR "levels.png: is 64x48, the render 32x24: give --size to match the reference image"
  ARGS render "${_tetdata}/two-tets.vtu" -o "${_tmp}/two-tets-img.png" --size 32x24 --error "${_img}/levels.png" -q)
art_expect_test(cli.render_mesh_error_image EXIT 0 STDOUT "reference +image .*levels.png.*error +PSNR"
  ARGS render "${_tetdata}/two-tets.vtu" -o "${_tmp}/two-tets-img8.png" --size 64x48 --error "${_img}/levels.png")
art_expect_test(cli.render_error_and_no_error EXIT 2 ONE_LINE_STDERR STDERR "--error and --no-error exclude each other"
  ARGS render "${_ct}" -o "${_tmp}/x.png" --no-error --error exact)
# --roll and --view-up turn the picture as a camera does (checked against the plain render turned).
art_add_python_test(cli.render_view_up_roll "${CMAKE_CURRENT_LIST_DIR}/test_view_up_roll.py")
art_expect_test(cli.render_view_up_along_view EXIT 2 ONE_LINE_STDERR
  STDERR "--view-up 0,1,0 is along the view direction; give one across it"
  ARGS render "${_ct}" -o "${_tmp}/x.png" --view-up 0,1,0)
art_expect_test(cli.render_view_up_zero EXIT 2 ONE_LINE_STDERR
  STDERR "--view-up expects a non-zero direction X,Y,Z, got '0,0,0'" ARGS render "${_ct}" -o "${_tmp}/x.png" --view-up 0,0,0)
# --save-mesh keeps the reduced mesh that was rendered (it was lost with the image); usage errors
# come before anything is loaded.
add_test(NAME cli.render_save_mesh COMMAND ${CMAKE_COMMAND} "-DART=$<TARGET_FILE:adaptivert>" "-DDATA=${_ct}"
  "-DOUT=${ART_TEST_OUTPUT}/save-mesh" -P "${CMAKE_CURRENT_LIST_DIR}/save_mesh_check.cmake")
set_tests_properties(cli.render_save_mesh PROPERTIES LABELS unit)
art_expect_test(cli.render_save_mesh_needs_reduction EXIT 2 ONE_LINE_STDERR
  STDERR "--save-mesh writes the reduced mesh: give --tets N or --max-error E"
  ARGS render "${_ct}" -o "${_tmp}/x.png" --save-mesh "${_tmp}/x.vtu")
art_expect_test(cli.render_save_mesh_vtu EXIT 2 ONE_LINE_STDERR STDERR "--save-mesh writes a .vtu, got '.*x.vtk'"
  ARGS render "${_ct}" -o "${_tmp}/x.png" --tets 100 --save-mesh "${_tmp}/x.vtk")
# Values that contradict each other or are not decimal numbers were taken without a word.
art_expect_test(cli.render_reference_with_tets EXIT 2 STDERR "--reference renders the full-resolution voxels; --tets"
  ONE_LINE_STDERR ARGS render "${_ct}" -o "${ART_TEST_OUTPUT}/never.png" --reference --tets 500)
art_expect_test(cli.render_relocate_both EXIT 2 STDERR "--relocate and --no-relocate contradict each other"
  ONE_LINE_STDERR ARGS render "${_ct}" -o "${ART_TEST_OUTPUT}/never.png" --tets 500 --relocate --no-relocate)
art_expect_test(cli.render_tets_hexadecimal EXIT 2 STDERR "--tets wants a positive number or a percentage, got '0x10'"
  ONE_LINE_STDERR ARGS render "${_ct}" -o "${ART_TEST_OUTPUT}/never.png" --tets 0x10)
art_expect_test(cli.render_zoom_hexadecimal EXIT 2 STDERR "option '--zoom' expects a number, got '0x2'"
  ONE_LINE_STDERR ARGS render "${_ct}" -o "${ART_TEST_OUTPUT}/never.png" --zoom 0x2)
art_expect_test(cli.render_frame_on_surface EXIT 2 STDERR "--frame does not apply to a surface"
  ONE_LINE_STDERR ARGS render "${CMAKE_SOURCE_DIR}/data/am_underworks.ply" -o "${ART_TEST_OUTPUT}/never.png" --frame vtk)

# Default transfer functions from the data (tests/data/make_synthetic_volumes.py): an MRI-like heart
# (noisy background clear, blood pools bright), a skull-stripped-brain-like volume, a label map in
# categorical colours, and MIP over the heart's robust window; each framed to its visible part.
# Thresholds as the other baselines: PSNR >= 40 dB, SSIM >= 0.98.
set(_synthetic "${CMAKE_SOURCE_DIR}/tests/data/synthetic")
foreach(_case heart-like brain-like labels)
  art_render_baseline_test(image.default_tf_${_case} BASELINE default-tf-${_case}.png MIN_PSNR 40 MIN_SSIM 0.98
    ARGS "${_synthetic}/${_case}.vti" --size 120x120 --azimuth 30 --no-error)
endforeach()
art_render_baseline_test(image.default_tf_mip BASELINE default-tf-heart-mip.png MIN_PSNR 40 MIN_SSIM 0.98
  ARGS "${_synthetic}/heart-like.vti" --size 120x120 --mip --no-error)
add_test(NAME cli.render_mesh_default_tf_as_volume COMMAND ${CMAKE_COMMAND} "-DART=$<TARGET_FILE:adaptivert>"
  "-DDATA=${_synthetic}/heart-like.vti" "-DOUT=${ART_TEST_OUTPUT}/mesh-default-tf"
  -P "${CMAKE_CURRENT_LIST_DIR}/mesh_default_tf_check.cmake")
art_expect_test(cli.render_bad_fit EXIT 2 STDERR "--fit expects view or orbit, got 'tight'" ONE_LINE_STDERR
  ARGS render "${_synthetic}/labels.vti" -o "${ART_TEST_OUTPUT}/never.png" --fit tight)
# --json reports the camera it framed (what ParaView or a vtkCamera needs to draw the same view).
art_expect_test(cli.render_json_camera EXIT 0
  STDOUT "\"camera\":\\{\"position\":\\[[-0-9.e]+,[-0-9.e]+,[-0-9.e]+\\],\"focal_point\":\\[.*\"view_angle\":30,"
  ARGS render "${_synthetic}/labels.vti" -o "${ART_TEST_OUTPUT}/camera.png" --size 32x32 --json --no-error -q)
# A label mesh (reduce --labels: cell array "label") in the categorical table, each tet in its
# label's colour up to the interface; the cell values averaged to the points drew it grey.
art_render_baseline_test(image.labels_categorical BASELINE labels-cubes.png MIN_PSNR 40 MIN_SSIM 0.98
  ARGS "${CMAKE_SOURCE_DIR}/tests/data/meshing/cubes-labels.vtu" --size 96x96 --azimuth 30 --elevation 30)
art_expect_test(cli.render_label_mesh EXIT 0 STDOUT "mesh +label mesh: 1044 tets"
  ARGS render "${CMAKE_SOURCE_DIR}/tests/data/meshing/cubes-labels.vtu" -o "${ART_TEST_OUTPUT}/labels.png" --size 32x32 --quiet)
# A label mesh with a volume's values (tests/data/meshing/ct-tissue-values.vtu: the CT head's soft
# tissue and bone as labels, the CT's values fitted inside them): by default the values inside
# each label in its hue; flat gives the labels alone, off the values alone.
set(_tissue "${CMAKE_SOURCE_DIR}/tests/data/meshing/ct-tissue-values.vtu")
art_render_baseline_test(image.labels_values_ct BASELINE labels-values-ct.png MIN_PSNR 40 MIN_SSIM 0.98
  ARGS "${_tissue}" --size 160x160 --azimuth 30 --elevation 10 --no-error)
art_expect_test(cli.render_label_values EXIT 0 STDOUT "mesh +label mesh with values: 4261 tets"
  ARGS render "${_tissue}" -o "${ART_TEST_OUTPUT}/label-values.png" --size 32x32 --no-error --quiet)
art_expect_test(cli.render_label_colours_flat EXIT 0 STDOUT "mesh +label mesh: 4261 tets"
  ARGS render "${_tissue}" -o "${ART_TEST_OUTPUT}/label-flat.png" --size 32x32 --label-colours flat --no-error --quiet)
art_expect_test(cli.render_label_colours_off EXIT 0 STDOUT "mesh +tet mesh: 4261 tets"
  ARGS render "${_tissue}" -o "${ART_TEST_OUTPUT}/label-off.png" --size 32x32 --label-colours off --no-error --quiet)
art_expect_test(cli.render_label_colours_bad EXIT 2 ONE_LINE_STDERR
  STDERR "--label-colours expects values, flat or off, got 'hue'"
  ARGS render "${_tissue}" -o "${ART_TEST_OUTPUT}/never.png" --label-colours hue)
# --refinement anisotropic reduces through MMG3D; the label says so and the image is scored.
art_expect_test(cli.render_tets_anisotropic EXIT 0
  STDOUT "least-squares reduction, anisotropic \\(MMG3D\\), vertices relocated, RMS error [0-9.]+.*: (1[89][0-9][0-9]|20[0-9][0-9]) tets.*error +PSNR [0-9.]+ dB"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/aniso.png" --size 48x48 --tets 2000
  --refinement anisotropic --plain-reduction -q)
# A small budget is met too: with edges capped at 24 voxels, 500 tets came out as 967; the longest
# edge now grows with a coarse budget. Below what any remeshing of the box makes, a note says so.
art_expect_test(cli.render_tets_anisotropic_small_budget EXIT 0 STDOUT "anisotropic \\(MMG3D\\).*\\): (4[89][0-9]|5[0-2][0-9]) tets"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/aniso-500.png" --size 16x16 --tets 500 --no-error)
art_expect_test(cli.render_tets_anisotropic_budget_missed EXIT 0
  STDOUT "tet budget missed by [0-9]+%: the remeshings ran out before MMG's count came within 5%\\): [0-9]+ tets"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/aniso-6.png" --size 16x16 --tets 6 --no-error)
# The anisotropic mesh's long, thin tets (slivers down to a few degrees) walked face to face without
# the stability fallback once, over every ray of a 200 x 200 frame.
art_expect_test(cli.render_tets_anisotropic_walk EXIT 0 STDOUT "\"tets_crossed\":[1-9][0-9]+,.*\"fallback_exits\":0[,}]"
  ARGS render "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" -o "${_tmp}/aniso-walk.png" --size 200x200 --tets 20000
  --refinement anisotropic --json --no-error -q)
# --shade lights the volume by its gradient (vtkVolumeProperty::ShadeOn); the unlit voxel reference
# gives no error figures then, and --reference refuses it.
art_render_baseline_test(image.render_shade BASELINE tets-shade-ct-head.png MIN_PSNR 40 MIN_SSIM 0.98
  ARGS "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha" --size 160x160 --azimuth 30 --shade)
art_expect_test(cli.render_shade_no_voxel_error EXIT 0 STDOUT "no error figures: the voxel reference does not shade"
  ARGS render "${_synthetic}/brain-like.vti" -o "${ART_TEST_OUTPUT}/shade.png" --size 32x32 --shade)
art_expect_test(cli.render_shade_reference EXIT 2 STDERR "--shade: the voxel reference does not shade" ONE_LINE_STDERR
  ARGS render "${_synthetic}/brain-like.vti" -o "${ART_TEST_OUTPUT}/never.png" --reference --shade)
# A volume with NaN voxels is refused with their count and place (the default framing crashed on
# them before the caster could say so).
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/nan-3x3x3.nrrd" "NRRD0004\ntype: float\ndimension: 3\nsizes: 3 3 3\n"
  "encoding: ascii\n\n0 0 0 0 0 0 0 0 0 0 0 0 0 1000 nan 0 0 0 0 0 0 0 0 0 0 0 0\n")
art_expect_test(cli.render_nan_voxels EXIT 1 ONE_LINE_STDERR
  STDERR "nan-3x3x3.nrrd: 1 voxel holds NaN or infinite values \\(the first at i, j, k = 2, 1, 1\\)"
  ARGS render "${CMAKE_CURRENT_BINARY_DIR}/nan-3x3x3.nrrd" -o "${ART_TEST_OUTPUT}/never.png" --size 16x16 --no-error)
# A slab a few voxels thin is reduced by bisection unless anisotropic is asked for (MMG took
# 30-60 s on it, bisection 0.1 s), with a note.
set(_slab "")
foreach(_i RANGE 1199)
  math(EXPR _x "(${_i} % 20) * (${_i} / 20 % 20)")
  string(APPEND _slab "${_x} ")
endforeach()
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/slab-20x20x3.nrrd"
  "NRRD0004\ntype: float\ndimension: 3\nsizes: 20 20 3\nencoding: ascii\n\n${_slab}\n")
art_expect_test(cli.render_thin_slab_bisection EXIT 0
  STDERR "note: reducing with bisection: the volume is 3 voxels thin"
  STDOUT "least-squares reduction, vertices relocated, RMS"
  ARGS render "${CMAKE_CURRENT_BINARY_DIR}/slab-20x20x3.nrrd" -o "${ART_TEST_OUTPUT}/slab.png" --size 16x16 --tets 300
  --tf grey-ramp --no-error)
