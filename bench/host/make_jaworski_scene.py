#!/usr/bin/env python3
"""Writes the Jaworski speed scene: 640x480, 20 spheres (diffuse,
mirror and mixed), a floor, a directional and a spherical light, ray depth
4. Deterministic (fixed seed).

Usage: make_jaworski_scene.py > scene.txt
"""
import random

rng = random.Random(12)
print("imWidth 640 imHeight 480 canvWidth 4 canvHeight 3 depth 4 bgColor 0.1 0.1 0.15 rayDepth 4")
print("lights")
print("directional 0.8 white 1 -1 1")
print("spherical 6 1 0.9 0.8 -2 3 2")
print("objects")
print("plane 0 -1 0 0 1 0 mixed 0.7 diffusive 0.8 0.8 0.8 0.3 reflective")
for i in range(20):
    x, y, z = rng.uniform(-4, 4), rng.uniform(-0.8, 1.5), rng.uniform(5, 14)
    r = rng.uniform(0.2, 0.8)
    kind = i % 3
    if kind == 0:
        surf = f"diffusive {rng.random():.3f} {rng.random():.3f} {rng.random():.3f}"
    elif kind == 1:
        surf = "reflective"
    else:
        surf = f"mixed 0.5 diffusive {rng.random():.3f} {rng.random():.3f} {rng.random():.3f} 0.5 reflective"
    print(f"sphere {x:.3f} {y:.3f} {z:.3f} {r:.3f} {surf}")
