#!/usr/bin/env bash
# The contact solver's random campaign (tests/campaign/contact_campaign.cpp): 2000 seeded load
# sweeps, 1-4 harmonics, n up to 1024, m in [0, 35], loads to beyond full contact, every
# contact checked on the whole period. The sweeps are split over the cores; each part's log
# is kept in OUT (default build/campaign), and the summary lines are printed at the end.
#   scripts/contact_campaign.sh [SWEEPS] [SEED] [OUT]
set -euo pipefail
cd "$(dirname "$0")/.."
sweeps=${1:-2000}
seed=${2:-1}
out=${3:-build/campaign}
scripts/build.sh >/dev/null
mkdir -p "$out"
parts=$(nproc)
per=$(( (sweeps + parts - 1) / parts ))
pids=()
for ((p = 0; p < parts; ++p)); do
  first=$(( p * per ))
  count=$(( first + per > sweeps ? sweeps - first : per ))
  (( count > 0 )) || continue
  build/tests/contact_campaign --seed "$seed" --first "$first" --sweeps "$count" --max-n 1024 \
    > "$out/part$p.log" &
  pids+=($!)
done
status=0
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
grep -h "^campaign" "$out"/part*.log
grep -h "STALL\|VIOLATION" "$out"/part*.log || true
exit $status
