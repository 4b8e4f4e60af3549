#!/usr/bin/env bash
# Fails, listing the files, if a tracked C++ source differs from the style of .clang-format
# (clang-format 14). generated/ keeps the layout wavecontact-derive gives it.
#   scripts/check_format.sh          check (CI)
#   scripts/check_format.sh --fix    reformat in place
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t sources < <(git ls-files '*.cpp' '*.hpp' '*.inc' ':!:generated/*')
if [ "${1:-}" = "--fix" ]; then
  clang-format-14 -i "${sources[@]}"
  exit 0
fi
report=$(mktemp)
trap 'rm -f "$report"' EXIT
if ! clang-format-14 --dry-run --Werror "${sources[@]}" 2> "$report"; then
  grep -o '^[^:]*:[0-9]*:[0-9]*: error' "$report" | cut -d: -f1 | sort -u | sed 's/^/  /' >&2
  echo "check_format: the files above differ from .clang-format; scripts/check_format.sh --fix reformats them" >&2
  exit 1
fi
echo "check_format: ${#sources[@]} sources follow .clang-format"
