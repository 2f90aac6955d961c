"""The paper's statements over an ensemble of fault-bend runs that differ in round-off only
(issue 19, item 7), and the comparison of the static-friction anchors (item 4).

--set ensemble (default): the same deck and mesh, run with different linear solvers (MUMPS,
UMFPACK, SKYLINE: --solver), BLAS/OpenMP thread counts (OPENBLAS_NUM_THREADS and
OMP_NUM_THREADS 1 or 2), with and without factor reuse (the deck's *SOLVER, REUSE TOLERANCE
solves a tangent by GMRES with an earlier tangent's factors to a relative residual of 1e-10;
--reuse-tolerance 0 factorises every tangent) and, with an MPI build (bin/fcs3d-mpi and mpirun),
MUMPS distributed over 2 processes. These change the round-off of each solve, nothing else.
(MUMPS's ordering is not varied: fcs3d gives MUMPS its own METIS ordering, with no option to
change it.)

--set anchors (issue 19, item 4): the paper's literal law (fault_bend_paper_law.inp,
d(phi)/dt = 0) with its floor below VC = 1e-6 mm/s (static level mu(VC) = 0.7036) against the
same deck with the floor at the reference velocity (VC = V0: static level mu_s = MU0 = 0.60),
and the reference deck (Ruina's slip law), with event times measured from the first slip
(which removes the unknown duration of stage 1 and the static level the first slip depends
on). fcs3d has no option for the literal reading of eq. (3) (V including the elastic stick
part of the relative velocity), so that reading is not run.

For each run (fault_bend_study.measure, and post/fault_bend_zones.py for the verdicts of the
paper's statements 1-6) it records:
  nucleation   first slip -> first event on at least half of the fault's slave nodes is at
               least NUCLEATION_SECONDS long;
  arrest       an event nucleates on D-E, involves at least half as many nodes as D-E has, and
               slips E-F by less than ARREST_RATIO of its mean slip on D-E (mean slip of each
               segment from the mean displacement of its two sides, a *HISTORY added to the
               deck copy);
  restart      after the first arrested event, an event nucleates on E-F, involves at least
               half as many nodes as E-F has, and slips E-F more than D-E;
  zones 1-6    post/fault_bend_zones.py's verdicts (yes / partly / no); 3 (D-E released, C-D
               and E-F loaded) and 6 (C-D and F-G loaded at the end) are the paper's order of
               loading;
and the first slip, the nucleation duration and the onsets of the first three system-size
events. Table: for each statement, the number of runs in which it holds (and partly holds),
and the spread (min, max) of the times; runs whose increment logs are identical are marked
(the same trajectory, not an independent member).

Usage: fault_bend_ensemble.py --fcs3d BIN --work DIR [--out DIR] [--deck DECK] [--set ensemble|
           anchors] [--only a,b] [--end T] [--jobs 2] [--summarise-only]
Output: DIR/fault_bend_ensemble.md/.csv or DIR/fault_bend_anchors.md/.csv. Exit status 0 when
every run completed and the table was written; the statements' fractions are results, not
checks.
"""
import argparse
import concurrent.futures
import csv
import hashlib
import os
import re
import stat
import subprocess
import sys

import fault_bend_study as study

NUCLEATION_SECONDS = 1.0
ARREST_RATIO = 0.1
ZONES = os.path.join(study.ROOT, 'post', 'fault_bend_zones.py')
MPI_BIN = os.path.join(study.ROOT, 'bin', 'fcs3d-mpi')
ONE = {'OPENBLAS_NUM_THREADS': '1', 'OMP_NUM_THREADS': '1'}
TWO = {'OPENBLAS_NUM_THREADS': '2', 'OMP_NUM_THREADS': '2'}
ENSEMBLE = {
    # name: (description, fcs3d options, environment, processes)
    'mumps_t1': ('MUMPS, 1 thread', '--solver MUMPS', ONE, 1),
    'mumps_t2': ('MUMPS, 2 threads', '--solver MUMPS', TWO, 1),
    'umfpack_t1': ('UMFPACK, 1 thread', '--solver UMFPACK', ONE, 1),
    'umfpack_t2': ('UMFPACK, 2 threads', '--solver UMFPACK', TWO, 1),
    'skyline': ('SKYLINE, 1 thread', '--solver SKYLINE', ONE, 1),
    'mumps_noreuse': ('MUMPS, no factor reuse (every tangent factorised)', '--solver MUMPS '
                      '--reuse-tolerance 0', ONE, 1),
    'umfpack_noreuse': ('UMFPACK, no factor reuse', '--solver UMFPACK --reuse-tolerance 0',
                        ONE, 1),
    'mumps_mpi2': ('MUMPS distributed on 2 MPI processes, 1 thread each', '--solver MUMPS',
                   ONE, 2),
    'mumps_mpi2_t2': ('MUMPS distributed on 2 MPI processes, 2 threads each', '--solver MUMPS',
                      TWO, 2),
}


