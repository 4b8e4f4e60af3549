#!/usr/bin/python3
"""The benchmark's figures from its JSON (Google Benchmark, written by scripts/bench.sh).

    scripts/bench_report.py RESULTS.json [--isa-run JSON]... [--python FILE] [--docs PATH]...

Prints each figure next to its baseline with the ratio. --isa-run: a run of the waviness
array kernel on one path (WAVECONTACT_ISA) beside the plain kernel built for it. With --docs
(a folder or a file, repeatable), rewrites the tables that come from a run, each between the lines `<!-- bench:NAME -->` and
`<!-- /bench:NAME -->`, and names the run (date, machine, commit) above each; a table whose
figures are missing from the run is left as it was, and the script says so.
"""
import argparse
import json
import os

import doc_tables


class Results:
    """The run's figures by name; with --benchmark_repetitions, the medians."""

    def __init__(self, path):
        data = json.load(open(path))
        self.context = data.get("context", {})
        runs = data["benchmarks"]
        self.by_name = {b["name"]: b for b in runs if b.get("run_type") != "aggregate"}
        self.by_name.update({b["run_name"]: b for b in runs if b.get("aggregate_name") == "median"})
        self.python = {}  # bench/python_pressure.py's figures by name, ns, where it ran
        self.isa_runs = []  # Results of the waviness kernel on each path (--isa-run)

    @property
    def python_ns(self):
        """The Python module's ns a point on 10^6 points, None where it did not run."""
        return self.python.get("python_pressure_ns_per_point")

    def get(self, prefix):
        """The figure named `prefix`, or `prefix/...` (Google Benchmark appends /real_time,
        /iterations:1, /repeats:3 to a name); None if the run has none or it failed."""
        for name, b in self.by_name.items():
            if (name == prefix or name.startswith(prefix + "/")) and not b.get("error_occurred"):
                return b
        return None

    def seconds(self, prefix):
        b = self.get(prefix)
        if b is None:
            return None
        return b["real_time"] * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]

    def ns_per_item(self, prefix):
        b = self.get(prefix)
        return None if b is None or "items_per_second" not in b else 1e9 / b["items_per_second"]

    def run_name(self):
        c = self.context
        commit = f"commit {c['commit']}" if "commit" in c else "commit not recorded"
        return (f"Run of {c.get('date', '?')} on {c.get('host_name', '?')} ({c.get('num_cpus', '?')} CPUs at "
                f"{c.get('mhz_per_cpu', '?')} MHz), {commit}, `{os.path.basename(c.get('executable', '?'))}`")


def duration(seconds):
    if seconds >= 1:
        return f"{seconds:.3g} s"
    if seconds >= 1e-3:
        return f"{seconds * 1e3:.3g} ms"
    if seconds >= 1e-6:
        return f"{seconds * 1e6:.3g} µs"
    return f"{seconds * 1e9:.3g} ns"


# ---- the console report -------------------------------------------------------------------

def seconds_cell(seconds):
    """A figure in seconds, 12 wide; `not run` where the run left its benchmark out (the smoke
    mode filters the slow ones)."""
    return f"{seconds:12.4g}" if seconds is not None else f"{'not run':>12}"


