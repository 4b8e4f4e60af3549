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
                        benchmark("BM_contact_curve_200/0/real_time", 37.8)])
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
