#!/usr/bin/python3
"""Builds the peer drivers of bench/peers/ against checkouts outside the tree,
runs every configuration ROUNDS times in alternation (round 1 runs each once,
then round 2, ...), then writes each configuration's points once to CSV and runs
`pds analyze` on them; prints the rows of docs/benchmarks.md's table "pds
against its peers" (median and range of samples per CPU second of the sampling
call, rho and maximality from `pds analyze`, median peak RSS of the process).

    bench/peers/run_peers.py [--rounds 3] [--cpu N] [--only REGEX] [--skip-analyze] [--no-build] [--from-log LOG]

Where the peers are (environment, defaults in brackets):
  THINKS_V03 [/tmp/thinks-v0.3]       thinks/poisson-disk-sampling at tag v0.3
  THINKS_HEAD [/tmp/thinks-head]      thinks/poisson-disk-sampling at e436117 (C header)
  CORPORATESHARK [/tmp/corporateshark] corporateshark/poisson-disk-generator at 5339f69
  CYCODEBASE [/tmp/cyCodeBase]        cemyuksel/cyCodeBase at 348dad1
  FAST2D_NODE_MODULES [/tmp/npmpeer/node_modules]  npm install fast-2d-poisson-disk-sampling@1.0.3
  PDS_BUILD [build]                   a Release build of pds (libpds_registry.so, apps/pds/pds)
  PEERS_OUT [/tmp/peers-build]        where the binaries, CSVs and the log go
Flags: those of pds's Release build, -O3 -DNDEBUG -ffp-contract=off (C++20; the C
header as C17), no -march, no OpenMP.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
env = os.environ.get
THINKS_V03 = env("THINKS_V03", "/tmp/thinks-v0.3")
THINKS_HEAD = env("THINKS_HEAD", "/tmp/thinks-head")
CORP = env("CORPORATESHARK", "/tmp/corporateshark")
CY = env("CYCODEBASE", "/tmp/cyCodeBase")
NODE_MODULES = env("FAST2D_NODE_MODULES", "/tmp/npmpeer/node_modules")
PDS_BUILD = os.path.abspath(env("PDS_BUILD", os.path.join(ROOT, "build")))
OUT = env("PEERS_OUT", "/tmp/peers-build")
FLAGS = ["-O3", "-DNDEBUG", "-ffp-contract=off"]
PIN_CPU = ""  # --cpu
PDS = os.path.join(PDS_BUILD, "apps/pds/pds")


def build():
    os.makedirs(OUT, exist_ok=True)
    cxx = ["c++", "-std=c++20", *FLAGS, "-I", HERE]
    jobs = [
        cxx + ["-I", THINKS_V03, f"{HERE}/thinks_v03.cpp", "-o", f"{OUT}/thinks_v03"],
        ["cc", "-std=c17", "-D_POSIX_C_SOURCE=199309L", *FLAGS, "-I", HERE, "-I", f"{THINKS_HEAD}/include",
         f"{HERE}/thinks_c.c", "-o", f"{OUT}/thinks_c", "-lm"],
        cxx + ["-I", CORP, f"{HERE}/corporateshark.cpp", "-o", f"{OUT}/corporateshark"],
        cxx + ["-I", CY, f"{HERE}/cyse.cpp", "-o", f"{OUT}/cyse"],
        cxx + ["-I", os.path.join(ROOT, "include"), f"{HERE}/pds_driver.cpp", "-o", f"{OUT}/pds_driver",
               f"-L{PDS_BUILD}", f"-Wl,-rpath,{PDS_BUILD}", "-lpds_registry", "-lpds_core"],
    ]
    for j in jobs:
        subprocess.run(j, check=True)


# name, domain, dim, command (CSV path appended as {csv}), radius for pds analyze (None: no maximality)
R2 = 0.00078     # Bridson-type, k = 30: about 10^6 samples in 2D
R2_5 = 0.00248   # about 10^5
R3 = 0.008387    # Bridson 3D, about 10^6
R3_5 = 0.01807   # about 10^5


def configs():
    P = f"{OUT}/pds_driver"
    node = ["env", f"NODE_PATH={NODE_MODULES}", "node", f"{HERE}/fast2d.js"]
    c = []
    add = lambda name, dom, dim, cmd, r: c.append(dict(name=name, domain=dom, dim=dim, cmd=cmd, radius=r))
    # 2D, about 10^6 (10^5 and less for the slow ones)
    add("thinks v0.3 bridson k=30", "box", 2, [f"{OUT}/thinks_v03", "2", str(R2), "30", "0", "{csv}"], R2)
    add("thinks C header bridson k=30", "box", 2, [f"{OUT}/thinks_c", "2", str(R2), "30", "0", "{csv}"], R2)
    add("pds bridson k=30", "box", 2, [P, "bridson", "2", "box", "radius", str(R2), "0", "{csv}"], R2)
    add("pds bridson k=30", "torus", 2, [P, "bridson", "2", "torus", "radius", str(R2), "0", "{csv}"], R2)
    add("corporateshark k=30", "box", 2, [f"{OUT}/corporateshark", str(R2), "30", "0", "{csv}"], R2)
    add("npm fast-2d-poisson-disk-sampling tries=30", "box", 2, node + [str(R2), "30", "{csv}"], R2)
    add("pds ebeida", "torus", 2, [P, "ebeida", "2", "torus", "radius", "0.000837", "0", "{csv}"], 0.000837)
    add("pds maximal-darts", "torus", 2, [P, "maximal-darts", "2", "torus", "radius", "0.000837", "0", "{csv}"], 0.000837)
    add("pds wei", "torus", 2, [P, "wei", "2", "torus", "radius", "0.000837", "0", "{csv}"], 0.000837)
    add("pds dunbar-humphreys (variant 0)", "torus", 2, [P, "dunbar-humphreys", "2", "torus", "radius", "0.00094", "0", "{csv}"], 0.00094)
    add("pds elimination", "torus", 2, [P, "elimination", "2", "torus", "count", "1000000", "0", "{csv}"], None)
    add("pds elimination", "torus", 2, [P, "elimination", "2", "torus", "count", "100000", "0", "{csv}"], None)
    add("cySampleElim", "torus", 2, [f"{OUT}/cyse", "100000", "1", "{csv}"], None)
    add("pds dart-throwing (to its failure bound)", "torus", 2, [P, "dart-throwing", "2", "torus", "radius", "0.008", "0", "{csv}"], 0.008)
    add("pds dart-throwing (to its failure bound)", "torus", 2, [P, "dart-throwing", "2", "torus", "radius", "0.0025", "0", "{csv}"], 0.0025)
    add("pds best-candidate m=10", "torus", 2, [P, "best-candidate", "2", "torus", "count", "100000", "0", "{csv}"], None)
    add("SciPy qmc.PoissonDisk", "box", 2, ["/usr/bin/python3", f"{HERE}/scipy_pd.py", "2", "0.0075", "0", "{csv}"], 0.0075)
    # Bridson at 10^5 in 2D, and 3D at 10^5 and 10^6 (the 3x target)
    add("thinks v0.3 bridson k=30", "box", 2, [f"{OUT}/thinks_v03", "2", str(R2_5), "30", "0", "{csv}"], R2_5)
    add("thinks C header bridson k=30", "box", 2, [f"{OUT}/thinks_c", "2", str(R2_5), "30", "0", "{csv}"], R2_5)
    add("pds bridson k=30", "box", 2, [P, "bridson", "2", "box", "radius", str(R2_5), "0", "{csv}"], R2_5)
    for r in (R3_5, R3):
        add("thinks v0.3 bridson k=30", "box", 3, [f"{OUT}/thinks_v03", "3", str(r), "30", "0", "{csv}"], r)
        add("thinks C header bridson k=30", "box", 3, [f"{OUT}/thinks_c", "3", str(r), "30", "0", "{csv}"], r)
        add("pds bridson k=30", "box", 3, [P, "bridson", "3", "box", "radius", str(r), "0", "{csv}"], r)
        add("pds bridson k=30", "torus", 3, [P, "bridson", "3", "torus", "radius", str(r), "0", "{csv}"], r)
    return c


RESULT = re.compile(r"RESULT (\S+) dim=(\d) samples=(\d+) cpu_s=([\d.]+) wall_s=([\d.]+)")


def run_cmd(cfg, csv):
    cmd = [a for a in cfg["cmd"] if a != "{csv}"] if csv is None else [csv if a == "{csv}" else a for a in cfg["cmd"]]
    # pds_driver takes "-" for no CSV (its params follow)
    if csv is None and os.path.basename(cmd[0]) == "pds_driver":
        cmd.append("-")
    return cmd


def run_once(cfg, csv=None, log=None):
    cmd = run_cmd(cfg, csv)
    pin = ["taskset", "-c", PIN_CPU] if PIN_CPU else []
    p = subprocess.run(pin + ["/usr/bin/time", "-f", "PEAK_KB %M"] + cmd, capture_output=True, text=True)
    text = p.stdout + p.stderr
    if log:
        log.write(" ".join(cmd) + "\n" + text)
        log.flush()
    m = RESULT.search(text)
    peak = re.search(r"PEAK_KB (\d+)", text)
    if p.returncode != 0 or not m:
        sys.exit(f"failed: {' '.join(cmd)}\n{text}")
    return dict(n=int(m.group(3)), cpu=float(m.group(4)), wall=float(m.group(5)), peak_mb=int(peak.group(1)) / 1024)


def analyze(cfg, csv):
    cmd = [PDS, "analyze", csv]
    if cfg["domain"] == "torus":
        cmd.append("--torus")
    radius = cfg["radius"]
    if not radius:  # no radius asked (elimination, best-candidate): maximality at the set's own minimum distance
        out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
        radius = float(re.search(r'"min_distance": ([\d.eE+-]+)', out).group(1))
    p = subprocess.run(cmd + ["--radius", repr(radius)], capture_output=True, text=True)
    if p.returncode != 0 and "outside the domain" in p.stderr:
        # float32 peers can round a coordinate up to 1.0, outside the half-open unit box:
        # widen the box by 1e-6 (rho changes by about 1e-6)
        hi = ["1.000001"] * cfg["dim"]
        p = subprocess.run(cmd + ["--radius", repr(radius), "--bounds", *(["0"] * cfg["dim"]), *hi],
                           capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"pds analyze failed: {p.stderr}")
    out = p.stdout
    rho = float(re.search(r'"relative_radius": ([\d.eE+-]+)', out).group(1))
    mx = re.search(r'"maximal": (true|false)', out)
    return rho, (mx.group(1) if mx else None)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rounds", type=int, default=3)
    # Every timed run on this one CPU (taskset): on a shared virtual machine one
    # vCPU can run everything 1.5x slower at random, which decides a ratio.
    ap.add_argument("--cpu", default="", help="pin every timed run to this CPU (taskset -c)")
    ap.add_argument("--only", default="")
    ap.add_argument("--skip-analyze", action="store_true")
    ap.add_argument("--no-build", action="store_true")
    ap.add_argument("--from-log", help="take the timed rounds from this run.log instead of running them")
    a = ap.parse_args()
    global PIN_CPU
    PIN_CPU = a.cpu
    if not a.no_build:
        build()
    cfgs = [c for c in configs() if re.search(a.only, f'{c["name"]} {c["domain"]} {c["dim"]}D {" ".join(c["cmd"])}')]
    res = [[] for _ in cfgs]
    if a.from_log:
        # the timed rounds of an earlier run, from its log (command line, then its output)
        keys = [" ".join(run_cmd(c, None)) for c in cfgs]
        lines = open(a.from_log).read().splitlines()
        for j, line in enumerate(lines):
            if line in keys and j + 2 < len(lines) and lines[j + 1].startswith("RESULT"):
                m, peak = RESULT.search(lines[j + 1]), re.search(r"PEAK_KB (\d+)", lines[j + 2])
                res[keys.index(line)].append(dict(n=int(m.group(3)), cpu=float(m.group(4)), wall=float(m.group(5)),
                                                  peak_mb=int(peak.group(1)) / 1024))
    with open(f"{OUT}/run.log", "a") as log:
        for rnd in range(0 if a.from_log else a.rounds):
            log.write(f"# round {rnd + 1}, load {os.getloadavg()}\n")
            print(f"# round {rnd + 1}, load average {os.getloadavg()[0]:.2f}", file=sys.stderr, flush=True)
            for i, c in enumerate(cfgs):
                res[i].append(run_once(c, log=log))
        print(f"# load average after the rounds {os.getloadavg()}", file=sys.stderr, flush=True)
        print("| method | domain | D | samples | M samples/s (median, range) | rho | maximal | peak RSS MB |")
        print("|---|---|---|---|---|---|---|---|")
        for i, c in enumerate(cfgs):
            rates = [r["n"] / r["cpu"] * 1e-6 for r in res[i]]
            rho, mx = ("", "")
            if not a.skip_analyze:
                csv = f"{OUT}/points_{i}.csv"
                run_once(c, csv=csv, log=log)
                rho, mx = analyze(c, csv)
                rho = f"{rho:.3f}"
                os.remove(csv)
            med = statistics.median(rates)
            print(f'| {c["name"]} | {c["domain"]} | {c["dim"]} | {res[i][0]["n"]:,} | {med:.4g} ({min(rates):.4g}-{max(rates):.4g}) '
                  f'| {rho} | { {"true": "yes", "false": "no"}.get(mx, "-") } | {statistics.median(r["peak_mb"] for r in res[i]):.1f} |', flush=True)
        # The 3x target: pds bridson (box) against thinks v0.3 in the same round, per round
        print("\nratios pds bridson (box) / thinks v0.3, per round (median, range):")
        for i, c in enumerate(cfgs):
            if c["name"].startswith("thinks v0.3"):
                for j, d in enumerate(cfgs):
                    if d["name"] == "pds bridson k=30" and d["domain"] == "box" and d["dim"] == c["dim"] and d["radius"] == c["radius"]:
                        rc = None  # the C header's runs, when --only kept them
                        for k, e in enumerate(cfgs):
                            if e["name"].startswith("thinks C") and e["dim"] == c["dim"] and e["radius"] == c["radius"]:
                                rc = [(d2["n"] / d2["cpu"]) / (e2["n"] / e2["cpu"]) for d2, e2 in zip(res[j], res[k])]
                        r = [(d2["n"] / d2["cpu"]) / (c2["n"] / c2["cpu"]) for d2, c2 in zip(res[j], res[i])]
                        line = f'  {c["dim"]}D ~{res[j][0]["n"]:,}: vs v0.3 {statistics.median(r):.2f} ({min(r):.2f}-{max(r):.2f})'
                        if rc:
                            line += f'; vs C header {statistics.median(rc):.2f} ({min(rc):.2f}-{max(rc):.2f})'
                        print(line)


if __name__ == "__main__":
    main()
