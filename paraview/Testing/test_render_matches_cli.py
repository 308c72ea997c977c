"""pvbatch: the plugin's reducer gives the default CT the tets and errors `adaptivert reduce`
gives it, and 'Tet Ray Cast Volume' draws a mesh as `adaptivert render` draws it with the same
camera and transfer function (PSNR >= MIN_PSNR_CLI dB), and as vtkTetRayCastMapper draws it in a
window of the project's own VTK (>= MIN_PSNR_WINDOW dB: what ParaView adds). The first bound is
lower because the mapper's window image is its own engine image stretched by one pixel in 400
(the textured quad), in any VTK window; ParaView's is the same. The caster's settings on the
display (trapezoid rule, an iso-surface, early ray termination) draw what render's options draw,
and each changes the image (PSNR against the default below MAX_PSNR_CHANGED dB)."""
import os
import sys

from paraview.simple import AdaptiveTetReducer, Hide, OpenDataFile, SaveData

import art_pv

MIN_PSNR_CLI = 40.0
MIN_PSNR_WINDOW = 50.0
MIN_PSNR_SETTINGS = 35.0
MAX_PSNR_CHANGED = 35.0
# (label, display settings, render's options, bound against the VTK window): early termination
# is a threshold, so a pixel whose opacity reaches it in another tet than in the window ends
# elsewhere; the bound is lower.
SETTINGS = (("trapezoid", {"Integrator": "Trapezoid"}, ["--integrator", "trapezoid"], MIN_PSNR_WINDOW),
            ("iso-300", {"IsoValues": [300], "IsoOpacity": 0.8}, ["--iso", "300", "--iso-opacity", "0.8"],
             MIN_PSNR_WINDOW),
            ("ert-0.8", {"EarlyRayTermination": 0.8}, ["--ert", "0.8"], 40.0))
TETS = 30000
SIZE = (400, 400)
out = os.path.join(art_pv.OUTPUT, "pv-render")
os.makedirs(out, exist_ok=True)
cli_mesh, cli_png = os.path.join(out, "cli.vtu"), os.path.join(out, "cli.png")
art_pv.adaptivert("reduce", art_pv.DEFAULT_CT, cli_mesh, "--tets", str(TETS), "--tf", art_pv.TF_FILE, "--quiet")
camera = art_pv.render_json(cli_mesh, "-o", cli_png, "--tf", art_pv.TF_FILE, "--size", "%dx%d" % SIZE, "--no-error",
                            "--quiet")["camera"]

# The reducer in ParaView, weighted by the same opacities: the same mesh.
reader = OpenDataFile(art_pv.DEFAULT_CT)
reducer = AdaptiveTetReducer(Input=reader)
reducer.Scalars = ["POINTS", "MetaImage"]
reducer.TargetTets = TETS
reducer.TransferFunctionWeighting = art_pv.opacity_function("MetaImage")
pv_mesh = os.path.join(out, "pv.vtu")
SaveData(pv_mesh, proxy=reducer)
ours, theirs = OpenDataFile(pv_mesh), OpenDataFile(cli_mesh)
fails = []
for name in ("tets", "vertices", "rms_error", "weighted_rms_error", "max_error"):
    a, b = ours.FieldData[name].GetRange()[0], theirs.FieldData[name].GetRange()[0]
    print("%-20s plugin %-10.6g adaptivert reduce %.6g" % (name, a, b))
    if abs(a - b) > 1e-9 * max(1.0, abs(b)):
        fails.append(name)

# 'Tet Ray Cast Volume' of the CLI's mesh and of the plugin's own reduction.
window_png = None
for label, source in (("cli-mesh", theirs), ("plugin-reduction", reducer)):
    view, display = art_pv.show_tets(source, "MetaImage", SIZE)
    art_pv.camera_of_render(view, camera)
    png = art_pv.screenshot(view, os.path.join(out, "pv-%s.png" % label), SIZE)
    if window_png is None:
        window_png = art_pv.vtk_window_render(cli_mesh, os.path.join(out, "vtk-window.png"), view, SIZE)
    Hide(source, view)
    for against, path, bound in (("adaptivert render", cli_png, MIN_PSNR_CLI),
                                 ("the mapper in a VTK window", window_png, MIN_PSNR_WINDOW)):
        code, f = art_pv.compare(png, path, bound)
        print("%-17s against %-27s PSNR %6.2f dB (bound %.0f), max |diff| %.4f, SSIM %.5f"
              % (label, against + ":", f.get("psnr_db", 0), bound, f.get("max_abs", 1), f.get("ssim", 0)))
        if code != 0:
            fails.append("%s vs %s" % (label, against))
# The caster's settings, on the CLI's mesh: as in a VTK window with the same settings, as render
# draws them (to MIN_PSNR_SETTINGS: the stretched quad weighs more on iso-surfaces' edges), and
# unlike the default image.
default_png = os.path.join(out, "pv-cli-mesh.png")
for label, settings, options, window_bound in SETTINGS:
    cli = os.path.join(out, "cli-%s.png" % label)
    shown = art_pv.render_json(cli_mesh, "-o", cli, "--tf", art_pv.TF_FILE, "--size", "%dx%d" % SIZE, "--no-error",
                               "--quiet", *options)["camera"]
    view, display = art_pv.show_tets(theirs, "MetaImage", SIZE, **settings)
    art_pv.camera_of_render(view, shown)
    png = art_pv.screenshot(view, os.path.join(out, "pv-%s.png" % label), SIZE)
    window = art_pv.vtk_window_render(cli_mesh, os.path.join(out, "vtk-window-%s.png" % label), view, SIZE,
                                      options=options)
    Hide(theirs, view)
    for against, path, bound in (("the mapper in a VTK window", window, window_bound),
                                 ("adaptivert render", cli, MIN_PSNR_SETTINGS)):
        code, f = art_pv.compare(png, path, bound)
        print("%-9s (%s) against %-27s PSNR %6.2f dB (bound %.0f)"
              % (label, " ".join(options), against + ":", f.get("psnr_db", 0), bound))
        if code != 0:
            fails.append("%s vs %s" % (label, against))
    _, g = art_pv.compare(png, default_png, 0)
    print("%-9s against the default settings' image: PSNR %.2f dB (below %.0f)" % (label, g.get("psnr_db", 99),
                                                                                  MAX_PSNR_CHANGED))
    if not g.get("psnr_db", 99) < MAX_PSNR_CHANGED:
        fails.append("%s did not change the image" % label)
if fails:
    sys.exit("differs: " + ", ".join(fails))
print("ok")
