#!/bin/sh
# `make bench`: fcs3d against CalculiX on cube meshes of about 25k, 200k and 700k degrees of
# freedom (tests/bench/bench.py: what is measured and how). Not part of `make test`; prints
# figures, asserts nothing. Installs CalculiX (calculix-ccx) and GNU time when missing.
# Environment: FCS3D (the binary), PYTHON, BENCH_SIZES (cube edge counts, default 20,40,61),
# BENCH_THREADS (default 2: OMP_NUM_THREADS, OPENBLAS_NUM_THREADS, CCX_NPROC_*),
# BENCH_WORK (scratch directory, default a new one under $TMPDIR, kept for inspection),
# BENCH_TIMEOUT (seconds per run, default 3600).
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
: "${FCS3D:?FCS3D must name the fcs3d binary}"
py=${PYTHON:-/usr/bin/python3}
sh "$here/tools/ensure_packages.sh" calculix-ccx time || exit 1
work=${BENCH_WORK:-$(mktemp -d "${TMPDIR:-/tmp}/fcs3d-bench.XXXXXX")}
mkdir -p "$work" || exit 1
echo "fcs3d bench in $work ($(date -u '+%Y-%m-%d %H:%M UTC'), fcs3d $("$FCS3D" --version | head -1))"
"$py" "$here/tests/bench/bench.py" --fcs3d "$FCS3D" --work "$work" \
  --sizes "${BENCH_SIZES:-20,40,61}" --threads "${BENCH_THREADS:-2}" \
  --timeout "${BENCH_TIMEOUT:-3600}" --markdown "$work/bench.md" || exit 1
echo "table (Markdown) in $work/bench.md"
