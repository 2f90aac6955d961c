"""Shared helpers of the NLGEOM / R-minimum stepper tests (tests/integration/nlgeom_*.sh).

Deck writing (a block of hexahedra with named node sets), running fcs3d, and reading what it
writes: the CalculiX-layout tables of <job>.dat and the one-line-per-increment <job>.log.
numpy only.
"""
import os
import re
import subprocess
import sys

import numpy as np

# Hexahedron corner order of C3D8 (CalculiX/Abaqus): bottom face counter-clockwise, then top.
HEX8_CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


class Block:
    """A box [0,lx] x [0,ly] x [0,lz] meshed with nx x ny x nz hexahedra (C3D8)."""

    def __init__(self, lx=1.0, ly=1.0, lz=1.0, nx=1, ny=1, nz=1, origin=(0.0, 0.0, 0.0),
                 first_node=1, first_element=1):
        self.n = (nx, ny, nz)
        self.size = (lx, ly, lz)
        self.origin = np.array(origin, dtype=float)
        self.first_node = first_node
        self.first_element = first_element
        ids = {}
        coords = []
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    ids[(i, j, k)] = first_node + len(coords)
                    coords.append((lx * i / nx, ly * j / ny, lz * k / nz))
        self.ids = ids
        self.x = np.array(coords) + self.origin
        self.elements = []
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    self.elements.append([ids[(i + a, j + b, k + c)] for a, b, c in HEX8_CORNERS])

    def nodes_where(self, predicate):
        """Ids of the nodes whose coordinates (x, y, z) satisfy predicate."""
        return [self.first_node + n for n, p in enumerate(self.x) if predicate(*p)]

    def face(self, axis, side):
        """Node ids on the face axis (0, 1, 2) = its lowest (side 0) or highest (side 1) value."""
        value = self.origin[axis] + (0.0 if side == 0 else self.size[axis])
        return [self.first_node + n for n, p in enumerate(self.x) if abs(p[axis] - value) < 1e-12]

    def mesh_cards(self, node_sets):
        """*NODE (NSET=ALL_NODES), *ELEMENT (ELSET=ALL_ELEMENTS) and *NSET cards; node_sets:
        name -> ids. Several blocks (distinct first_node, first_element) add up."""
        lines = ['*NODE, NSET=ALL_NODES']
        lines += ['%d, %.17g, %.17g, %.17g' % (self.first_node + n, *p)
                  for n, p in enumerate(self.x)]
        lines.append('*ELEMENT, TYPE=C3D8, ELSET=ALL_ELEMENTS')
        lines += ['%d, %s' % (self.first_element + e, ', '.join(str(n) for n in conn))
                  for e, conn in enumerate(self.elements)]
        for name, ids in node_sets.items():
            lines.append('*NSET, NSET=%s' % name)
            for start in range(0, len(ids), 12):
                lines.append(', '.join(str(n) for n in ids[start:start + 12]))
        return lines


def material_cards(young, poisson, bbar=False, law='HYPOELASTIC'):
    """One material on every element: hypoelastic (*HYPOELASTIC, the rate form of the paper,
    whose closed forms these tests check) or, with law='ELASTIC', *ELASTIC (St Venant-Kirchhoff
    under NLGEOM)."""
    section = '*SOLID SECTION, ELSET=ALL_ELEMENTS, MATERIAL=STEEL'
    if bbar:
        section += ', FORMULATION=BBAR'
    return ['*MATERIAL, NAME=STEEL', '*' + law, '%.17g, %.17g' % (young, poisson), section]


def amplitude_card(name, times, values, time='STEP TIME'):
    """A tabular *AMPLITUDE with four (time, value) pairs per data line."""
    lines = ['*AMPLITUDE, NAME=%s, TIME=%s' % (name, time)]
    pairs = ['%.17g, %.17g' % (t, v) for t, v in zip(times, values)]
    for start in range(0, len(pairs), 4):
        lines.append(', '.join(pairs[start:start + 4]))
    return lines


def write_deck(path, lines):
    with open(path, 'w') as out:
        out.write('\n'.join(lines) + '\n')


def run_fcs3d(deck, *options):
    """Run $FCS3D on deck (quietly); exit the test with status 1 if it fails."""
    binary = os.environ.get('FCS3D')
    if not binary:
        fail('FCS3D is not set')
    result = subprocess.run([binary, '-q', *options, deck], capture_output=True, text=True)
    if result.returncode != 0:
        fail('fcs3d %s exited with status %d:\n%s%s' % (deck, result.returncode, result.stdout,
                                                        result.stderr))
    return result


# CalculiX writes the header of PE/PEEQ blocks without a blank before "for"
# ("equivalent plastic strain (elem, integ.pnt.,pe)for set ..."); fcs3d does the same.
HEADER = re.compile(r'^ (.*?) ?for set (\S+) and time\s+(\S+)\s*$')


def read_dat(path):
    """Blocks of a CalculiX-layout .dat file: list of (title, set, time, rows as 2-D array).

    A block is a header line ' <title> for set <SET> and time <t>', a blank line, then rows
    of numbers up to the next blank line or header. `time` is the float printed (e14.7)."""
    blocks = []
    current = None
    with open(path) as dat:
        for line in dat:
            match = HEADER.match(line.rstrip('\n'))
            if match:
                current = (match.group(1), match.group(2), float(match.group(3)), [])
                blocks.append(current)
                continue
            fields = line.split()
            if current is not None and fields:
                current[3].append([float(v) for v in fields])
    return [(title, name, time, np.array(rows)) for title, name, time, rows in blocks]


