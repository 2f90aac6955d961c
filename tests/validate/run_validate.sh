#!/bin/sh
# The fcs3d validations (run by `make validate`, not part of `make test`): every
# tests/validate/*.sh other than this runner, each run from a scratch directory, exit 0 pass,
# 77 skip, anything else fail, as the integration tests of tests/run_tests.sh.
# Prints one line per validation and ends with "N passed, N failed".
# Environment: FCS3D (the binary), PYTHON (/usr/bin/python3).
set -u
here=$(cd "$(dirname "$0")" && pwd)
: "${FCS3D:?FCS3D must name the fcs3d binary}"
: "${PYTHON:=/usr/bin/python3}"
export FCS3D PYTHON
work=$(mktemp -d "${TMPDIR:-/tmp}/fcs3d-validate.XXXXXX")
export FCS3D_TEST_WORK="$work"
export FCS3D_TEST_DATA="$here/../data"
passed=0; failed=0; skipped=0; failures=""
for t in "$here"/*.sh; do
  [ -f "$t" ] || continue
  name=$(basename "$t" .sh)
  # run_validate: this runner; calculix_suite: run by the Makefile after this runner, so that
  # its table is shown (this runner shows the output of failures only).
  case "$name" in run_validate|calculix_suite) continue ;; esac
  mkdir -p "$work/$name"
  start=$(date +%s)
  out=$(cd "$work/$name" && timeout 7200 sh "$t" 2>&1); status=$?
  seconds=$(( $(date +%s) - start ))
  if [ "$status" -eq 0 ]; then passed=$((passed + 1)); printf 'PASS validate/%s (%d s)\n' "$name" "$seconds"
  elif [ "$status" -eq 77 ]; then skipped=$((skipped + 1)); printf 'SKIP validate/%s\n' "$name"
  else failed=$((failed + 1)); failures="$failures $name"; printf 'FAIL validate/%s\n' "$name"
    printf '%s\n' "$out" | tail -20 | sed 's/^/     /'
  fi
done
rm -rf "$work"
echo
[ -n "$failures" ] && echo "failed:$failures"
if [ "$skipped" -gt 0 ]; then
  echo "$passed passed, $failed failed ($skipped skipped)"
else
  echo "$passed passed, $failed failed"
fi
[ "$failed" -eq 0 ]
