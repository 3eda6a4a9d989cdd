#!/usr/bin/python3
"""Peak resident memory of `pds generate` per method, next to the output's size.

    scripts/peak_memory.py [--pds build/apps/pds/pds] [--count 1000000] [--dim 2] [--by-radius]
                           [METHOD[:NAME=VALUE,...]...]

Runs each method once in a process of its own on the unit torus of --dim
dimensions with about --count points (`--count`, or for a method that takes
only a radius the radius of relative radius 0.75 at that count, the registry's
count policy), writes a float64 .npy to a temporary directory, and prints a
Markdown table: points, output size (8 bytes a coordinate), the process's peak
RSS (getrusage of the child), its growth over `pds generate random --count 1`
(the process itself), both over the output, and the growth over the registry's
estimate (`pds::peak_memory_estimate`, what `--max-memory` compares with; read
from the refusal of a 1 KB budget), which must stay below 1. The figures in
docs/reliability.md come from here.
"""

import argparse
import json
import math
import os
import re
import resource
import subprocess
import sys
import tempfile
import time


def peak_rss_mb(cmd):
    """Runs cmd in a child of a fresh Python process, so that the child's
    maximum RSS is the only one RUSAGE_CHILDREN reports."""
    probe = (
        "import resource, subprocess, sys, json, time\n"
        "t = time.monotonic()\n"
        "r = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)\n"
        "print(json.dumps([r.returncode, r.stderr, time.monotonic() - t,\n"
        "                  resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0]))\n"
    )
    out = subprocess.run([sys.executable, "-c", probe, *cmd], capture_output=True, text=True, check=True).stdout
    code, err, seconds, mb = json.loads(out)
    if code != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {code}: {err.strip()}")
    return mb, seconds


def estimate_mb(cmd):
    """The registry's peak estimate for cmd in MiB, from the refusal of a 1 KB budget."""
    err = subprocess.run(cmd + ["--max-memory", "1K"], capture_output=True, text=True).stderr
    found = re.search(r"needs about ([0-9.e+]+) (B|KiB|MiB|GiB)\b", err)
    if not found:
        raise RuntimeError(f"{' '.join(cmd)}: no estimate in {err.strip()!r}")
    return float(found.group(1)) * {"B": 2**-20, "KiB": 2**-10, "MiB": 1.0, "GiB": 2**10}[found.group(2)]


# The densest packings' densities (Conway & Sloane; analysis/relative_radius.cpp).
PACKING_DENSITY = {1: 1.0, 2: math.pi / math.sqrt(12.0), 3: math.pi / math.sqrt(18.0), 4: math.pi**2 / 16.0,
                   5: math.pi**2 / (15.0 * math.sqrt(2.0)), 6: math.pi**3 / (48.0 * math.sqrt(3.0)),
                   7: math.pi**3 / 105.0, 8: math.pi**4 / 384.0}


def densest_spacing(count, dim):
    """The spacing of the densest packing of count points in the unit cube (relative radius 1)."""
    ball = math.pi ** (dim / 2.0) / math.gamma(dim / 2.0 + 1.0)
    return 2.0 * (PACKING_DENSITY[dim] / (ball * count)) ** (1.0 / dim)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pds", default="build/apps/pds/pds")
    parser.add_argument("--count", type=int, default=1_000_000)
    parser.add_argument("--dim", type=int, default=2)
    parser.add_argument("--by-radius", action="store_true",
                        help="size by the radius every method that takes one (default: by the count where taken)")
    parser.add_argument("methods", nargs="*")
    args = parser.parse_args()
    listing = subprocess.run([args.pds, "methods"], capture_output=True, text=True, check=True).stdout
    methods = args.methods or re.findall(r"^  ([a-z][a-z0-9-]*) ", listing, re.MULTILINE)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "points.npy")
        base, _ = peak_rss_mb([args.pds, "generate", "random", "--count", "1", "-o", out])
        # Past 8 dimensions no method takes a radius (and no packing density is known).
        if args.dim in PACKING_DENSITY:
            radius = 0.75 * densest_spacing(args.count, args.dim)
            sizing = f"radius-only methods at r = {radius:.6g}"
        else:
            radius, sizing = 1.0, "no method takes a radius"
        print(f"process alone: {base:.1f} MB; {args.dim}D, count {args.count}, {sizing}")
        print("| method | points | output | peak RSS | growth | peak / output | growth / output | growth / estimate | time |")
        print("|---|---|---|---|---|---|---|---|---|")
        for entry in methods:
            # METHOD:NAME=VALUE,... passes method parameters (fpo:sweeps=1: the
            # triangulation's memory without the hundred sweeps' time).
            method, _, params = entry.partition(":")
            sized = ["--radius", repr(radius)] if args.by_radius else ["--count", str(args.count)]
            cmd = [args.pds, "generate", method, "--torus", "--dim", str(args.dim), "-o", out]
            for item in filter(None, params.split(",")):
                cmd += ["--param", item]
            try:
                mb, seconds = peak_rss_mb(cmd + sized)
            except RuntimeError as e:
                if "does not take --count" not in str(e) and "does not take --radius" not in str(e):
                    print(f"| {method} | refused: {e} ||||||||")
                    continue
                sized = ["--count", str(args.count)] if args.by_radius else ["--radius", repr(radius)]
                mb, seconds = peak_rss_mb(cmd + sized)
            estimate = estimate_mb(cmd + sized)
            with open(out, "rb") as f:
                head = f.read(10)
            data = os.path.getsize(out) - 10 - int.from_bytes(head[8:10], "little")
            points = data // (8 * args.dim)  # float64
            output = points * 8 * args.dim / 2**20
            print(f"| {entry} | {points:,} | {output:.1f} MB | {mb:.1f} MB | {mb - base:.1f} MB | "
                  f"{mb / output:.1f} | {(mb - base) / output:.1f} | {(mb - base) / estimate:.2f} | {seconds:.1f} s |",
                  flush=True)


if __name__ == "__main__":
    main()
