# `adaptivert tetrahedralize` (AdaptiveRT::Meshing, TetGen): a closed torus meshed to its volume;
# open, self-intersecting and non-surface inputs refused in one line, before TetGen sees them.
set(_mesh "${CMAKE_SOURCE_DIR}/tests/data/meshing")
art_expect_test(cli.tetrahedralize_torus EXIT 0
  STDOUT "input +.*torus.ply \\(1,536 triangles, 768 points: closed, manifold, no self-intersection; encloses 3.0689.*volume 3.0689[0-9]* \\(100.000% of the surface's\\).*0 inverted"
  ARGS tetrahedralize "${_mesh}/torus.ply" "${_out}/torus.vtu" --tets 5000 --quiet)
art_expect_test(cli.tetrahedralize_json EXIT 0 STDOUT "^\\{\"input\":.*\"triangles\":1536,.*\"tets\":[0-9]+,"
  ARGS tetrahedralize "${_mesh}/torus.ply" -o "${_out}/torus_json.vtu" --max-volume 0.01 --json --quiet)
art_expect_test(cli.tetrahedralize_open EXIT 1
  STDERR "^adaptivert: [^ ]*torus-open.ply: is not a closed surface: 3 open edges \\(edges of only one triangle" ONE_LINE_STDERR
  ARGS tetrahedralize "${_mesh}/torus-open.ply" "${_out}/never.vtu" --tets 5000 --quiet)
art_expect_test(cli.tetrahedralize_self_intersecting EXIT 1
  STDERR "^adaptivert: [^ ]*tori-crossing.ply: intersects itself: [0-9]+ pairs of triangles cross or touch" ONE_LINE_STDERR
  ARGS tetrahedralize "${_mesh}/tori-crossing.ply" "${_out}/never.vtu" --tets 5000 --quiet)
art_expect_test(cli.tetrahedralize_volume_input EXIT 1
  STDERR "sphere-32.mha: is a volume; tetrahedralize takes a closed surface" ONE_LINE_STDERR
  ARGS tetrahedralize "${_mesh}/sphere-32.mha" "${_out}/never.vtu" --tets 5000)
art_expect_test(cli.tetrahedralize_no_budget EXIT 2 STDERR "give --tets N or --max-volume V" ONE_LINE_STDERR
  ARGS tetrahedralize "${_mesh}/torus.ply" "${_out}/never.vtu")
art_expect_test(cli.tetrahedralize_help EXIT 0 STDOUT "examples:.*adaptivert tetrahedralize" ARGS tetrahedralize --help)
# A budget below what the surface itself needs is said, not met silently.
art_expect_test(cli.tetrahedralize_budget_below_surface EXIT 0
  STDOUT "output .*torus_small.vtu \\(more tets than --tets: TetGen's quality bounds on this surface alone ask for that many\\)"
  ARGS tetrahedralize "${_mesh}/torus.ply" "${_out}/torus_small.vtu" --tets 500 --quiet)
