#!/usr/bin/env python3
"""Convert a Quake-3 BSP map (IBSP v46) to a binary little-endian PLY of triangles.

Usage: bsp2ply.py MAP.bsp OUT.ply
       bsp2ply.py PAK.pk3 maps/NAME.bsp OUT.ply   (read the map straight from a pk3/zip)

Only numpy and the standard library are needed (no VTK), so data/fetch can run it early.

Output layout (chosen to reproduce ../shared/data/*.ply byte for byte):
  * vertices: the whole BSP vertex lump (positions only, float32), in lump order,
    including vertices of dropped faces, followed by 5x5 tessellated vertices of
    every kept Bezier sub-patch;
  * faces: in BSP face order; types 1 (polygon) and 3 (mesh) give triangles
    `first_vertex + meshvert[first_meshvert + k]`; type 2 (patch) gives 32
    triangles per 3x3 biquadratic sub-patch; type 4 (billboards) is ignored;
  * faces whose texture has surface flag 0x4 (SURF_SKY) or 0x80 (SURF_NODRAW)
    are dropped: they are invisible, and the sky box would swamp the level bounds.
"""
import os
import struct
import sys
import zipfile

import numpy as np

STEPS = 4  # tessellation steps per sub-patch side -> (STEPS+1)^2 vertices
SURF_SKY, SURF_NODRAW = 0x4, 0x80

TEXTURE = np.dtype([("name", "S64"), ("flags", "<i4"), ("contents", "<i4")])
VERTEX = np.dtype([("pos", "<f4", 3), ("tc", "<f4", 4), ("normal", "<f4", 3), ("color", "u1", 4)])
FACE = np.dtype([
    ("texture", "<i4"), ("effect", "<i4"), ("type", "<i4"),
    ("vertex", "<i4"), ("n_vertexes", "<i4"), ("meshvert", "<i4"), ("n_meshverts", "<i4"),
    ("lm_index", "<i4"), ("lm_start", "<i4", 2), ("lm_size", "<i4", 2),
    ("lm_origin", "<f4", 3), ("lm_vecs", "<f4", 6), ("normal", "<f4", 3), ("size", "<i4", 2),
])
assert TEXTURE.itemsize == 72 and VERTEX.itemsize == 44 and FACE.itemsize == 104


def lump(data, index, dtype):
    offset, length = struct.unpack_from("<ii", data, 8 + 8 * index)
    if length % np.dtype(dtype).itemsize:
        raise ValueError(f"lump {index}: length {length} is not a multiple of {np.dtype(dtype).itemsize}")
    return np.frombuffer(data, dtype=dtype, count=length // np.dtype(dtype).itemsize, offset=offset)


def bezier_weights(steps):
    """Quadratic Bernstein weights, shape (steps+1, 3), evaluated in float64."""
    t = np.arange(steps + 1, dtype=np.float64) / steps
    return np.stack([(1 - t) ** 2, 2 * t * (1 - t), t ** 2], axis=1)


def tessellate_patch(ctrl, width, height, steps=STEPS):
    """Split a width x height control grid into 3x3 sub-patches (sharing edges)
    and tessellate each one on its own: returns (vertices, local triangles)."""
    grid = ctrl.reshape(height, width, 3).astype(np.float64)
    w = bezier_weights(steps)
    n = steps + 1
    a, b = np.meshgrid(np.arange(steps), np.arange(steps), indexing="ij")
    p = (a * n + b).ravel()
    # two triangles per quad, quads ordered with a (u, across columns) outermost
    quad = np.stack([np.stack([p, p + n, p + 1], 1), np.stack([p + 1, p + n, p + n + 1], 1)], 1).reshape(-1, 3)
    verts, tris = [], []
    for py in range((height - 1) // 2):
        for px in range((width - 1) // 2):
            c = grid[2 * py:2 * py + 3, 2 * px:2 * px + 3]  # [row(v), col(u), xyz]
            # vertex (i, j) = sum_r sum_k w[i,k] w[j,r] c[r,k]: i steps along u, j along v
            pts = np.einsum("ik,jr,rkx->ijx", w, w, c).reshape(-1, 3)
            tris.append(quad + n * n * len(verts))
            verts.append(pts)
    return np.concatenate(verts), np.concatenate(tris)


def convert(data):
    if data[:4] != b"IBSP" or struct.unpack_from("<i", data, 4)[0] != 46:
        raise ValueError("not a Quake-3 IBSP version 46 map")
    textures = lump(data, 1, TEXTURE)
    vertexes = lump(data, 10, VERTEX)
    meshverts = lump(data, 11, "<i4")
    faces = lump(data, 13, FACE)

    positions = [vertexes["pos"].astype(np.float32)]
    n_points = len(vertexes)
    triangles = []
    hidden = (textures["flags"] & (SURF_SKY | SURF_NODRAW)) != 0
    for f in faces:
        if hidden[f["texture"]]:
            continue
        if f["type"] in (1, 3):
            idx = f["vertex"] + meshverts[f["meshvert"]:f["meshvert"] + f["n_meshverts"]]
            triangles.append(idx.reshape(-1, 3))
        elif f["type"] == 2:
            width, height = (int(s) for s in f["size"])
            ctrl = vertexes["pos"][f["vertex"]:f["vertex"] + f["n_vertexes"]]
            pts, tris = tessellate_patch(ctrl, width, height)
            positions.append(pts.astype(np.float32))
            triangles.append(tris + n_points)
            n_points += len(pts)
    points = np.concatenate(positions)
    tris = np.concatenate(triangles).astype("<i4") if triangles else np.zeros((0, 3), "<i4")
    return points, tris


def write_ply(path, points, tris, comment):
    rec = np.zeros(len(tris), dtype=np.dtype([("n", "u1"), ("i", "<i4", 3)]))
    rec["n"] = 3
    rec["i"] = tris
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        f"comment {comment}\n"
        f"element vertex {len(points)}\n"
        "property float x\nproperty float y\nproperty float z\n"
        f"element face {len(tris)}\n"
        "property list uchar int vertex_indices\nend_header\n"
    )
    with open(path, "wb") as out:
        out.write(header.encode("ascii"))
        out.write(points.astype("<f4").tobytes())
        out.write(rec.tobytes())


def main(argv):
    if len(argv) == 3:
        src, dst = argv[1], argv[2]
        with open(src, "rb") as fh:
            data = fh.read()
    elif len(argv) == 4:
        src, dst = argv[2], argv[3]
        with zipfile.ZipFile(argv[1]) as pk3:
            data = pk3.read(src)
    else:
        sys.exit(__doc__.strip().split("\n\n")[1])
    points, tris = convert(data)
    write_ply(dst, points, tris, f"converted from {os.path.basename(src)}")
    print(f"{src}: {len(points)} vertices, {len(tris)} triangles")


if __name__ == "__main__":
    main(sys.argv)
