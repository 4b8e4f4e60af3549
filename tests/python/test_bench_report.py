"""scripts/bench_report.py: the docs' tables are rewritten from a benchmark run between their
markers, name the run, and are left as they were when the run lacks their figures."""
import json
import os
import subprocess
import sys


def run(source_dir, results, docs):
    script = os.path.join(source_dir, "scripts", "bench_report.py")
    return subprocess.run([sys.executable, script, str(results), "--docs", str(docs)], capture_output=True, text=True)


def benchmark(name, seconds, **counters):
    return {"name": name, "run_name": name, "run_type": "iteration", "real_time": seconds * 1e3, "time_unit": "ms",
            **counters}


def write_run(path, benchmarks):
    context = {"date": "2026-11-26T05:00:00+00:00", "host_name": "testhost", "num_cpus": 2, "mhz_per_cpu": 2596,
               "executable": "build/bench/wavecontact_bench", "commit": "abc1234"}
    path.write_text(json.dumps({"context": context, "benchmarks": benchmarks}))


def test_contact_solves_table_is_written_and_names_its_run(tmp_path, source_dir):
    docs = tmp_path / "docs"
    docs.mkdir()
    page = docs / "contact.md"
    page.write_text("before\n<!-- bench:contact-solves -->\nold table\n<!-- /bench:contact-solves -->\nafter\n")
    results = tmp_path / "results.json"
    write_run(results, [benchmark("BM_contact_multi_zone_n16/real_time", 0.0228),
                        benchmark("BM_contact_bem_oracle/real_time", 0.798),
                        benchmark("BM_contact_two_scales_6_64/real_time", 0.0697),
                        benchmark("BM_contact_curve_200/1/real_time", 0.485),
                        benchmark("BM_contact_curve_200/0/real_time", 37.8),
                        benchmark("BM_contact_dense_sweep/1/real_time", 2.6),
                        benchmark("BM_contact_dense_sweep/0/real_time", 2.0)])
    r = run(source_dir, results, docs)
    assert r.returncode == 0, r.stderr
    text = page.read_text()
    assert "old table" not in text
    assert text.startswith("before\n<!-- bench:contact-solves -->\n") and text.endswith(
        "<!-- /bench:contact-solves -->\nafter\n")
    assert "Run of 2026-11-26T05:00:00+00:00 on testhost (2 CPUs at 2596 MHz), commit abc1234" in text
    assert "| 22.8 ms | 10 ms (missed) |" in text
    assert "| 69.7 ms | 1 s (met) |" in text
    assert "| 37.8 s | 1 s (missed) |" in text
    assert "| 2.6 s | ≤ 1.25× the same loads one call a load (missed) |" in text  # 1.3×
    assert "| the same loads, one call a load | 2 s | |" in text


def test_a_table_the_run_lacks_is_left_as_it_was(tmp_path, source_dir):
    docs = tmp_path / "docs"
    docs.mkdir()
    original = "<!-- bench:contact-many-zones -->\nkept\n<!-- /bench:contact-many-zones -->\n"
    (docs / "contact.md").write_text(original)
    results = tmp_path / "results.json"
    write_run(results, [benchmark("BM_contact_many_zones/0/real_time", 0.08, zones=71, error_estimate=5e-12)])
    r = run(source_dir, results, docs)
    assert r.returncode == 0, r.stderr
    assert (docs / "contact.md").read_text() == original
    assert "left as it was" in r.stdout


def test_an_unknown_table_is_refused(tmp_path, source_dir):
    docs = tmp_path / "docs"
    docs.mkdir()
    (docs / "a.md").write_text("<!-- bench:no-such-table -->\n<!-- /bench:no-such-table -->\n")
    results = tmp_path / "results.json"
    write_run(results, [])
    r = run(source_dir, results, docs)
    assert r.returncode != 0
    assert "no-such-table" in r.stderr


