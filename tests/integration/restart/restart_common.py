"""Shared helpers of the checkpoint/restart tests (tests/integration/restart_*.sh and
event_catalog.sh).

The test problem: a block pushed sideways on a block, with rate-weakening friction (stick-slip):
lower block 4 x 4 x 1 hexahedra on [0,4]^2 x [-1,0] (base fixed), upper block 3 x 3 x 1 on
[1.1,3.1]^2 x [0,1] (top nodes held in x and y), E = 1000, nu = 0.3, penalty contact 1e4,
*FRICTION, LAW=RATE DEPENDENT (mu0 0.3, a 0.010, b 0.025: rate weakening). Step 1 (NLGEOM):
pressure 10 on the upper top. Step 2 (NLGEOM): the top nodes move 0.025 in x over 0.5 time
units. About a hundred increments and a dozen slip events in all (fcs3d 798158c: 108 and 15),
1-2 s. The optional step 3 (the "added step" of the deck-change test) pushes on to 0.03
over 0.1.

Also: running fcs3d, and comparing the outputs of two runs bit for bit (every dataset and
attribute of <job>.h5, <job>.dat, <job>.xdmf, the history and event CSVs). numpy and h5py.
"""
import os
import random
import subprocess
import sys
import time

import numpy as np

try:
    import h5py
except ImportError:  # the scripts exit 77 (skip) through require_h5py()
    h5py = None

FCS3D = os.environ.get('FCS3D', 'fcs3d')
PAIR = 'UPPERBOTTOM-LOWERTOP'
HISTORY = 'fault'
#: Event catalog threshold [length/time] of the default deck.
THRESHOLD = 0.02


def require_h5py():
    if h5py is None:
        print('h5py is not available to %s' % sys.executable)
        sys.exit(77)


# ------------------------------------------------------------------------------ the deck

def _block(x0, x1, y0, y1, z0, z1, n, first):
    """Nodes and C3D8 elements of an n x n x 1 block; ids from first + 1."""
    ids, nodes, elements = {}, [], []
    for k in range(2):
        for j in range(n + 1):
            for i in range(n + 1):
                ids[(i, j, k)] = first + len(nodes) + 1
                nodes.append((ids[(i, j, k)], x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * j / n,
                              (z0, z1)[k]))
    for j in range(n):
        for i in range(n):
            corners = [(i, j, 0), (i + 1, j, 0), (i + 1, j + 1, 0), (i, j + 1, 0),
                       (i, j, 1), (i + 1, j, 1), (i + 1, j + 1, 1), (i, j + 1, 1)]
            elements.append((first + len(elements) + 1, [ids[c] for c in corners]))
    return nodes, elements, ids


STEP_CARDS = {
    1: ['*STEP, NLGEOM', '*STATIC', '0.1, 1.', '*DSLOAD', 'UPPERTOP, P, 10.',
        '*NODE PRINT, NSET=TOP, TOTALS=ONLY', 'RF'],
    2: ['*STEP, NLGEOM', '*STATIC', '0.01, 0.5',
        '*TIME POINTS, NAME=TP, GENERATE', '0.05, 0.5, 0.05',
        '*BOUNDARY', 'TOP, 1, 1, 0.025',
        '*NODE PRINT, NSET=TOP, TOTALS=ONLY, TIME POINTS=TP', 'RF',
        '*CONTACT PRINT, FREQUENCY=40', 'CDIS, CSTR'],
    3: ['*STEP, NLGEOM', '*STATIC', '0.01, 0.1', '*BOUNDARY', 'TOP, 1, 1, 0.03',
        '*NODE PRINT, NSET=TOP, TOTALS=ONLY, FREQUENCY=20', 'RF'],
}


