#!/usr/bin/env python3
"""Writes data/sobol/new-joe-kuo-6.21201.bin, the Sobol direction numbers
pds embeds (src/pds/samplers/sobol.cpp), from Joe & Kuo's table.

Source: S. Joe and F. Y. Kuo, new-joe-kuo-6.21201,
https://web.maths.unsw.edu.au/~fkuo/sobol/ (BSD-style licence, see
data/sobol/README.md). Either the original text file (columns d s a m_i) or
SciPy's copy of it, scipy/stats/_sobol_direction_numbers.npz (arrays `poly`:
the primitive polynomial with its leading and trailing 1, and `vinit`: m_i),
which Debian's python3-scipy ships.

Format (little-endian): b"JK6\\0", uint32 rows, then one bit stream read
least significant bit first, one row per axis d = 2 ... rows + 1:
s in 5 bits, a in s - 1 bits, then (m_i - 1) / 2 in i - 1 bits for
i = 1 ... s (every m_i is odd and below 2^i): 397 KB for 21,200 rows.

  scripts/sobol_directions.py [--npz PATH | --text new-joe-kuo-6.21201] [-o OUT]
"""
import argparse
import struct
import sys

DEFAULT_NPZ = "/usr/lib/python3/dist-packages/scipy/stats/_sobol_direction_numbers.npz"


def rows_from_npz(path):
    import numpy as np

    z = np.load(path)
    poly, vinit = z["poly"], z["vinit"]
    rows = []
    for d in range(1, len(poly)):  # row 0 is axis 1, van der Corput (not in Joe & Kuo's file)
        p = int(poly[d])
        s = p.bit_length() - 1
        a = (p >> 1) & ((1 << (s - 1)) - 1)
        rows.append((s, a, [int(v) for v in vinit[d][:s]]))
    return rows


def rows_from_text(path):
    rows = []
    with open(path) as f:
        next(f)  # header: d s a m_i
        for line in f:
            fields = line.split()
            if not fields:
                continue
            s, a = int(fields[1]), int(fields[2])
            rows.append((s, a, [int(v) for v in fields[3:3 + s]]))
    return rows


def pack(rows):
    out = bytearray(b"JK6\0" + struct.pack("<I", len(rows)))
    acc = 0
    nbits = 0

    def put(value, width):
        nonlocal acc, nbits
        assert 0 <= value < (1 << width) or width == 0 and value == 0
        acc |= value << nbits
        nbits += width
        while nbits >= 8:
            out.append(acc & 0xFF)
            acc >>= 8
            nbits -= 8

    for s, a, m in rows:
        assert 1 <= s < 32 and len(m) == s
        put(s, 5)
        put(a, s - 1)
        for i, mi in enumerate(m, start=1):
            assert mi % 2 == 1 and mi < (1 << i), (s, a, m)
            put((mi - 1) // 2, i - 1)
    if nbits:
        out.append(acc & 0xFF)
    return bytes(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--npz", default=None)
    ap.add_argument("--text", default=None)
    ap.add_argument("-o", "--output", default="data/sobol/new-joe-kuo-6.21201.bin")
    args = ap.parse_args()
    rows = rows_from_text(args.text) if args.text else rows_from_npz(args.npz or DEFAULT_NPZ)
    data = pack(rows)
    with open(args.output, "wb") as f:
        f.write(data)
    print(f"{args.output}: {len(rows)} rows (axes 2 to {len(rows) + 1}), {len(data)} bytes", file=sys.stderr)


if __name__ == "__main__":
    main()