def static_level_at_reference(text):
    """The deck with the rate-dependent law's floor at its reference velocity (VC = V0):
    static friction mu_s = MU0."""
    m = re.search(r'^\*FRICTION,[^\n]*LAW=RATE DEPENDENT[^\n]*$', text, re.M)
    if m is None or 'VC=' not in m.group(0) or 'V0=' not in m.group(0):
        raise ValueError('the deck has no *FRICTION, LAW=RATE DEPENDENT line with VC= and V0=')
    v0 = re.search(r'V0=([^,\s]+)', m.group(0)).group(1)
    line = re.sub(r'VC=[^,\s]+', 'VC=' + v0, m.group(0))
    return text[:m.start()] + line + text[m.end():]


PAPER_LAW = os.path.join(study.ROOT, 'input', 'fault_bend', 'fault_bend_paper_law.inp')
ANCHORS = {
    # name: (description, deck, deck edit)
    'paper_law_floor': ("the paper's law, d(phi)/dt = 0, floor below VC = 1e-6 mm/s "
                        '(mu_s = 0.7036): fault_bend_paper_law.inp', PAPER_LAW, lambda t: t),
    'paper_law_mu_s_0.60': ("the paper's law with the floor at VC = V0 (mu_s = MU0 = 0.60)",
                            PAPER_LAW, static_level_at_reference),
    'ruina_slip_law': ("Ruina's slip law, L = 1e-3 mm, radiation damping: fault_bend.inp (the "
                       'reference deck)', study.DECK, lambda t: t),
}


def launcher(work, processes, mpi_bin):
    """The fcs3d to give tools/run_default.sh: the binary, or a script running the MPI build
    on `processes` processes."""
    if processes == 1:
        return None
    path = os.path.join(work, 'fcs3d_mpi%d.sh' % processes)
    with open(path, 'w') as f:
        f.write('#!/bin/sh\nexport OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 '
                'OMPI_MCA_mpi_yield_when_idle=1\n'
                'exec mpirun --oversubscribe -np %d %s "$@"\n' % (processes, mpi_bin))
    os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)
    return path


def zone_verdicts(directory):
    """{statement number: verdict} of post/fault_bend_zones.py on the run's results."""
    results = os.path.join(directory, 'fault_bend.h5')
    if not os.path.exists(results):
        return {}
    out = subprocess.run([sys.executable, ZONES, '--results', results], capture_output=True,
                         text=True, cwd=os.path.join(study.ROOT, 'post'))
    with open(os.path.join(directory, 'zones.md'), 'w') as f:
        f.write(out.stdout + out.stderr)
    return dict(re.findall(r'^\| (\d) \| [^|]* \| \*\*([^*]+)\*\* \|', out.stdout, re.M))


def increments_digest(directory):
    """Digest of the run's `inc` lines without their residuals (equal digests: the same
    increments, limits and events: the same trajectory)."""
    path = os.path.join(directory, 'fault_bend.log')
    if not os.path.exists(path):
        return None
    lines = [re.sub(r' residual .*', '', line) for line in open(path) if line.startswith('inc ')]
    return hashlib.sha1(''.join(lines).encode()).hexdigest()[:10]


