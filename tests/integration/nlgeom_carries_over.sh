#!/bin/sh
# NLGEOM stays on in the steps that follow until one says NLGEOM=NO, as in CalculiX (steps.f
# keeps iperturb(2) from step to step) and Abaqus. A block stretched 10 % in step 1 (NLGEOM) and
# 20 % in step 2 (no parameter): step 2 must be geometrically nonlinear, its results identical to
# the same deck with NLGEOM written on step 2, and different from NLGEOM=NO on step 2.
# Fails before e8a57d8 (step 2 was small-strain).
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/nlgeom_carries_over.sh'
set -u
mkdir -p nlgeom_carries_over && cd nlgeom_carries_over || exit 1
deck() {  # $1 file, $2 the parameters of step 2's *STEP card
  cat > "$1" <<DECK
*NODE, NSET=NALL
1, 0, 0, 0
2, 2, 0, 0
3, 2, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 2, 0, 1
7, 2, 1, 1
8, 0, 1, 1
9, 4, 0, 0
10, 4, 1, 0
11, 4, 0, 1
12, 4, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
2, 2, 9, 10, 3, 6, 11, 12, 7
*NSET, NSET=LEFT
1, 4, 5, 8
*NSET, NSET=RIGHT
9, 10, 11, 12
*MATERIAL, NAME=M
*ELASTIC
1000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=M
*BOUNDARY
LEFT, 1, 1
1, 2, 3
4, 3, 3
5, 2, 2
*STEP, NLGEOM
*STATIC
*BOUNDARY
RIGHT, 1, 1, 0.4
*NODE PRINT, NSET=RIGHT
RF
*END STEP
*STEP$2
*STATIC
*BOUNDARY
RIGHT, 1, 1, 0.8
*NODE PRINT, NSET=RIGHT
RF
*END STEP
DECK
}
deck inherit.inp ""
deck stated.inp ", NLGEOM"
deck linear.inp ", NLGEOM=NO"
for j in inherit stated linear; do
  "$FCS3D" -q $j.inp || { echo "fcs3d failed on $j.inp"; exit 1; }
done
fail=0
grep -q '^step 2 .*NLGEOM' inherit.log || { echo "step 2 of inherit.inp is not NLGEOM:"; grep '^step' inherit.log; fail=1; }
grep -q '^step 2 .*NLGEOM' linear.log && { echo "step 2 of linear.inp (NLGEOM=NO) is NLGEOM"; fail=1; }
cmp -s inherit.dat stated.dat || { echo "inherit.dat differs from stated.dat (step 2 with NLGEOM written)"; fail=1; }
cmp -s inherit.dat linear.dat && { echo "inherit.dat equals linear.dat: NLGEOM=NO changed nothing"; fail=1; }
[ $fail = 0 ] && echo "step 2 inherits NLGEOM; NLGEOM=NO turns it off"
exit $fail