def deck_text(steps=2, frequency=4, generations=3, young='1000.', history_frequency=1,
              frame_frequency=10, threshold=THRESHOLD, min_slip=None, step_changes=None,
              restart=True):
    """The deck as text. steps: 1, 2 or 3 (each deck is the start of the longer ones: same
    model section, same earlier steps). frequency, generations: *RESTART, WRITE (restart=False:
    no *RESTART card). young: Young's modulus as written in the deck. frame_frequency: *NODE FILE
    and *CONTACT FILE frequency in every step. threshold, min_slip: *EVENT CATALOG, SLIP RATE=,
    MIN SLIP= (None: not given). step_changes: {step: [(old, new), ...]} text
    replacements in that step's cards."""
    lower_nodes, lower_elements, lower = _block(0, 4, 0, 4, -1, 0, 4, 0)
    upper_nodes, upper_elements, upper = _block(1.1, 3.1, 1.1, 3.1, 0, 1, 3, 10000)
    out = ['*HEADING', 'block on block, pushed sideways (stick-slip, rate-weakening friction)',
           '*NODE, NSET=NALL']
    out += ['%d, %.15g, %.15g, %.15g' % n for n in lower_nodes + upper_nodes]
    out.append('*ELEMENT, TYPE=C3D8, ELSET=LOWER')
    out += ['%d, %s' % (e, ', '.join(map(str, c))) for e, c in lower_elements]
    out.append('*ELEMENT, TYPE=C3D8, ELSET=UPPER')
    out += ['%d, %s' % (e, ', '.join(map(str, c))) for e, c in upper_elements]
    out += ['*NSET, NSET=BASE'] + ['%d,' % n for key, n in sorted(lower.items()) if key[2] == 0]
    out += ['*NSET, NSET=TOP'] + ['%d,' % n for key, n in sorted(upper.items()) if key[2] == 1]
    out += ['*ELSET, ELSET=EALL', 'LOWER, UPPER',
            '*SURFACE, NAME=LOWERTOP', 'LOWER, S2', '*SURFACE, NAME=UPPERBOTTOM', 'UPPER, S1',
            '*SURFACE, NAME=UPPERTOP', 'UPPER, S2',
            '*MATERIAL, NAME=M', '*ELASTIC', '%s, 0.3' % young,
            '*SOLID SECTION, ELSET=EALL, MATERIAL=M',
            '*SURFACE INTERACTION, NAME=SI',
            '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR', '1.e4',
            '*FRICTION, LAW=RATE DEPENDENT, MU0=0.3, A=0.010, B=0.025, V0=0.05, VC=1e-6, '
            'REGULARISATION=FLOOR, STICK SLOPE=1.e4',
            '*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE', 'UPPERBOTTOM, LOWERTOP',
            '*BOUNDARY', 'BASE, 1, 3', 'TOP, 1, 2',
            '*HISTORY, NAME=%s, FREQUENCY=%d' % (HISTORY, history_frequency),
            'CONTACT, %s' % PAIR, 'NSET, TOP, RF', 'NSET, TOP, U', 'ENERGY',
            '*EVENT CATALOG, SLIP RATE=%r' % threshold +
            (', MIN SLIP=%r' % min_slip if min_slip is not None else '')]
    if restart:
        out.append('*RESTART, WRITE, FREQUENCY=%d, GENERATIONS=%d' % (frequency, generations))
    for k in range(1, steps + 1):
        cards = list(STEP_CARDS[k])
        if frame_frequency > 0:
            cards += ['*NODE FILE, FREQUENCY=%d' % frame_frequency, 'U',
                      '*CONTACT FILE, FREQUENCY=%d' % frame_frequency, 'CDIS, CSTR']
        cards.append('*END STEP')
        text = '\n'.join(cards)
        for old, new in (step_changes or {}).get(k, []):
            assert old in text, (old, k)
            text = text.replace(old, new)
        out.append(text)
    return '\n'.join(out) + '\n'


def write_deck(path, **options):
    with open(path, 'w') as f:
        f.write(deck_text(**options))


# ------------------------------------------------------------------------------ running

