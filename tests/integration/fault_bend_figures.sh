#!/bin/sh
# post/make_figures.py (make figures) on a small fault-bend run: the default deck and .geo on a
# coarse mesh (one element layer), stage 2 cut to 40 s with B moved ten times faster, so that
# the fault slips within the run (with today's deck: one event over all 46 nodes of pair DF at
# 34.9 s). Checks: every figure is written, with the flat-against-bent
# figure (the run compared with itself); one before/after map per event over half the fault's
# frictional slave nodes (counted here from the deck and the results file); the station values
# of <prefix>_stations.csv equal the contact fields of the results file at the same grid, node
# and frame (to the 17 digits written); the station at E is the slave node nearest to E; the
# footer names the run by deck and job, not by the directory it ran in. About 20 s.
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/fault_bend_figures.sh'
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py, matplotlib' 2>/dev/null || {
  echo "numpy, h5py or matplotlib not available to $py"; exit 77; }
command -v gmsh >/dev/null 2>&1 || { echo "gmsh not installed"; exit 77; }
mkdir -p run || exit 1
cp "$root/input/fault_bend/fault_bend.geo" run/ || exit 1
options="-setnumber h_fault 15 -setnumber h_far 50 -setnumber layers 1"
# shellcheck disable=SC2086
(cd run && gmsh -3 -format msh41 $options fault_bend.geo -o fault_bend.msh > gmsh.log 2>&1) || {
  echo "gmsh failed:"; tail -5 run/gmsh.log; exit 1; }
printf '%s\n' "$options" > run/mesh_options.txt
"$py" - "$root/input/fault_bend/fault_bend.inp" run/fault_bend.inp <<'PY' || exit 1
# The default deck with the second *STATIC's period set to 40 s and the velocities of
# *BOUNDARY, TYPE=VELOCITY multiplied by 10.
import sys
lines = open(sys.argv[1]).read().split("\n")
statics, velocities, keyword = 0, 0, ""
for i, line in enumerate(lines):
    if line.startswith("**") or not line.strip():
        continue
    if line.startswith("*"):
        keyword = line.upper().replace(" ", "")
        if keyword.startswith("*STATIC"):
            statics += 1
        continue
    if keyword.startswith("*STATIC") and statics == 2:
        fields = line.split(",")
        fields[1] = " 40."
        lines[i] = ",".join(fields)
        keyword = ""
    elif keyword.startswith("*BOUNDARY") and "TYPE=VELOCITY" in keyword:
        fields = line.split(",")
        fields[3] = " %r" % (10 * float(fields[3]))
        lines[i] = ",".join(fields)
        velocities += 1
if statics != 2 or velocities == 0:
    print("fault_bend.inp: expected two *STATIC steps and a *BOUNDARY, TYPE=VELOCITY "
          "(found %d, %d): update this test" % (statics, velocities))
    sys.exit(1)
open(sys.argv[2], "w").write("\n".join(lines))
PY
(cd run && "$FCS3D" -q fault_bend.inp > run.out 2>&1) || {
  echo "fcs3d failed:"; tail -5 run/run.out; exit 1; }
"$py" "$root/post/make_figures.py" --results run/fault_bend.h5 --out figures \
  --compare-results run/fault_bend.h5 --dpi 60 > figures.out 2>&1 || {
  echo "make_figures.py failed:"; tail -20 figures.out; exit 1; }
"$py" - "$PWD" <<'PY'
import csv
import os
import sys

import h5py
import numpy as np

here = sys.argv[1]
out = os.path.join(here, "figures")
failed = []


def check(condition, text):
    print(("ok   " if condition else "FAIL ") + text)
    if not condition:
        failed.append(text)


names = ["model", "mises_fig2", "mises_paper", "fault_histories", "stick_slip",
         "space_time", "stations", "loading", "history", "compare"]
for name in names:
    path = os.path.join(out, f"fault_bend_{name}.png")
    check(os.path.exists(path) and os.path.getsize(path) > 1000, f"fault_bend_{name}.png written")

