#!/bin/sh
# A block pressed on a block with quadratic and triangular contact faces (issue 16;
# tests/integration/contact/quadratic_blocks.py: model, closed forms, tolerances).
# 1. Frictionless, p = 1, matching meshes, default increments: the normal reaction is p A
#    (1e-9) and no slave node carries shear, for every pairing of C3D8, C3D20R (8-node
#    quadrilateral faces) and C3D10 (6-node triangles) tried; with a C3D10 slider (consistent
#    slave shares: corners 0, mid-sides 1/3) the contact pressure is p at every slave node
#    (1e-6; measured 0), on a C3D10 or a C3D20R base.
# 2. Coulomb mu = 0.3, pressed then pushed sideways (default increments): T/N = mu within 1e-3
#    (the equilibrium tolerance) once sliding, a C3D10 and a C3D20R slider on a C3D20R base.
# 3. A *TIE on 6-node triangular faces runs as CalculiX's tie (one equation per slave node and
#    direction; doc/theory.md 4.7; its agreement with ccx: calculix_compare's tie_*.inp): the
#    base carries the load, total z reaction p A = 1 within 1e-9 (equilibrium).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
script=$tests/integration/contact/quadratic_blocks.py
mkdir -p contact_quadratic_blocks && cd contact_quadratic_blocks || exit 1
fail=0
for pairing in "C3D10 C3D10" "C3D20R C3D10" "C3D20R C3D20R" "C3D20R C3D8" "C3D8 C3D20R"; do
  set -- $pairing
  job=frictionless_$1_$2
  "$py" "$script" deck $job.inp --base $1 --slider $2 || exit 1
  "$FCS3D" -q $job.inp || { echo "fcs3d failed on $job.inp"; fail=1; continue; }
  "$py" "$script" check $job --base $1 --slider $2 || fail=1
done
for pairing in "C3D20R C3D10" "C3D20R C3D20R"; do
  set -- $pairing
  job=sliding_$1_$2
  "$py" "$script" deck $job.inp --base $1 --slider $2 --mu 0.3 || exit 1
  "$FCS3D" -q $job.inp || { echo "fcs3d failed on $job.inp"; fail=1; continue; }
  "$py" "$script" check $job --base $1 --slider $2 --mu 0.3 || fail=1
done
"$py" "$script" deck tie.inp --base C3D10 --slider C3D10 --tie || exit 1
"$FCS3D" -q tie.inp > tie.out 2>&1
status=$?
reaction=$(awk '/total force .* for set BOTTOM/ {getline; getline; print $3}' tie.dat 2>/dev/null | tail -1)
if [ $status -ne 0 ] || [ -z "$reaction" ] || \
   ! awk -v r="$reaction" 'BEGIN { d = r - 1; if (d < 0) d = -d; exit !(d <= 1e-9) }'; then
  echo "FAIL *TIE on 6-node faces: exit $status, base reaction '$reaction', expected 1:"; cat tie.out
  fail=1
else
  echo "ok   *TIE on 6-node faces: base reaction $reaction (p A = 1)"
fi
exit $fail
