#!/usr/bin/python3
"""A map of 10^4 points against the loops a user writes without one (docs/maps.md): the same
points, the same tolerance (1e-8) and budget, timed on this machine in one run.

- `wavecontact map`: one continuation a load line, the lines on every core;
- a shell loop of `wavecontact solve`, one process a point (bash, serial, as users write it);
- a serial Python loop of wavecontact.solve_contact, one call a point;
- the shell loop's processes alone (`wavecontact solve --help`, the same pipe), the part of the
  shell loop that no solver's speed changes.

Every loop's contact fraction is checked against the map's (the continuation and a solve from
scratch agree to the tolerance, not to the bit). Prints a table; with --docs, rewrites the
`maps-bench:map-vs-loops` tables of the given .md files (with --m other than 0, the tables
`maps-bench:map-vs-loops-m<m>`, a point as p).

    PYTHONPATH=build/python /usr/bin/python3 bench/map_vs_loops.py [--m 10] [--docs README.md --docs docs/maps.md]
"""
import argparse
import csv
import datetime
import os
import platform
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

import wavecontact as wc

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
import doc_tables  # noqa: E402

H1, B1, E = 1.0, 10.0, 1.0
H2 = np.geomspace(0.002, 0.02, 25)
N = [8, 16, 24, 32]
RATIOS = np.linspace(0.01, 1.0, 100)
TOLERANCE = 1e-8


def points():
    """(H2, n, pa/p*) of every point, in the map's order of index."""
    return [(h, n, r) for h in H2 for n in N for r in RATIOS]


def digits(x):
    return repr(float(x))


def run_map(cli, folder, m):
    out = os.path.join(folder, "map.csv")
    command = [cli, "map", "--H1", "1", "--b1", "10", "--E", "1", "--m", digits(m), "--H2",
               ",".join(digits(h) for h in H2), "--n", ",".join(map(str, N)), "--pa-over-pstar", ",".join(digits(r) for r in RATIOS),
               "--tolerance", digits(TOLERANCE), "--out", out]
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    seconds = time.perf_counter() - start
    fraction = {}
    with open(out) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        for row in rows:
            assert row["status"] == "solved", row
            fraction[int(row["index"])] = float(row["contact_fraction"])
    return seconds, [fraction[i] for i in range(len(fraction))]


def time_shell_script(folder, name, commands):
    """Runs the commands as one bash script (stopping at a failure): its wall time and stdout."""
    script = os.path.join(folder, name)
    with open(script, "w") as f:
        f.write("set -e\n" + "".join(command + "\n" for command in commands))
    start = time.perf_counter()
    out = subprocess.run(["bash", script], check=True, capture_output=True, text=True).stdout
    return time.perf_counter() - start, out


def run_shell_loop(cli, folder, m):
    seconds, out = time_shell_script(folder, "loop.sh", [
        f"'{cli}' solve --H1 1 --b1 10 --E 1 --m {digits(m)} --H2 {digits(h)} --n {n} "
        f"--pa-over-pstar {digits(r)} --tolerance {digits(TOLERANCE)} | tail -n 1" for h, n, r in points()])
    header = "P,pa,pa_over_pstar,zones,contact_fraction".split(",")
    return seconds, [float(line.split(",")[header.index("contact_fraction")]) for line in out.splitlines()]


def run_shell_starts(cli, folder):
    """The shell loop's processes without the solving: as many, each parsing its options and exiting."""
    return time_shell_script(folder, "starts.sh", [f"'{cli}' solve --help | tail -n 1" for _ in points()])[0]


def run_python_loop(m):
    fractions = []
    start = time.perf_counter()
    for h, n, r in points():
        surface = wc.Surface(wc.WavinessParams(H1, B1, m, E), [wc.Harmonic(h, n)])
        fractions.append(wc.solve_contact(surface, r * np.pi * E * H1, tolerance=TOLERANCE).contact_fraction)
    return time.perf_counter() - start, fractions


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", default="build/runtime/wavecontact")
    parser.add_argument("--m", type=float, default=0.0,
                        help="the wave curve's shape (0: a sine); other than 0, the table map-vs-loops-m<m>")
    parser.add_argument("--docs", action="append", help="rewrite the table of this .md file (repeatable)")
    args = parser.parse_args()
    cli = os.path.abspath(args.cli)
    with tempfile.TemporaryDirectory() as folder:
        map_seconds, reference = run_map(cli, folder, args.m)
        shell_seconds, shell = run_shell_loop(cli, folder, args.m)
        starts_seconds = run_shell_starts(cli, folder)
    python_seconds, python = run_python_loop(args.m)
    count = len(reference)
    worst = {}
    for name, values in (("shell", shell), ("python", python)):
        assert len(values) == count, (name, len(values))
        worst[name] = max(abs(a - b) for a, b in zip(values, reference))
        assert worst[name] < 1e-5, (name, worst[name])  # the same contacts, to the tolerance
    rows = [("`wavecontact map`, every core", map_seconds, "the reference"),
            ("shell loop of `wavecontact solve`", shell_seconds, f"{worst['shell']:.1e}"),
            ("Python loop of `wavecontact.solve_contact`", python_seconds, f"{worst['python']:.1e}"),
            ("the shell loop's processes alone (`wavecontact solve --help`)", starts_seconds, "nothing solved")]
    lines = [f"{count} points: m = {args.m:g}, H2 0.002 to 0.02 mm (25, log) at n = {', '.join(map(str, N))}, pa/p* 0.01 "
             f"to 1 (100); tolerance {TOLERANCE:g}, on {os.cpu_count()} cores", "",
             "| run | wall time | per point | the map's speed-up | contact fraction, largest difference |",
             "|---|---|---|---|---|"]
    for name, seconds, difference in rows:
        lines.append(f"| {name} | {seconds:.1f} s | {seconds / count * 1e3:.2f} ms | {seconds / map_seconds:.1f}× "
                     f"| {difference} |")
    print("\n".join(lines))
    if args.docs:
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
        run = (f"Run of {datetime.datetime.now().isoformat(timespec='seconds')} on {platform.node()} "
               f"({os.cpu_count()} CPUs), commit {commit or 'not recorded'}, `bench/map_vs_loops.py`")
        table = "map-vs-loops" if args.m == 0 else "map-vs-loops-m" + f"{args.m:g}".replace(".", "p")
        # The other shapes' tables are left as they are.
        others = {name: lambda: None for path in args.docs
                  for name in re.findall(r"<!-- maps-bench:([a-z0-9-]+) -->", open(path).read())}
        doc_tables.rewrite(args.docs, "maps-bench", {**others, table: lambda: lines}, run)


if __name__ == "__main__":
    main()
