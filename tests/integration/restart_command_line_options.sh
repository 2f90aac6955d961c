#!/bin/sh
# A checkpoint records the command-line options of its run that change results (--solver,
# --reuse-tolerance, --contact-events, --low-rank-tolerance; doc/restart.md, "Command-line
# options"), and a restart takes those it is not given from it. On the block on a block of
# contact_events_iterated.sh at N = 6 (contact/contact_events.py: two steps, Coulomb contact,
# NLGEOM; CLOSING takes 40 increments, ALL 62, so the setting shows in the .dat):
#  a. a --contact-events CLOSING run restarted from its end-of-step-1 checkpoint WITHOUT the
#     option repeats its .dat and history byte for byte, and the log says the option came from
#     the checkpoint (at 2854d27, which did not record it, the restart ran ALL: .dat differs);
#  b. restarted with --contact-events ALL --reuse-tolerance 1e-10 instead: runs (exit 0), and
#     warns in the log and on standard error that the continuation will not be bit-identical
#     (the event setting differs from the checkpoint's; the reuse tolerance was not given to
#     the run that wrote it); its .dat is not the CLOSING run's (so a. can fail);
#  d. the final checkpoint of b. records the options b. ran with: restarted without options
#     it takes both from the checkpoint (log), and the run summary shows the reuse tolerance;
#  e. the record is in the overall checksum: a checkpoint whose record was changed is refused
#     (exit 2), and so is one whose record the command line would refuse;
#  c. a checkpoint of format version 4 (written by fcs3d 2854d27 and earlier: the same file
#     without the /meta attribute `options`; made here from a run with no options given, by
#     deleting the attribute and setting the version to 4 with h5py, which leaves the overall
#     checksum valid) restarts as before, the deck's *RMIN, CONTACT EVENTS=CLOSING in effect,
#     byte for byte the run in one go, and the log says the checkpoint does not record the
#     run's options.
# About 30 s.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
script=$tests/integration/contact/contact_events.py
mkdir -p restart_command_line_options && cd restart_command_line_options || exit 1
rm -f ./*.rst*.h5 ./*.log ./*.dat ./*.csv
fail=0
pass() { echo "PASS  $1"; }
failed() { echo "FAIL  $1"; fail=1; }
has_line() { grep -qF -- "$2" "$1"; }

"$py" "$script" deck 6 closing.inp || exit 1
"$py" "$script" deck 6 deck.inp --in-deck CLOSING || exit 1
"$FCS3D" -q --contact-events CLOSING closing.inp || { echo "fcs3d failed on closing.inp"; exit 1; }
cp closing.rst.1.h5 step1.rst.h5 && cp closing.dat once.dat && cp closing_h.csv once_h.csv || exit 1

# a. The option from the checkpoint.
if "$FCS3D" -q --restart step1.rst.h5 closing.inp; then
  if cmp -s closing.dat once.dat && cmp -s closing_h.csv once_h.csv; then
    pass "a. restart without --contact-events CLOSING: .dat and history identical to the run in one go"
  else
    failed "a. restart without --contact-events CLOSING: .dat or history differ from the run in one go"
  fi
  if has_line closing.log 'restart: --contact-events CLOSING from the checkpoint'; then
    pass "a. the log names the option taken from the checkpoint"
  else
    failed "a. no 'restart: --contact-events CLOSING from the checkpoint' in closing.log"
  fi
else
  failed "a. restart from step1.rst.h5 without options failed"
fi

# b. Other values given: used, with a warning in the log and on standard error.
warning='restart: --contact-events ALL given, but the run that wrote the checkpoint had --contact-events CLOSING: the continuation will not be bit-identical to the uninterrupted run'
reuse_warning='restart: --reuse-tolerance 1E-10 given, but the run that wrote the checkpoint had no --reuse-tolerance'
if "$FCS3D" -q --contact-events ALL --reuse-tolerance 1e-10 --restart step1.rst.h5 closing.inp 2> b.err; then
  for text in "$warning" "$reuse_warning"; do
    option=$(printf '%s' "$text" | cut -d' ' -f2-3)
    if has_line b.err "warning: $text" && has_line closing.log "warning: $text"; then
      pass "b. $option: warned on standard error and in the log"
    else
      failed "b. the warning '$text' is missing from standard error or the log; standard error: $(cat b.err)"
    fi
  done
  if cmp -s closing.dat once.dat; then
    failed "b. the restart with --contact-events ALL gave the CLOSING run's .dat (the setting had no effect)"
  else
    pass "b. the restart with --contact-events ALL ran with ALL (.dat differs from the CLOSING run's)"
  fi
else
  failed "b. restart with --contact-events ALL --reuse-tolerance 1e-10 failed"
fi

# d. The checkpoints of a restart record the options it ran with.
if "$FCS3D" -q --restart closing.rst.h5 closing.inp; then
  tail_log=$(sed -n '/^restart from closing.rst.h5/,$p' closing.log)
  if has_line closing.log 'restart: --reuse-tolerance 1E-10 from the checkpoint' &&
     has_line closing.log 'restart: --contact-events ALL from the checkpoint' &&
     printf '%s' "$tail_log" | grep -qF 'factorisation reuse (tolerance 1E-10)'; then
    pass "d. the end checkpoint of b. gives --reuse-tolerance 1E-10 and --contact-events ALL to a restart without options"
  else
    failed "d. restart from the end checkpoint of b.: options not taken from it; log: $(tail -20 closing.log)"
  fi
else
  failed "d. restart from the end checkpoint of b. failed"
fi

# e. The record is in the overall checksum: changed (1E-10 to 1E-09; the attribute keeps its
# length), the checkpoint is refused; changed into text the command line refuses, too.
for change in '1E-10 1E-09 the overall checksum does not match' \
              'ALL XYZ its record of the command-line options ("--reuse-tolerance 1E-10 --contact-events XYZ") cannot be read'; do
  cp closing.rst.h5 changed.rst.h5 || exit 1
  set -- $change
  "$py" - "$1" "$2" <<'EOF' || exit 1
import sys
import h5py
import numpy as np
with h5py.File('changed.rst.h5', 'r+') as f:
    text = f['meta'].attrs['options'].replace(sys.argv[1].encode(), sys.argv[2].encode())
    f['meta'].attrs.modify('options', np.bytes_(text))
EOF
  wanted=${change#* * }
  "$FCS3D" -q --restart changed.rst.h5 closing.inp 2> e.err; status=$?
  if [ "$status" -eq 2 ] && has_line e.err "$wanted"; then
    pass "e. recorded $1 changed to $2: refused (exit 2, '$wanted')"
  else
    failed "e. recorded $1 changed to $2: exit status $status (expected 2 and '$wanted'); $(cat e.err)"
  fi
done

# c. A version-4 checkpoint (no recorded options).
"$FCS3D" -q deck.inp || { echo "fcs3d failed on deck.inp"; exit 1; }
cp deck.rst.1.h5 old.rst.h5 && cp deck.dat deck_once.dat && cp deck_h.csv deck_once_h.csv || exit 1
"$py" - <<'EOF' || exit 1
import h5py
with h5py.File('old.rst.h5', 'r+') as f:
    meta = f['meta']
    assert meta.attrs['options'].strip() == b'', meta.attrs['options']
    del meta.attrs['options']
    meta.attrs['version'] = 4
EOF
if "$FCS3D" -q --restart old.rst.h5 deck.inp; then
  if cmp -s deck.dat deck_once.dat && cmp -s deck_h.csv deck_once_h.csv; then
    pass "c. restart from a version-4 checkpoint: .dat and history identical to the run in one go"
  else
    failed "c. restart from a version-4 checkpoint: .dat or history differ from the run in one go"
  fi
  if has_line deck.log 'restart: the checkpoint old.rst.h5 does not record the command-line options of the run that wrote it'; then
    pass "c. the log says the version-4 checkpoint does not record the run's options"
  else
    failed "c. no note about the unrecorded options in deck.log"
  fi
else
  failed "c. restart from a version-4 checkpoint failed"
fi
exit $fail
