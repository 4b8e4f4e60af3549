#!/usr/bin/env bash
# Every refused input of wavecontact-derive --profile exits 2 (a budget spent: 4) with one
# line on stderr that names what and why, and leaves the output directory exactly as it was;
# an input at the bounds but within them is derived.
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
check() {  # check [STATUS] EXPECTED ARGS...
  local want=2
  case $1 in [0-9]) want=$1; shift ;; esac
  local expected=$1
  shift
  count=$((count + 1))
  local status=0
  "$derive" "$@" --out "$work/out" > "$work/stdout" 2> "$work/stderr" || status=$?
  local lines
  lines=$(wc -l < "$work/stderr")
  if [ "$status" -ne "$want" ] || [ "$lines" -ne 1 ] || ! grep -qF -- "$expected" "$work/stderr" ||
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
# Parameter names the emitted C++ cannot take: keywords, its own names, macros.
for name in int out sqrt A; do
  check "parameter \"$name\" is a C++ keyword or a name of the emitted code" --profile "$name*cos(x)" --param "$name" --name p
done
for name in NULL M_PI EOF; do
  check "parameter \"$name\" is all capitals" --profile "$name*cos(x)" --param "$name" --name p
done
# Numbers are decimals: no octal, no hex, no nan.
check '--n: "010" is not a decimal integer without leading zeros' --n 010
check '--n: "0x10" is not a decimal integer' --n 0x10
check '--max-seconds: "nan" is not a decimal number' --n 4 --max-seconds nan
check "The following argument was not expected: --bogus" --bogus
# Within the bounds but beyond the budget: four parameter-dependent poles take minutes.
slow="1/((H+cos(x))*(H2+cos(x))*(H3+cos(x))*(H4+cos(x)))"
check 4 "exceeds its budget of 1 s (--max-seconds); nothing is written" --profile "$slow" \
  --param H=3 --param H2=5 --param H3=7 --param H4=11 --name p --max-seconds 1
# The memory budget (not enforced under AddressSanitizer, where the time budget ends it).
check 4 "the derivation exceeds its" --profile "(H*cos(x)+H2*cos(2*x)+H3*cos(3*x)+H4*cos(4*x))^64" \
  --param H=3 --param H2=5 --param H3=7 --param H4=11 --name p --max-memory-mb 100 --max-seconds 5

# A constant-led denominator of order 32 is within the bounds (issue 28: it was refused with a
# false reason): it is derived, in about 2 s (12 to 22 s, by the run's hash order, before the
# monomial E pi was taken out of its factorisation; a 2-s budget then failed one run in ten).
count=$((count + 1))
if ! "$derive" --profile "1/(2+cos(x))^32" --name p --out "$work/accepted" > "$work/stdout" 2> "$work/stderr" ||
   [ -s "$work/stderr" ] || [ ! -s "$work/accepted/profile_p.hpp" ]; then
  echo "FAIL: 1/(2+cos(x))^32, within the bounds, was not derived:" >&2
  cat "$work/stderr" >&2
  failures=$((failures + 1))
fi

if [ "$failures" -ne 0 ]; then
  echo "$failures of $count cases failed" >&2
  exit 1
fi
echo "$((count - 1)) refusals: exit 2 (4 for a budget), one line, output directory untouched; 1 input at the bounds derived"
