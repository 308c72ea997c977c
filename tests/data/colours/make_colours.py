# Writes a unit cube whose six faces are coloured, twice: colours on the faces (face-colours.ply,
# as MeshLab and CAD exports write them) and the same colours on corners of each face's own
# (corner-colours.ply). Both must render alike; the baseline is rendered from the second.
P = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
F = [([0, 3, 2, 1], (255, 0, 0)), ([4, 5, 6, 7], (0, 255, 0)), ([0, 1, 5, 4], (0, 0, 255)),
     ([1, 2, 6, 5], (255, 255, 0)), ([2, 3, 7, 6], (0, 255, 255)), ([3, 0, 4, 7], (255, 0, 255))]
HEAD = "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
with open("face-colours.ply", "w") as f:
    f.write(HEAD.format(len(P)) + "element face 6\nproperty list uchar int vertex_indices\n"
            "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n")
    f.writelines("%g %g %g\n" % p for p in P)
    f.writelines("4 %d %d %d %d %d %d %d\n" % (*q, *c) for q, c in F)
with open("corner-colours.ply", "w") as f:
    f.write(HEAD.format(24) + "property uchar red\nproperty uchar green\nproperty uchar blue\n"
            "element face 6\nproperty list uchar int vertex_indices\nend_header\n")
    for q, c in F:
        f.writelines("%g %g %g %d %d %d\n" % (*P[i], *c) for i in q)
    f.writelines("4 %d %d %d %d\n" % tuple(range(4 * k, 4 * k + 4)) for k in range(6))
# The same cube as an OBJ whose faces take their colours from materials (cube.mtl, Kd), as
# SketchUp, Blender and CAD exports write them; two libraries on one mtllib line.
NAMES = ["red", "green", "blue", "yellow", "cyan", "magenta"]
with open("cube.obj", "w") as f:
    f.write("mtllib cube.mtl more.mtl\n")
    f.writelines("v %g %g %g\n" % p for p in P)
    for (q, c), name in zip(F, NAMES):
        f.write("usemtl %s\nf %d %d %d %d\n" % (name, *[i + 1 for i in q]))
with open("cube.mtl", "w") as f:
    for (q, c), name in list(zip(F, NAMES))[:3]:
        f.write("newmtl %s\nKa 0 0 0\nKd %g %g %g\n" % (name, *[x / 255 for x in c]))
with open("more.mtl", "w") as f:
    for (q, c), name in list(zip(F, NAMES))[3:]:
        f.write("newmtl %s\nKd %g %g %g\n" % (name, *[x / 255 for x in c]))
