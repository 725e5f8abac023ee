#!/usr/bin/env python3
"""Writes a large CS418 scene for the speed benchmark: 800x800, 10,000
spheres (a quarter mirrors, a tenth glass, some rough), three suns and a
bulb, a floor plane, aa 40, bounces 16. Deterministic (fixed seed).

Usage: make_cs418_large.py [N_SPHERES] [SIZE] [AA] [BOUNCES] > scene.txt
"""
import random
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
size = int(sys.argv[2]) if len(sys.argv) > 2 else 800
aa = int(sys.argv[3]) if len(sys.argv) > 3 else 40
bounces = int(sys.argv[4]) if len(sys.argv) > 4 else 16
rng = random.Random(418)
print(f"png {size} {size} large.png")
print(f"bounces {bounces}")
print(f"aa {aa}")
print("eye 0 2 6")
print("forward 0 -0.3 -1")
print("color 1 1 1")
print("sun 1 2 1")
print("color 0.4 0.4 0.5")
print("sun -1 1 0.5")
print("color 0.2 0.2 0.2")
print("sun 0 1 -1")
print("color 3 3 3")
print("bulb 0 3 0")
print("color 0.8 0.8 0.8")
print("plane 0 1 0 1")
for i in range(n):
    x, z = rng.uniform(-20, 20), rng.uniform(-40, 2)
    r = rng.uniform(0.05, 0.35)
    kind = rng.random()
    print(f"color {rng.random():.3f} {rng.random():.3f} {rng.random():.3f}")
    if kind < 0.25:
        print("shininess 0.7")
        print("transparency 0")
        print("roughness 0")
    elif kind < 0.35:
        print("shininess 0.1")
        print("transparency 0.9")
        print("roughness 0")
    elif kind < 0.45:
        print("shininess 0.5")
        print("transparency 0")
        print("roughness 0.05")
    else:
        print("shininess 0")
        print("transparency 0")
        print("roughness 0")
    print(f"sphere {x:.4f} {-1 + r:.4f} {z:.4f} {r:.4f}")
