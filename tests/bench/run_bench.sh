#!/bin/sh
# `make bench`: fcs3d against CalculiX, and the fault-bend default run (not part of `make test`;
# they print figures and assert nothing). Installs CalculiX (calculix-ccx) and GNU time when
# missing.
#  cube     a linear static step on cube meshes of about 25k, 200k and 700k degrees of freedom
#           (tests/bench/bench.py: what is measured and how);
#  contact  frictional block sliding (pressed, then pushed until it slides; NLGEOM) at about
#           20k, 100k and 300k degrees of freedom: time per increment, time to the final load,
#           peak memory, ratios, and the growth exponent with size
#           (tests/bench/contact_bench.py, decks of tests/bench/contact_deck.py);
#  fault    the `make run` deck, with and without factorisation reuse, and with
#           BENCH_FAULT_BEFORE=/path/to/old/fcs3d the deck before issue 19 run by that build
#           and this one (tests/bench/fault_bend_bench.py).
# Environment: FCS3D (the binary), FCS3D_MPI (optional: the MPI build, adds MUMPS on
# BENCH_RANKS ranks, default 2, to the contact bench), PYTHON,
# BENCH_ONLY (cube, contact or fault: run only that one; default all three, contact first,
# fault last), BENCH_FAULT_OPTIONS (the fault runs, "LABEL=options;...", default the default
# options and --reuse-tolerance 1e-10), BENCH_FAULT_BEFORE (see fault above),
# BENCH_SIZES (cube edge counts, default 20,40,61),
# BENCH_CONTACT_SIZES (contact_deck.py sizes N, default 13,24,35),
# BENCH_THREADS (default 2: OMP_NUM_THREADS, OPENBLAS_NUM_THREADS, CCX_NPROC_*),
# BENCH_CONTACT_EVENTS (fcs3d's --contact-events values of the contact bench, each fcs3d run
# once per value; default ALL,CLOSING: the R-minimum events and the contact changes left to
# the equilibrium iterations, doc/performance.md section 11),
# BENCH_WORK (scratch directory, default a new one under $TMPDIR, kept for inspection),
# BENCH_TIMEOUT (seconds per run, default 3600; a contact run that exceeds it is stopped and
# reported with the increments it did), BENCH_SKIP (contact runs not to start, e.g.
# "fcs3d SKYLINE@13,ccx@35").
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
: "${FCS3D:?FCS3D must name the fcs3d binary}"
py=${PYTHON:-/usr/bin/python3}
only=${BENCH_ONLY:-}
case "$only" in
  ""|cube|contact|fault) ;;
  *) echo "BENCH_ONLY must be cube, contact or fault, not '$only'" >&2; exit 2 ;;
esac
sh "$here/tools/ensure_packages.sh" calculix-ccx time || exit 1
work=${BENCH_WORK:-$(mktemp -d "${TMPDIR:-/tmp}/fcs3d-bench.XXXXXX")}
mkdir -p "$work" || exit 1
echo "fcs3d bench in $work ($(date -u '+%Y-%m-%d %H:%M UTC'), fcs3d $("$FCS3D" --version | head -1))"
status=0
if [ -z "$only" ] || [ "$only" = contact ]; then
  set -- --fcs3d "$FCS3D" --work "$work" --sizes "${BENCH_CONTACT_SIZES:-13,24,35}" \
    --threads "${BENCH_THREADS:-2}" --ranks "${BENCH_RANKS:-2}" \
    --timeout "${BENCH_TIMEOUT:-3600}" --skip "${BENCH_SKIP:-}" \
    --contact-events "${BENCH_CONTACT_EVENTS:-ALL,CLOSING}" \
    --markdown "$work/contact_bench.md"
  if [ -n "${FCS3D_MPI:-}" ]; then
    set -- "$@" --fcs3d-mpi "$FCS3D_MPI"
  fi
  echo "contact bench (tests/bench/contact_bench.py)"
  if "$py" "$here/tests/bench/contact_bench.py" "$@"; then
    echo "table (Markdown) in $work/contact_bench.md"
  else
    status=1
  fi
fi
if [ -z "$only" ] || [ "$only" = cube ]; then
  echo "cube bench (tests/bench/bench.py)"
  if "$py" "$here/tests/bench/bench.py" --fcs3d "$FCS3D" --work "$work" \
      --sizes "${BENCH_SIZES:-20,40,61}" --threads "${BENCH_THREADS:-2}" \
      --timeout "${BENCH_TIMEOUT:-3600}" --markdown "$work/bench.md"; then
    echo "table (Markdown) in $work/bench.md"
  else
    status=1
  fi
fi
if [ -z "$only" ] || [ "$only" = fault ]; then
  echo "fault-bend bench (tests/bench/fault_bend_bench.py)"
  set -- --fcs3d "$FCS3D" --work "$work/fault_bend" --timeout "${BENCH_TIMEOUT:-3600}" \
    --markdown "$work/fault_bend_bench.md"
  [ -n "${BENCH_FAULT_OPTIONS:-}" ] && set -- "$@" --options "$BENCH_FAULT_OPTIONS"
  [ -n "${BENCH_FAULT_BEFORE:-}" ] && set -- "$@" --before "$BENCH_FAULT_BEFORE"
  if "$py" "$here/tests/bench/fault_bend_bench.py" "$@"; then
    echo "table (Markdown) in $work/fault_bend_bench.md"
  else
    status=1
  fi
fi
exit $status
