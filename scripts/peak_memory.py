#!/usr/bin/python3
"""Peak resident memory of `pds generate` per method, next to the output's size.

    scripts/peak_memory.py [--pds build/apps/pds/pds] [--count 1000000] [METHOD[:NAME=VALUE,...]...]

Runs each method once in a process of its own on the 2D unit torus with about
--count points (`--count`, or for a method that takes only a radius the radius
of relative radius 0.75 at that count, the registry's count policy), writes a
float64 .npy to a temporary directory, and prints a Markdown table: points,
output size (8 bytes a coordinate), the process's peak RSS (getrusage of the
child), its growth over `pds generate random --count 1` (the process itself),
and both over the output. The figures in docs/reliability.md come from here.
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pds", default="build/apps/pds/pds")
    parser.add_argument("--count", type=int, default=1_000_000)
    parser.add_argument("methods", nargs="*")
    args = parser.parse_args()
    listing = subprocess.run([args.pds, "methods"], capture_output=True, text=True, check=True).stdout
    methods = args.methods or re.findall(r"^  ([a-z][a-z0-9-]*) ", listing, re.MULTILINE)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "points.npy")
        base, _ = peak_rss_mb([args.pds, "generate", "random", "--count", "1", "-o", out])
        # Relative radius 0.75 at the count on the unit square (analysis/relative_radius.h).
        radius = 0.75 * math.sqrt(2.0 / (math.sqrt(3.0) * args.count))
        print(f"process alone: {base:.1f} MB; count {args.count}, radius-only methods at r = {radius:.6g}")
        print("| method | points | output | peak RSS | growth | peak / output | growth / output | time |")
        print("|---|---|---|---|---|---|---|---|")
        for entry in methods:
            # METHOD:NAME=VALUE,... passes method parameters (fpo:sweeps=1: the
            # triangulation's memory without the hundred sweeps' time).
            method, _, params = entry.partition(":")
            sized = ["--count", str(args.count)]
            cmd = [args.pds, "generate", method, "--torus", "-o", out]
            for item in filter(None, params.split(",")):
                cmd += ["--param", item]
            try:
                mb, seconds = peak_rss_mb(cmd + sized)
            except RuntimeError as e:
                if "does not take --count" not in str(e):
                    print(f"| {method} | refused: {e} |||||||")
                    continue
                mb, seconds = peak_rss_mb(cmd + ["--radius", repr(radius)])
            with open(out, "rb") as f:
                head = f.read(10)
            data = os.path.getsize(out) - 10 - int.from_bytes(head[8:10], "little")
            points = data // 16  # 2D float64
            output = points * 16 / 2**20
            print(f"| {entry} | {points:,} | {output:.1f} MB | {mb:.1f} MB | {mb - base:.1f} MB | "
                  f"{mb / output:.1f} | {(mb - base) / output:.1f} | {seconds:.1f} s |", flush=True)


if __name__ == "__main__":
    main()
