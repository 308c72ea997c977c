# `adaptivert compare`: image metrics with known answers.

# levels_plus16.png is levels.png with RGB + 16/255, both opaque (alpha left out):
# RMSE = 16/255 = 0.062745, PSNR = 24.048 dB.
art_expect_test(cli.compare_identical EXIT 0 STDOUT "RMSE +0.000000.*PSNR +inf dB.*SSIM +1.00000"
  ARGS compare "${_img}/levels.png" "${_img}/levels.png")
art_expect_test(cli.compare_known_offset EXIT 0 STDOUT "\"rmse\":0.06274.*\"psnr_db\":24.04.*\"channels\":\"RGB\""
  ARGS compare --json "${_img}/levels.png" "${_img}/levels_plus16.png")
art_expect_test(cli.compare_threshold_fails EXIT 1 STDERR "levels_plus16.png: differs from .*PSNR below 30 dB" ONE_LINE_STDERR
  ARGS compare --quiet --min-psnr 30 "${_img}/levels.png" "${_img}/levels_plus16.png")
art_expect_test(cli.compare_size_mismatch EXIT 1 STDERR "size 8x8 differs" ONE_LINE_STDERR
  ARGS compare "${_img}/levels.png" "${_img}/small.png")
art_expect_test(cli.compare_bad_image EXIT 1 STDERR "random.ply: cannot read image" ONE_LINE_STDERR
  ARGS compare "${_img}/levels.png" "${_bad}/random.ply")
# compare --diff naming one of the inputs replaced it with the difference image: refused. The
# inputs are copies, so a regression cannot damage the committed images.
add_test(NAME cli.compare_diff_copy COMMAND ${CMAKE_COMMAND} -E copy "${_img}/levels.png" "${_img}/levels_plus16.png"
  "${ART_TEST_OUTPUT}/")
set_tests_properties(cli.compare_diff_copy PROPERTIES FIXTURES_SETUP compare_copies LABELS unit)
art_expect_test(cli.compare_diff_is_input EXIT 2 STDERR "--diff .*levels_plus16.png is one of the images compared"
  ONE_LINE_STDERR ARGS compare "${ART_TEST_OUTPUT}/levels.png" "${ART_TEST_OUTPUT}/levels_plus16.png"
  --diff "${ART_TEST_OUTPUT}/../Temporary/levels_plus16.png")
set_tests_properties(cli.compare_diff_is_input PROPERTIES FIXTURES_REQUIRED compare_copies)
# One pair of images has one PSNR: render's figures equal compare's on the PNGs it wrote (within
# 0.05 dB of 8-bit rounding), whole frame and object alike, on a coloured background.
add_test(NAME cli.compare_equals_render COMMAND ${CMAKE_COMMAND} "-DART=$<TARGET_FILE:adaptivert>"
  "-DDATA=${_ct}" "-DOUT=${ART_TEST_OUTPUT}/one-psnr" -P "${CMAKE_CURRENT_LIST_DIR}/one_psnr_check.cmake")
set_tests_properties(cli.compare_equals_render PROPERTIES LABELS unit)
