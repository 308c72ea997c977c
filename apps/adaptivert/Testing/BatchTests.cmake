# `adaptivert batch`: job files, resuming, shared output folders and their refusals.

# Job files that are wrong fail in one line naming the job file.
art_expect_test(cli.batch_missing_job EXIT 1 STDERR "nope.json: no such file" ONE_LINE_STDERR
  ARGS batch "${_jobs}/nope.json")
art_expect_test(cli.batch_no_datasets EXIT 1 STDERR "bad_no_datasets.json: needs \"datasets\"" ONE_LINE_STDERR
  ARGS batch "${_jobs}/bad_no_datasets.json")
art_expect_test(cli.batch_bad_syntax EXIT 1 STDERR "bad_syntax.json: not valid JSON" ONE_LINE_STDERR
  ARGS batch "${_jobs}/bad_syntax.json")
art_expect_test(cli.batch_bad_field_type EXIT 1 STDERR "bad_field_type.json: \"size\" must be a string, got 400" ONE_LINE_STDERR
  ARGS batch "${_jobs}/bad_field_type.json")
# batch --json printed its paths unescaped: an output folder named with a quote gave JSON that no
# parser reads ("csv":"/../out"x/results.csv"); now the quote is escaped.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/quote-job/job.json"
  "{\"output\": \"out\\\"x\", \"datasets\": [\"../floor.obj\"], \"size\": \"16x16\"}\n")
art_expect_test(cli.batch_json_escapes_paths EXIT 0 STDOUT "\"csv\":\"[^\"]*/out[^\"]\"x/results.csv\""
  ARGS batch "${CMAKE_CURRENT_BINARY_DIR}/quote-job/job.json" --json --quiet)
# A setting with its own transfer function is scored against the reference's picture: the batch
# says so once per such setting before it renders (setting 0 differs only in how it approximates:
# no note, hence one line); frames with their own tf scored 14-18 dB without a word.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/look-job/job.json"
  "{\"output\": \"out\", \"datasets\": [\"${CMAKE_SOURCE_DIR}/data/ct-head-128.mha\"], \"size\": \"16x16\",\n"
  " \"settings\": [{\"tets\": 300, \"integrator\": \"trapezoid\"}, {\"tets\": 300, \"tf\": \"ct-bone\"}],\n"
  " \"reference\": {\"reference\": true}}\n")
art_expect_test(cli.batch_note_other_look EXIT 0 ONE_LINE_STDERR
  STDERR "job.json: note: setting 1 .* differs from the reference in tf: its error is against the reference's picture"
  ARGS batch "${CMAKE_CURRENT_BINARY_DIR}/look-job/job.json" --quiet)
art_clean_first(cli.batch_note_other_look "${CMAKE_CURRENT_BINARY_DIR}/look-job/out")
# A setting only volumes take (tets) is left out for a surface, and its frames there repeat the
# default ones: the batch says so once per setting and data set.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/kind-job/job.json"
  "{\"output\": \"out\", \"datasets\": [\"../floor.obj\"], \"size\": \"16x16\", \"cameras\": {\"orbit\": 2},\n"
  " \"settings\": [{\"tets\": 300}]}\n")
art_expect_test(cli.batch_note_option_left_out EXIT 0 ONE_LINE_STDERR
  STDERR "job.json: note: setting 0's tets does not apply to surfaces: left out for .*floor.obj"
  ARGS batch "${CMAKE_CURRENT_BINARY_DIR}/kind-job/job.json" --quiet)
art_clean_first(cli.batch_note_option_left_out "${CMAKE_CURRENT_BINARY_DIR}/kind-job/out")
art_expect_test(cli.batch_bad_setting EXIT 1 STDERR "bad_setting.json: setting 'tets' must be a number" ONE_LINE_STDERR
  ARGS batch "${_jobs}/bad_setting.json")
# A setting may not redirect a frame's image ({"output": ..} overwrote that file) or replace the
# job's size and cameras.
art_expect_test(cli.batch_own_setting EXIT 1
  STDERR "bad_own_setting.json: setting 'output' is the batch's own: it sets it for every frame" ONE_LINE_STDERR
  ARGS batch "${_jobs}/bad_own_setting.json")
