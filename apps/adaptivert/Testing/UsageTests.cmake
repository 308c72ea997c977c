# Usage, help and the exit codes every command shares.

# Usage and help.
art_expect_test(cli.help EXIT 0 STDOUT "info" ARGS --help)
art_expect_test(cli.no_args EXIT 2 STDOUT "usage" ARGS)
art_expect_test(cli.unknown_command EXIT 2 STDERR "unknown command 'frobnicate'" ONE_LINE_STDERR ARGS frobnicate)
