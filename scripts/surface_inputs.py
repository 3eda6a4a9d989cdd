#!/usr/bin/env python3
"""Inputs of docs/surface.md's pictures (scripts/surface_pictures.sh).

surface_inputs.py DIR writes DIR/torus.obj (a torus of radii 1 and 0.4,
96 x 48 quads as triangles) and DIR/torus-density.csv (one density a vertex:
1 on the inner side of the tube rising to 6 on the outer rim).

surface_inputs.py --project IN.csv OUT.csv turns pds's surface samples
(x,y,z,nx,ny,nz,face) into the plane of a picture: the torus turned 60
degrees about the x axis, orthographic, keeping the samples whose normal
faces the viewer, mapped into the unit square.
"""
import math
import sys


def torus(path, density_path, around=96, tube=48, big=1.0, small=0.4):
    with open(path, "w") as obj, open(density_path, "w") as dens:
        dens.write("density\n")
        for i in range(around):
            for j in range(tube):
                u = 2 * math.pi * i / around
                v = 2 * math.pi * j / tube
                ring = big + small * math.cos(v)
                obj.write("v %.17g %.17g %.17g\n" % (ring * math.cos(u), ring * math.sin(u), small * math.sin(v)))
                dens.write("%.17g\n" % (3.5 + 2.5 * math.cos(v)))
        at = lambda i, j: (i % around) * tube + (j % tube) + 1
        for i in range(around):
            for j in range(tube):
                obj.write("f %d %d %d\n" % (at(i, j), at(i + 1, j), at(i + 1, j + 1)))
                obj.write("f %d %d %d\n" % (at(i, j), at(i + 1, j + 1), at(i, j + 1)))


def project(src, dst, tilt=math.radians(60)):
    c, s = math.cos(tilt), math.sin(tilt)
    with open(src) as f, open(dst, "w") as out:
        out.write("x,y\n")
        next(f)
        for line in f:
            x, y, z, nx, ny, nz, _ = (float(t) for t in line.split(","))
            # Rotate about x: y' = c y - s z, z' = s y + c z (z' toward the viewer).
            if s * ny + c * nz <= 0:
                continue
            px, py = x, c * y - s * z
            out.write("%.17g,%.17g\n" % (0.5 + px / 2.9, 0.5 + py / 2.9))


if __name__ == "__main__":
    if sys.argv[1] == "--project":
        project(sys.argv[2], sys.argv[3])
    else:
        import os

        os.makedirs(sys.argv[1], exist_ok=True)
        torus(os.path.join(sys.argv[1], "torus.obj"), os.path.join(sys.argv[1], "torus-density.csv"))
