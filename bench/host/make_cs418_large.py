#!/usr/bin/env python3
"""Writes one of the large CS418 scenes of the speed benchmark. They are of
the kind of the course's own large examples (an 800x800 field of 10,000
small spheres, spirals of overlapping growing spheres, a triangle model
lit with global illumination), generated here; deterministic (fixed seed).

  spheres  800x800, 10,000 spheres of radius 0.02 in a box in front of the
           eye, two suns, a shiny rough floor, shininess 0.25 and roughness
           0.2 on every sphere, aa 40, bounces 16, dof
  spiral   800x800, ten spirals of 500 spheres each whose radius grows to 1
           as they descend (neighbours overlap: hard to bound), moved eye,
           aa 20, bounces 16
  chair    800x800, a chair of about 1,700 triangles over shared vertices
           (seat, back slats and legs as subdivided boxes and cylinders), a
           glass and a mirror sphere, fisheye, expose, gi 2, aa 20
  mixed    800x800, 10,000 spheres of radius 0.05-0.35 (a quarter mirrors,
           a tenth glass, a tenth rough), three suns and a bulb, aa 40,
           bounces 16

Usage: make_cs418_large.py [spheres|spiral|chair|mixed] [--size N] [--aa N] > scene.txt
"""
import math
import random
import sys


def header(out, size, aa, name):
    out.append(f"png {size} {size} {name}.png")
    if aa > 1:
        out.append(f"aa {aa}")


def spheres(out, size, aa):
    rng = random.Random(4181)
    header(out, size, aa, "spheres")
    out += ["bounces 16", "dof 2.3 0.01",
            "color 0.5 0.75 1", "sun 1 1 1", "color 0.5 0.25 0", "sun -1 0.5 0.5",
            "shininess 0.75", "roughness 0.05", "color 0.3 0.5 0.1", "plane 0 1 0 1.25",
            "shininess 0.25", "roughness 0.2"]
    for _ in range(10000):
        out.append(f"color {rng.uniform(0.5, 0.95):.2f} {rng.uniform(0.5, 0.95):.2f} {rng.uniform(0.4, 0.9):.2f}")
        x, y, z = rng.uniform(-1.75, 1.75), rng.uniform(-1.75, 0.75), rng.uniform(-3.75, -1.25)
        out.append(f"sphere {x:.6f} {y:.6f} {z:.6f} 0.02")


