#!/usr/bin/env bash
# Runs the benchmarks and prints each figure next to its baseline, with the ratio.
#   scripts/bench.sh [extra Google Benchmark options, e.g. --benchmark_min_time=0.01, or
#                    --benchmark_repetitions=5 for medians]
# Raw results: build/bench/results.json (--benchmark_format=json).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/bench/wavecontact_bench ] || scripts/build.sh
build/bench/wavecontact_bench --benchmark_out=build/bench/results.json \
  --benchmark_out_format=json "$@"
# The Python module's figure (timeit), where it is built: bench/python_pressure.py.
python_figure=build/bench/python_pressure.txt
rm -f "$python_figure"
if [ -d build/python/wavecontact ]; then
  PYTHONPATH=build/python /usr/bin/python3 bench/python_pressure.py > "$python_figure"
fi
python3 - build/bench/results.json "$python_figure" <<'PY'
import json
import os
import sys

# With --benchmark_repetitions, each figure is the median of the repetitions.
runs = json.load(open(sys.argv[1]))["benchmarks"]
results = {b["name"]: b for b in runs if b.get("run_type") != "aggregate"}
results.update({b["run_name"]: b for b in runs if b.get("aggregate_name") == "median"})
python_ns = None
if os.path.exists(sys.argv[2]):
    python_ns = float(open(sys.argv[2]).read().split()[1])

def per_item_ns(name):
    b = results.get(name)
    if b is None or "items_per_second" not in b:
        return None
    return 1e9 / b["items_per_second"]

def time_ns(name):
    b = results.get(name)
    if b is None or b.get("error_occurred"):
        return None
    scale = {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}[b["time_unit"]]
    return b["real_time"] * scale

rows = [
    ("waviness pressure, ns/point", per_item_ns, "BM_waviness_pressure_generated/1000000",
     [("plain -ffast-math kernel", "BM_waviness_pressure_plain_fast_math/1000000"),
      ("same formula, scalar libm", "BM_waviness_pressure_scalar_libm/1000000"),
      ("numerical inversion", "BM_waviness_pressure_numerical/10000"),
      ("print_csrc, no CSE", "BM_waviness_pressure_no_cse/1000000")]),
]
for n in (16, 64, 256):
    rows.append((f"roughness pressure n={n}, ns/point", per_item_ns,
                 f"BM_roughness_pressure_generated/{n}",
                 [("numerical inversion", f"BM_roughness_pressure_numerical/{n}"),
                  ("point API, per call", f"BM_roughness_pressure_point/{n}")]))
rows.append(("k_1..k_128, ns", time_ns, "BM_kcoefficients/128",
             [("SymPy", "BM_sympy_kcoefficients/128/iterations:1/manual_time")]))
rows.append(("contact n=16, 7 zones, 1e-8, ns", time_ns, "BM_contact_multi_zone_n16",
             [("BEM oracle, 3 grids", "BM_contact_bem_oracle")]))
print(f"\n{'figure':40} {'ours':>12} {'baseline':>24} {'value':>12} {'ratio':>8}")
for label, measure, ours_name, baselines in rows:
    ours = measure(ours_name)
    for baseline_label, baseline_name in baselines:
        base = measure(baseline_name)
        if ours is None or base is None:
            print(f"{label:40} {'n/a':>12} {baseline_label:>24} {'n/a':>12}")
            continue
        print(f"{label:40} {ours:12.4g} {baseline_label:>24} {base:12.4g} {base / ours:7.1f}x")
# The many-zone contacts beside boundary elements: time, zones, accuracy of each.
def named(prefix):  # a benchmark's name with its suffixes (/iterations:1/repeats:3)
    return next((name for name in results if name == prefix or name.startswith(prefix + "/")), None)

for i in range(6):
    ours_name, bem_name = named(f"BM_contact_many_zones/{i}"), named(f"BM_contact_many_zones_bem/{i}")
    if ours_name is None or bem_name is None:
        continue
    ours, bem = results[ours_name], results[bem_name]
    t_ours, t_bem = time_ns(ours_name) / 1e6, time_ns(bem_name) / 1e6
    print(f"{ours.get('label', '')[:40]:40} {t_ours:10.4g} ms, {int(ours['zones'])} zones, estimate "
          f"{ours['error_estimate']:.1e} | BEM {int(bem['grid'])} points {t_bem:10.4g} ms, p(0) off by "
          f"{bem['p0_error']:.1e}, fraction off by {bem['fraction_error']:.1e} | {t_bem / t_ours:5.1f}x")
for k in (8, 16, 32, 64, 128, 256):
    for label, shape in (("H cos(k x)", "harmonic"), ("H cos(x)^k", "power")):
        now = time_ns(f"BM_derive_profile_{shape}/{k}/iterations:1")
        whole = time_ns(f"BM_derive_whole_{shape}/{k}/iterations:1")
        row = f"{'derive ' + label + ', k = ' + str(k) + ', ms':40} {now / 1e6 if now else float('nan'):12.4g}"
        if whole is not None and now is not None:
            row += f" {'whole, partial fractions':>24} {whole / 1e6:12.4g} {whole / now:7.1f}x"
        print(row)
one, two = time_ns("BM_waviness_pressure_threads/1/real_time"), time_ns("BM_waviness_pressure_threads/2/real_time")
if one is not None and two is not None:
    print(f"{'waviness 1e6 points, 2 threads, ns':40} {two:12.4g} {'1 thread':>24} {one:12.4g} {one / two:7.2f}x")
ours = per_item_ns("BM_waviness_pressure_generated/1000000")
if python_ns is not None and ours is not None:
    print(f"{'pressure 1e6 points from Python, ns/point':40} {python_ns:12.4g} {'C++ array API':>24} {ours:12.4g}"
          f" {python_ns / ours:7.2f}x (Python / C++)")
for label, ours_name, baseline_name in (
        ("pressure beyond b1/2, array, ns/point", "BM_pressure_beyond_half_array/10000", "BM_pressure_beyond_half_quadrature"),
        ("pressure beyond b1/2, per point", "BM_pressure_beyond_half", "BM_pressure_beyond_half_quadrature"),
        ("the same within 1e-2..1e-12 of the kink", "BM_pressure_beyond_half_near_kink",
         "BM_pressure_beyond_half_near_kink_quadrature")):
    ours, base = per_item_ns(ours_name), per_item_ns(baseline_name)
    if ours is None or base is None:
        print(f"{label:40} {'n/a':>12} {'quadrature of eq. 12':>24} {'n/a':>12}")
        continue
    print(f"{label:40} {ours:12.4g} {'quadrature of eq. 12':>24} {base:12.4g} {base / ours:7.1f}x")
for label, name in (("load P(a), ns/call", "BM_load"), ("load P(a) beyond b1/2, ns/call", "BM_load_beyond_half"), ("inverse a(P) for a <= b1/2, ns/call", "BM_single_asperity_half_width"),
                    ("all zones for P, given LoadCurve, ns", "BM_equilibria"),
                    ("LoadCurve (turning points of P(a)), ns", "BM_load_curve"),
                    ("pa/p* curve of 1000 points, ns", "BM_pa_over_pstar_curve_1000"),
                    ("k_1..k_1024, ns", "BM_kcoefficients/1024"),
                    ("full regeneration of generated/, ns", "BM_regenerate_default/iterations:1"),
                    ("contact, 200 loads, two-scale n = 8, ns", "BM_contact_curve_200/1"),
                    ("contact, 200 loads, m = 10 to full, ns", "BM_contact_curve_200/0")):
    value = time_ns(name)
    print(f"{label:40} {value if value is not None else float('nan'):12.4g}")
PY
