# `adaptivert info`: what it says of every format, and the bad files it refuses in one line.

art_expect_test(cli.info_help EXIT 0 STDOUT "examples:.*adaptivert info" ARGS info --help)
art_expect_test(cli.info_unknown_option EXIT 2 STDERR "unknown option '--bogus'" ONE_LINE_STDERR ARGS info --bogus x)
# The embedded default data.
art_expect_test(cli.info_default_volume EXIT 0
  STDOUT "dimensions +128 x 128 x 54.*spacing +1.914 x 1.914 x 3.*short.*range -1024"
  ARGS info "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha")
art_expect_test(cli.info_default_scene EXIT 0 STDOUT "2,653 triangles"
  ARGS info "${CMAKE_SOURCE_DIR}/data/am_underworks.ply")
art_expect_test(cli.info_json EXIT 0 STDOUT "^\\{\"files\":\\[\\{\"file\":.*\"triangles\":2653"
  ARGS info --json "${CMAKE_SOURCE_DIR}/data/am_underworks.ply")
# Bad input: one line naming the file and the problem, exit 1, no crash, no hang.
art_expect_test(cli.bad_missing_file EXIT 1 STDERR "nonexistent.mha: no such file" ONE_LINE_STDERR
  ARGS info "${_bad}/nonexistent.mha")
art_expect_test(cli.bad_unknown_extension EXIT 1 STDERR "volume.xyz: unknown file type '.xyz'" ONE_LINE_STDERR
  ARGS info "${_bad}/volume.xyz")
art_expect_test(cli.bad_truncated_mha EXIT 1 STDERR "truncated.mha: truncated" ONE_LINE_STDERR
  ARGS info "${_bad}/truncated.mha")
art_expect_test(cli.bad_random_ply EXIT 1 STDERR "random.ply: not a PLY file" ONE_LINE_STDERR
  ARGS info "${_bad}/random.ply")
art_expect_test(cli.bad_truncated_ply EXIT 1 STDERR "truncated.ply: truncated" ONE_LINE_STDERR
  ARGS info "${_bad}/truncated.ply")
art_expect_test(cli.bad_directory EXIT 1 STDERR "bad: folder holds no readable DICOM series" ONE_LINE_STDERR
  ARGS info "${_bad}")
art_expect_test(cli.bad_directory_as_surface EXIT 1 STDERR "dir.ply: is a directory" ONE_LINE_STDERR
  ARGS info "${_bad}/dir.ply")
art_expect_test(cli.bad_empty_file EXIT 1 STDERR "empty.vtp: file is empty" ONE_LINE_STDERR
  ARGS info "${_bad}/empty.vtp")
art_expect_test(cli.bad_garbage_vti EXIT 1 STDERR "garbage.vti: cannot read" ONE_LINE_STDERR
  ARGS info "${_bad}/garbage.vti")
# info gave a vector's component 0 range as the range; now its magnitude's, and how to choose.
art_expect_test(cli.info_vector_scalars EXIT 0
  STDOUT "scalars +unsigned char, 3 components, magnitude range 0 .. 97.28[0-9]* \\(--array rgb:magnitude or rgb:0 .. rgb:2\\)"
  ARGS info "${_bad}/rgb-3x3x3.vti")
# Every file of the development data is summarised correctly (skipped without ../shared).
if(EXISTS "${ART_SHARED_DATA}/ct-head.mha")
  art_expect_test(cli.info_shared_ct EXIT 0
    STDOUT "dimensions +256 x 256 x 108.*spacing +0.957 x 0.957 x 1.5.*short.*range -1024 .. 2986"
    ARGS info "${ART_SHARED_DATA}/ct-head.mha")
  art_expect_test(cli.info_shared_bunny EXIT 0 STDOUT "points +50,000.*99,785 triangles"
    ARGS info "${ART_SHARED_DATA}/bunny.ply")
  art_expect_test(cli.info_shared_underworks EXIT 0 STDOUT "2,653 triangles" ARGS info "${ART_SHARED_DATA}/am_underworks.ply")
  art_expect_test(cli.info_shared_hydronex EXIT 0 STDOUT "7,679 triangles" ARGS info "${ART_SHARED_DATA}/hydronex2.ply")
  art_expect_test(cli.info_shared_minia EXIT 0 STDOUT "28,888 triangles" ARGS info "${ART_SHARED_DATA}/oa_minia.ply")