art_expect_test(cli.batch_camera_setting EXIT 1
  STDERR "bad_camera_setting.json: setting 'zoom' belongs in the job's \"size\" or \"cameras\"" ONE_LINE_STDERR
  ARGS batch "${_jobs}/bad_camera_setting.json")
# batch: two data sets of one file name (here one file under two spellings; a/ct.mha and b/ct.mha
# in practice) shared their frame names, so the second was never rendered.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/same_stem.json"
  "{\"output\": \"${ART_TEST_OUTPUT}/same_stem\", \"size\": \"24x24\", \"cameras\": {\"orbit\": 1},\n"
  " \"datasets\": [\"${CMAKE_SOURCE_DIR}/data/ct-head-128.mha\", \"${CMAKE_SOURCE_DIR}/data/../data/ct-head-128.mha\"],\n"
  " \"settings\": [{\"tets\": 300, \"no-error\": true}]}\n")
art_expect_test(cli.batch_same_file_name EXIT 0 STDOUT "tasks +2 \\(2 rendered now, 0 failed\\)"
  ARGS batch --quiet "${CMAKE_CURRENT_BINARY_DIR}/same_stem.json")
art_clean_first(cli.batch_same_file_name "${ART_TEST_OUTPUT}/same_stem")
# batch: a job's reference for a tet mesh is the mesh by the exact rule (as render compares a mesh),
# as a surface's is the surface; every mesh frame failed on "--reference needs a voxel volume" and
# the batch exited 1 in a job of volumes and meshes.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/mesh_reference.json"
  "{\"output\": \"${ART_TEST_OUTPUT}/mesh_reference\", \"size\": \"24x24\", \"cameras\": {\"orbit\": 1},\n"
  " \"datasets\": [\"${CMAKE_SOURCE_DIR}/data/ct-head-128.mha\", \"${CMAKE_SOURCE_DIR}/tests/data/mixed/hex-and-triangle.vtu\"],\n"
  " \"settings\": [{\"tets\": 300, \"integrator\": \"trapezoid\"}], \"reference\": {\"reference\": true}}\n")
art_expect_test(cli.batch_mesh_reference EXIT 0 STDOUT "tasks +4 \\(4 rendered now, 0 failed\\)"
  ARGS batch --quiet "${CMAKE_CURRENT_BINARY_DIR}/mesh_reference.json")
art_clean_first(cli.batch_mesh_reference "${ART_TEST_OUTPUT}/mesh_reference")
# A misspelt key ("setting", "azimut") was ignored: the batch rendered the default setting or camera
# and reported success.
art_expect_test(cli.batch_unknown_key EXIT 1
  STDERR "bad_unknown_key.json: unknown key \"setting\" in the job \\(known: cameras, datasets, output, reference, settings, size\\)"
  ONE_LINE_STDERR ARGS batch "${_jobs}/bad_unknown_key.json")
art_expect_test(cli.batch_unknown_camera_key EXIT 1
  STDERR "bad_camera_key.json: unknown key \"azimut\" in a camera \\(known: azimuth, elevation, zoom\\)"
  ONE_LINE_STDERR ARGS batch "${_jobs}/bad_camera_key.json")
# A frame that failed (here a missing file) fails the batch again when it is run once more: the
# re-run said '0 failed' and exited 0. The renderer's error is given once, without its prefix.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/fail-job/job.json"
  "{\"datasets\": [\"../floor.obj\", \"missing.obj\"], \"size\": \"16x16\", \"cameras\": [{\"elevation\": 90}]}\n")
art_expect_test(cli.batch_failed_first EXIT 1 STDOUT "tasks +2 \\(2 rendered now, 1 failed\\)"
  STDERR "missing.obj: frame missing_c000_s00 failed: no such file or directory"
  ARGS batch "${CMAKE_CURRENT_BINARY_DIR}/fail-job/job.json")
art_clean_first(cli.batch_failed_first "${CMAKE_CURRENT_BINARY_DIR}/fail-job/frames")
set_tests_properties(cli.batch_failed_first PROPERTIES FIXTURES_SETUP batch_failed_once)
art_expect_test(cli.batch_failed_again EXIT 1
  STDOUT "tasks +2 \\(0 rendered now, 1 failed, 1 of them in an earlier run: --retry-failed renders them again\\)"
  ARGS batch "${CMAKE_CURRENT_BINARY_DIR}/fail-job/job.json")
