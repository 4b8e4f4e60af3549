#!/usr/bin/env bash
# Every refused input of wavecontact-derive --profile exits 2 with one line on stderr that
# names what and why, and leaves the output directory exactly as it was.
#   derive_refusals_test.sh DERIVE CASES WORKDIR
# CASES: one case a line, "EXPRESSION|PART OF THE MESSAGE" (the profile has --param H).
set -euo pipefail
derive=$1 cases=$2 work=$3
# Under the sanitize preset LeakSanitizer would add its suppression statistics to stderr.
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}print_suppressions=0"
rm -rf "$work"
mkdir -p "$work/out"
echo "kept" > "$work/out/user_file.txt"
checksum() { (cd "$1" && find . -print0 | sort -z | xargs -0 ls -ld --time-style=+%s.%N | sha256sum); }
before=$(checksum "$work/out")

failures=0 count=0
check() {  # check EXPECTED ARGS...
  local expected=$1
  shift
  count=$((count + 1))
  local status=0
  "$derive" "$@" --out "$work/out" > "$work/stdout" 2> "$work/stderr" || status=$?
  local lines
  lines=$(wc -l < "$work/stderr")
  if [ "$status" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -qF -- "$expected" "$work/stderr" ||
     [ -s "$work/stdout" ] || [ "$(checksum "$work/out")" != "$before" ]; then
    echo "FAIL: $* -> exit $status, $lines stderr line(s), expected \"$expected\":" >&2
    cat "$work/stderr" >&2
    failures=$((failures + 1))
  fi
}

while IFS="|" read -r expression expected; do
  [ -z "$expected" ] && continue
  check "$expected" --profile "$expression" --param H --name p
done < "$cases"
# The --param values and the name are read with the same bounds.
check "--param H=1e99: the number 1e99" --profile "H*cos(x)" --param H=1e99 --name p
check "--param H=factorial(9): \"factorial\" at character 1: a number is expected" \
  --profile "H*cos(x)" --param "H=factorial(9)" --name p
check "must be a C++ identifier" --profile "cos(x)" --name "9lives"
# Within the bounds but beyond the budget: four parameter-dependent poles take minutes.
slow="1/((H+cos(x))*(H2+cos(x))*(H3+cos(x))*(H4+cos(x)))"
check "exceeds its budget of 1 s (--max-seconds); nothing is written" --profile "$slow" \
  --param H=3 --param H2=5 --param H3=7 --param H4=11 --name p --max-seconds 1
# The memory budget (not enforced under AddressSanitizer, where the time budget ends it).
check "the derivation exceeds its" --profile "(H*cos(x)+H2*cos(2*x)+H3*cos(3*x)+H4*cos(4*x))^64" \
  --param H=3 --param H2=5 --param H3=7 --param H4=11 --name p --max-memory-mb 100 --max-seconds 5

if [ "$failures" -ne 0 ]; then
  echo "$failures of $count refusals failed" >&2
  exit 1
fi
echo "$count refusals: exit 2, one line, output directory untouched"
