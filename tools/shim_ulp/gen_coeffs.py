#!/usr/bin/python3
"""Regenerates the constants of core/math/math_portable.hpp (run with Debian's
python3-mpmath: /usr/bin/python3 tools/shim_ulp/gen_coeffs.py).

Polynomials: Chebyshev interpolation (mpmath.chebyfit, near-minimax) of the
smooth "remainder" function of z = r*r, then rounded to float.  The script
also prints the maximum relative error of the float-rounded polynomial
(evaluated in high precision) on a fine grid, so the truncation error can be
compared with float's 2^-24.
"""
import struct
import mpmath as mp

mp.mp.prec = 400


def f32(v):
    return struct.unpack('<f', struct.pack('<f', float(v)))[0]


def f32hex(v):
    return float.hex(f32(v)) + 'f'


def fit(g, lo, hi, deg):
    # chebyfit returns highest-degree first
    coeffs, err = mp.chebyfit(g, [lo, hi], deg + 1, error=True)
    return [f32(c) for c in reversed(coeffs)], err


def horner(cs, z):
    acc = mp.mpf(0)
    for c in reversed(cs):
        acc = acc * z + c
    return acc


def report(name, cs, approx, exact, lo, hi, n=4000):
    worst = mp.mpf(0)
    for i in range(1, n + 1):
        x = lo + (hi - lo) * i / n
        e = exact(x)
        if e != 0:
            worst = max(worst, abs((approx(cs, x) - e) / e))
    print('// %s: max rel err of float coefficients ~ 2^%.1f' %
          (name, float(mp.log(worst, 2)) if worst else -999))
    print('//   ' + ', '.join(f32hex(c) for c in cs))


R = mp.pi / 4 * mp.mpf('1.002')  # a little beyond pi/4: k may round either way
Z = R * R


def sin_g(z):
    if z == 0:
        return mp.mpf(-1) / 6
    s = mp.sqrt(z)
    return (mp.sin(s) / s - 1) / z


def cos_h(z):
    if z == 0:
        return mp.mpf(1) / 24
    s = mp.sqrt(z)
    return (mp.cos(s) - 1 + z / 2) / (z * z)


def atan_q(z):
    if z == 0:
        return mp.mpf(-1) / 3
    s = mp.sqrt(z)
    return (mp.atan(s) / s - 1) / z


def cos_full(z):
    # level 0 fits the whole of (cos r - 1) / r^2, -1/2 included
    if z == 0:
        return mp.mpf(-1) / 2
    s = mp.sqrt(z)
    return (mp.cos(s) - 1) / z


# Level 0 (float/portable-min) takes the shortest polynomial whose float
# coefficients stay well under the course's bound (2^-18 sin/cos, 2^-20
# atan) once float rounding (a few 2^-24) is added: sin degree 5 (2^-17.2)
# is too coarse, so sin keeps degree 7; cos degree 6 as 1 + z C(z) (kCosMin6);
# atan degree 9 on |t| <= tan(pi/8) (kAtan9; degree 7 gives only 2^-18.7).
for deg in (1, 2, 3):
    cs, _ = fit(sin_g, 0, Z, deg)
    report('sin deg %d' % (2 * deg + 3), cs,
           lambda c, r: r + r * r * r * horner(c, r * r), mp.sin, 0, R)
for deg in (2, 3):
    cs, _ = fit(cos_h, 0, Z, deg)
    report('cos deg %d' % (2 * deg + 4), cs,
           lambda c, r: 1 - r * r / 2 + r ** 4 * horner(c, r * r), mp.cos, 0, R)
for deg in (2, 3):
    cs, _ = fit(cos_full, 0, Z, deg)
    report('cos 1 + z C(z) deg %d (level 0)' % (2 * deg + 2), cs,
           lambda c, r: 1 + r * r * horner(c, r * r), mp.cos, 0, R)
T1 = mp.tan(mp.pi / 8) * mp.mpf('1.0001')
for deg in (2, 3, 4, 5, 6):
    cs, _ = fit(atan_q, 0, T1 * T1, deg)
    report('atan |t|<=tan(pi/8) deg %d' % (2 * deg + 3), cs,
           lambda c, t: t + t ** 3 * horner(c, t * t), mp.atan, 0, T1)
T2 = mp.mpf(7) / 16
for deg in (4, 5, 6):
    cs, _ = fit(atan_q, 0, T2 * T2, deg)
    report('atan |t|<=7/16 deg %d' % (2 * deg + 3), cs,
           lambda c, t: t + t ** 3 * horner(c, t * t), mp.atan, 0, T2)


def split_hi_lo(v):
    hi = f32(v)
    lo = f32(v - mp.mpf(hi))
    return hi, lo


print('// atan constants (hi, lo)')
for nm, v in (('atan(1/2)', mp.atan(0.5)), ('pi/4', mp.pi / 4),
              ('atan(3/2)', mp.atan(1.5)), ('pi/2', mp.pi / 2)):
    hi, lo = split_hi_lo(v)
    print('//   %s: %s, %s' % (nm, f32hex(hi), f32hex(lo)))
print('// tan(pi/8) = %s, tan(3pi/8) = %s (level 0 atan thresholds)' %
      (f32hex(mp.tan(mp.pi / 8)), f32hex(mp.tan(3 * mp.pi / 8))))


def trunc_bits(v, bits):
    # v truncated to `bits` significant bits (v > 0)
    e = int(mp.floor(mp.log(v, 2)))
    scale = mp.mpf(2) ** (bits - 1 - e)
    return mp.floor(v * scale) / scale


print('// Cody-Waite pieces of pi/2 (11 significant bits each, last full float)')
rest = mp.pi / 2
parts = []
for i in range(5):
    p = trunc_bits(rest, 11)
    parts.append(p)
    rest -= p
parts.append(mp.mpf(f32(rest)))
print('//   ' + ', '.join(f32hex(p) for p in parts) +
      '  (residual %s)' % mp.nstr(rest - parts[-1], 5))
short3 = mp.pi / 2 - sum(parts[:3])
print('// minimum level: first three pieces, then %s (residual %s)' %
      (f32hex(short3), mp.nstr(short3 - mp.mpf(f32(short3)), 5)))
short = mp.pi / 2 - sum(parts[:4])
print('// fast level: first four pieces, then %s (residual %s)' %
      (f32hex(short), mp.nstr(short - mp.mpf(f32(short)), 5)))
print('// 2/pi = %s' % f32hex(2 / mp.pi))
print('// 2/pi bits, 32 per word, first word = bits 2^-1 .. 2^-32')
v = 2 / mp.pi
words = []
for i in range(10):
    v *= 2 ** 32
    w = int(mp.floor(v))
    words.append(w)
    v -= w
print('//   ' + ', '.join('0x%08x' % w for w in words))
print('// pi/2 * 2^62 = 0x%016x' % int(mp.floor(mp.pi / 2 * mp.mpf(2) ** 62 + mp.mpf(0.5))))
