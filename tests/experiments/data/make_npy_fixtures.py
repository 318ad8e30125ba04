#!/usr/bin/python3
"""Regenerates the .npy fixtures of tests/experiments/test_npy.cpp with numpy (1.24.2 made them).

Run from this directory: /usr/bin/python3 make_npy_fixtures.py
"""
import numpy as np

# Exact in float32 and float64, so every reader must return exactly these values.
A = (np.arange(12, dtype=np.float64).reshape(3, 4) * 0.5 - 1.0)

np.save("f4_c.npy", A.astype("<f4"))
np.save("f8_c.npy", A.astype("<f8"))
np.save("f4_f.npy", np.asfortranarray(A.astype("<f4")))
np.save("f8_f.npy", np.asfortranarray(A.astype("<f8")))
np.save("empty_f4.npy", np.zeros((0, 5), dtype="<f4"))
np.save("one_d.npy", np.arange(4, dtype="<f4"))
np.save("three_d.npy", np.zeros((2, 2, 2), dtype="<f4"))
np.save("int32.npy", A.astype("<i4"))
np.save("big_endian.npy", A.astype(">f4"))

# Format versions 2.0 and 3.0 (4-byte header length); numpy only writes them when asked.
for version, name in (((2, 0), "f4_v2.npy"), ((3, 0), "f8_v3.npy")):
    arr = A.astype("<f4" if version == (2, 0) else "<f8")
    with open(name, "wb") as f:
        np.lib.format.write_array(f, arr, version=version)

# A valid file cut short in the middle of its data.
with open("f4_c.npy", "rb") as f:
    whole = f.read()
with open("truncated.npy", "wb") as f:
    f.write(whole[:-7])