def print_report(r, python_ns):
    rows = [("waviness pressure, ns/point", r.ns_per_item, "BM_waviness_pressure_generated/1000000",
             [("plain kernel, same path", "BM_waviness_pressure_plain_same_isa/1000000"),
              ("same formula, scalar libm", "BM_waviness_pressure_scalar_libm/1000000"),
              ("numerical inversion", "BM_waviness_pressure_numerical/10000"),
              ("print_csrc, no CSE", "BM_waviness_pressure_no_cse/1000000")])]
    for n in (16, 64, 256):
        rows.append((f"roughness pressure n={n}, ns/point", r.ns_per_item, f"BM_roughness_pressure_generated/{n}",
                     [("numerical inversion", f"BM_roughness_pressure_numerical/{n}"),
                      ("point API, per call", f"BM_roughness_pressure_point/{n}")]))
    rows.append(("k_1..k_128, s", r.seconds, "BM_kcoefficients/128",
                 [("SymPy", "BM_sympy_kcoefficients/128")]))
    rows.append(("contact n=16, 7 zones, 1e-8, s", r.seconds, "BM_contact_multi_zone_n16",
                 [("BEM oracle, 3 grids", "BM_contact_bem_oracle")]))
    rows.append(("pressure beyond b1/2, array, ns/point", r.ns_per_item, "BM_pressure_beyond_half_array/10000",
                 [("quadrature of eq. 12", "BM_pressure_beyond_half_quadrature")]))
    rows.append(("pressure beyond b1/2, per point", r.ns_per_item, "BM_pressure_beyond_half",
                 [("quadrature of eq. 12", "BM_pressure_beyond_half_quadrature")]))
    rows.append(("the same within 1e-2..1e-12 of the kink", r.ns_per_item, "BM_pressure_beyond_half_near_kink",
                 [("quadrature of eq. 12", "BM_pressure_beyond_half_near_kink_quadrature")]))
    print(r.run_name())
    print(f"\n{'figure':40} {'ours':>12} {'baseline':>24} {'value':>12} {'ratio':>8}")
    for label, measure, ours_name, baselines in rows:
        ours = measure(ours_name)
        for baseline_label, baseline_name in baselines:
            base = measure(baseline_name)
            if ours is None or base is None:
                print(f"{label:40} {'n/a':>12} {baseline_label:>24} {'n/a':>12}")
                continue
            print(f"{label:40} {ours:12.4g} {baseline_label:>24} {base:12.4g} {base / ours:7.1f}x")
    for i in range(6):
        ours, bem = r.get(f"BM_contact_many_zones/{i}"), r.get(f"BM_contact_many_zones_bem/{i}")
        if ours is None or bem is None:
            continue
        t_ours, t_bem = r.seconds(f"BM_contact_many_zones/{i}"), r.seconds(f"BM_contact_many_zones_bem/{i}")
        print(f"{ours.get('label', '')[:40]:40} {duration(t_ours):>10}, {int(ours['zones'])} zones, estimate "
              f"{ours['error_estimate']:.1e} | BEM {int(bem['grid'])} points {duration(t_bem):>10}, p(0) off by "
              f"{bem['p0_error']:.1e}, fraction off by {bem['fraction_error']:.1e} | {t_bem / t_ours:5.1f}x")
    for k in (8, 16, 32, 64, 128, 256):
        for label, shape in (("H cos(k x)", "harmonic"), ("H cos(x)^k", "power")):
            now, whole = r.seconds(f"BM_derive_profile_{shape}/{k}"), r.seconds(f"BM_derive_whole_{shape}/{k}")
            row = f"{'derive ' + label + ', k = ' + str(k) + ', s':40} {seconds_cell(now)}"
            if whole is not None and now is not None:
                row += f" {'whole, partial fractions':>24} {whole:12.4g} {whole / now:7.1f}x"
            print(row)
        pole = r.seconds(f"BM_derive_profile_pole/{k}")
        if pole is not None:
            print(f"{'derive 1/(2 + cos x)^k, k = ' + str(k) + ', s':40} {pole:12.4g}")
    one, two = r.seconds("BM_waviness_pressure_threads/1"), r.seconds("BM_waviness_pressure_threads/2")
    if one is not None and two is not None:
        print(f"{'waviness 1e6 points, 2 threads, s':40} {two:12.4g} {'1 thread':>24} {one:12.4g} {one / two:7.2f}x")
    for label, ours, limit, ratio, target in near_limit_rows(r):
        if ours is not None:
            shown = f"{limit:>24} {duration(ratio[1]) if ratio else '':>12}" if limit else f"{'':>24} {'':>12}"
            print(f"{label[:40]:40} {duration(ours):>12} {shown} {ratio[0] if ratio else '':>8} {target or ''}")
    ours = r.ns_per_item("BM_waviness_pressure_generated/1000000")
    if python_ns is not None and ours is not None:
        print(f"{'pressure 1e6 points from Python, ns/point':40} {python_ns:12.4g} {'C++ array API':>24} "
              f"{ours:12.4g} {python_ns / ours:7.2f}x (Python / C++)")
    for label, name in (("load P(a), s/call", "BM_load"), ("load P(a) beyond b1/2, s/call", "BM_load_beyond_half"),
                        ("inverse a(P) for a <= b1/2, s/call", "BM_single_asperity_half_width"),
                        ("all zones for P, given LoadCurve, s", "BM_equilibria"),
                        ("LoadCurve (turning points of P(a)), s", "BM_load_curve"),
                        ("pa/p* curve of 1000 points, s", "BM_pa_over_pstar_curve_1000"),
                        ("k_1..k_1024, s", "BM_kcoefficients/1024"),
                        ("full regeneration of generated/, s", "BM_regenerate_default"),
                        ("contact, two scales n = 6, 64 at P = 5.3, s", "BM_contact_two_scales_6_64"),
                        ("contact, 200 loads, two-scale n = 8, s", "BM_contact_curve_200/1"),
                        ("contact, 200 loads, m = 10 to full, s", "BM_contact_curve_200/0")):
        print(f"{label:40} {seconds_cell(r.seconds(name))}")


