#!/bin/sh
# MUMPS block low-rank (BLR) factorisation (*SOLVER, LOW RANK TOLERANCE; --low-rank-tolerance;
# fcs_mumps: ICNTL(35) = 2, CNTL(7) = eps) on the partial-slip block on a block of
# contact/factor_reuse.py (stick, partial slip, gross slip; 119 increments, about 2 s a run):
#  - MUMPS full rank (--solver MUMPS) and MUMPS with BLR at eps = 1e-8 (the deck's *SOLVER,
#    TYPE=MUMPS, LOW RANK TOLERANCE=1e-8) give the same tables in the .dat (same increments,
#    times and rows), every value within 1e-3 of its table's scale, and T/(mu N) at the end
#    within 1e-3. Why 1e-3: a BLR solve has a relative error of order eps times a condition
#    factor, and the equilibrium iterations of each increment correct the out-of-balance force
#    only down to the EQUILIBRIUM TOLERANCE of *RMIN, 1e-3 of the force scale; that is the
#    accuracy the run promises for any approximate solve, so it is the bound a BLR run must
#    meet. eps = 1e-8: on the contact benchmark (doc/performance.md section 10) it kept the
#    limiting events and event counts of the first increments of the full-rank run. On this
#    small deck (2.6e5 factor entries) MUMPS compresses nothing (its fronts are too small), so
#    the measured difference is round-off, about 4e-13: the test checks the path (deck and
#    command line into MUMPS, the log's BLR figures), section 10 the gain;
#  - the log of the BLR run reports BLR on (eps, effective entries and flops, at most 100 % of
#    full rank) and one analysis for all factorisations (the analysis, where MUMPS clusters
#    the variables for BLR, is kept while the sparsity pattern stays); the full-rank log
#    does not mention BLR;
#  - --low-rank-tolerance 1e-8 with --solver MUMPS on the full-rank deck (the option overrides
#    the deck's 0) agrees with the deck's LOW RANK TOLERANCE=1e-8 within the same 1e-3. Not
#    bit for bit: MUMPS 5.5.1's BLR factorisation is not repeatable to the last bit (3 of 10
#    runs of the same deck gave .dat files differing by about 1e-13 of the scale, also with
#    OMP_NUM_THREADS=1 and without address randomisation; full rank: 10 of 10 identical);
#  - refused with exit status 2: --low-rank-tolerance without MUMPS (the default UMFPACK),
#    --solver UMFPACK on the deck that asks for BLR, --low-rank-tolerance 0.5 (range
#    [0, 1e-2]), and the bad decks solver_low_rank_range.inp and solver_low_rank_needs_mumps.inp
#    (file:line and the message of their "** expect:" line).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/contact/factor_reuse.py
mkdir -p mumps_low_rank && cd mumps_low_rank || exit 1
fail=0
"$py" "$script" deck full.inp || exit 1
# The BLR deck: the same model with *SOLVER, TYPE=MUMPS, LOW RANK TOLERANCE=1e-8 before the
# first step.
awk 'BEGIN { done = 0 } /^\*STEP, NLGEOM/ && !done { print "*SOLVER, TYPE=MUMPS, LOW RANK TOLERANCE=1e-8"; done = 1 } { print }' \
  full.inp > blr.inp || exit 1
cp full.inp option.inp || exit 1
"$FCS3D" -q --solver MUMPS full.inp || { echo "fcs3d failed on full.inp"; exit 1; }
"$FCS3D" -q blr.inp || { echo "fcs3d failed on blr.inp"; exit 1; }
"$FCS3D" -q --solver MUMPS --low-rank-tolerance 1e-8 option.inp || { echo "fcs3d failed on option.inp"; exit 1; }
"$py" "$script" compare full blr --relative 1e-3 || fail=1

# check NAME CONDITION: PASS/FAIL line.
check() {
  if [ "$2" -eq 0 ]; then echo "PASS  $1"; else echo "FAIL  $1"; fail=1; fi
}
blr_line=$(grep -F 'linear solver:' blr.log | tail -1)
echo "     blr.log: $blr_line"
printf '%s' "$blr_line" | grep -qE 'block low-rank \(eps 1(\.0*)?E-0?8\) on: [0-9.E+]+ entries \(([0-9.]+)% of full rank\), [0-9.E+]+ flops'
check "the BLR run's summary reports BLR on with eps 1e-8, its entries and flops" $?
percent=$(printf '%s' "$blr_line" | sed -n 's/.*entries (\([0-9.]*\)% of full rank).*/\1/p')
awk -v p="${percent:-200}" 'BEGIN { exit !(p > 0 && p <= 100) }'
check "BLR factors at most 100 % of the full-rank ones (${percent:-none} %)" $?
printf '%s' "$blr_line" | grep -qE '^ *linear solver: 1 analysis\(es\), [0-9]+ factorisation'
check "one analysis for all factorisations of the BLR run (kept across increments)" $?
if grep -qF 'block low-rank' full.log; then check "the full-rank log does not mention BLR" 1; else
  check "the full-rank log does not mention BLR" 0; fi
echo "     --low-rank-tolerance 1e-8 against the deck's LOW RANK TOLERANCE=1e-8:"
"$py" "$script" compare blr option --relative 1e-3 || fail=1

# refused NAME EXPECTED-TEXT COMMAND...: exit status 2 and the text in the output.
refused() {
  name=$1; expected=$2; shift 2
  out=$("$@" 2>&1); status=$?
  if [ "$status" -eq 2 ] && printf '%s' "$out" | grep -qF -- "$expected"; then
    echo "PASS  $name refused (exit 2)"
  else
    echo "FAIL  $name: exit status $status, output: $out"; fail=1
  fi
}
refused "--low-rank-tolerance with UMFPACK" 'needs the MUMPS solver' \
  "$FCS3D" --check --low-rank-tolerance 1e-8 full.inp
refused "--solver UMFPACK on the BLR deck" 'needs the MUMPS solver' \
  "$FCS3D" --check --solver UMFPACK blr.inp
refused "--low-rank-tolerance 0.5" '--low-rank-tolerance 0.5: expected a number in [0, 1e-2]' \
  "$FCS3D" --check --solver MUMPS --low-rank-tolerance 0.5 full.inp
for name in solver_low_rank_range solver_low_rank_needs_mumps; do
  deck=$tests/decks/bad/$name.inp
  expect=$(sed -n 's/^\*\* expect: //p' "$deck")
  line=$(grep -n '^\*SOLVER' "$deck" | cut -d: -f1)
  refused "$name.inp" "$name.inp:$line: $expect" "$FCS3D" --check -o . "$deck"
done
exit $fail