endif()
art_expect_test(cli.info_surface_cell_data EXIT 0 STDOUT "cell data +RGB \\[unsigned char x3"
  ARGS info "${CMAKE_SOURCE_DIR}/tests/data/colours/face-colours.ply")
# info counts a volume's NaN and infinite voxels (a masked MRI map): VTK's range leaves NaN out, so
# the volume looked fine until render and reduce refused it.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/nan-2x2x2.nrrd"
  "NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 2\nencoding: ascii\n\n1 2 nan 4 5 6 inf 8\n")
art_expect_test(cli.info_nan_voxels EXIT 0 STDOUT "non-finite +1 NaN and 1 infinite values \\(render and reduce need finite voxels"
  ARGS info "${CMAKE_CURRENT_BINARY_DIR}/nan-2x2x2.nrrd")
# info on a mirrored volume 1e7 from the origin: the bounds told neither ("x [1e+07, 1e+07]").
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/far_mirrored.mha"
  "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nOffset = 10000000.5 0 0\n"
  "ElementSpacing = 1 1 1\nTransformMatrix = -1 0 0 0 1 0 0 0 1\nElementDataFile = LOCAL\nABCDEFGH")
art_expect_test(cli.info_far_mirrored_volume EXIT 0
  STDOUT "origin +10000000.5, 0, 0 +direction +\\[-1 0 0; 0 1 0; 0 0 1\\] +bounds +x \\[9999999.5, 10000000.5\\]"
  ARGS info "${CMAKE_CURRENT_BINARY_DIR}/far_mirrored.mha")
# A radiological NIfTI (x flipped by its sform; make_nifti_radiological.py) rendered mirrored:
# vtkNIFTIImageReader leaves qform and sform to the caller. info names the placement and the
# file's axes as fslhd and nibabel do (LAS), in the LPS world of DICOM and MetaImage.
art_expect_test(cli.info_nifti_radiological EXIT 0
  STDOUT "origin +-10, -20, 34 +direction +\\[1 0 0; 0 -1 0; 0 0 -1\\] +bounds +x \\[-10, -4\\]  y \\[-26, -20\\]  z \\[30, 34\\] +orientation +LAS \\(the file's i, j, k toward left, anterior, superior.*placed by +NIfTI sform code 1 \\(scanner\\)"
  ARGS info "${CMAKE_SOURCE_DIR}/tests/data/nifti-radiological.nii")
# DICOM folders as PACS exports leave them (make_dicom_series_mix.py): vtkDICOMImageReader read the
# series whose UID sorts first (here a 5 x 5 scout) with another series' image size, and a slice of
# another size beside the others: both segfaulted. The largest series is read; mixed sizes are one line.
art_expect_test(cli.info_dicom_beside_scout EXIT 0
  STDOUT "dimensions +4 x 3 x 3 .*spacing +1 x 1 x 1.5.*range 0 .. 223"
  ARGS info "${CMAKE_SOURCE_DIR}/tests/data/dicom-scout")
art_expect_test(cli.info_dicom_mixed_size EXIT 1
  STDERR "dicom-mixed-size: images of one DICOM series differ in size: ct1.dcm is 2 x 2, ct0.dcm 4 x 3" ONE_LINE_STDERR
  ARGS info "${CMAKE_SOURCE_DIR}/tests/data/dicom-mixed-size")
art_expect_test(cli.info_dicom_compressed EXIT 1
  STDERR "dicom-compressed: holds compressed DICOM images \\(transfer syntax 1.2.840.10008.1.2.4.70 in jpeg0.dcm\\), which VTK's reader cannot decode: decompress them first" ONE_LINE_STDERR
  ARGS info "${CMAKE_SOURCE_DIR}/tests/data/dicom-compressed")
# A readable surface of lines and points only says what it holds, not "empty or unreadable".
art_expect_test(cli.info_lines_only_surface EXIT 1
  STDERR "lines-only.obj: holds no polygons, only 2 lines and 1 vertices \\(surfaces are drawn from polygons and triangle strips\\)"
  ONE_LINE_STDERR ARGS info "${_bad}/lines-only.obj")