set_tests_properties(cli.batch_failed_again PROPERTIES FIXTURES_REQUIRED batch_failed_once)
# A DICOM folder named with its trailing slash gave frames without a name ('_c000_s00.png').
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/dicom-job/job.json"
  "{\"datasets\": [\"${CMAKE_SOURCE_DIR}/tests/data/dicom-rotated/\"], \"size\": \"16x16\"}\n")
art_expect_test(cli.batch_dicom_folder EXIT 0 STDOUT "tasks +1 \\(1 rendered now, 0 failed\\)"
  ARGS batch "${CMAKE_CURRENT_BINARY_DIR}/dicom-job/job.json" --quiet)
art_clean_first(cli.batch_dicom_folder "${CMAKE_CURRENT_BINARY_DIR}/dicom-job/frames")
set_tests_properties(cli.batch_dicom_folder PROPERTIES FIXTURES_SETUP batch_dicom_done)
add_test(NAME cli.batch_dicom_folder_named COMMAND ${CMAKE_COMMAND} -E cat
  "${CMAKE_CURRENT_BINARY_DIR}/dicom-job/frames/dicom-rotated_c000_s00.result.json")
set_tests_properties(cli.batch_dicom_folder_named PROPERTIES FIXTURES_REQUIRED batch_dicom_done LABELS unit)
# A gzipped NIfTI's frames are named after "brain", not "brain.nii" (brain.nii_c000_s00); the
# CSV gives each reduced frame its reduction's time and the object's figures beside the frame's.
file(MAKE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/nii-job")
file(COPY_FILE "${CMAKE_SOURCE_DIR}/tests/data/nifti-radiological.nii" "${CMAKE_CURRENT_BINARY_DIR}/nii-job/brain.nii")
file(ARCHIVE_CREATE OUTPUT "${CMAKE_CURRENT_BINARY_DIR}/nii-job/brain.nii.gz"
  PATHS "${CMAKE_CURRENT_BINARY_DIR}/nii-job/brain.nii" FORMAT raw COMPRESSION GZip)
file(REMOVE "${CMAKE_CURRENT_BINARY_DIR}/nii-job/brain.nii")
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/nii-job/job.json"
  "{\"output\": \"frames\", \"datasets\": [\"brain.nii.gz\"], \"size\": \"16x16\", \"cameras\": {\"orbit\": 1},\n"
  " \"settings\": [{\"tets\": 12}], \"reference\": {\"reference\": true}}\n")
art_expect_test(cli.batch_gz_stem EXIT 0 STDOUT "tasks +2 \\(2 rendered now, 0 failed\\)"
  ARGS batch "${CMAKE_CURRENT_BINARY_DIR}/nii-job/job.json" --quiet)
art_clean_first(cli.batch_gz_stem "${CMAKE_CURRENT_BINARY_DIR}/nii-job/frames")
set_tests_properties(cli.batch_gz_stem PROPERTIES FIXTURES_SETUP batch_gz_done)
add_test(NAME cli.batch_gz_stem_csv COMMAND ${CMAKE_COMMAND}
  "-DCSV=${CMAKE_CURRENT_BINARY_DIR}/nii-job/frames/results.csv" -P "${CMAKE_CURRENT_LIST_DIR}/batch_csv_check.cmake")
set_tests_properties(cli.batch_gz_stem_csv PROPERTIES FIXTURES_REQUIRED batch_gz_done LABELS unit)
# A job file edited between runs (a setting changed) kept the frames of the old setting as done.
# Two job files share one output folder and frame names; the second's frame is rendered again.
foreach(_o 1 0.5)
  file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/edit-job/job-${_o}.json" "{\"datasets\": [\"../floor.obj\"], \"size\": \"16x16\", "
    "\"cameras\": [{\"elevation\": 90}], \"settings\": [{\"opacity\": ${_o}}]}\n")
endforeach()
art_expect_test(cli.batch_edited_first EXIT 0 STDOUT "tasks +1 \\(1 rendered now, 0 failed\\)"
  ARGS batch "${CMAKE_CURRENT_BINARY_DIR}/edit-job/job-1.json")
