#!/bin/sh
# MUMPS block low-rank factorisation on the contact benchmark (doc/performance.md, section 10):
# the deck of contact_deck.py at size N (--own-increments), run with --solver MUMPS and
# --low-rank-tolerance EPS for each EPS of LOW_RANK_EPS (0 = full rank, the reference), one run
# at a time, each stopped after LOW_RANK_TIMEOUT seconds with SIGINT (fcs3d then writes a
# checkpoint and its "stopped:" summary with the phase times and MUMPS's figures), under
# /usr/bin/time -v (peak resident memory), with the 1-minute load printed before and after;
# then the table of low_rank_compare.py. A benchmark: it prints figures, asserts nothing.
#
#   FCS3D=bin/fcs3d sh tests/bench/low_rank_bench.sh N [WORK]
#
# Environment: LOW_RANK_EPS (default "0 1e-10 1e-8 1e-6"), LOW_RANK_TIMEOUT (default 120),
# LOW_RANK_NICE (default 5); OPENBLAS_NUM_THREADS=1 (one thread, so that the times of a shared
# machine are comparable).
set -u
here=$(cd "$(dirname "$0")" && pwd)
n=${1:?usage: low_rank_bench.sh N [WORK]}
work=${2:-low_rank_$n}
fcs3d=$(cd "$(dirname "${FCS3D:-bin/fcs3d}")" && pwd)/$(basename "${FCS3D:-bin/fcs3d}")
eps_list=${LOW_RANK_EPS:-0 1e-10 1e-8 1e-6}
limit=${LOW_RANK_TIMEOUT:-120}
niceness=${LOW_RANK_NICE:-5}
mkdir -p "$work" && cd "$work" || exit 1
/usr/bin/python3 "$here/contact_deck.py" "$n" deck.inp --own-increments || exit 1
jobs=''
for eps in $eps_list; do
  job=eps_$eps
  cp deck.inp "$job.inp" || exit 1
  rm -f "$job".rst*.h5 "$job.log" "$job.lock"
  echo "== N=$n eps=$eps start $(date -u +%H:%M:%S), load $(uptime | sed 's/.*load average: //')"
  OPENBLAS_NUM_THREADS=1 nice -n "$niceness" /usr/bin/time -v -o "$job.time" \
    timeout -s INT "$limit" "$fcs3d" -q --solver MUMPS --low-rank-tolerance "$eps" "$job.inp" \
    > "$job.out" 2>&1
  echo "   exit $?, end $(date -u +%H:%M:%S), load $(uptime | sed 's/.*load average: //')"
  grep -E 'stopped:|done:|  factorisation:|linear solver' "$job.log"
  jobs="$jobs $job"
done
reference=eps_$(echo "$eps_list" | cut -d' ' -f1)
/usr/bin/python3 "$here/low_rank_compare.py" "$reference" $jobs