def statements(m):
    """{'nucleation', 'arrest', 'restart'}: 'yes' / 'no' / '-' (not measurable) with numbers."""
    out = {}
    if m['nucleation'] is None:
        out['nucleation'] = ('-', 'no system-size event')
    else:
        out['nucleation'] = ('yes' if m['nucleation'] >= NUCLEATION_SECONDS else 'no',
                             '%.2f s' % m['nucleation'])
    nodes = m['segment_nodes']
    with_slip = [e for e in m['events'] if e['slip_DE'] is not None]
    if not nodes or not with_slip:
        out['arrest'] = out['restart'] = ('-', 'no segment history or trace')
        return out
    arrested = [e for e in with_slip if e['segment'] == 'DE' and e['nodes'] >= 0.5 * nodes['DE']
                and e['slip_DE'] > 0 and e['slip_EF'] < ARREST_RATIO * e['slip_DE']]
    shown = arrested or [e for e in with_slip if e['segment'] == 'DE' and
                         e['nodes'] >= 0.5 * nodes['DE'] and e['slip_DE'] > 0]
    out['arrest'] = ('yes' if arrested else 'no', ', '.join(
        '%.3f s (%d nodes, E-F/D-E slip %.2f)' % (e['onset'], e['nodes'],
                                                  e['slip_EF'] / e['slip_DE'])
        for e in shown[:3]) or 'no event over half of D-E nucleates on it')
    if not arrested:
        out['restart'] = ('-', 'no arrested event')
        return out
    restarts = [e for e in with_slip if e['onset'] > arrested[0]['onset'] and
                e['segment'] == 'EF' and e['nodes'] >= 0.5 * nodes['EF'] and
                e['slip_EF'] > e['slip_DE']]
    out['restart'] = ('yes' if restarts else 'no', ', '.join(
        '%.2f s (%d nodes)' % (e['onset'], e['nodes']) for e in restarts[:3]) or 'none')
    return out


def run_member(name, members, fcs3d, work, text, gmsh, mpi_bin):
    description, options, env, processes = members[name]
    binary = launcher(work, processes, mpi_bin) or fcs3d
    status, wall, cpu = study.run_case(os.path.join(work, name), binary, text, gmsh,
                                       '-q ' + options, env)
    return name, status, wall, cpu


def fmt(value, digits=2):
    return '-' if value is None else '%.*f' % (digits, value)


STATEMENT_ROWS = (
    ('nucleation', 'nucleation phase: first system-size event at least %g s after the first '
     'slip' % NUCLEATION_SECONDS),
    ('arrest', 'arrest at the bend: an event over at least half of D-E slips E-F by less than '
     '%g of its D-E slip' % ARREST_RATIO),
    ('restart', 'restart on E-F after the arrest: an event nucleating on E-F over at least half '
     'of it, more slip on E-F than on D-E'),
    ('1', 'zones 1: stage 1 smooth except at both ends'),
    ('2', 'zones 2: unchanged until the first stick-to-slip (228.7 s)'),
    ('3', 'zones 3: D-E released, C-D and E-F loaded (292.75-296.15 s) - order of loading'),
    ('4', 'zones 4: most stress rises except around D-E (302.98 s)'),
    ('5', 'zones 5: stick-slip on E-F (311.08-369.78 s)'),
    ('6', 'zones 6: C-D and F-G loaded at the end (329.93-369.78 s) - order of loading'),
)


def header(set_name, deck, gmsh):
    what = ('an ensemble of runs of one deck and mesh that differ in round-off only (solver, '
            'threads, factor reuse, MPI processes)' if set_name == 'ensemble' else
            'the static-friction anchors of the paper\'s law and the reference deck, event times '
            'measured from the first slip')
    return ['Written by `tests/validate/fault_bend_ensemble.py --set %s` (`sh tests/validate/'
            'fault_bend_ensemble.sh`): %s. Deck: `%s` with a *HISTORY of the mean displacement of '
            'the sides of D-E and E-F added (output only); mesh: %s. Times are total times '
            '(stage 1 ends at 10 s).' % (set_name, what, deck, '`%s`' % gmsh if gmsh else
                                         'the .geo defaults'), '',
            'Definitions: first slip = first increment of stage 2 with a slipping node of the '
            'frictional pair (history CSV); system-size event = catalogued event on at least half '
            'of its slave nodes; nucleation = first slip -> onset of the first system-size event. '
            'Statements: nucleation holds if it lasts at least %g s; arrest if an event '
            'nucleating on D-E over at least half of its nodes slips E-F by less than %g times '
            'its mean slip on D-E; restart if, after that, an event nucleates on E-F over at least '
            'half of its nodes with more slip on E-F than on D-E; zones 1-6 are the verdicts of '
            '`post/fault_bend_zones.py` (its rules are printed in its report, `zones.md` in each '
            'run directory).' % (NUCLEATION_SECONDS, ARREST_RATIO), '']