def blocks_of(blocks, title_start, set_name=None):
    """The blocks whose title starts with title_start (and of set set_name)."""
    return [b for b in blocks if b[0].startswith(title_start)
            and (set_name is None or b[1].upper() == set_name.upper())]


def unique_times(blocks):
    """The blocks with the first of any repeated time only. fcs3d at fbf1617 prints a block
    twice when an output request is due on the last increment of a step (a time point at the
    step end, or FREQUENCY) and again at the end of the step; tests/pending/dat_output_once.sh
    tests that separately (still failing at b2c7e0d), so the numerical tests do not depend on it."""
    seen = set()
    out = []
    for block in blocks:
        key = (block[0], block[1], block[2])
        if key not in seen:
            seen.add(key)
            out.append(block)
    return out


def same_printed_time(printed, requested):
    """Whether a .dat header time (Fortran E14.7: 0.ddddddd E+xx, 7 significant digits)
    is the requested time to printing precision (half a unit of the 7th digit)."""
    if requested == 0.0:
        return printed == 0.0
    unit = 10.0 ** (np.floor(np.log10(abs(requested))) - 6)
    return abs(printed - requested) <= 0.5 * unit * (1.0 + 1e-9)


def same_times(printed, requested):
    """Whether the lists of printed and requested times agree one by one (same_printed_time)."""
    return len(printed) == len(requested) and \
        all(same_printed_time(p, r) for p, r in zip(printed, requested))


def stress_blocks(blocks, set_name='ALL_ELEMENTS'):
    """(time, stress (n_points, 6) in Voigt order 11 22 33 12 13 23) of every S block, each
    time once."""
    return [(t, rows[:, 2:8])
            for _, _, t, rows in unique_times(blocks_of(blocks, 'stresses', set_name))]


LIMIT_NAMES = ('full', 'strain-limit', 'rotation-limit', 'yield', 'close', 'open',
               'stick->slip', 'slip->stick', 'segment-change', 'slip-rate-change',
               'friction-change', 'state-change', 'penetration-limit', 'plastic-strain-limit')
#: Limits that name an element and integration point in the log.
ELEMENT_LIMITS = ('strain-limit', 'rotation-limit', 'yield', 'plastic-strain-limit')
NUMBER = r'[-+0-9.Ee]+'
INCREMENT_LINE = re.compile(
    r'^inc (\d+) step (\d+) time (%s) dt (%s) r (%s) limit (\S+)( element \d+ ip \d+| node \d+)?'
    r'( \(floor\))? events (\d+)( switches \d+)?( iterations \d+)?( cuts \d+)?(?: krylov \d+)? residual (%s)$'
    % (NUMBER, NUMBER, NUMBER, NUMBER))


def read_increments(path):
    """The increment lines of <job>.log, checked against the format fcs_driver writes: every line
    names its limiting criterion, and an element-level limit names its element and point.

    Returns a list of dicts (inc, step, time, dt, r, limit, entity, floored, residual: the
    out-of-balance ratio left by the increment) and the number of
    increments the summary line reports; fails the test on any malformed line."""
    records = []
    done = None
    with open(path) as log:
        for line in log:
            line = line.rstrip('\n')
            if line.startswith('done: '):
                done = int(line.split()[1])
            if not line.startswith('inc '):
                continue
            match = INCREMENT_LINE.match(line)
            if not match:
                fail('%s: increment line not in the expected format:\n  %s' % (path, line))
            limit = match.group(6)
            if limit not in LIMIT_NAMES:
                fail('%s: unknown limiting criterion "%s" in:\n  %s' % (path, limit, line))
            if limit in ELEMENT_LIMITS and \
                    not (match.group(7) or '').startswith(' element'):
                fail('%s: limit %s without its element and point:\n  %s' % (path, limit, line))
            records.append(dict(inc=int(match.group(1)), step=int(match.group(2)),
                                time=float(match.group(3)), dt=float(match.group(4)),
                                r=float(match.group(5)), limit=limit,
                                entity=(match.group(7) or '').strip(),
                                floored=bool(match.group(8)),
                                residual=float(match.group(13))))
    if done is None:
        fail('%s: no "done: N increment(s)" summary line' % path)
    if len(records) != done or [r['inc'] for r in records] != list(range(1, done + 1)):
        fail('%s: %d increment lines for %d increments' % (path, len(records), done))
    return records, done


def mises(s):
    """von Mises stress of Voigt stresses s (..., 6)."""
    s = np.asarray(s, dtype=float)
    p = s[..., 0:3].sum(axis=-1) / 3.0
    dev = s[..., 0:3] - p[..., None]
    return np.sqrt(1.5 * ((dev ** 2).sum(axis=-1) + 2.0 * (s[..., 3:6] ** 2).sum(axis=-1)))


class Checker:
    """Collects check results, prints one line each, and exits 1 at the end if any failed."""

    def __init__(self):
        self.failed = 0

    def check(self, ok, text):
        print(('ok   ' if ok else 'FAIL ') + text)
        if not ok:
            self.failed += 1

    def relative(self, name, got, expected, tolerance, scale=None):
        """|got - expected| <= tolerance * |scale or expected|; returns the relative error."""
        reference = abs(expected) if scale is None else abs(scale)
        error = abs(got - expected) / reference
        self.check(error <= tolerance, '%s: got %.7g, expected %.7g, relative error %.3e '
                   '(tolerance %.1e)' % (name, got, expected, error, tolerance))
        return error

    def finish(self):
        if self.failed:
            print('%d check(s) failed' % self.failed)
            sys.exit(1)
        print('all checks passed')


def fail(text):
    print('FAIL ' + text)
    sys.exit(1)