art_clean_first(cli.batch_edited_first "${CMAKE_CURRENT_BINARY_DIR}/edit-job/frames")
set_tests_properties(cli.batch_edited_first PROPERTIES FIXTURES_SETUP batch_edited_once)
art_expect_test(cli.batch_edited_again EXIT 0 STDOUT "tasks +1 \\(1 rendered now, 0 failed\\)"
  STDERR "job-0.5.json: 1 frame in .*frames was rendered with other settings: rendering again"
  ARGS batch "${CMAKE_CURRENT_BINARY_DIR}/edit-job/job-0.5.json")
set_tests_properties(cli.batch_edited_again PROPERTIES FIXTURES_REQUIRED batch_edited_once)
# cameras.orbit 2.5 rendered 2 frames without a word.
art_expect_test(cli.batch_fractional_orbit EXIT 1
  STDERR "bad_orbit.json: cameras.orbit must be a whole number 1..100000, got 2.5" ONE_LINE_STDERR
  ARGS batch "${_jobs}/bad_orbit.json")
# batch: a setting's transfer-function file is relative to the job file, as its data sets and
# output are (run here from the test's folder, not the job's); it was taken relative to the folder
# the batch ran in, and every frame failed with "cannot open transfer-function file".
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/tf-beside-job/bone.tf" "-1000 0 0 0 0\n300 1 0.9 0.8 0.05\n2000 1 1 1 0.6\n")
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/tf-beside-job/job.json"
  "{\"output\": \"${ART_TEST_OUTPUT}/tf_beside_job\", \"size\": \"24x24\", \"cameras\": {\"orbit\": 1},\n"
  " \"datasets\": [\"${CMAKE_SOURCE_DIR}/data/ct-head-128.mha\"],\n"
  " \"settings\": [{\"tets\": 300, \"tf\": \"bone.tf\", \"no-error\": true}, {\"tets\": 300, \"tf\": \"grey-ramp\", \"no-error\": true}]}\n")
art_expect_test(cli.batch_tf_beside_job EXIT 0 STDOUT "tasks +2 \\(2 rendered now, 0 failed\\)"
  ARGS batch --quiet "${CMAKE_CURRENT_BINARY_DIR}/tf-beside-job/job.json")
art_clean_first(cli.batch_tf_beside_job "${ART_TEST_OUTPUT}/tf_beside_job")
# batch: a data set's frames that fail alike (a missing file fails every camera and setting: 120
# lines for 40 cameras) are named once and then counted; the good data set's frames still render.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/failed-alike.json"
  "{\"output\": \"${ART_TEST_OUTPUT}/failed_alike\", \"size\": \"16x16\", \"cameras\": {\"orbit\": 3},\n"
  " \"datasets\": [\"${_tetdata}/two-tets.vtu\", \"missing.vtu\"],\n"
  " \"settings\": [{\"tf\": \"grey-ramp\", \"no-error\": true}]}\n")
art_expect_test(cli.batch_failed_alike EXIT 1 STDOUT "tasks +6 \\(6 rendered now, 3 failed\\)"
  STDERR "frame missing_c000_s00 failed: no such file or directory[^a-z]+adaptivert: [^ ]*missing.vtu: 2 more frames failed alike \\(no such file or directory\\)"
  ARGS batch --quiet "${CMAKE_CURRENT_BINARY_DIR}/failed-alike.json")
art_clean_first(cli.batch_failed_alike "${ART_TEST_OUTPUT}/failed_alike")
# A setting's key render does not know ("name") is one line before any frame; every frame failed
# with render's 'unknown option --name' after the job had started. A '_' key is a comment.
art_expect_test(cli.batch_setting_not_an_option EXIT 1
  STDERR "bad_setting_option.json: setting 'name' is not a render option \\(a setting's keys are render's long options"
  ONE_LINE_STDERR ARGS batch "${_jobs}/bad_setting_option.json")
add_test(NAME batch.resume_share_results COMMAND bash "${CMAKE_CURRENT_LIST_DIR}/batch_check.sh"
  "$<TARGET_FILE:adaptivert>" "${CMAKE_SOURCE_DIR}" "${ART_TEST_OUTPUT}/batch")
set_tests_properties(batch.resume_share_results PROPERTIES LABELS "image;slow" TIMEOUT 600)
