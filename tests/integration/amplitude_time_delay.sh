#!/bin/sh
# *CLOAD, AMPLITUDE=A, TIME DELAY=d (CalculiX): the load follows a(t - d). A linear bar of 4
# C3D20 elements pulled by an end force with the ramp a(0) = 0, a(1) = 1 and a delay of 0.25:
# at step times 0.5 and 1 the end displacement must be a(0.25) = 0.25 and a(0.75) = 0.75 of
# the undelayed run's at time 1 (linear problem: the ratio is exact to round-off; the .dat
# prints 7 digits, so 1e-6); before t = 0.25 the force is 0, so the displacement at 0.2 must be
# 0 (the increments stop at the delayed amplitude's kink at 0.25).
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
PYTHONPATH="$here/tests/tools" "$py" - <<'PY' || exit 1
import numpy as np
import kind_meshes
coords, hexes, _ = kind_meshes.hex_grid([4, 1, 1], [4.0, 1.0, 1.0], 0.0, np.random.default_rng(1))
elements = kind_meshes.convert(coords, hexes, "C3D20")
cards, _ = kind_meshes.element_cards(elements, "EALL")
fixed = [n for n, x in coords.items() if abs(x[0]) < 1e-12]
end = [n for n, x in coords.items() if abs(x[0] - 4.0) < 1e-12]
for name, delay in (("plain", ""), ("delayed", ", TIME DELAY=0.25")):
    lines = ["*NODE, NSET=NALL"] + [f"{n}, {x[0]!r}, {x[1]!r}, {x[2]!r}" for n, x in sorted(coords.items())]
    lines += cards
    lines += ["*NSET, NSET=FIX"] + [str(n) for n in sorted(fixed)]
    lines += ["*NSET, NSET=END"] + [str(n) for n in sorted(end)]
    lines += ["*AMPLITUDE, NAME=RAMP", "0., 0., 1., 1.",
              "*TIME POINTS, NAME=TP", "0.2, 0.5, 1.",
              "*MATERIAL, NAME=EL", "*ELASTIC", "1000., 0.", "*SOLID SECTION, ELSET=EALL, MATERIAL=EL",
              "*BOUNDARY", "FIX, 1, 3", "*STEP", "*STATIC",
              f"*CLOAD, AMPLITUDE=RAMP{delay}", f"END, 1, {10.0 / len(end)!r}",
              "*NODE PRINT, NSET=END, TIME POINTS=TP", "U", "*END STEP"]
    open(f"{name}.inp", "w").write("\n".join(lines) + "\n")
PY
for job in plain delayed; do "$FCS3D" -q "$job.inp" || { echo "fcs3d failed on $job"; exit 1; }; done
PYTHONPATH="$here/tests/tools" "$py" - <<'PY'
import sys
import datfile
def end_u(path):
    return {b.time: max(v[0] for v in b.rows.values())
            for b in datfile.read_blocks(path) if b.kind == "displacements"}
plain, delayed = end_u("plain.dat"), end_u("delayed.dat")
full = plain[1.0]
problems = []
for time, expected in ((0.2, 0.0), (0.5, 0.25), (1.0, 0.75)):
    got = delayed.get(time)
    print(f"t = {time}: end displacement {got} (expected {expected} x {full:.6e})")
    if got is None or abs(got - expected * full) > 1e-6 * full:
        problems.append(f"t = {time}: {got}, expected {expected * full:.6e}")
for problem in problems:
    print("FAIL: " + problem)
sys.exit(1 if problems else 0)
PY