# info prints a range with the digits that tell its ends apart (1000 + 1e-9 printed "1000 .. 1000").
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/narrow_range.vti"
  "<VTKFile type=\"ImageData\" version=\"0.1\" byte_order=\"LittleEndian\"><ImageData WholeExtent=\"0 1 0 1 0 1\" "
  "Origin=\"0 0 0\" Spacing=\"1 1 1\"><Piece Extent=\"0 1 0 1 0 1\"><PointData Scalars=\"p\"><DataArray type=\"Float64\" "
  "Name=\"p\" format=\"ascii\">1000 1000 1000 1000 1000 1000 1000 1000.000000001</DataArray></PointData></Piece>"
  "</ImageData></VTKFile>\n")
art_expect_test(cli.info_narrow_range EXIT 0 STDOUT "double, 1 component, range 1000 .. 1000.000000001"
  ARGS info "${CMAKE_CURRENT_BINARY_DIR}/narrow_range.vti")
# NIfTI headers vtkNIFTIImageReader trusts (tests/data/bad/make_bad_nifti.py): an unknown datatype
# segfaulted, a NaN pixdim became the spacing, 30000^3 voxels in 400 bytes ran out of memory.
art_expect_test(cli.bad_nifti_datatype EXIT 1 STDERR "datatype-1234.nii: NIfTI datatype 1234 is not one VTK reads"
  ONE_LINE_STDERR ARGS info "${_bad}/datatype-1234.nii")
art_expect_test(cli.bad_nifti_nan_spacing EXIT 1 STDERR "nan-spacing.nii: NIfTI spacing pixdim\\[1\\] is not a finite number"
  ONE_LINE_STDERR ARGS info "${_bad}/nan-spacing.nii")
art_expect_test(cli.bad_nifti_huge_sizes EXIT 1
  STDERR "huge-sizes.nii: truncated: the header promises 54000000000000 data bytes, the file holds 48"
  ONE_LINE_STDERR ARGS info "${_bad}/huge-sizes.nii")
# A 4-D NIfTI (fMRI, DWI) loads its first volume: info says how many the file holds; without a
# qform or sform it names no orientation.
art_expect_test(cli.info_nifti_4d EXIT 0
  STDOUT "placed by +NIfTI none \\(no qform or sform: axes as stored, origin 0\\) +volumes +5 in the file \\(dim\\[4..7\\]\\); the first is loaded +scalars +short, 1 component, range 0 .. 23"
  ARGS info "${CMAKE_SOURCE_DIR}/tests/data/nifti-4d.nii")
art_expect_test(cli.info_dicom_gap EXIT 1
  STDERR "dicom-gap: slices are not evenly spaced: ct0.dcm and ct1.dcm are 1.5 mm apart, ct2.dcm and ct3.dcm 3 mm \\(a missing slice"
  ONE_LINE_STDERR ARGS info "${CMAKE_SOURCE_DIR}/tests/data/dicom-gap")
art_expect_test(cli.info_dicom_multiframe EXIT 1
  STDERR "dicom-multiframe: holds a multi-frame DICOM image \\(3 frames in frames.dcm\\), which VTK's reader reads as its first frame only"
  ONE_LINE_STDERR ARGS info "${CMAKE_SOURCE_DIR}/tests/data/dicom-multiframe")
# info shows the range render and reduce refuse, and why (it showed it as any other range).
art_expect_test(cli.info_denormal_values EXIT 0
  STDOUT "range 1e-310 .. 2.73205e-310.  magnitude +the scalars' range 1e-310 .. 2.73205e-310 lies below 1e-150 in magnitude"
  ARGS info "${_bad}/denormal-4x4x4.vti")
art_expect_test(cli.info_nan_cell EXIT 0 STDOUT "cell data +pressure \\[double x1, 1..1, NaN or infinite: 1\\]"
  ARGS info "${_bad}/nan-cell.vtu")
# info: a 3000^3 16-bit volume (54 GB) is refused from its header, before the read (without the
# check the read ran out, 'out of memory while reading it'; uncapped, it was killed half-way).
set(_w "${ART_TEST_OUTPUT}/read-memory")
add_test(NAME io.read_memory_check COMMAND bash "${_mem}" "${_w}" "3000 3000 3000" MET_USHORT 54000000000
  "big.mhd: holding its 3000 x 3000 x 3000 voxels needs about 54 GB, more than the .* GB of memory available; crop or downsample it first"
  - -- "$<TARGET_FILE:adaptivert>" info "${_w}/big.mhd")
