#!/usr/bin/env bash
# wavecontact-derive --out touches only the files it writes (issue 28, item 2).
#   derive_output_safety_test.sh DERIVE WORKDIR
# Each case is one that lost or rewrote the user's data when the tool copied, exchanged and
# deleted its output directory: concurrent runs, a symbolic link, the current and the root
# directory, a directory of the user's, a file held open while it runs, a failed run.
set -euo pipefail
derive=$1 work=$2
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}print_suppressions=0"
rm -rf "$work"
mkdir -p "$work"
ns=(--n 4 --n 6)
expect_status() {  # expect_status STATUS MESSAGE-PART ARGS...
  local want=$1 part=$2 status=0
  shift 2
  "$derive" "$@" > "$work/stdout" 2> "$work/stderr" || status=$?
  if [ "$status" -ne "$want" ] || ! grep -qF -- "$part" "$work/stderr"; then
    echo "FAIL: $* -> exit $status (expected $want, \"$part\"):" >&2
    cat "$work/stderr" >&2
    exit 1
  fi
}

# 1. Six concurrent runs into one new directory: all succeed, every file is there and whole.
"$derive" "${ns[@]}" --out "$work/reference"
pids=()
for i in 1 2 3 4 5 6; do
  "$derive" "${ns[@]}" --out "$work/concurrent" & pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid"; done
diff -r "$work/reference" "$work/concurrent"
echo "6 concurrent runs: all exit 0, every file whole"

# 2. A symbolic link is written through: the link stays, its target is updated.
mkdir -p "$work/target"
cp "$work/reference"/* "$work/target/"
echo "// stale" >> "$work/target/roughness_n4.hpp"
ln -s target "$work/link"
"$derive" "${ns[@]}" --out "$work/link"
[ -L "$work/link" ]
diff -r "$work/reference" "$work/target"
echo "a symbolic link: kept, its target updated"

# 3. The root, the current directory and a directory of the user's are refused (exit 2),
#    untouched; --force writes into the user's directory and keeps what it holds.
mkdir -p "$work/mine/sub"
echo "mine" > "$work/mine/notes.txt"
echo "deep" > "$work/mine/sub/deep.txt"
ln "$work/mine/notes.txt" "$work/hardlink"
before=$(cd "$work/mine" && find . -print0 | sort -z | xargs -0 ls -ld --time-style=+%s.%N | sha256sum)
expect_status 2 "it is the root directory" "${ns[@]}" --out /
(cd "$work/mine" && expect_status 2 "it is the current directory" "${ns[@]}" --out .)
expect_status 2 "holds no file written by wavecontact-derive" "${ns[@]}" --out "$work/mine"
[ "$(cd "$work/mine" && find . -print0 | sort -z | xargs -0 ls -ld --time-style=+%s.%N | sha256sum)" = "$before" ]
"$derive" "${ns[@]}" --out "$work/mine" --force
[ "$(cat "$work/mine/notes.txt")" = mine ] && [ "$(cat "$work/mine/sub/deep.txt")" = deep ]
[ "$(stat -c %h "$work/mine/notes.txt")" = 2 ]
cmp "$work/reference/roughness_n4.hpp" "$work/mine/roughness_n4.hpp"
echo "root, current and user directories refused; --force keeps the user's files and links"

# 4. A file of the user's held open and written while the tool runs loses nothing.
mkdir -p "$work/open"
cp "$work/reference"/* "$work/open/"
( exec 3>> "$work/open/log.txt"; for i in $(seq 1 200); do echo "line $i" >&3; sleep 0.005; done ) &
writer=$!
"$derive" "${ns[@]}" --out "$work/open"
wait "$writer"
[ "$(wc -l < "$work/open/log.txt")" = 200 ]
echo "a file held open: all 200 lines kept"

# 5. A failed run (a target that is a directory: refused as not ours, or with --force, a write
#    that fails) exits 5 and leaves nothing behind.
mkdir -p "$work/failing/roughness_n6.hpp"
cp "$work/reference/roughness_n4.hpp" "$work/failing/"
expect_status 2 "roughness_n6.hpp exists and was not written by wavecontact-derive" "${ns[@]}" --out "$work/failing"
expect_status 5 "roughness_n6.hpp exists and is not a regular file" "${ns[@]}" --out "$work/failing" --force
if ls -A "$work/failing" | grep -q '\.tmp-'; then
  echo "FAIL: a failed run left a temporary file" >&2
  exit 1
fi
echo "a failed run: exit 5, no temporary file left"
