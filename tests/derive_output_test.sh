#!/usr/bin/env bash
# wavecontact-derive writes deterministically and atomically.
#   derive_output_test.sh DERIVE COMMITTED_GENERATED WORKDIR
# 1. Two full runs under different locales, and --n runs with the options in either order,
#    give byte-identical files.
# 2. Killed (SIGKILL) at moments spread over a full run, it leaves the output directory
#    exactly as it was or fully updated (files it does not write are kept).
set -euo pipefail
derive=$1 committed=$2 work=$3
rm -rf "$work"
mkdir -p "$work"

checksum() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 sha256sum) | sha256sum | cut -d' ' -f1; }

start=$(date +%s.%N)
LC_ALL=C "$derive" --out "$work/a"
duration=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { print e - s }')
# The second run with the environment grown by some kB and malloc's fill changed, which moves the
# addresses GiNaC's ordering of terms depends on (a sign or an order taken from it shows here).
WAVECONTACT_TEST_PADDING=$(head -c 5003 /dev/zero | tr '\0' x) MALLOC_PERTURB_=91 \
  LC_ALL=C.UTF-8 LANG=de_DE.UTF-8 LC_NUMERIC=de_DE.UTF-8 "$derive" --out "$work/b"
diff -r "$work/a" "$work/b"
"$derive" --n 4 --n 96 --out "$work/c"
"$derive" --n 96 --n 4 --out "$work/d"
diff -r "$work/c" "$work/d"
echo "deterministic: two full runs and two --n orders agree"

# The fully updated state keeps a file the tool does not write.
cp -r "$work/a" "$work/expected_new"
echo "user file" > "$work/expected_new/notes.txt"
new=$(checksum "$work/expected_new")

old_count=0 new_count=0
# Kill moments as fractions of a full run (the sanitizer build is several times slower).
for fraction in 0 0.02 0.1 0.3 0.5 0.7 0.9 3; do
  delay=$(awk -v d="$duration" -v f="$fraction" 'BEGIN { print d * f }')
  rm -rf "$work/out"
  cp -r "$committed" "$work/out"
  echo "// an older version" >> "$work/out/waviness.hpp"
  echo "user file" > "$work/out/notes.txt"
  old=$(checksum "$work/out")
  "$derive" --out "$work/out" &
  pid=$!
  sleep "$delay"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  now=$(checksum "$work/out")
  if [ "$now" = "$old" ]; then
    old_count=$((old_count + 1))
  elif [ "$now" = "$new" ]; then
    new_count=$((new_count + 1))
  else
    echo "killed after ${delay}s (full run ${duration}s): $work/out is neither the old nor the new state" >&2
    exit 1
  fi
done
echo "interrupted runs: $old_count left the old state, $new_count the new state, none a mixture"
[ "$old_count" -gt 0 ] && [ "$new_count" -gt 0 ]
