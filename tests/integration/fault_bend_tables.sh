#!/bin/sh
# The table builders of the fault-bend convergence and ensemble studies
# (tests/validate/fault_bend_convergence.py, fault_bend_ensemble.py, with the measurements of
# fault_bend_study.py) on one small run made here: the paper's-law variant of the fault-bend
# deck (input/fault_bend/fault_bend_paper_law.inp: no state evolution, a few seconds; the
# reference deck's events take thousands of increments) on a coarse mesh (h_fault and h_far
# x 2.5, 1 layer) to 300 s. Checks, each against a source the measurement
# does not use:
#   - the first slip equals the log's first stick->slip increment of stage 2, and the
#     nucleation duration is the onset of the first event on >= half of the slave nodes of
#     <job>_events.csv minus it (read here with the csv module);
#   - the segment history added to the deck copy gives each event a mean slip on D-E and E-F;
#   - convergence table: the same run under two mesh names differs by 0 %; a copy whose
#     catalogued stress drops are x 1.1 differs by (1.1 - 1) / 1.1 = 9.1 % in the stress drop
#     (not within 5 %: "no") and by 0 % in the first slip ("yes");
#   - ensemble table: two copies of one run are one trajectory ("same increments as"), and
#     each statement counts both runs the same way.
# About 20 s on a loaded machine (the run); needs gmsh, h5py and numpy.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
command -v gmsh >/dev/null 2>&1 || { echo "gmsh not installed"; exit 77; }
"$py" -c 'import h5py, numpy' 2>/dev/null || { echo "no h5py/numpy"; exit 77; }
v="$root/tests/validate"
deck="$root/input/fault_bend/fault_bend_paper_law.inp"
"$py" "$v/fault_bend_convergence.py" --fcs3d "$FCS3D" --deck "$deck" --work "$PWD/conv" \
  --factors 0.4 --end 300 --jobs 1 > conv_run.txt 2>&1 || { echo "the coarse run failed:"; tail -5 conv_run.txt
  tail -5 conv/h_over_0_4/case.out; exit 1; }
cp -r conv/h_over_0_4 conv/h_over_0_5 || exit 1
"$py" - conv/h_over_0_5/fault_bend_events.csv <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
if not rows:
    sys.exit('the coarse run catalogued no event by 300 s')
for r in rows:
    r['stress_drop'] = repr(1.1 * float(r['stress_drop']))
with open(sys.argv[1], 'w', newline='') as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
PY
"$py" "$v/fault_bend_convergence.py" --fcs3d "$FCS3D" --deck "$deck" --work "$PWD/conv" \
  --factors 0.4,0.5 --end 300 --summarise-only --out "$PWD/out" --name conv > conv_table.txt 2>&1 || {
  echo "convergence table:"; tail -5 conv_table.txt; exit 1; }
mkdir -p ens || exit 1
cp -r conv/h_over_0_4 ens/mumps_t1 && cp -r conv/h_over_0_4 ens/umfpack_t1 || exit 1
"$py" "$v/fault_bend_ensemble.py" --fcs3d "$FCS3D" --deck "$deck" --work "$PWD/ens" --end 300 \
  --only mumps_t1,umfpack_t1 --summarise-only --out "$PWD/out" > ens_table.txt 2>&1 || {
  echo "ensemble table:"; tail -5 ens_table.txt; exit 1; }
PYTHONPATH="$v" "$py" - <<'PY'
import csv, re, sys
import fault_bend_study as study

failures = []
def check(ok, text):
    print(('ok   ' if ok else 'FAIL ') + text)
    if not ok:
        failures.append(text)

m = study.measure('conv/h_over_0_4')
log = open('conv/h_over_0_4/fault_bend.log').read()
first = next(float(t) for s, t in re.findall(r'^inc \d+ step (\d+) time (\S+) .*limit stick->slip',
                                             log, re.M) if s == '2')
check(m['first_slip'] is not None and abs(m['first_slip'] - first) <= 1e-6 * first,
      'first slip %s s = the log\'s first stick->slip of stage 2, %.7g s' % (m['first_slip'], first))
events = list(csv.DictReader(open('conv/h_over_0_4/fault_bend_events.csv')))
big = [e for e in events if int(e['nodes']) >= 0.5 * m['slaves']]
check(len(m['events']) == len(events) and len(m['big']) == len(big),
      '%d events, %d on at least half of the %s slave nodes' % (len(events), len(big), m['slaves']))
if big:
    expected = float(big[0]['onset']) - first
    check(abs(m['nucleation'] - expected) <= 1e-6, 'nucleation %.4f s = %.4f s' % (
        m['nucleation'], expected))
check(all(e['slip_DE'] is not None and e['slip_EF'] is not None for e in m['events']) and
      any(e['slip_DE'] + e['slip_EF'] > 0 for e in m['events']),
      'every event has a mean slip on D-E and E-F from the segment history')
rows = {r[0]: r for r in csv.reader(open('out/conv.csv'))}
header = rows['quantity']
rel = header.index('rel_h_over_0_4_h_over_0_5')
check(float(rows['first_slip'][rel]) == 0.0 and rows['first_slip'][-1] == 'yes',
      'convergence table, first slip: %s, %s' % (rows['first_slip'][rel], rows['first_slip'][-1]))
if big:
    value = float(rows['event1_drop'][rel])
    check(abs(value - 0.1 / 1.1) < 1e-3 and rows['event1_drop'][-1] == 'no',
          'convergence table, stress drop x 1.1: %s (expected 0.0909), %s' % (
              value, rows['event1_drop'][-1]))
md = open('out/fault_bend_ensemble.md').read()
check(re.search(r'^\| umfpack_t1 \|.*\| mumps_t1 \|', md, re.M) is not None,
      'ensemble table: the copy is the same trajectory as mumps_t1')
check('2 runs completed of 2; 1 distinct trajectories' in md, 'ensemble: 2 runs, 1 trajectory')
table = [r for r in csv.reader(open('out/fault_bend_ensemble.csv'))]
counted = [r for r in table[1:] if not r[0].startswith('spread')]
check(all(r[1] == r[2] for r in counted) and len(counted) == 9,
      'ensemble table: the two copies get the same verdict for each of the 9 statements')
sys.exit(1 if failures else 0)
PY
