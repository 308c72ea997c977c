# `adaptivert bench`: its usage (the benchmarks themselves are not tests).

# bench --runs 0 ran the whole benchmark as if it were 1.
art_expect_test(cli.bench_zero_runs EXIT 2 STDERR "--runs expects 1..1000 timed runs, got '0'" ONE_LINE_STDERR
  ARGS bench triangles --runs 0)
art_expect_test(cli.bench_results_is_a_file EXIT 1 STDERR "README.md: cannot make the results folder" ONE_LINE_STDERR
  ARGS bench triangles --runs 1 --results "${CMAKE_SOURCE_DIR}/README.md")