# ---- the docs' tables ---------------------------------------------------------------------

def many_zones_table(r):
    """docs/contact.md: the six many-zone cases beside boundary elements."""
    lines = ["| case | zones a period | wavecontact, tolerance 1e-8 | its estimate | boundary elements: grid | time "
             "| p(0) off | fraction off | time ratio |", "|---|---|---|---|---|---|---|---|---|"]
    for i in range(6):
        ours, bem = r.get(f"BM_contact_many_zones/{i}"), r.get(f"BM_contact_many_zones_bem/{i}")
        if ours is None or bem is None:
            return None
        t_ours, t_bem = r.seconds(f"BM_contact_many_zones/{i}"), r.seconds(f"BM_contact_many_zones_bem/{i}")
        lines.append(f"| {ours.get('label', '')} | {int(ours['zones'])} | {duration(t_ours)} | "
                     f"{ours['error_estimate']:.1e} | {int(bem['grid'])} | {duration(t_bem)} | {bem['p0_error']:.1e} "
                     f"| {bem['fraction_error']:.1e} | {t_bem / t_ours:.1f}× |")
    return lines


def contact_solves_table(r):
    """docs/contact.md: single solves and continuations, with their targets."""
    rows = [("n = 16, H2 = 0.15, pa/p* = 0.3 (7 zones a period), tolerance 1e-8", "BM_contact_multi_zone_n16", 0.01),
            ("FFT boundary elements on the same contact (three grids, Richardson; p(0) to about 1e-5)",
             "BM_contact_bem_oracle", None),
            ("two scales n = 6, 64 (H2 = 0.15, 0.01), P = 5.3 (8 zones), tolerance 1e-8",
             "BM_contact_two_scales_6_64", 1.0),
            ("200 loads by one continuation: n = 8, pa/p* to 0.6, tolerance 1e-10", "BM_contact_curve_200/1", 1.0),
            ("200 loads: the wave curve m = 10 through snap-through to full contact, tolerance 1e-10 (its "
             "kink's windows kept from an earlier run in the process)", "BM_contact_curve_200/0", 1.0)]
    lines = ["| solve | wall time | target |", "|---|---|---|"]
    for label, name, target in rows:
        t = r.seconds(name)
        if t is None:
            return None
        verdict = "" if target is None else f"{duration(target)} ({'met' if t <= target else 'missed'})"
        lines.append(f"| {label} | {duration(t)} | {verdict} |")
    # A sweep whose zones change at every load, against its loads solved one by one.
    dense, one_by_one = r.seconds("BM_contact_dense_sweep/1"), r.seconds("BM_contact_dense_sweep/0")
    if dense is None or one_by_one is None:
        return None
    lines.append("| 40 loads in one call: two roughness scales (n = 34, 412) on m = 3.74, the zones changing from "
                 f"load to load, tolerance 1e-8 | {duration(dense)} | ≤ 1.25× the same loads one call a load "
                 f"({'met' if dense <= 1.25 * one_by_one else 'missed'}) |")
    lines.append(f"| the same loads, one call a load | {duration(one_by_one)} | |")
    return lines