set_tests_properties(io.read_memory_check PROPERTIES LABELS "unit" TIMEOUT 60)
# The corpus of bad files (tests/data/corpus, made by its make_corpus.py and grown by the fuzzing
# targets): VTK's readers crashed on, hung on or misread each; every one is one line, exit 1.
add_test(NAME cli.info_bad_corpus COMMAND ${CMAKE_COMMAND} "-DPROGRAM=$<TARGET_FILE:adaptivert>" "-DARGS=info"
  "-DDIR=${CMAKE_SOURCE_DIR}/tests/data/corpus" -P "${CMAKE_CURRENT_LIST_DIR}/corpus_check.cmake")
add_test(NAME cli.render_bad_corpus COMMAND ${CMAKE_COMMAND} "-DPROGRAM=$<TARGET_FILE:adaptivert>"
  "-DARGS=render|-o|${ART_TEST_OUTPUT}/never-corpus.png|--size|20x20"
  "-DDIR=${CMAKE_SOURCE_DIR}/tests/data/corpus" -P "${CMAKE_CURRENT_LIST_DIR}/corpus_check.cmake")
set_tests_properties(cli.info_bad_corpus cli.render_bad_corpus PROPERTIES LABELS unit)
# A FIFO, a device, a file only another user may read, a full disk, a write-protected output and
# raw voxels, made at run time (files_check.sh; 77 = skipped where the machine cannot).
foreach(_mode fifo permission diskfull protected raw frame batchkill)
  add_test(NAME cli.files_${_mode} COMMAND bash "${CMAKE_CURRENT_LIST_DIR}/files_check.sh" "$<TARGET_FILE:adaptivert>"
    ${_mode} "${ART_TEST_OUTPUT}/files_${_mode}" "${CMAKE_SOURCE_DIR}")
  set_tests_properties(cli.files_${_mode} PROPERTIES LABELS unit SKIP_RETURN_CODE 77 TIMEOUT 120)
endforeach()
# A .vtp of triangle strips counts their triangles (it showed 0); a volume names its arrays.
art_expect_test(cli.info_strip_triangles EXIT 0 STDOUT "strips +18 \\(96 triangles\\).*triangles +96"
  ARGS info "${CMAKE_SOURCE_DIR}/tests/data/sphere-strips.vtp")
art_expect_test(cli.info_volume_arrays EXIT 0 STDOUT "point data +MetaImage .short x1, -1024..2697"
  ARGS info "${CMAKE_SOURCE_DIR}/data/ct-head-128.mha")
# MetaIO printed eight lines of its own before our one.
art_expect_test(cli.info_metaio_quiet EXIT 1 STDERR "mha-spacing-before-ndims.mha: ElementSpacing comes before NDims"
  ONE_LINE_STDERR ARGS info "${CMAKE_SOURCE_DIR}/tests/data/corpus/mha-spacing-before-ndims.mha")
art_expect_test(cli.info_far_vertex EXIT 1 STDERR "vtu-far-vertex.vtu: a cell refers to point 1000000000 of 27"
  ONE_LINE_STDERR ARGS info "${CMAKE_SOURCE_DIR}/tests/data/corpus/vtu-far-vertex.vtu")
# What the default transfer function is made from: a label map's labels, an MRI-like volume's
# background and window (tests/data/make_synthetic_volumes.py).
art_expect_test(cli.info_statistics_labels EXIT 0 STDOUT "statistics   window .*; labels: 0 1 2 3"
  ARGS info "${CMAKE_SOURCE_DIR}/tests/data/synthetic/labels.vti")
art_expect_test(cli.info_statistics_background EXIT 0
  STDOUT "statistics   window 9[0-9]\\.[0-9]+ \\.\\. 21[0-9]\\.[0-9]+ \\(1st-99\\.5th percentile above the background 0 \\.\\. [0-9.]+\\)"
  ARGS info "${CMAKE_SOURCE_DIR}/tests/data/synthetic/heart-like.vti")