def spiral(out, size, aa):
    rng = random.Random(4182)
    header(out, size, aa, "spiral")
    out += ["bounces 16", "color 0.5 0.75 1", "sun 1 1 1", "color 0.5 0.25 0", "sun -1 0.5 0.5",
            "eye 2 4 -4.5", "forward -.3 -.75 -.8",
            "shininess 0.75", "roughness 0.05", "color 0.3 0.5 0.1", "plane 0 1 0 2",
            "shininess 0.5", "roughness 0"]
    per = 500
    for k in range(10):
        cx, cz = (k % 2) * 4.0, -6.0 - (k // 2) * 2.0
        turn = rng.uniform(0, 2 * math.pi)
        for i in range(per):
            s = i / per
            r = s * s
            a = turn + 12 * math.pi * s
            reach = 5 * s * s
            out.append(f"color {rng.uniform(0.4, 0.9):.2f} {rng.uniform(0.4, 0.9):.2f} {rng.uniform(0.4, 0.9):.2f}")
            out.append(f"sphere {cx + reach * math.cos(a):.6f} {4 - 7 * s * s:.6f} {cz + reach * math.sin(a):.6f} {r:.6f}")


class Mesh:
    def __init__(self):
        self.verts, self.tris = [], []

    def vertex(self, p):
        self.verts.append(p)
        return len(self.verts)  # 1-based, as `tri` counts

    def grid(self, origin, du, dv, nu, nv):
        """A quad subdivided nu x nv, its vertices shared inside it."""
        idx = [[self.vertex(tuple(origin[c] + du[c] * i / nu + dv[c] * j / nv for c in range(3)))
                for j in range(nv + 1)] for i in range(nu + 1)]
        for i in range(nu):
            for j in range(nv):
                a, b, c, d = idx[i][j], idx[i + 1][j], idx[i + 1][j + 1], idx[i][j + 1]
                self.tris += [(a, b, c), (a, c, d)]

    def box(self, lo, hi, n):
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        ex, ey, ez = (x1 - x0, 0, 0), (0, y1 - y0, 0), (0, 0, z1 - z0)
        self.grid((x0, y0, z0), ey, ex, n, n)
        self.grid((x0, y0, z1), ex, ey, n, n)
        self.grid((x0, y0, z0), ex, ez, n, n)
        self.grid((x0, y1, z0), ez, ex, n, n)
        self.grid((x0, y0, z0), ez, ey, n, n)
        self.grid((x1, y0, z0), ey, ez, n, n)

    def cylinder(self, base, radius, height, sides, rings):
        rows = []
        for j in range(rings + 1):
            y = base[1] + height * j / rings
            rows.append([self.vertex((base[0] + radius * math.cos(2 * math.pi * k / sides), y,
                                      base[2] + radius * math.sin(2 * math.pi * k / sides))) for k in range(sides)])
        for j in range(rings):
            for k in range(sides):
                a, b = rows[j][k], rows[j][(k + 1) % sides]
                c, d = rows[j + 1][(k + 1) % sides], rows[j + 1][k]
                self.tris += [(a, c, b), (a, d, c)]
        for j, y in ((0, base[1]), (rings, base[1] + height)):
            centre = self.vertex((base[0], y, base[2]))
            for k in range(sides):
                self.tris.append((centre, rows[j][k], rows[j][(k + 1) % sides]))


def chair(out, size, aa):
    header(out, size, aa, "chair")
    out += ["expose 2", "fisheye", "gi 2",
            "color 1.5 1.5 1.5", "sun -1 3 -2", "color 0.25 0.25 0.25", "sun 0 1 2",
            "eye 15 42 40", "forward -.7 -1.1 -1.8",
            "color 0.2 0.2 0.2", "plane 0 1 0 0", "color 0.75 0 0"]
    m = Mesh()
    m.box((-8, 17, 0), (8, 18.5, 16), 4)  # seat
    for x in (-6.5, 6.5):  # back posts
        m.box((x - 0.7, 18.5, 0), (x + 0.7, 40, 1.4), 3)
    for y in (24, 29, 34, 38.5):  # back rails
        m.box((-6, y, 0.2), (6, y + 1.5, 1.2), 3)
    for x in (-7, 7):  # legs
        for z in (1, 15):
            m.cylinder((x, 0, z), 0.8, 17, 12, 8)
    for v in m.verts:
        out.append(f"xyz {v[0]:.6f} {v[1]:.6f} {v[2]:.6f}")
    for t in m.tris:
        out.append(f"tri {t[0]} {t[1]} {t[2]}")
    out += ["color 1 1 1", "transparency 1", "shininess 0.25", "ior 2", "sphere 0 24 9 4",
            "transparency 0", "shininess 1 0.75 0.5", "sphere -14 5 8 5"]


def mixed(out, size, aa):
    rng = random.Random(418)
    header(out, size, aa, "mixed")
    out += ["bounces 16", "eye 0 2 6", "forward 0 -0.3 -1",
            "color 1 1 1", "sun 1 2 1", "color 0.4 0.4 0.5", "sun -1 1 0.5",
            "color 0.2 0.2 0.2", "sun 0 1 -1", "color 3 3 3", "bulb 0 3 0",
            "color 0.8 0.8 0.8", "plane 0 1 0 1"]
    for _ in range(10000):
        x, z = rng.uniform(-20, 20), rng.uniform(-40, 2)
        r = rng.uniform(0.05, 0.35)
        kind = rng.random()
        out.append(f"color {rng.random():.3f} {rng.random():.3f} {rng.random():.3f}")
        s, t, g = (0.7, 0, 0) if kind < 0.25 else (0.1, 0.9, 0) if kind < 0.35 else (0.5, 0, 0.05) if kind < 0.45 else (0, 0, 0)
        out += [f"shininess {s}", f"transparency {t}", f"roughness {g}"]
        out.append(f"sphere {x:.4f} {-1 + r:.4f} {z:.4f} {r:.4f}")


SCENES = {"spheres": (spheres, 40), "spiral": (spiral, 20), "chair": (chair, 20), "mixed": (mixed, 40)}


def main(argv):
    name, size, aa = "spheres", 800, None
    i = 0
    while i < len(argv):
        if argv[i] in ("--size", "--aa") and i + 1 < len(argv):
            if argv[i] == "--size":
                size = int(argv[i + 1])
            else:
                aa = int(argv[i + 1])
            i += 2
        elif argv[i] in SCENES:
            name = argv[i]
            i += 1
        else:
            sys.exit(f"make_cs418_large.py: error: unknown argument '{argv[i]}' (scenes: {', '.join(SCENES)})")
    make, default_aa = SCENES[name]
    out = []
    make(out, size, default_aa if aa is None else aa)
    print("\n".join(out))


if __name__ == "__main__":
    main(sys.argv[1:])
