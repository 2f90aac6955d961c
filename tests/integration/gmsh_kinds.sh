#!/bin/sh
# Every 3D kind gmsh writes, read by *MESH (issue 16): tests/data/gmsh/kinds.geo meshed by gmsh
# at test time as tetrahedra, prisms, hexahedra and hexahedra + prisms, first order and second
# order (Mesh.SecondOrderIncomplete = 1: 10-node tetrahedra, 15-node prisms, 20-node
# hexahedra), each saved as text and as binary MSH 4.1 (-bin). Each mesh runs the same deck:
# rollers on the physical surfaces XMIN, YMIN, ZMIN, a pressure *DSLOAD on XMAX. Checked by
# tests/tools/check_gmsh_kinds.py: the cell types, uniaxial stress -p at every integration
# point and the exact linear displacement field to round-off, the total reaction on XMIN
# equal to the pressure's resultant p A; and the XDMF opens in VTK's Xdmf reader with every
# cell a positive 3D solid in VTK's node order (post/check_xdmf_vtk.py). The 20-node
# hexahedra also run as C3D20R (*MESH, HEX20=C3D20R: 8 integration points instead of 27).
# Skips (77) only without gmsh.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
command -v gmsh >/dev/null 2>&1 || { echo "gmsh not installed"; exit 77; }
fail=0
xdmf=""
deck() { # deck JOB MESH [extra *MESH parameters]
  cat > "$1.inp" <<DECK
*HEADING
gmsh kinds: $2
*MESH, FILE=$2$3
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL
*STEP
*STATIC
*BOUNDARY
XMIN, 1, 1
YMIN, 2, 2
ZMIN, 3, 3
*DSLOAD
XMAX, P, 100.
*NODE PRINT, NSET=XMIN, TOTALS=ONLY
RF
*NODE FILE
U, RF
*EL FILE
S
*END STEP
DECK
}
run() { # run JOB MESH CELLS [POINTS] [extra *MESH parameters]
  job=$1 mesh=$2 cells=$3 points=${4:-} extra=${5:-}
  echo "== $job ($mesh${extra})"
  deck "$job" "$mesh" "$extra"
  "$FCS3D" -q "$job.inp" > "$job.out" 2>&1 || { echo "fcs3d failed:"; tail -5 "$job.out"; fail=1; return; }
  if [ -n "$points" ]; then
    "$py" "$here/tests/tools/check_gmsh_kinds.py" "$job.h5" "$job.dat" --cells "$cells" --points "$points" || fail=1
  else
    "$py" "$here/tests/tools/check_gmsh_kinds.py" "$job.h5" "$job.dat" --cells "$cells" || fail=1
  fi
  xdmf="$xdmf $job.xdmf"
}
# shape (kinds.geo), order, name, XDMF cell types
for case in "0 1 tet4 6" "1 1 prism6 8" "2 1 hex8 9" "3 1 hex8_prism6 8,9" \
            "0 2 tet10 38" "1 2 prism15 40" "2 2 hex20 48" "3 2 hex20_prism15 40,48"; do
  set -- $case
  for format in text binary; do
    mesh=$3_$format.msh
    options="-format msh41 -setnumber shape $1"
    [ "$2" = 2 ] && options="$options -order 2 -setnumber Mesh.SecondOrderIncomplete 1"
    [ "$format" = binary ] && options="$options -bin"
    gmsh -3 $options "$here/tests/data/gmsh/kinds.geo" -o "$mesh" > "$mesh.log" 2>&1 || {
      echo "gmsh failed on $mesh:"; tail -5 "$mesh.log"; fail=1; continue; }
    run "$3_$format" "$mesh" "$4"
  done
done
run hex20_c3d20 hex20_text.msh 48 27
run hex20_c3d20r hex20_binary.msh 48 8 ", HEX20=C3D20R"
# One VTK reader process for all the results (its start-up dominates the test's time).
"$py" "$here/post/check_xdmf_vtk.py" $xdmf; status=$?
[ $status -eq 0 ] || [ $status -eq 77 ] || fail=1
exit $fail
