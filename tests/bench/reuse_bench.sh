#!/bin/sh
# Factorisation reuse on against off (issue 20, item 1; not part of `make test`: it prints
# figures and asserts nothing). In one script run, each pair back to back:
#  1. the fault-bend default run (`make run`'s deck and mesh, tools/run_default.sh, MUMPS, one
#     thread) with --reuse-tolerance 0 and with REUSE_TOLERANCE: wall time, increments,
#     factorisations, GMRES iterations, the time of the first stick->slip switch of step 2 (the
#     shear step; step 1 presses the blocks together) and the
#     onset of the first slip event (fault_bend_events.csv);
#  2. the contact benchmark (tests/bench/contact_bench.py) at REUSE_SIZES (default 13:
#     19,257 DOF) with REUSE_SOLVERS (default UMFPACK,MUMPS), each with --reuse 0 and
#     REUSE_TOLERANCE, CalculiX not run: time to the final load, factorisations, T/(mu N).
# Usage: FCS3D=bin/fcs3d sh tests/bench/reuse_bench.sh
# Environment: FCS3D, PYTHON, REUSE_TOLERANCE (default 1e-10), REUSE_SIZES, REUSE_SOLVERS,
# REUSE_WORK (scratch directory, default a new one under $TMPDIR), REUSE_ONLY (fault or
# contact: only that part), BENCH_THREADS (contact runs, default 2).
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
: "${FCS3D:?FCS3D must name the fcs3d binary}"
py=${PYTHON:-/usr/bin/python3}
tolerance=${REUSE_TOLERANCE:-1e-10}
only=${REUSE_ONLY:-}
work=${REUSE_WORK:-$(mktemp -d "${TMPDIR:-/tmp}/fcs3d-reuse.XXXXXX")}
mkdir -p "$work" || exit 1
echo "reuse bench in $work ($(date -u '+%Y-%m-%d %H:%M UTC'), fcs3d $("$FCS3D" --version | head -1))"
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
status=0
if [ "$only" != contact ]; then
  echo "fault-bend default run (tools/run_default.sh), reuse off, then tolerance $tolerance"
  printf '| reuse | fcs3d wall [s] | increments | factorisations | GMRES iterations | first stick->slip of step 2 [s] | first event onset [s] | events | load |\n'
  printf '|---|---|---|---|---|---|---|---|---|\n'
  for t in 0 "$tolerance"; do
    dir=$work/fault_bend_$t
    if ! FAULT_BEND_DIR=$dir FCS3D_OPTIONS="-q --reuse-tolerance $t" \
        sh "$here/tools/run_default.sh" "$FCS3D" > "$work/fault_bend_$t.out" 2>&1; then
      echo "| $t | failed: $(tail -2 "$work/fault_bend_$t.out" | tr '\n' ' ') |"
      status=1
      continue
    fi
    "$py" - "$dir" "$t" <<'EOF'
import csv, os, re, sys
d, t = sys.argv[1], sys.argv[2]
log = open(os.path.join(d, 'fault_bend.log')).read()
wall = re.search(r'^done: (\d+) increment\(s\), time \S+, wall ([^,]+),', log, re.M)
fact = re.search(r'linear solver: .*?(\d+) factorisation\(s\)', log)
krylov = re.search(r'by GMRES with (\d+) iteration', log)
slip = re.search(r'^inc \d+ step 2 time (\S+) .*limit stick->slip', log, re.M)
onset, n_events = '-', 0
path = os.path.join(d, 'fault_bend_events.csv')
if os.path.exists(path):
    rows = list(csv.DictReader(open(path)))
    n_events = len(rows)
    if rows:
        key = next((k for k in rows[0] if 'onset' in k or 'start' in k), None)
        onset = rows[0][key] if key else '-'
print('| %s | %s | %s | %s | %s | %s | %s | %d | %.1f |' % (
    'off' if float(t) == 0 else t, wall.group(2) if wall else '-', wall.group(1) if wall else '-',
    fact.group(1) if fact else '-', krylov.group(1) if krylov else '0',
    slip.group(1) if slip else '-', onset, n_events, os.getloadavg()[0]))
EOF
    grep -h "factorisation reuse" "$dir/fault_bend.log" | sed 's/^ */    /'
  done
fi
if [ "$only" != fault ]; then
  echo "contact benchmark (tests/bench/contact_bench.py), reuse off and $tolerance"
  sizes=${REUSE_SIZES:-13}
  skip=""
  for n in $(echo "$sizes" | tr ',' ' '); do
    skip="$skip,ccx@$n,ccx own increments@$n"
  done
  "$py" "$here/tests/bench/contact_bench.py" --fcs3d "$FCS3D" --work "$work" --sizes "$sizes" \
    --threads "${BENCH_THREADS:-2}" --solvers "${REUSE_SOLVERS:-UMFPACK,MUMPS}" \
    --reuse "0,$tolerance" --skip "${skip#,}" --markdown "$work/contact_reuse.md" || status=1
fi
exit $status
