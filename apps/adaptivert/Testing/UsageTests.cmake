# Usage, help and the exit codes every command shares.

# Usage and help.
art_expect_test(cli.help EXIT 0 STDOUT "info" ARGS --help)
art_expect_test(cli.no_args EXIT 2 STDOUT "usage" ARGS)
art_expect_test(cli.unknown_command EXIT 2 STDERR "unknown command 'frobnicate'" ONE_LINE_STDERR ARGS frobnicate)
# An unknown option near a declared one names it: a typo, or a name cut short.
art_expect_test(cli.unknown_option_suggests EXIT 2 ONE_LINE_STDERR
  STDERR "unknown option '--tet' \\(did you mean --tets\\?\\)" ARGS render x.mha -o x.png --tet 100)
art_expect_test(cli.unknown_option_far EXIT 2 ONE_LINE_STDERR
  STDERR "unknown option '--bogus' \\(try" ARGS render x.mha -o x.png --bogus 100)
# The formats read are listed once (art::InputFormats) and shown by both programs' help: the
# viewer's listed .nhdr and the CLI's listed none.
art_expect_test(cli.help_lists_inputs EXIT 0 STDOUT "inputs \\(by extension\\): +volumes +[^ ]* .*\\.nhdr.* surfaces +\\.ply.* meshes +\\.vtu"
  ARGS --help)