def write_tables(names, members, rows, out, stem, set_name, preamble=()):
    md = list(preamble) + ['| run | what differs | first slip [s] | nucleation [s] | system-size events: onset '
          '[s] (since the first slip) | events (system-size) | same increments as | '
          'increments | wall [s] | CPU [s] |', '|---|---|---:|---:|---|---|---|---:|---:|---:|']
    seen = {}
    for name in names:
        r = rows[name]
        m = r['m']
        same = seen.get(r['digest'], '') if r['digest'] else ''
        if r['digest'] and r['digest'] not in seen:
            seen[r['digest']] = name
        onsets = ', '.join('%.3f (%s)' % (e['onset'], fmt(e['onset'] - m['first_slip'], 3))
                           for e in m['big'][:3]) or '-'
        md.append('| %s | %s | %s | %s | %s | %d (%d) | %s | %s | %s | %s |' % (
            name, members[name][0], fmt(m['first_slip']), fmt(m['nucleation']), onsets,
            len(m['events']), len(m['big']), same or '-', m['increments'] or 'failed',
            fmt(r['wall'], 0), fmt(r['cpu'], 0)))
    distinct = len({rows[n]['digest'] for n in names if rows[n]['digest']})
    complete = [n for n in names if rows[n]['m']['status'] == 0]
    md += ['', '%d runs completed of %d; %d distinct trajectories (increment logs).' % (
        len(complete), len(names), distinct), '']
    md += ['| statement | holds (yes) | partly | no | not measurable | per run (%s) |' %
           ', '.join(names), '|---|---:|---:|---:|---:|---|']
    csv_rows = [['statement'] + names + ['yes', 'partly', 'no', 'n']]
    for key, label in STATEMENT_ROWS:
        verdicts = [rows[n]['statements'].get(key, ('-', ''))[0] for n in complete]
        counts = {v: verdicts.count(v) for v in ('yes', 'partly', 'no')}
        n = len(verdicts)
        md.append('| %s | %d/%d | %d/%d | %d/%d | %d | %s |' % (
            label, counts['yes'], n, counts['partly'], n, counts['no'], n,
            n - sum(counts.values()), ', '.join(verdicts)))
        csv_rows.append([key] + [rows[nm]['statements'].get(key, ('-', ''))[0] for nm in names] +
                        [counts['yes'], counts['partly'], counts['no'], n])
    md += ['', '| quantity | min | max | max - min | runs |', '|---|---:|---:|---:|---:|']
    spread = [('first slip [s]', lambda m: m['first_slip']),
              ('nucleation [s]', lambda m: m['nucleation'])]
    for k in range(3):
        spread.append(('system-size event %d onset [s]' % (k + 1),
                       lambda m, k=k: m['big'][k]['onset'] if len(m['big']) > k else None))
        spread.append(('system-size event %d onset since the first slip [s]' % (k + 1),
                       lambda m, k=k: m['big'][k]['onset'] - m['first_slip']
                       if len(m['big']) > k and m['first_slip'] is not None else None))
    for label, get in spread:
        values = [get(rows[n]['m']) for n in complete]
        values = [v for v in values if v is not None]
        if values:
            md.append('| %s | %.3f | %.3f | %.3f | %d |' % (label, min(values), max(values),
                                                             max(values) - min(values),
                                                             len(values)))
        else:
            md.append('| %s | - | - | - | 0 |' % label)
        csv_rows.append(['spread: ' + label] + [fmt(get(rows[n]['m']), 4) if rows[n]['m']['status'] == 0 else ''
                                                for n in names] + ['', '', '', len(values)])
    md += ['', 'Numbers behind the verdicts:', '']
    for name in complete:
        s = rows[name]['statements']
        md.append('- %s: ' % name + '; '.join('%s %s (%s)' % (k, v[0], v[1]) for k, v in s.items()
                                                 if k in ('nucleation', 'arrest', 'restart')))
    print('\n'.join(md))
    if out:
        os.makedirs(out, exist_ok=True)
        with open(os.path.join(out, stem + '.md'), 'w') as f:
            f.write('\n'.join(md) + '\n')
        with open(os.path.join(out, stem + '.csv'), 'w', newline='') as f:
            csv.writer(f).writerows(csv_rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--fcs3d', required=True)
    parser.add_argument('--work', required=True)
    parser.add_argument('--out', default=None)
    parser.add_argument('--deck', default=study.DECK, help='the deck of the ensemble (the '
                        'anchors have theirs)')
    parser.add_argument('--set', choices=('ensemble', 'anchors'), default='ensemble')
    parser.add_argument('--only', default=None)
    parser.add_argument('--end', type=float, default=None)
    parser.add_argument('--gmsh', default='', help='gmsh options of the mesh (default: the '
                        '.geo defaults)')
    parser.add_argument('--mpi-fcs3d', default=MPI_BIN, help='the MPI build (default '
                        'bin/fcs3d-mpi of this checkout)')
    parser.add_argument('--jobs', type=int, default=2)
    parser.add_argument('--summarise-only', action='store_true')
    args = parser.parse_args()
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    fcs3d = os.path.abspath(args.fcs3d)
    mpi_bin = os.path.abspath(args.mpi_fcs3d)
    text = open(args.deck).read()
    if args.end is not None:
        text = study.with_end_time(text, args.end)
    text = study.with_segment_history(text)
    if args.set == 'ensemble':
        members = dict(ENSEMBLE)
        mpi = os.path.exists(mpi_bin) and subprocess.call(
            ['sh', '-c', 'command -v mpirun'], stdout=subprocess.DEVNULL) == 0
        if not mpi:
            print('no MPI build (%s) or no mpirun: the MPI members are left out' % mpi_bin)
            members = {k: v for k, v in members.items() if v[3] == 1}
        texts = {name: text for name in members}
    else:
        members = {name: (d, '', ONE, 1) for name, (d, _, _) in ANCHORS.items()}
        texts = {}
        for name, (_, deck, edit) in ANCHORS.items():
            anchor = open(deck).read()
            if args.end is not None:
                anchor = study.with_end_time(anchor, args.end)
            texts[name] = edit(study.with_segment_history(anchor))
    names = args.only.split(',') if args.only else list(members)
    unknown = [n for n in names if n not in members]
    if unknown:
        print('left out (not a member of this set or no MPI build): ' + ', '.join(unknown))
        names = [n for n in names if n in members]
    if not args.summarise_only:
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            jobs = [pool.submit(run_member, n, members, fcs3d, work, texts[n], args.gmsh,
                                mpi_bin)
                    for n in names]
            for job in concurrent.futures.as_completed(jobs):
                name, status, wall, cpu = job.result()
                print('%s: status %d, wall %.0f s, CPU %.0f s' % (name, status, wall, cpu),
                      flush=True)
    rows = {}
    for name in names:
        directory = os.path.join(work, name)
        m = study.measure(directory)
        wall, cpu = (None, None)
        if os.path.exists(os.path.join(directory, 'case.time')):
            words = open(os.path.join(directory, 'case.time')).read().split()
            wall, cpu = float(words[1]), float(words[3])
        s = statements(m)
        if m['status'] == 0:
            for number, verdict in zone_verdicts(directory).items():
                s[number] = (verdict, 'post/fault_bend_zones.py')
        rows[name] = {'m': m, 'statements': s, 'digest': increments_digest(directory),
                      'wall': wall, 'cpu': cpu}
    stem = 'fault_bend_ensemble' if args.set == 'ensemble' else 'fault_bend_anchors'
    deck = os.path.relpath(os.path.abspath(args.deck), study.ROOT) if args.set == 'ensemble' \
        else ', '.join(sorted({os.path.relpath(d, study.ROOT) for _, d, _ in ANCHORS.values()}))
    write_tables(names, members, rows, args.out, stem, args.set,
                 header(args.set, deck, args.gmsh))
    expected_end = study.end_time(text)
    failed = [n for n in names if rows[n]['m']['status'] != 0 or
              abs((rows[n]['m']['end_time'] or -1) - expected_end) > 1e-6]
    for n in failed:
        print('FAIL %s: the run did not complete' % n)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
