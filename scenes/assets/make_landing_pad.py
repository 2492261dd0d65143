#!/usr/bin/env python3
"""Writes landing_pad.obj + landing_pad.mtl: a 4 m octagonal helipad, 0.1 m thick, with a raised white
"H" and a yellow ring. Axes y_up (x east, y up, z south), the glTF/OBJ convention airis reads by default;
origin at the centre of the pad's underside. Run from this folder: python3 make_landing_pad.py"""
import math

vertices, faces = [], []  # faces: (material, [vertex indices, 1-based, counter-clockwise from outside])


def add_prism(outline, y0, y1, material):
    """Extrudes a convex-or-not polygon (x, z pairs, counter-clockwise seen from above, +y) from y0 to y1."""
    base = len(vertices)
    for x, z in outline:
        vertices.append((x, y0, z))
    for x, z in outline:
        vertices.append((x, y1, z))
    n = len(outline)
    faces.append((material, [base + n + i + 1 for i in range(n)]))                # top, facing +y
    faces.append((material, [base + i + 1 for i in reversed(range(n))]))          # bottom, facing -y
    for i in range(n):
        j = (i + 1) % n
        faces.append((material, [base + i + 1, base + j + 1, base + n + j + 1, base + n + i + 1]))


def ccw_from_above(points):
    """Seen from +y looking down, x east and z south: counter-clockwise means decreasing angle in (x, z)."""
    return list(reversed(points))


def box(x0, x1, z0, z1, y0, y1, material):
    add_prism(ccw_from_above([(x0, z0), (x1, z0), (x1, z1), (x0, z1)]), y0, y1, material)


radius, thickness = 2.0, 0.1
octagon = [(radius * math.cos(math.pi / 8 + k * math.pi / 4), radius * math.sin(math.pi / 8 + k * math.pi / 4))
           for k in range(8)]
add_prism(ccw_from_above(octagon), 0.0, thickness, "pad")
top, mark = thickness, thickness + 0.01
# The H: two uprights and a bar, 1.6 m tall (along z) and 1.0 m wide (along x).
box(-0.5, -0.3, -0.8, 0.8, top, mark, "marking")
box(0.3, 0.5, -0.8, 0.8, top, mark, "marking")
box(-0.3, 0.3, -0.1, 0.1, top, mark, "marking")
# The ring: 16 short segments.
for k in range(16):
    a0, a1 = k * math.pi / 8, (k + 1) * math.pi / 8
    r0, r1 = 1.55, 1.75
    quad = [(r0 * math.cos(a0), r0 * math.sin(a0)), (r1 * math.cos(a0), r1 * math.sin(a0)),
            (r1 * math.cos(a1), r1 * math.sin(a1)), (r0 * math.cos(a1), r0 * math.sin(a1))]
    add_prism(ccw_from_above(quad), top, mark, "ring")

with open("landing_pad.mtl", "w") as f:
    f.write("# Materials of landing_pad.obj (written by make_landing_pad.py)\n")
    for name, rgb in (("pad", (0.25, 0.27, 0.3)), ("marking", (0.95, 0.95, 0.95)), ("ring", (0.95, 0.75, 0.1))):
        f.write(f"newmtl {name}\nKd {rgb[0]} {rgb[1]} {rgb[2]}\nKa 0 0 0\nKs 0.1 0.1 0.1\nNs 10\nillum 2\n\n")

with open("landing_pad.obj", "w") as f:
    f.write("# 4 m helipad, y up, metres (written by make_landing_pad.py)\nmtllib landing_pad.mtl\no landing_pad\n")
    for v in vertices:
        f.write("v %.4f %.4f %.4f\n" % v)
    current = None
    for material, idx in faces:
        if material != current:
            f.write(f"usemtl {material}\n")
            current = material
        f.write("f " + " ".join(str(i) for i in idx) + "\n")
