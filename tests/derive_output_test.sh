#!/usr/bin/env bash
# wavecontact-derive writes deterministically and atomically.
#   derive_output_test.sh DERIVE COMMITTED_GENERATED WORKDIR
# 1. Two full runs under different locales, and --n runs with the options in either order,
#    give byte-identical files.
# 2. Killed (SIGKILL) at moments spread over a full run, it leaves each file it writes whole
#    (old or new), the user's files untouched, and the next run completes the update.
set -euo pipefail
committed=$2 work=$3
# A known job, not a test of the budget: under the sanitizers and beside other tests, a full
# run outlasts the default --max-seconds of 60.
derive=("$1" --max-seconds 3600)
rm -rf "$work"
mkdir -p "$work"

start=$(date +%s.%N)
LC_ALL=C "${derive[@]}" --out "$work/a"
duration=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { print e - s }')
# The second run with the environment grown by some kB and malloc's fill changed, which moves the
# addresses GiNaC's ordering of terms depends on (a sign or an order taken from it shows here).
WAVECONTACT_TEST_PADDING=$(head -c 5003 /dev/zero | tr '\0' x) MALLOC_PERTURB_=91 \
  LC_ALL=C.UTF-8 LANG=de_DE.UTF-8 LC_NUMERIC=de_DE.UTF-8 "${derive[@]}" --out "$work/b"
diff -r "$work/a" "$work/b"
"${derive[@]}" --n 4 --n 96 --out "$work/c"
"${derive[@]}" --n 96 --n 4 --out "$work/d"
diff -r "$work/c" "$work/d"
echo "deterministic: two full runs and two --n orders agree"

# Killed (SIGKILL) at moments spread over a full run: every file it writes is whole, its old
# or its new version; the user's file is untouched; only the killed run's temporary file
# (.NAME.tmp-PID) may be left, and the next run removes it and completes the update.
old_states=0 new_states=0
# The last, "end", lets the run finish before the kill: beside other tests the run can take
# several times the first one's duration, so no fixed multiple of it is surely after the end.
for fraction in 0 0.5 0.9 0.97 0.99 end; do
  delay=$(awk -v d="$duration" -v f="$fraction" 'BEGIN { print f == "end" ? 0 : d * f }')
  rm -rf "$work/out" "$work/before"
  cp -r "$committed" "$work/out"
  echo "// an older version" >> "$work/out/waviness_evaluators.hpp"
  echo "user file" > "$work/out/notes.txt"
  cp -r "$work/out" "$work/before"
  "${derive[@]}" --out "$work/out" &
  pid=$!
  if [ "$fraction" = end ]; then
    wait "$pid"
  else
    sleep "$delay"
  fi
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  for path in "$work/out"/* "$work/out"/.[!.]*; do
    [ -e "$path" ] || continue
    name=$(basename "$path")
    case "$name" in
      .*.tmp-"$pid") continue ;;
      notes.txt) cmp -s "$path" "$work/before/$name" || { echo "the user's file changed" >&2; exit 1; } ;;
      *)
        if ! { [ -f "$work/before/$name" ] && cmp -s "$path" "$work/before/$name"; } &&
           ! { [ -f "$work/a/$name" ] && cmp -s "$path" "$work/a/$name"; }; then
          echo "killed after ${delay}s: $name is neither its old nor its new version" >&2
          exit 1
        fi ;;
    esac
  done
  if cmp -s "$work/out/waviness_evaluators.hpp" "$work/before/waviness_evaluators.hpp"; then
    old_states=$((old_states + 1))
  else
    new_states=$((new_states + 1))
  fi
  # The next run completes the update and leaves nothing of the killed one.
  "${derive[@]}" --out "$work/out"
  rm "$work/out/notes.txt"
  diff -r "$work/a" "$work/out"
done
echo "interrupted runs: $old_states before waviness_evaluators.hpp was replaced, $new_states after; each file whole; every rerun completed the update"
[ "$old_states" -gt 0 ] && [ "$new_states" -gt 0 ]