def performance_table(r):
    """docs/performance.md: each figure beside its baseline in the same run, with its target.
    A row: (figure, ours in seconds, baseline, the baseline's seconds, target), the target a
    pair (text, test of ours and the baseline's seconds) or None."""
    per_point = lambda name: None if r.ns_per_item(name) is None else r.ns_per_item(name) * 1e-9
    wave = per_point("BM_waviness_pressure_generated/1000000")
    python = None if r.python_ns is None else r.python_ns * 1e-9
    inversion = "numerical inversion at equal accuracy"
    quadrature = "long-double quadrature of eq. 12"
    rows = [("waviness pressure, array API, 10⁶ points, one thread, per point", wave,
             "the same formula written plainly, -O3 -ffast-math, for the same path (bench/plain_kernel.cpp)",
             per_point("BM_waviness_pressure_plain_same_isa/1000000"), ("≤ 1.5× its time", lambda t, b: t <= 1.5 * b)),
            ("", wave, "the same formula, atoms from scalar libm", per_point("BM_waviness_pressure_scalar_libm/1000000"),
             None),
            ("", wave, inversion, per_point("BM_waviness_pressure_numerical/10000"), None),
            ("", wave, "GiNaC print_csrc, no CSE", per_point("BM_waviness_pressure_no_cse/1000000"), None),
            ("the same, 10⁶ points on 2 threads", r.seconds("BM_waviness_pressure_threads/2"), "1 thread",
             r.seconds("BM_waviness_pressure_threads/1"), ("≥ 1.8×", lambda t, b: b >= 1.8 * t)),
            ("the same from Python (bench/python_pressure.py), per point", python, "the C++ array API", wave,
             ("within 1.1×", lambda t, b: t <= 1.1 * b))]
    targets = {16: ("≤ 4 ns", lambda t, b: t <= 4e-9), 256: ("≤ 25 ns, ≥ 50×", lambda t, b: t <= 25e-9 and b >= 50 * t)}
    for n in (16, 64, 256):
        ours = per_point(f"BM_roughness_pressure_generated/{n}")
        rows += [(f"roughness pressure, array API, n = {n}, per point", ours, inversion,
                  per_point(f"BM_roughness_pressure_numerical/{n}"), targets.get(n)),
                 ("", ours, "the point API, per call", per_point(f"BM_roughness_pressure_point/{n}"), None)]
    rows += [("k₁…k₁₂₈ (eq. 18)", r.seconds("BM_kcoefficients/128"), "SymPy (bench/sympy_kcoef.py)",
              r.seconds("BM_sympy_kcoefficients/128"), ("≥ 20×", lambda t, b: b >= 20 * t)),
             ("pressure beyond b1/2, a = 0.75 b1, m = 2: array of 10⁴ points, per point",
              per_point("BM_pressure_beyond_half_array/10000"), quadrature,
              per_point("BM_pressure_beyond_half_quadrature"), ("≤ 200 ns", lambda t, b: t <= 200e-9)),
             ("the same point by point", per_point("BM_pressure_beyond_half"), quadrature,
              per_point("BM_pressure_beyond_half_quadrature"), None),
             ("the same within 10⁻² … 10⁻¹² of the kink", per_point("BM_pressure_beyond_half_near_kink"), quadrature,
              per_point("BM_pressure_beyond_half_near_kink_quadrature"), None)]
    for label, name, bound in (("load P(a), a ≤ b1/2", "BM_load", None),
                               ("load P(a), beyond b1/2", "BM_load_beyond_half", None),
                               ("inverse a(P), a ≤ b1/2", "BM_single_asperity_half_width", 200e-9),
                               ("every zone for P (LoadCurve::equilibria)", "BM_equilibria", None),
                               ("LoadCurve itself", "BM_load_curve", None),
                               ("pa/p* against 2a/L1, 1000 points", "BM_pa_over_pstar_curve_1000", None),
                               ("k₁…k₁₀₂₄", "BM_kcoefficients/1024", 1.0),
                               ("full regeneration of generated/", "BM_regenerate_default", 60.0)):
        rows.append((label, r.seconds(name), "", None,
                     None if bound is None else (f"≤ {duration(bound)}", lambda t, b, bound=bound: t <= bound)))
    lines = ["| figure | ours | baseline | its time | baseline / ours | target |", "|---|---|---|---|---|---|"]
    for label, ours, base_label, base, target in rows:
        if ours is None or (base_label and base is None):
            return None
        ratio = "" if not base_label else f"{base / ours:,.0f}×" if base >= 100 * ours else f"{base / ours:.3g}×"
        verdict = f"{target[0]} ({'met' if target[1](ours, base) else 'missed'})" if target else ""
        lines.append(f"| {label} | {duration(ours)} | {base_label} | {duration(base) if base_label else ''} | "
                     f"{ratio} | {verdict} |")
    return lines