def run(job_dir, job, *args, check=True, timeout=600):
    """Run fcs3d -q <job>.inp [args] in job_dir; returns (exit status, stderr text)."""
    p = subprocess.run([FCS3D, '-q', job + '.inp', *args], cwd=job_dir, timeout=timeout,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if check and p.returncode != 0:
        raise SystemExit('fcs3d %s.inp %s in %s: exit status %d\n%s' % (
            job, ' '.join(args), job_dir, p.returncode, p.stderr))
    return p.returncode, p.stderr


def fresh_dir(path):
    """An empty directory (a previous run's files removed)."""
    os.makedirs(path, exist_ok=True)
    for name in os.listdir(path):
        os.remove(os.path.join(path, name))
    return path


def checkpoint_info(path):
    """(step, increment, time, step_time) of a checkpoint, from its /meta."""
    with h5py.File(path, 'r') as f:
        sizes = f['meta/sizes'][()]
        values = f['meta/values'][()]
    return int(sizes[4]), int(sizes[5]), float(values[0]), float(values[2])


def seeded_random(name):
    """A random generator seeded from $FCS3D_TEST_SEED, else from the clock; the seed is
    printed so that a failing run can be repeated (up to the timing of the machine)."""
    seed = os.environ.get('FCS3D_TEST_SEED')
    seed = int(seed) if seed else int(time.time() * 1000) % 1000000
    print('%s: seed %d (repeat with FCS3D_TEST_SEED=%d)' % (name, seed, seed))
    return random.Random(seed)


def remove_checkpoints(job_dir, job):
    """Delete <job>.rst*.h5, so that a checkpoint found later is the new run's."""
    for name in os.listdir(job_dir):
        if name.startswith(job + '.rst.'):
            os.remove(os.path.join(job_dir, name))


def start(job_dir, job, *args):
    return subprocess.Popen([FCS3D, '-q', job + '.inp', *args], cwd=job_dir,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def wait_for_checkpoint(process, path, newer_than=-1, timeout=120.0):
    """Poll until the checkpoint `path` exists with an increment > newer_than; returns its
    increment, or None if the process ended first."""
    deadline = time.monotonic() + timeout
    last = None
    while time.monotonic() < deadline:
        if process.poll() is not None:
            return None
        try:
            stamp = os.stat(path)
            stamp = (stamp.st_ino, stamp.st_mtime_ns)
        except FileNotFoundError:
            stamp = None
        if stamp is not None and stamp != last:
            last = stamp
            try:
                increment = checkpoint_info(path)[1]
            except (OSError, KeyError):
                increment = -1  # replaced while being read
                last = None
            if increment > newer_than:
                return increment
        time.sleep(0.005)
    process.kill()
    raise SystemExit('no checkpoint %s after %g s' % (path, timeout))


# ------------------------------------------------------------------------------ comparing

def _objects(f):
    items = {'/': f}
    f.visititems(lambda name, obj: items.__setitem__('/' + name, obj))
    return items


def _same_attributes(a, b):
    if set(a.attrs) != set(b.attrs):
        return 'attributes %s vs %s' % (sorted(a.attrs), sorted(b.attrs))
    for key in a.attrs:
        x, y = a.attrs[key], b.attrs[key]
        if isinstance(x, np.ndarray) or isinstance(y, np.ndarray):
            same = np.array_equal(np.asarray(x), np.asarray(y))
        else:
            same = x == y
        if not same:
            return 'attribute %s: %r vs %r' % (key, x, y)
    return None


def compare_h5(reference, other, select=None):
    """Differences between two results files: the same groups and datasets, every dataset
    bit-identical (np.array_equal, same dtype and shape), the same attributes everywhere
    (frame time, step, increment, complete; table column names...). select(path) -> bool
    limits the comparison (default: everything). Returns a list of differences."""
    problems = []
    with h5py.File(reference, 'r') as fa, h5py.File(other, 'r') as fb:
        a, b = _objects(fa), _objects(fb)
        names_a = {n for n in a if select is None or select(n)}
        names_b = {n for n in b if select is None or select(n)}
        for n in sorted(names_a ^ names_b):
            problems.append('%s only in %s' % (n, reference if n in names_a else other))
        for n in sorted(names_a & names_b):
            x, y = a[n], b[n]
            if isinstance(x, h5py.Dataset) != isinstance(y, h5py.Dataset):
                problems.append('%s: dataset in one file, group in the other' % n)
                continue
            if isinstance(x, h5py.Dataset):
                u, v = x[()], y[()]
                if u.dtype != v.dtype or u.shape != v.shape:
                    problems.append('%s: %s%s vs %s%s' % (n, u.dtype, u.shape, v.dtype, v.shape))
                elif not np.array_equal(u, v):
                    diff = ''
                    if u.dtype.kind == 'f':
                        diff = ' (largest difference %.3e)' % np.max(np.abs(u - v))
                    problems.append('%s: values differ%s' % (n, diff))
            why = _same_attributes(x, y)
            if why:
                problems.append('%s: %s' % (n, why))
    return problems


def compare_files(reference_dir, other_dir, names):
    """Byte-for-byte comparison of text outputs; returns a list of differences."""
    problems = []
    for name in names:
        pa, pb = os.path.join(reference_dir, name), os.path.join(other_dir, name)
        if not os.path.exists(pb):
            problems.append('%s: missing in %s' % (name, other_dir))
            continue
        with open(pa, 'rb') as fa, open(pb, 'rb') as fb:
            ta, tb = fa.read(), fb.read()
        if ta != tb:
            la, lb = ta.splitlines(), tb.splitlines()
            first = next((i for i in range(min(len(la), len(lb))) if la[i] != lb[i]),
                         min(len(la), len(lb)))
            problems.append('%s: differs from line %d (%d vs %d lines, %d vs %d bytes)' % (
                name, first + 1, len(la), len(lb), len(ta), len(tb)))
    return problems


def xdmf_frames(path):
    """The frames of an XDMF file as comparable data: per frame its time and, per grid, the
    topology, geometry and the attributes sorted by name (after a restart fcs3d rebuilds the
    XDMF of the earlier frames from job.h5 and lists their attributes in the file's
    alphabetical order instead of the order written: same content, other order)."""
    import xml.etree.ElementTree as ET

    def item(element):
        return (element.tag, tuple(sorted(element.attrib.items())), (element.text or '').strip(),
                tuple(item(child) for child in element))

    root = ET.parse(path).getroot()
    series = root.find('Domain/Grid')
    frames = []
    for frame in series.findall('Grid'):
        grids = frame.findall('Grid') or [frame]
        described = []
        for grid in grids:
            fixed = tuple(item(c) for c in grid if c.tag != 'Attribute')
            attributes = sorted(item(c) for c in grid if c.tag == 'Attribute')
            described.append((grid.get('Name'), fixed, tuple(attributes)))
        frames.append((frame.find('Time').get('Value'), tuple(described)))
    return frames


def compare_xdmf(reference, other):
    a, b = xdmf_frames(reference), xdmf_frames(other)
    if a == b:
        return []
    if len(a) != len(b):
        return ['%s: %d frames, %d in %s' % (other, len(b), len(a), reference)]
    first = next(i for i in range(len(a)) if a[i] != b[i])
    return ['%s: frame %d (time %s) differs from %s' % (other, first + 1, b[first][0], reference)]


def output_names(job):
    return [job + '.dat', '%s_%s.csv' % (job, HISTORY), job + '_events.csv']


def compare_runs(reference_dir, other_dir, job, what):
    """All outputs of two runs of `job` (h5 bit for bit, text files byte for byte, the XDMF
    frame by frame); prints and returns the differences."""
    problems = compare_h5(os.path.join(reference_dir, job + '.h5'),
                          os.path.join(other_dir, job + '.h5'))
    problems += compare_files(reference_dir, other_dir, output_names(job))
    problems += compare_xdmf(os.path.join(reference_dir, job + '.xdmf'),
                             os.path.join(other_dir, job + '.xdmf'))
    if problems:
        print('%s: the outputs differ from the one-go run:' % what)
        for p in problems[:30]:
            print('  ' + p)
        if len(problems) > 30:
            print('  ... %d differences in all' % len(problems))
    else:
        print('%s: %s.h5 (every dataset and attribute), %s and the frames of %s.xdmf identical '
              'to the one-go run' % (what, job, ', '.join(output_names(job)), job))
    return problems


def h5_summary(path):
    """Number of datasets and frames of a results file."""
    with h5py.File(path, 'r') as f:
        names = []
        f.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        return len(names), len(f['frames'])
