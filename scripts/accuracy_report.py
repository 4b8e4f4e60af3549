#!/usr/bin/python3
"""The accuracy tables of docs/ from a run of tests/accuracy_test on every array-kernel path.

    scripts/accuracy_report.py [--build DIR] [--docs DIR]

Runs DIR/tests/accuracy_test (DIR: build) once per path (WAVECONTACT_ISA = scalar, avx2,
avx512; a path the CPU lacks is skipped), prints what it measured against the 40-digit
references, and with --docs rewrites the tables between `<!-- accuracy:NAME -->` and
`<!-- /accuracy:NAME -->`, naming the run (date, machine, commit). Fails if the test fails.
"""
import argparse
import datetime
import os
import platform
import re
import subprocess
import sys

import doc_tables

ISAS = ("scalar", "avx2", "avx512")
SUMMARY = re.compile(r"^(?P<name>.+?): (?P<count>\d+) points, max (?P<max>\S+) eps, mean (?P<mean>\S+) eps, "
                     r"worst at (?P<worst>.*)$")
ROUGHNESS = re.compile(r"^n = (?P<n>\d+): roughness pressure max error (?P<point>\S+) \(array API (?P<array>\S+)\) "
                       r"x E\*H2 n pi/b1; naive eq. 18 sum max error (?P<naive>\S+)")


class Run:
    """One path's figures: summaries by name, the roughness by n."""

    def __init__(self, output):
        self.summaries, self.roughness, self.isa = {}, {}, None
        for line in output.splitlines():
            line = line.strip()
            if line.startswith("array kernels: "):
                self.isa = line.split(": ", 1)[1]
            elif m := SUMMARY.match(line):
                self.summaries[m["name"]] = m
            elif m := ROUGHNESS.match(line):
                self.roughness[int(m["n"])] = m


def run_test(build, isa):
    env = dict(os.environ)
    if isa is not None:
        env["WAVECONTACT_ISA"] = isa
    test = os.path.join(build, "tests", "accuracy_test")
    r = subprocess.run([test, "--log_level=message", "--color_output=no"], env=env, capture_output=True, text=True)
    if r.returncode == 77:
        return None  # the CPU lacks this path
    if r.returncode != 0:
        sys.exit(f"accuracy_report: {test} failed (WAVECONTACT_ISA={isa}):\n{r.stdout}{r.stderr}")
    return Run(r.stdout)


def eps(value):
    return f"{float(value):.3g} ε"


SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def scaled(value):
    mantissa, exponent = f"{float(value):.2e}".split("e")
    return f"{float(mantissa):.2g}·10{str(int(exponent)).translate(SUPERSCRIPT)}"


def summary_table(run, rows):
    lines = ["| evaluator | points | max error | mean error | worst at |", "|---|---|---|---|---|"]
    for label, name in rows:
        m = run.summaries.get(name)
        if m is None:
            return None
        lines.append(f"| {label} | {m['count']} | {eps(m['max'])} | {eps(m['mean'])} | {m['worst']} |")
    return lines


SINGLE_ZONE = [("pressure, exact (eq. 13/14 derived)", "pressure, exact"),
               ("pressure, printed eq. 14", "pressure, printed eq. 14"), ("load P", "load"), ("pa/p*", "pa/p*"),
               ("a(P(a)), the inverse and back", "a(P(a))")]
BEYOND_HALF = [("load P", "load, a > b1/2"), ("pa/p*", "pa/p*, a > b1/2"), ("dP/da", "dP/da, a > b1/2"),
               ("pressure, \\|x\\| < b1/2, of the zone's largest \\|p\\|", "pressure, a > b1/2, |x| < b1/2"),
               ("pressure, \\|x\\| > b1/2, likewise", "pressure, a > b1/2, |x| > b1/2"),
               ("full contact, eq. 2, \\|x\\| < b1/2", "full contact, eq. 2, |x| < b1/2"),
               ("full contact, eq. 2, \\|x\\| ≥ b1/2", "full contact, eq. 2, |x| >= b1/2")]
ARRAY_ROWS = [("pressure, exact: max / mean", "pressure, exact, array API", True),
              ("pressure, printed eq. 14: max / mean", "pressure, printed, array API", True),
              ("pressure beyond b1/2, \\|x\\| < b1/2: max", "pressure (array), a > b1/2, |x| < b1/2", False),
              ("pressure beyond b1/2, \\|x\\| > b1/2: max", "pressure (array), a > b1/2, |x| > b1/2", False)]


def array_paths_table(runs):
    isas = [isa for isa in ISAS if runs.get(isa) is not None]
    lines = ["| array API | " + " | ".join(isas) + " |", "|---" * (len(isas) + 1) + "|"]
    for label, name, with_mean in ARRAY_ROWS:
        cells = []
        for isa in isas:
            m = runs[isa].summaries.get(name)
            if m is None:
                return None
            cells.append(f"{eps(m['max'])} / {eps(m['mean'])}" if with_mean else eps(m["max"]))
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    cells = []
    for isa in isas:
        m = runs[isa].roughness.get(256)
        if m is None:
            return None
        cells.append(scaled(m["array"]))
    lines.append("| roughness, n = 256, in E*H2nπ/b1 | " + " | ".join(cells) + " |")
    return lines


def roughness_table(run):
    if not run.roughness:
        return None
    lines = ["| n | pressure, point API | array API | eq. 18 summed naively |", "|---|---|---|---|"]
    for n, m in sorted(run.roughness.items()):
        lines.append(f"| {n} | {scaled(m['point'])} | {scaled(m['array'])} | {scaled(m['naive'])} |")
    return lines


def run_name(build, best):
    try:
        commit = subprocess.run(["git", "describe", "--always", "--dirty"], capture_output=True, text=True,
                                check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = "not recorded"
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    return (f"Run of {date} on {platform.node()} ({os.cpu_count()} CPUs, best path {best.isa}), commit {commit}, "
            f"`{os.path.join(build, 'tests', 'accuracy_test')}`")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build")
    parser.add_argument("--docs", help="rewrite the tables of the .md files in this folder")
    args = parser.parse_args()
    best = run_test(args.build, None)
    runs = {isa: run_test(args.build, isa) for isa in ISAS}
    tables = {"single-zone": lambda: summary_table(best, SINGLE_ZONE),
              "beyond-half": lambda: summary_table(best, BEYOND_HALF),
              "array-paths": lambda: array_paths_table(runs),
              "roughness": lambda: roughness_table(best)}
    for name, table in tables.items():
        print(f"\n{name}:")
        print("\n".join(table() or ["(missing from the run)"]))
    if args.docs:
        doc_tables.rewrite(args.docs, "accuracy", tables, run_name(args.build, best))


if __name__ == "__main__":
    main()
