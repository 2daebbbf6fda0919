"""The periodic 32 x 32 height map (m) of tests/it/map_pull_off.rs:
random phases on a power-law spectrum (|k|^-1.8, cut at 0.35 of the
sampling frequency), RMS 5 nm, periodic by construction (an inverse FFT).

    python tests/data/pull_off_map32.py   # writes pull_off_map32.npy
"""
from pathlib import Path

import numpy as np

rng = np.random.default_rng(1)
n = 32
kx = np.fft.fftfreq(n)[:, None]
ky = np.fft.fftfreq(n)[None, :]
k = np.hypot(kx, ky)
k[0, 0] = 1
amp = k ** (-1.8)
amp[0, 0] = 0
amp[k > 0.35] = 0
z = np.real(np.fft.ifft2(amp * np.exp(2j * np.pi * rng.random((n, n)))))
z *= 5e-9 / z.std()
np.save(Path(__file__).with_name("pull_off_map32.npy"), z)
