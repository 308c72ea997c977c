# `adaptivert demo`: the main job on the embedded data.

# demo -i reduces a volume: a mesh or a surface was refused with '--tets does not apply to a
# surface', an option the user never gave. Now one usage line naming the kind and render.
art_expect_test(cli.demo_surface_input EXIT 2
  STDERR "--input must be a volume \\(the demo reduces it\\); '.*am_underworks.ply' is a surface: render it with"
  ONE_LINE_STDERR ARGS demo -i "${CMAKE_SOURCE_DIR}/data/am_underworks.ply" -o "${ART_TEST_OUTPUT}/never.png")
art_expect_test(cli.demo_mesh_input EXIT 2 STDERR "'.*two-tets.vtu' is a mesh: render it with 'adaptivert render"
  ONE_LINE_STDERR ARGS demo -i "${_tetdata}/two-tets.vtu"
  -o "${ART_TEST_OUTPUT}/never.png")
