#!/usr/bin/env python3
"""Writes the small sample inputs the README's command lines read (examples/data/).

Standard library only; deterministic (no random state but a fixed LCG).
Run from the repository root:  python3 tools/make_example_data.py

- selfaffine-64-nm.txt: examples/data/selfaffine-256.npy (periodic, pixel 3.90625e-7 m,
  heights in m) taken every 4th pixel in both directions: a periodic 64 x 64 map of
  pixel 1.5625e-6 m, heights written in nm (so `--scale 1e-9`), one row per line.
- spots.csv: 12 contact spots (x_m, y_m, radius_m) of a gold switch contact, radii
  50-200 nm scattered over 10 um x 10 um.
- punch-gelatin.csv: (phase, radius_m, load_N) on the loading and unloading envelopes
  of Kesari & Lew (2011) eq. 4.9 with their gelatin values (E* 17.08 kPa,
  w 80.4 mJ/m^2, A sqrt(l) 1.1e-4 m^1/2, R 0.25 m), 12 radii per phase, each load
  perturbed by a relative 0.5 % (deterministic), as a measurement would be.
"""
import math
import pathlib
import struct

DATA = pathlib.Path(__file__).resolve().parent.parent / "examples" / "data"


def lcg(seed):
    state = seed
    while True:
        state = (6364136223846793005 * state + 1442695040888963407) % 2**64
        yield (state >> 11) / 2**53  # uniform in [0, 1)


def read_npy(path):
    raw = path.read_bytes()
    assert raw[:6] == b"\x93NUMPY"
    major = raw[6]
    hlen = struct.unpack("<H" if major == 1 else "<I", raw[8:10] if major == 1 else raw[8:12])[0]
    start = (10 if major == 1 else 12) + hlen
    header = raw[(10 if major == 1 else 12):start].decode()
    assert "'<f8'" in header and "False" in header, header
    shape = tuple(int(s) for s in header.split("(")[1].split(")")[0].split(",") if s.strip())
    n = shape[0] * shape[1]
    vals = struct.unpack(f"<{n}d", raw[start:start + 8 * n])
    return shape, vals


def selfaffine_txt():
    (rows, cols), v = read_npy(DATA / "selfaffine-256.npy")
    lines = []
    for i in range(0, rows, 4):
        row = [v[i * cols + j] * 1e9 for j in range(0, cols, 4)]
        lines.append(" ".join(f"{h:.4f}" for h in row))
    header = "# examples/data/selfaffine-256.npy every 4th pixel: periodic, pixel 1.5625e-6 m, heights in nm\n"
    (DATA / "selfaffine-64-nm.txt").write_text(header + "\n".join(lines) + "\n")


def spots_csv():
    u = lcg(7)
    rows = ["x_m,y_m,radius_m"]
    for _ in range(12):
        x, y = 10e-6 * next(u), 10e-6 * next(u)
        a = 50e-9 + 150e-9 * next(u)
        rows.append(f"{x:.4e},{y:.4e},{a:.4e}")
    (DATA / "spots.csv").write_text("\n".join(rows) + "\n")


def punch_csv():
    e, w, eps, r = 17.08e3, 80.4e-3, 1.1e-4, 0.25
    u = lcg(11)
    rows = ["phase,radius_m,load_N"]
    for phase, sign in (("loading", 1.0), ("unloading", -1.0)):
        for i in range(12):
            a = 0.008 + 0.018 * i / 11
            pm = 4 * e * a**3 / (3 * r) - math.sqrt(8 * math.pi * w * e * a**3)
            d = 2 * math.pi * e * eps * a**1.5
            p = (pm + sign * d) * (1 + 0.005 * (2 * next(u) - 1))
            rows.append(f"{phase},{a:.5e},{p:.6e}")
    (DATA / "punch-gelatin.csv").write_text("\n".join(rows) + "\n")


if __name__ == "__main__":
    selfaffine_txt()
    spots_csv()
    punch_csv()
