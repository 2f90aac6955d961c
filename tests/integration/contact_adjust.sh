#!/bin/sh
# *CONTACT PAIR, ADJUST= (issue 17 item 5; tests/integration/contact/adjust_blocks.py: model
# and closed form). Two stacked blocks in uniaxial strain, slave nodes at chosen gaps above
# the master plane, the upper block's top pushed down by d = 1e-4 in one increment:
# 1. ADJUST=0.01, gaps 0.5, 0, -0.3, 0.9 x 0.01 (moved) and 2, 3 x 0.01 (left): the moved
#    nodes are in contact under d with a gap in [-d, 0], the others open.
# 2. ADJUST=0.01, every gap in [-0.003, 0.0099]: all moved, so the blocks touch over the
#    plane from the first increment and every slave node carries the closed-form pressure
#    d / (1.5/M + 1/K) (within 1e-3, the stepper's equilibrium tolerance; measured 2e-7).
# 3. ADJUST=<node set> of all slave nodes, gaps up to 0.03: all moved whatever their gap,
#    the same closed form.
# 4. Case 2 as TYPE=SURFACE TO SURFACE (no *CONTACT PRINT there): the total reaction of the
#    top is the closed form over its unit area (within 1e-3), and the log reports the nine
#    slave nodes moved and the largest move 0.0099.
# 5. The log of case 1 reports six nodes moved, largest 0.009 (node 109).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
script=$tests/integration/contact/adjust_blocks.py
mkdir -p contact_adjust && cd contact_adjust || exit 1
fail=0
args="--adjust 0.01 --d 1e-4 --stiffness 1e7"
for mode in mixed close set; do
  "$py" "$script" deck "$mode.inp" --mode $mode $args || exit 1
  "$FCS3D" "$mode.inp" > "$mode.out" 2>&1 || { echo "fcs3d failed on $mode.inp"; cat "$mode.out"; fail=1; continue; }
  "$py" "$script" check "$mode" --mode $mode $args || fail=1
done
grep -q "ADJUST: 6 slave node(s) moved onto the master surface, largest move 9.00000E-03 (node 109)" mixed.out || {
  echo "mixed: the log does not report 6 nodes moved, largest 9e-3 at node 109"; grep ADJUST mixed.out; fail=1; }
sed 's/TYPE=NODE TO SURFACE/TYPE=SURFACE TO SURFACE/; s/^\*CONTACT PRINT/*NODE PRINT, NSET=TOP, TOTALS=ONLY/; s/^CDIS, CSTR/RF/' \
  close.inp > s2s.inp
"$FCS3D" s2s.inp > s2s.out 2>&1 || { echo "fcs3d failed on s2s.inp"; cat s2s.out; fail=1; }
"$py" "$script" check-total s2s --mode close $args || fail=1
grep -q "ADJUST: 9 slave node(s) moved onto the master surface, largest move 9.90000E-03" s2s.out || {
  echo "s2s: the log does not report 9 nodes moved, largest 9.9e-3"; grep ADJUST s2s.out; fail=1; }
exit $fail
