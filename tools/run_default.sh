#!/bin/sh
# The default run (`make run`): the fault-bend model of Xing, Mora & Makinouchi (2003).
# Meshes input/fault_bend/fault_bend.geo with gmsh into run/fault_bend/, checks the mesh
# (post/check_fault_mesh.py), copies the deck there and runs fcs3d on it.
#
# Usage: sh tools/run_default.sh /path/to/bin/fcs3d
# Environment (also as make variables: make run FAULT_BEND_GMSH="..."):
#   FAULT_BEND_GMSH  extra gmsh options, e.g. "-setnumber h_fault 5 -setnumber h_far 12
#                    -setnumber layers 5" (finer mesh) or "-setnumber bend_angle 0" (flat
#                    fault); the parameters are listed at the head of fault_bend.geo
#   FAULT_BEND_DIR   work directory (default run/fault_bend of this checkout)
#   FAULT_BEND_DECK  the deck to run instead of input/fault_bend/fault_bend.inp (an edited copy,
#                    e.g. with the Coulomb friction of the comparison run); copied to
#                    fault_bend.inp in the work directory, next to the mesh
#   FCS3D_OPTIONS    extra fcs3d options, e.g. "--solver MUMPS" or "-q"
#   OPENBLAS_NUM_THREADS, OMP_NUM_THREADS  BLAS and OpenMP threads (default 1 each: the
#                    results then do not depend on the machine's core count)
set -eu
fcs3d=${1:?usage: sh tools/run_default.sh /path/to/bin/fcs3d}
root=$(cd "$(dirname "$0")/.." && pwd)
python=${PYTHON:-/usr/bin/python3}
work=${FAULT_BEND_DIR:-$root/run/fault_bend}
gmsh_options=${FAULT_BEND_GMSH:-}
fcs3d_options=${FCS3D_OPTIONS:-}

fail() {
  echo "run_default.sh: $*" >&2
  exit 1
}
[ -x "$fcs3d" ] || fail "$fcs3d is not an executable (build with make)"
command -v gmsh >/dev/null 2>&1 || fail "gmsh is not installed (Debian package gmsh)"
mkdir -p "$work"
work=$(cd "$work" && pwd)
deck=${FAULT_BEND_DECK:-$root/input/fault_bend/fault_bend.inp}
[ -f "$deck" ] || fail "$deck: no such deck"
deck=$(cd "$(dirname "$deck")" && pwd)/$(basename "$deck")
cp "$root/input/fault_bend/fault_bend.geo" "$work/"
[ "$deck" = "$work/fault_bend.inp" ] || cp "$deck" "$work/fault_bend.inp"
cd "$work"
# Results of an earlier run would be mixed with the new ones by a viewer: remove them.
rm -f fault_bend.h5 fault_bend.xdmf fault_bend.dat fault_bend.log fault_bend.echo fault_bend.rst.h5 \
  fault_bend_*.csv

echo "meshing fault_bend.geo ${gmsh_options:+($gmsh_options) }in $work"
# shellcheck disable=SC2086  # the options are words to split
if ! gmsh -3 -format msh41 $gmsh_options fault_bend.geo -o fault_bend.msh > gmsh.log 2>&1; then
  grep -i "error" gmsh.log >&2 || tail -20 gmsh.log >&2
  fail "gmsh failed; see $work/gmsh.log"
fi
# The checker takes the -setnumber options (it reads ASCII meshes only: no -bin).
setnumbers=""
# shellcheck disable=SC2086
set -f -- $gmsh_options
set +f
while [ $# -gt 0 ]; do
  if [ "$1" = "-setnumber" ] && [ $# -ge 3 ]; then
    setnumbers="$setnumbers -setnumber $2 $3"
    shift 3
  else
    shift
  fi
done
# shellcheck disable=SC2086
if ! "$python" "$root/post/check_fault_mesh.py" fault_bend.msh --geo fault_bend.geo $setnumbers \
     > mesh_check.txt 2>&1; then
  cat mesh_check.txt >&2
  fail "the mesh check failed; see $work/mesh_check.txt"
fi
head -n 1 mesh_check.txt
printf '%s\n' "$setnumbers" > mesh_options.txt   # read by post/make_figures.py

# One BLAS/OpenMP thread unless the caller sets them: the factorisation's round-off depends
# on the number of threads, and after the first slip event the fault-bend run amplifies
# round-off (doc/validation/fault_bend_paper_law.md, section 7; doc/validation/fault_bend.md,
# section 5.2), so a fixed count makes `make run`
# reproducible from machine to machine of one kind (and equal to the study's default run).
# At 6,600 unknowns a second thread gains little (doc/performance.md).
OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}
OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
export OPENBLAS_NUM_THREADS OMP_NUM_THREADS
echo "threads: OPENBLAS_NUM_THREADS=$OPENBLAS_NUM_THREADS OMP_NUM_THREADS=$OMP_NUM_THREADS"
start=$(date +%s)
status=0
# shellcheck disable=SC2086
"$fcs3d" $fcs3d_options fault_bend.inp || status=$?
end=$(date +%s)
echo "fcs3d finished in $((end - start)) s (exit status $status)"
if [ "$status" -ne 0 ]; then
  echo "run_default.sh: fcs3d failed; see $work/fault_bend.log" >&2
  exit "$status"
fi

cat <<EOF
results in $work:
  fault_bend.h5 + fault_bend.xdmf  result frames (open fault_bend.xdmf in ParaView)
  fault_bend.dat                   force on face B at the output times (*NODE PRINT)
  fault_bend.log                   run log, one line per increment
  fault_bend.echo                  the deck with every default filled in
  mesh_check.txt, gmsh.log         mesh statistics and checks
figures (into doc/figures/):   make figures
  or: $python $root/post/make_figures.py --results $work/fault_bend.h5 --out <directory>
EOF
