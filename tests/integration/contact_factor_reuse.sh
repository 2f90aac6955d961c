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
#  - --reuse-tolerance out of range is a command-line error (exit status 2);
#  - with the MPI build (FCS3D_MPI or bin/fcs3d-mpi, and mpirun): MUMPS distributed on 2 ranks
#    with reuse (products summed over the ranks, collective preconditioner) against the serial
#    fresh run, within the same 1e-6 (skipped without an MPI build).
# About 15 s serial, 1-2 min with the MPI part.
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
here=$(cd "$tests/.." && pwd)
mpi_bin=${FCS3D_MPI:-$here/bin/fcs3d-mpi}
if [ -x "$mpi_bin" ] && command -v mpirun >/dev/null 2>&1; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
  cp reused.inp ranks2.inp || exit 1
  if timeout 600 mpirun --oversubscribe -np 2 "$mpi_bin" -q --solver MUMPS ranks2.inp > ranks2.out 2>&1; then
    "$py" "$script" compare fresh ranks2 --relative 1e-6 || fail=1
    "$py" "$script" counts ranks2 || fail=1
  else
    echo "FAIL  fcs3d-mpi on 2 ranks failed: $(tail -3 ranks2.out)"; fail=1
  fi
else
  echo "SKIP  MPI part: no MPI build at $mpi_bin or no mpirun"
fi
exit $fail
