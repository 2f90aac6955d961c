#!/bin/sh
# Factorisation reuse (*SOLVER, REUSE TOLERANCE; --reuse-tolerance; fcs_factor_reuse) on the
# partial-slip block on a block (stick, partial slip, gross slip; contact/factor_reuse.py):
#  - factorising every tangent (--reuse-tolerance 0) and reusing the factors (the deck's
#    *SOLVER, REUSE TOLERANCE=1e-10) give the same tables in the .dat (same increments), every
#    value within 1e-6 of its table's scale, and T/(mu N) at the end within 1e-6;
#  - the same with MUMPS (--solver overrides the deck's TYPE, the tolerance stays);
#  - the reused run still meets the block-sliding checks (T/N = mu within 1 % in gross slip);
#  - the log reports solves by GMRES and fewer factorisations than solves;
#  - the same binary twice on the same deck writes identical .dat files (serial runs are
#    deterministic: reuse decisions depend on iteration counts, never on timings);
#  - --reuse-tolerance out of range is a command-line error (exit status 2).
# About 15 s.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/contact/factor_reuse.py
sliding=$tests/integration/contact/block_sliding.py
mkdir -p contact_factor_reuse && cd contact_factor_reuse || exit 1
fail=0
"$py" "$script" deck fresh.inp || exit 1
"$py" "$script" deck reused.inp --tolerance 1e-10 || exit 1
cp reused.inp again.inp && cp reused.inp mumps.inp || exit 1
"$FCS3D" -q --reuse-tolerance 0 fresh.inp || { echo "fcs3d failed on fresh.inp"; exit 1; }
"$FCS3D" -q reused.inp || { echo "fcs3d failed on reused.inp"; exit 1; }
"$FCS3D" -q again.inp || { echo "fcs3d failed on again.inp"; exit 1; }
"$FCS3D" -q --solver MUMPS mumps.inp || { echo "fcs3d failed on mumps.inp"; exit 1; }
"$py" "$script" compare fresh reused --relative 1e-6 || fail=1
"$py" "$script" compare fresh mumps --relative 1e-6 || fail=1
"$py" "$sliding" check reused --variant partial --tolerance 0.01 || fail=1
"$py" "$script" counts reused || fail=1
"$py" "$script" counts mumps || fail=1
if cmp -s reused.dat again.dat; then
  echo "PASS  same binary twice: identical .dat"
else
  echo "FAIL  same binary twice: the .dat files differ"; fail=1
fi
out=$("$FCS3D" --check --reuse-tolerance 0.5 fresh.inp 2>&1); status=$?
if [ "$status" -eq 2 ] && printf '%s' "$out" | grep -qF -- '--reuse-tolerance 0.5: expected a number in [0, 1e-3]'; then
  echo "PASS  --reuse-tolerance 0.5 refused (exit 2)"
else
  echo "FAIL  --reuse-tolerance 0.5: exit status $status, output: $out"; fail=1
fi
exit $fail
