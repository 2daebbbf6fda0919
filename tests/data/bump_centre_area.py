#!/usr/bin/env python3
"""Real-area fraction of elastic summits without adhesion (Hertz) at the
centre of the plastic bump (examples/scenes/switch-bump-plastic.toml at
its former load of 20 uN, where the real-area fraction reached 1.13):
pi eta R sigma F_1(h), F_1(h) = int_h^inf (s - h) phi(s) ds, at the central
separation -3.176380412445665e-09 m the scene reported there (sigma = 2 nm,
eta = 5e14 /m^2, R = 50 nm). Used by roughsphere::report's test of the
excess-area warning. Prints the fraction and twice it (the fully plastic
bound without adhesion).
"""
from mpmath import mp, mpf, npdf, ncdf, pi

mp.dps = 30
eta, R, sigma = mpf("5e14"), mpf("50e-9"), mpf("2e-9")
h = mpf("-3.176380412445665e-09") / sigma
f1 = npdf(h) - h * (1 - ncdf(h))
frac = pi * eta * R * sigma * f1
print(f"h = {mp.nstr(h, 10)}, F_1 = {mp.nstr(f1, 15)}, Hertz fraction = {mp.nstr(frac, 15)}, twice = {mp.nstr(2 * frac, 15)}")
