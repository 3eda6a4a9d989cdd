#!/usr/bin/env python3
"""The table of docs/quality.md: every registered method that runs in 2D on the
torus, measured in one run by `pds analyze --method M --count N --sets S
--torus --seed 1`, ranked by relative radius.

    /usr/bin/python3 scripts/quality_table.py build/apps/pds/pds [--count 4096] [--sets 10]

Columns: rho (relative radius of the closest pair, mean over the sets), rho of
the mean nearest-neighbour distance, the radial power's peak (height and
frequency, in units of the mean inter-point distance) and its mean over
frequencies <= 0.5, the mean anisotropy in dB (10 log10(1/sets) for an
isotropic spectrum), and the wall time of the whole command. Methods come from
`pds methods --markdown` (the registry), so a new method joins the table.
"""
import argparse
import json
import math
import subprocess
import sys
import time


def methods(pds):
    table = subprocess.run([pds, "methods", "--markdown"], check=True, capture_output=True, text=True).stdout
    out = []
    for line in table.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) > 3 and cells[1].startswith("`"):
            out.append((cells[1].strip("`"), cells[2]))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pds")
    parser.add_argument("--count", type=int, default=4096)
    parser.add_argument("--sets", type=int, default=10)
    args = parser.parse_args()
    rows, skipped = [], []
    for name, family in methods(args.pds):
        command = [args.pds, "analyze", "--method", name, "--count", str(args.count), "--sets", str(args.sets),
                   "--torus", "--seed", "1"]
        start = time.monotonic()
        run = subprocess.run(command, capture_output=True, text=True)
        seconds = time.monotonic() - start
        if run.returncode != 0:
            skipped.append(f"{name}: {run.stderr.strip()}")
            continue
        report = json.loads(run.stdout)
        spectrum = report["spectrum"]
        rows.append((report["rho_min"], name, family, report["count"], report["rho_mean"], spectrum["peak_power"],
                     spectrum["peak_frequency"], spectrum["low_frequency_power"], spectrum["mean_anisotropy_db"],
                     seconds))
        print(f"{name}: done in {seconds:.1f} s", file=sys.stderr)
    rows.sort(key=lambda r: -r[0] if not math.isnan(r[0]) else math.inf)
    print(f"| rank | method | family | points | rho | rho (mean NN) | peak power | at frequency | "
          f"power <= 0.5 | anisotropy (dB) | time (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for rank, (rho, name, family, count, rho_nn, peak, peak_f, low, aniso, seconds) in enumerate(rows, 1):
        print(f"| {rank} | `{name}` | {family} | {count} | {rho:.3f} | {rho_nn:.3f} | {peak:.2f} | {peak_f:.2f} | "
              f"{low:.3f} | {aniso:.2f} | {seconds:.1f} |")
    for line in skipped:
        print(f"\nnot measured: {line}")


if __name__ == "__main__":
    main()
