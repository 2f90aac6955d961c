#!/bin/sh
# MUMPS is the solver of a parallel run (issue 15, item 12): `mpirun -np 2 fcs3d-mpi` on a deck
# without *SOLVER used to announce "solver MUMPS" and then refuse to run ("a parallel run needs
# the MUMPS solver"). Now a deck without *SOLVER runs on 2 ranks with MUMPS (exit status 0, the
# log and the echo say MUMPS), and a deck that asks for UMFPACK explicitly is refused with exit
# status 2 and a message naming MUMPS. Needs bin/fcs3d-mpi and mpirun.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
mpi_bin=${FCS3D_MPI:-$here/bin/fcs3d-mpi}
[ -x "$mpi_bin" ] || { echo "no MPI build at $mpi_bin"; exit 77; }
command -v mpirun >/dev/null 2>&1 || { echo "mpirun not installed"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
deck="$here/tests/data/mpi/block_slide.inp"
mkdir -p default umfpack || exit 1
grep -v '^\*SOLVER' "$deck" > default/job.inp
sed 's/^\*SOLVER, TYPE=MUMPS/*SOLVER, TYPE=UMFPACK/' "$deck" > umfpack/job.inp
grep -q '^\*SOLVER' default/job.inp && { echo "could not remove *SOLVER from the deck"; exit 1; }
grep -q 'TYPE=UMFPACK' umfpack/job.inp || { echo "could not set TYPE=UMFPACK"; exit 1; }
(cd default && timeout 300 mpirun --oversubscribe -np 2 "$mpi_bin" -q job.inp > run.out 2>&1)
status=$?
[ "$status" -eq 0 ] || { echo "no *SOLVER on 2 ranks: exit status $status"; tail -5 default/run.out; exit 1; }
grep -q 'solver MUMPS' default/job.log || { echo "job.log does not say MUMPS"; exit 1; }
grep -q 'solver MUMPS' default/job.echo || { echo "job.echo does not say MUMPS"; exit 1; }
echo "no *SOLVER on 2 ranks: exit status 0 with MUMPS"
(cd umfpack && timeout 300 mpirun --oversubscribe -np 2 "$mpi_bin" -q job.inp > run.out 2>&1)
status=$?
[ "$status" -eq 2 ] || { echo "*SOLVER, TYPE=UMFPACK on 2 ranks: exit status $status, expected 2"; tail -5 umfpack/run.out; exit 1; }
grep -q 'a parallel run needs the MUMPS solver' umfpack/run.out || {
  echo "*SOLVER, TYPE=UMFPACK on 2 ranks: no message naming MUMPS"; cat umfpack/run.out; exit 1; }
echo "*SOLVER, TYPE=UMFPACK on 2 ranks: refused with exit status 2"