def test_derivation_times_table_gives_the_ratio_where_both_ran(tmp_path, source_dir):
    docs = tmp_path / "docs"
    docs.mkdir()
    page = docs / "performance.md"
    page.write_text("<!-- bench:derive-times -->\n<!-- /bench:derive-times -->\n")
    runs = []
    for k in (8, 16, 32, 64, 128, 256):
        runs += [benchmark(f"BM_derive_profile_harmonic/{k}/iterations:1", 0.001 * k),
                 benchmark(f"BM_derive_profile_power/{k}/iterations:1", 0.0005 * k)]
        if k <= 32:
            runs += [benchmark(f"BM_derive_whole_harmonic/{k}/iterations:1", 0.1 * k),
                     benchmark(f"BM_derive_whole_power/{k}/iterations:1", 0.1 * k)]
    results = tmp_path / "results.json"
    write_run(results, runs)
    r = run(source_dir, results, docs)
    assert r.returncode == 0, r.stderr
    text = page.read_text()
    assert "| 8 | 800 ms → 8 ms | 100× | 800 ms → 4 ms | 200× |" in text
    assert "| 256 | → 256 ms |  | → 128 ms |  |" in text


def kernel_run(path, isa, ours_ns, plain_ns):
    """A --isa-run: the waviness kernel and the plain kernel of one path, ns a point."""
    write_run(path, [benchmark("BM_waviness_pressure_generated/1000000", ours_ns * 1e-3, label=isa,
                               items_per_second=1e9 / ours_ns),
                     benchmark("BM_waviness_pressure_plain_same_isa/1000000", plain_ns * 1e-3, label=isa,
                               items_per_second=1e9 / plain_ns)])


def test_near_limit_table_compares_each_path_with_its_own_plain_kernel(tmp_path, source_dir):
    docs = tmp_path / "docs"
    docs.mkdir()
    readme = tmp_path / "README.md"
    readme.write_text("<!-- bench:near-limit -->\n<!-- /bench:near-limit -->\n")
    latency = {"BM_point_zone/0": 25, "BM_point_zone/1": 900, "BM_point_free_function/0": 120,
               "BM_point_free_function/1": 2500, "BM_ten_points_zone": 210}
    results = tmp_path / "results.json"
    write_run(results, [benchmark(name, ns * 1e-6, items_per_second=1e9 / ns) for name, ns in latency.items()])
    runs = []
    # A CPU without AVX-512: the avx512 run is capped at avx2 and must not make a second row.
    for isa, ran_as, ours, plain in (("scalar", "scalar", 9.0, 7.0), ("avx2", "avx2", 4.0, 2.0),
                                     ("avx512", "avx2", 4.1, 2.1)):
        kernel_run(tmp_path / f"results_{isa}.json", ran_as, ours, plain)
        runs += ["--isa-run", str(tmp_path / f"results_{isa}.json")]
    python = tmp_path / "python.txt"
    python.write_text("python_pressure_ns_per_point 2.6\npython_point_free_function_ns 250\n"
                      "python_point_zone_ns 180\npython_ten_points_free_function_ns 1200\n"
                      "python_ten_points_zone_ns 700\n")
    script = os.path.join(source_dir, "scripts", "bench_report.py")
    r = subprocess.run([sys.executable, script, str(results), *runs, "--python", str(python), "--docs", str(readme)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    text = readme.read_text()
    assert "| waviness array, 10⁶ points, one thread, a point (scalar path) | 9 ns | the plain formula, same path " \
           "| 7 ns | 1.29× | ≤ 1.5× (met) |" in text
    assert "(avx2 path) | 4 ns | the plain formula, same path | 2 ns | 2.00× | ≤ 1.5× (missed) |" in text
    assert text.count("avx2 path") == 1
    assert "| one point, WavinessZone, a ≤ b1/2 | 25 ns |  |  |  | ≤ 30 ns (met) |" in text
    assert "| one point, WavinessZone, a = 0.75 b1 | 900 ns |  |  |  | ≤ 200 ns (missed) |" in text
    assert "| Python: one point, wavecontact.pressure | 250 ns |  |  |  | ≤ 300 ns (met) |" in text
    assert "| Python: ten points, wavecontact.pressure | 1.2 µs |  |  |  | ≤ 1 µs (missed) |" in text


def test_console_report_says_which_figures_the_run_left_out(tmp_path, source_dir):
    results = tmp_path / "results.json"
    write_run(results, [benchmark("BM_contact_curve_200/1/real_time", 0.485)])
    script = os.path.join(source_dir, "scripts", "bench_report.py")
    r = subprocess.run([sys.executable, script, str(results)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    rows = {line[:40].rstrip(): line[40:].strip() for line in r.stdout.splitlines()}
    assert rows["contact, 200 loads, two-scale n = 8, s"] == "0.485"
    assert rows["contact, 200 loads, m = 10 to full, s"] == "not run"
    assert rows["derive H cos(k x), k = 8, s"] == "not run"
    assert "nan" not in r.stdout