# Large events, counted here: the frictional pairs are the *CONTACT PAIR cards of the deck.
deck = open(os.path.join(here, "run", "fault_bend.inp")).read().upper().split("\n")
pairs = [line.split("NAME=")[1].split(",")[0].strip() for line in deck
         if line.startswith("*CONTACT PAIR") and "NAME=" in line]
results = h5py.File(os.path.join(here, "run", "fault_bend.h5"), "r")
frames = results["frames"]
first = frames[sorted(frames)[0]]
total = sum(len(first[f"surfaces/contact_{p}/coordinates"]) for p in pairs)
catalog = os.path.join(here, "run", "fault_bend_events.csv")
rows = list(csv.DictReader(open(catalog))) if os.path.exists(catalog) else []
large = [int(r["event"]) for r in rows if float(r["nodes"]) >= 0.5 * total]
print(f"     {len(rows)} events, {len(large)} over half of the {total} frictional slave nodes")
if not large:
    # Not a failure of the figures: a friction law or deck that nucleates later than the
    # shortened run leaves only the "no large event" path to check.
    print("note the run has no large event: only the absence of event maps is checked")
    check("event maps: no event over 50 %" in open(os.path.join(out, "fault_bend_summary.txt"))
          .read(), "the summary says that no event map was drawn")
for number in large:
    check(os.path.exists(os.path.join(out, f"fault_bend_event{number}.png")),
          f"before/after map of event {number}")
extra = [f for f in os.listdir(out) if f.startswith("fault_bend_event") and f[16:-4].isdigit()
         and int(f[16:-4]) not in large]
check(not extra, f"no map of a smaller event ({extra})")

# Station values against the results file, frame by frame.
by_time = {}
for name in frames:
    if int(frames[name].attrs.get("complete", 1)) == 1:
        by_time[float(frames[name].attrs["time"])] = name   # the last frame at a time wins
stations = list(csv.DictReader(open(os.path.join(out, "fault_bend_stations.csv"))))
check(len(stations) == 5 * len(by_time), f"{len(stations)} station rows = 5 stations x "
      f"{len(by_time)} frame times")
worst = 0.0
for row in stations:
    frame = frames[by_time[float(row["time"])]]
    grid = frame[f"surfaces/{row['grid']}"]
    node = int(row["node"])
    for column, field in (("pressure", "pressure"), ("shear", "shear_magnitude"),
                          ("slip", "slip")):
        expected = float(grid[f"nodal/{field}"][node])
        worst = max(worst, abs(float(row[column]) - expected) / max(1.0, abs(expected)))
    xyz = first[f"surfaces/{row['grid']}/coordinates"][node]
    assert np.allclose(xyz, [float(row[k]) for k in "xyz"], atol=1e-4), row
check(worst <= 1e-15, f"station tractions and slip equal the contact fields (largest relative "
      f"difference {worst:.1e})")
loaded = [r for r in stations if r["station"] == "mid D-E"]
check(max(float(r["shear"]) for r in loaded) > 0.1,
      "the shear traction at mid D-E is loaded (> 0.1 MPa)")
# E of the default .geo is (150, 150): the station there is the nearest slave node of its level.
e_rows = [r for r in stations if r["station"] == "E"]
z_e = float(e_rows[0]["z"])
nearest = np.inf
for name in first["surfaces"]:
    xyz = first[f"surfaces/{name}/coordinates"][()]
    level = np.abs(xyz[:, 2] - z_e) < 1e-6
    nearest = min(nearest, np.min(np.hypot(xyz[level, 0] - 150, xyz[level, 1] - 150)))
distance = np.hypot(float(e_rows[0]["x"]) - 150, float(e_rows[0]["y"]) - 150)
check(abs(distance - nearest) < 1e-6, f"station E is the slave node nearest to E "
      f"({distance:.3f} mm)")

summary = open(os.path.join(out, "fault_bend_summary.txt")).read()
label = summary.split("\n")[0]
check("fault_bend.inp (job fault_bend" in label and here not in summary,
      "the footer names deck and job, and no figure text names the run directory")
check("fcs3d" in label and "h_fault=15" in label, "the footer names fcs3d and the mesh options")
sys.exit(1 if failed else 0)
PY
