#!/usr/bin/env bash
# Runs the benchmarks and prints each figure next to its baseline, with the ratio
# (scripts/bench_report.py).
#   scripts/bench.sh [--docs] [extra Google Benchmark options, e.g. --benchmark_min_time=0.01,
#                    or --benchmark_repetitions=3 for medians]
# --docs also rewrites the tables of docs/ and README.md that come from this run.
# Raw results: build/bench/results.json (--benchmark_format=json), with the commit.
set -euo pipefail
cd "$(dirname "$0")/.."
report_options=()
if [ "${1:-}" = --docs ]; then
  report_options=(--docs docs --docs README.md)
  shift
fi
[ -x build/bench/wavecontact_bench ] || scripts/build.sh
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD 2>/dev/null || commit="$commit with local changes"
build/bench/wavecontact_bench --benchmark_out=build/bench/results.json \
  --benchmark_out_format=json "--benchmark_context=commit=$commit" "$@"
# The waviness array kernel on every path (WAVECONTACT_ISA, capped at what the CPU has), each
# beside the plain kernel built for that path: like with like.
isa_runs=()
for isa in scalar avx2 avx512; do
  WAVECONTACT_ISA=$isa build/bench/wavecontact_bench --benchmark_out="build/bench/results_$isa.json" \
    --benchmark_out_format=json "$@" --benchmark_filter='BM_waviness_pressure_(generated|plain_same_isa)/' \
    > /dev/null
  isa_runs+=(--isa-run "build/bench/results_$isa.json")
done
# The Python module's figure (timeit), where it is built: bench/python_pressure.py.
python_figure=build/bench/python_pressure.txt
rm -f "$python_figure"
if [ -d build/python/wavecontact ]; then
  PYTHONPATH=build/python /usr/bin/python3 bench/python_pressure.py > "$python_figure"
fi
/usr/bin/python3 scripts/bench_report.py build/bench/results.json "${isa_runs[@]}" --python "$python_figure" \
  "${report_options[@]}"