def near_limit_rows(r):
    """The kernels beside what limits them (issue: performance like with like): the waviness
    array kernel on each path against the plain kernel built for that path, and the latency of
    one call, from C++ and from Python. A row: (figure, ours in seconds, the limit's name,
    (ratio text, the limit's seconds) or None, target text or None)."""
    rows = []
    for run in r.isa_runs:
        b = run.get("BM_waviness_pressure_generated/1000000")
        ours, plain = run.ns_per_item("BM_waviness_pressure_generated/1000000"), run.ns_per_item(
            "BM_waviness_pressure_plain_same_isa/1000000")
        if b is None or ours is None or plain is None or any(row[0].endswith(f"({b.get('label')} path)") for row in rows):
            continue  # a path the CPU lacks runs capped at the best it has: one row a path
        verdict = "met" if ours <= 1.5 * plain else "missed"
        rows.append((f"waviness array, 10⁶ points, one thread, a point ({b.get('label')} path)", ours * 1e-9,
                     "the plain formula, same path", (f"{ours / plain:.2f}×", plain * 1e-9), f"≤ 1.5× ({verdict})"))
    point = lambda name: None if r.ns_per_item(name) is None else r.ns_per_item(name) * 1e-9
    targets = [("one point, WavinessZone, a ≤ b1/2", point("BM_point_zone/0"), 30e-9),
               ("one point, WavinessZone, a = 0.75 b1", point("BM_point_zone/1"), 200e-9),
               ("one point, free function, a ≤ b1/2", point("BM_point_free_function/0"), None),
               ("one point, free function, a = 0.75 b1", point("BM_point_free_function/1"), None),
               ("ten points as an array, WavinessZone, a call", point("BM_ten_points_zone"), None)]
    py = lambda name: None if name not in r.python else r.python[name] * 1e-9
    targets += [("Python: one point, wavecontact.pressure", py("python_point_free_function_ns"), 300e-9),
                ("Python: one point, WavinessZone.pressure", py("python_point_zone_ns"), None),
                ("Python: ten points, wavecontact.pressure", py("python_ten_points_free_function_ns"), 1e-6),
                ("Python: ten points, WavinessZone.pressure", py("python_ten_points_zone_ns"), None)]
    for label, ours, bound in targets:
        verdict = None if bound is None or ours is None else (
            f"≤ {duration(bound)} ({'met' if ours <= bound else 'missed'})")
        rows.append((label, ours, "", None, verdict))
    return rows


def near_limit_table(r):
    """README.md and docs/performance.md: near_limit_rows, when the run has them all."""
    rows = near_limit_rows(r)
    if not r.isa_runs or any(ours is None for _, ours, _, _, _ in rows):
        return None
    lines = ["| figure | ours | the limit | its time | ours / limit | target |", "|---|---|---|---|---|---|"]
    for label, ours, limit, ratio, target in rows:
        lines.append(f"| {label} | {duration(ours)} | {limit} | {duration(ratio[1]) if ratio else ''} | "
                     f"{ratio[0] if ratio else ''} | {target or ''} |")
    return lines


def derive_times_table(r):
    """docs/performance.md: wavecontact-derive --profile end to end ("now") beside the closed
    forms alone through the engine's partial fractions ("whole"), up to order 32; and a pole
    1/(2 + cos x)^k end to end, up to the bound 32 of a denominator."""
    lines = ["| order k | H cos(k x): whole → now | ratio | H cos(x)^k: whole → now | ratio | 1/(2 + cos x)^k: now |",
             "|---|---|---|---|---|---|"]
    for k in (8, 16, 32, 64, 128, 256):
        cells = []
        for shape in ("harmonic", "power"):
            now, whole = r.seconds(f"BM_derive_profile_{shape}/{k}"), r.seconds(f"BM_derive_whole_{shape}/{k}")
            if now is None:
                return None
            cells += [f"{duration(whole)} → {duration(now)}", f"{whole / now:.3g}×"] if whole else [
                f"→ {duration(now)}", ""]
        pole = r.seconds(f"BM_derive_profile_pole/{k}")
        cells.append(duration(pole) if pole is not None else "")
        lines.append(f"| {k} | " + " | ".join(cells) + " |")
    return lines


TABLES = {"contact-many-zones": many_zones_table, "contact-solves": contact_solves_table,
          "performance": performance_table, "derive-times": derive_times_table, "near-limit": near_limit_table}


def write_docs(r, docs):
    doc_tables.rewrite(docs, "bench", {name: (lambda table=table: table(r)) for name, table in TABLES.items()},
                       r.run_name())


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results")
    parser.add_argument("--isa-run", action="append", default=[],
                        help="a run of the waviness kernel on one path (repeatable)")
    parser.add_argument("--python", help="bench/python_pressure.py's output")
    parser.add_argument("--docs", action="append",
                        help="rewrite the tables of this .md file, or of the .md files in this folder (repeatable)")
    args = parser.parse_args()
    r = Results(args.results)
    r.isa_runs = [Results(path) for path in args.isa_run if os.path.exists(path)]
    if args.python and os.path.exists(args.python):
        for line in open(args.python):
            name, value = line.split()
            r.python[name] = float(value)
    print_report(r, r.python_ns)
    if args.docs:
        write_docs(r, args.docs)


if __name__ == "__main__":
    main()
