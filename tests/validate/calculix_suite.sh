#!/bin/sh
# CalculiX's own static test decks through ccx and fcs3d (issues 16-17; `make validate` and
# `make ccx-suite`): every static deck of Debian's calculix-ccx-test (the ccx 2.11 test decks,
# installed by the Makefile's VALIDATE_PACKAGES) run by ccx 2.20 and by fcs3d, .dat tables
# compared; prints the table, the counts and fcs3d's refusal reasons ranked by decks, and
# rewrites the measured part of doc/validation/calculix_suite.md. tests/validate/calculix_suite.py
# says how decks are classified and compared. About 2 min (20 s when ccx's results are cached in
# build/calculix_suite/ccx). Not run by run_validate.sh, which shows a validation's output only
# when it fails: the Makefile runs it after the other validations, so that its table is shown.
# Fails when fewer than CCX_SUITE_MIN_AGREE (default 75, the count measured at the last
# landing, doc/validation/calculix_suite.md; none with --only) 3D-solid static decks agree
# with ccx within 1e-2; skips
# (exit 77) when ccx or the decks are not installed.
# Extra arguments go to calculix_suite.py (e.g. --only beam8p,friction1 --work DIR).
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
: "${FCS3D:?FCS3D must name the fcs3d binary}"
py=${PYTHON:-/usr/bin/python3}
decks=/usr/share/doc/calculix-ccx-test/examples/test
command -v ccx >/dev/null 2>&1 || { echo "SKIP: ccx (Debian package calculix-ccx) not installed"; exit 77; }
[ -d "$decks" ] || { echo "SKIP: $decks missing (Debian package calculix-ccx-test)"; exit 77; }
"$py" -c 'import numpy' 2>/dev/null || { echo "SKIP: numpy not available"; exit 77; }
markdown="$here/doc/validation/calculix_suite.md"
# A partial run (--only) prints its table but leaves the document alone, and by default
# requires no count of agreeing decks.
min_agree=${CCX_SUITE_MIN_AGREE:-75}
case " $* " in *" --only"*) markdown=""; min_agree=${CCX_SUITE_MIN_AGREE:-0} ;; esac
exec "$py" "$here/tests/validate/calculix_suite.py" --fcs3d "$FCS3D" --decks "$decks" \
  ${markdown:+--markdown "$markdown"} --min-agree "$min_agree" "$@"
