#!/bin/sh
# *BOUNDARY, FIXED (CalculiX): a C3D20R cantilever (4 x 2 x 2 cells over 4 x 1 x 1) bent by a
# tip force in step 1; in step 2 the force is replaced (*CLOAD, OP=NEW) by an axial one and the
# tip's y displacement is held by *BOUNDARY, FIXED. The tip must keep the y displacement it had
# at the end of step 1 (to the print precision of the .dat, 7 digits) while the beam stretches
# (other displacements change: the test would pass trivially otherwise).
# And *BOUNDARY, FIXED before the first step is refused with file:line (tests/decks/bad).
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
PYTHONPATH="$here/tests/tools" "$py" - <<'PY' || exit 1
import numpy as np
import kind_meshes
coords, hexes, _ = kind_meshes.hex_grid([4, 2, 2], [4.0, 1.0, 1.0], 0.0, np.random.default_rng(1))
elements = kind_meshes.convert(coords, hexes, "C3D20R")
cards, _ = kind_meshes.element_cards(elements, "EALL")
clamped = [n for n, x in coords.items() if abs(x[0]) < 1e-12]
tip = [n for n, x in coords.items() if abs(x[0] - 4.0) < 1e-12]
lines = ["*NODE, NSET=NALL"] + [f"{n}, {x[0]!r}, {x[1]!r}, {x[2]!r}" for n, x in sorted(coords.items())]
lines += cards
lines += ["*NSET, NSET=FIX"] + [str(n) for n in clamped]
lines += ["*NSET, NSET=TIP"] + [str(n) for n in tip]
lines += ["*MATERIAL, NAME=EL", "*ELASTIC", "210000., 0.3", "*SOLID SECTION, ELSET=EALL, MATERIAL=EL",
          "*BOUNDARY", "FIX, 1, 3",
          "*STEP", "*STATIC", "*CLOAD", f"TIP, 2, {-100.0 / len(tip)!r}",
          "*NODE PRINT, NSET=NALL", "U", "*END STEP",
          "*STEP", "*STATIC", "*CLOAD, OP=NEW", f"TIP, 1, {1000.0 / len(tip)!r}",
          "*BOUNDARY, FIXED", "TIP, 2, 2",
          "*NODE PRINT, NSET=NALL", "U", "*END STEP"]
open("fixed.inp", "w").write("\n".join(lines) + "\n")
open("tip.txt", "w").write(" ".join(str(n) for n in tip))
PY
"$FCS3D" -q fixed.inp || { echo "fcs3d failed"; exit 1; }
PYTHONPATH="$here/tests/tools" "$py" - <<'PY'
import sys
import numpy as np
import datfile
tip = [int(n) for n in open("tip.txt").read().split()]
blocks = [b for b in datfile.read_blocks("fixed.dat") if b.kind == "displacements"]
first, second = blocks[0], blocks[-1]
if first.time >= second.time:
    sys.exit("expected two displacement tables, step 1 then step 2")
scale = max(abs(v[1]) for v in first.rows.values())
held = max(abs(second.rows[(n,)][1] - first.rows[(n,)][1]) for n in tip)
moved = max(abs(second.rows[k] - first.rows[k]).max() for k in first.rows if k[0] not in tip)
print(f"tip y displacement at the end of step 1: {first.rows[(tip[0],)][1]:.6e}; "
      f"change in step 2: {held:.3e} (print precision {5e-7 * scale:.1e}); "
      f"largest change elsewhere: {moved:.3e}")
if held > 5e-7 * scale:
    sys.exit("FAIL: the FIXED tip moved in step 2")
if moved < 1e-3 * scale:
    sys.exit("FAIL: nothing moved in step 2 (the test does not test FIXED)")
PY
