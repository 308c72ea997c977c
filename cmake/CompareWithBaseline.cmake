# Checks image OUT against a committed BASELINE with `adaptivert compare`, writing OUT.diff.png;
# the test fails when PSNR or SSIM fall below the floors. Included by the -P test scripts.
function(art_compare_with_baseline art out baseline min_psnr min_ssim)
  execute_process(COMMAND "${art}" compare "${out}" "${baseline}" --min-psnr ${min_psnr} --min-ssim ${min_ssim}
    --diff "${out}.diff.png" RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 60)
  message(STATUS "${o}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${out} differs from ${baseline} (${rc}):\n${o}\n${e}")
  endif()
endfunction()
