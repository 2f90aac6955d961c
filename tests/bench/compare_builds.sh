#!/bin/sh
# Two builds of fcs3d side by side, in one script run: the speed (and output) check of a change
# that must not change results, such as issue 14's refactoring. Not part of `make test`: it
# prints figures and asserts nothing about time.
#
# Usage: sh tests/bench/compare_builds.sh BEFORE_BIN AFTER_BIN
#        (both builds run this tree's decks: BEFORE must read them)
#        (make bench-compare BEFORE=/path/to/old/fcs3d compares it with this tree's bin/fcs3d)
#
# Runs, alternately BEFORE, AFTER, BEFORE, AFTER, ... (COMPARE_REPEAT times each, default 2, so
# that a slow phase of a shared machine hits both builds alike):
#   fault-bend  the default deck (input/fault_bend/fault_bend.inp) on the default mesh, meshed
#               once by gmsh (serial, UMFPACK, one BLAS thread, as `make run`);
#   contact     the contact benchmark deck (tests/bench/contact_deck.py) at N = COMPARE_N
#               (default 13: 19,257 degrees of freedom), UMFPACK, one thread.
# Prints the wall and CPU (user + system) time of every run (fcs3d alone, GNU time; the mesh and
# deck are written before timing starts), the medians per build, the ratios AFTER/BEFORE, and
# whether each run's .dat (and the fault-bend CSVs) are byte-identical between the two builds.
# On a machine shared with other work the wall times follow its load; the CPU times much less
# (one thread each), so the CPU ratio is the figure to read there.
# Environment: COMPARE_REPEAT, COMPARE_N, COMPARE_WORK (scratch directory, default a new one
# under $TMPDIR, kept), PYTHON.
set -u
before=${1:?usage: compare_builds.sh BEFORE_BIN AFTER_BIN}
after=${2:?usage: compare_builds.sh BEFORE_BIN AFTER_BIN}
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
repeat=${COMPARE_REPEAT:-2}
size=${COMPARE_N:-13}
for bin in "$before" "$after"; do
  [ -x "$bin" ] || { echo "compare_builds.sh: $bin is not an executable" >&2; exit 2; }
done
command -v gmsh >/dev/null 2>&1 || { echo "compare_builds.sh: gmsh is not installed" >&2; exit 2; }
# GNU time (Debian package time) measures each run; installed when missing and root, as
# make bench does.
sh "$here/tools/ensure_packages.sh" time || exit 1
work=${COMPARE_WORK:-$(mktemp -d "${TMPDIR:-/tmp}/fcs3d-compare.XXXXXX")}
mkdir -p "$work/inputs" || exit 1
work=$(cd "$work" && pwd)
echo "compare_builds in $work ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc --all) cores, load $(cut -d' ' -f1-3 /proc/loadavg))"
OPENBLAS_NUM_THREADS=1
OMP_NUM_THREADS=1
export OPENBLAS_NUM_THREADS OMP_NUM_THREADS
echo "  before: $before ($("$before" --version | head -1))"
echo "  after:  $after ($("$after" --version | head -1))"

# Inputs, written once: the fault-bend mesh and deck, the contact deck.
cp "$here/input/fault_bend/fault_bend.geo" "$here/input/fault_bend/fault_bend.inp" "$work/inputs/" \
  || exit 1
if ! (cd "$work/inputs" && gmsh -3 -format msh41 fault_bend.geo -o fault_bend.msh > gmsh.log 2>&1); then
  echo "compare_builds.sh: gmsh failed; see $work/inputs/gmsh.log" >&2
  exit 1
fi
"$py" "$here/tests/bench/contact_deck.py" "$size" "$work/inputs/contact.inp" > /dev/null || exit 1

# run CASE BUILD K: one timed run of fcs3d in its own directory; prints the seconds.
run() {
  case_name=$1 build=$2 k=$3
  bin=$before
  [ "$build" = after ] && bin=$after
  dir=$work/$case_name.$build.$k
  mkdir -p "$dir"
  if [ "$case_name" = fault_bend ]; then
    cp "$work/inputs/fault_bend.inp" "$work/inputs/fault_bend.msh" "$dir/"
    deck=$dir/fault_bend.inp
    options=""
  else
    cp "$work/inputs/contact.inp" "$dir/"
    deck=$dir/contact.inp
    options="--solver UMFPACK"
  fi
  # shellcheck disable=SC2086
  (cd "$dir" && /usr/bin/time -f '%e %U %S' -o times.txt "$bin" -q $options "$deck" > stdout.txt 2>&1)
  status=$?
  [ $status -eq 0 ] || echo "  $case_name $build run $k: fcs3d exited with $status (see $dir)" >&2
  read -r wall user system < "$dir/times.txt"
  "$py" -c "print(f'{$wall:.2f} {$user + $system:.2f}')" > "$dir/wall.txt"
  echo "  $case_name $build run $k: wall, CPU $(cat "$dir/wall.txt") s"
}

for case_name in fault_bend contact; do
  echo "$case_name:"
  k=1
  while [ $k -le "$repeat" ]; do
    run "$case_name" before $k
    run "$case_name" after $k
    k=$((k + 1))
  done
done

# The table: medians, ratio, identical outputs.
"$py" - "$work" "$repeat" <<'EOF'
import filecmp, glob, os, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
print()
print(f"{'case':<12}{'wall before':>12}{'wall after':>12}{'ratio':>8}{'CPU before':>12}{'CPU after':>12}{'ratio':>8}  outputs")
for case in ("fault_bend", "contact"):
    times = {}
    for build in ("before", "after"):
        times[build] = [[float(v) for v in open(os.path.join(work, f"{case}.{build}.{k}", "wall.txt")).read().split()]
                        for k in range(1, repeat + 1)]
    wb = statistics.median(t[0] for t in times["before"])
    wa = statistics.median(t[0] for t in times["after"])
    cb = statistics.median(t[1] for t in times["before"])
    ca = statistics.median(t[1] for t in times["after"])
    names = [os.path.basename(p) for p in glob.glob(os.path.join(work, f"{case}.before.1", "*"))
             if p.endswith((".dat", ".csv"))]
    same = all(filecmp.cmp(os.path.join(work, f"{case}.before.{k}", n),
                           os.path.join(work, f"{case}.after.{k}", n), shallow=False)
               for n in names for k in range(1, repeat + 1))
    label = ("identical" if same else "DIFFER") + f" ({', '.join(sorted(names)) or 'none'})"
    print(f"{case:<12}{wb:>12.2f}{wa:>12.2f}{wa / wb:>8.3f}{cb:>12.2f}{ca:>12.2f}{ca / cb:>8.3f}  {label}")
print("(medians of", repeat, "runs each, run alternately)")
EOF
