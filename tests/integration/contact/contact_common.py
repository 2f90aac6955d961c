"""Shared helpers of the contact tests (tests/integration/contact_*.sh and
tests/validate/contact_*.sh, calculix_contact.sh).

Structured hexahedral boxes with named node and element sets, the contact cards of a deck,
running fcs3d, and reading what it writes: the CalculiX-layout tables of <job>.dat (node
totals, *CONTACT PRINT blocks), the per-pair contact grids of <job>.h5 and the increment
lines of <job>.log (the reader of tests/integration/nlgeom/fcs_check.py). numpy (and h5py
for the results file) only.
"""
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'nlgeom'))
import fcs_check  # noqa: E402  (read_increments, Checker)

Checker = fcs_check.Checker
read_increments = fcs_check.read_increments

# C3D8 corner order: bottom face counter-clockwise seen from the top, then the top face.
HEX8_CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
# C3D8 faces: S1 z-, S2 z+, S3 y-, S4 x+, S5 y+, S6 x-  ->  (axis, side)
FACE_OF = {(2, 0): 'S1', (2, 1): 'S2', (1, 0): 'S3', (0, 1): 'S4', (1, 1): 'S5', (0, 0): 'S6'}


def graded(length, n, ratio=1.0, start=0.0):
    """n + 1 coordinates from start to start + length, each element `ratio` times the one
    before (ratio > 1: fine at start)."""
    if abs(ratio - 1.0) < 1e-12:
        sizes = np.ones(n)
    else:
        sizes = ratio ** np.arange(n)
    return start + length * np.concatenate([[0.0], np.cumsum(sizes)]) / sizes.sum()


class Box:
    """A structured box of hexahedra: nodes at (xs[i], ys[j], zs[k]) (1-D coordinate arrays),
    optionally moved by warp(x, y, z) -> (x, y, z) (e.g. a kinked top surface). Node and
    element ids start at first_node, first_element."""

    def __init__(self, xs, ys, zs, first_node=1, first_element=1, warp=None):
        self.xs, self.ys, self.zs = (np.asarray(c, dtype=float) for c in (xs, ys, zs))
        self.n = (len(self.xs) - 1, len(self.ys) - 1, len(self.zs) - 1)
        self.first_node = first_node
        self.first_element = first_element
        self.ids = {}
        coords = []
        for k, z in enumerate(self.zs):
            for j, y in enumerate(self.ys):
                for i, x in enumerate(self.xs):
                    self.ids[(i, j, k)] = first_node + len(coords)
                    coords.append(warp(x, y, z) if warp else (x, y, z))
        # Rounded so that the deck's numbers stay short (CalculiX reads at most 20 characters
        # per field) and exact: 1e-12 of the model size is far below any tolerance here.
        self.x = np.round(np.array(coords, dtype=float), 12) + 0.0
        self.elements = []   # (id, connectivity, (i, j, k))
        nx, ny, nz = self.n
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    conn = [self.ids[(i + a, j + b, k + c)] for a, b, c in HEX8_CORNERS]
                    self.elements.append((first_element + len(self.elements), conn, (i, j, k)))

    @property
    def node_ids(self):
        return list(range(self.first_node, self.first_node + len(self.x)))

    @property
    def element_ids(self):
        return [e[0] for e in self.elements]

    def coordinates(self, node):
        return self.x[node - self.first_node]

    def nodes_where(self, predicate):
        """Ids of the nodes whose coordinates satisfy predicate(x, y, z)."""
        return [self.first_node + n for n, p in enumerate(self.x) if predicate(*p)]

    def face_nodes(self, axis, side):
        """Node ids of the box face axis (0, 1, 2) = lowest (side 0) / highest (side 1) index."""
        index = 0 if side == 0 else self.n[axis]
        return sorted(node for ijk, node in self.ids.items() if ijk[axis] == index)

    def face_elements(self, axis, side):
        """(element ids, face label S1..S6) of the element faces on a box face."""
        index = 0 if side == 0 else self.n[axis] - 1
        return [e[0] for e in self.elements if e[2][axis] == index], FACE_OF[(axis, side)]

    def mesh_cards(self, elset):
        """*NODE and *ELEMENT cards; the elements also go to element set `elset`."""
        lines = ['*NODE, NSET=ALL_NODES']
        lines += ['%d, %.12g, %.12g, %.12g' % (self.first_node + n, *p)
                  for n, p in enumerate(self.x)]
        lines.append('*ELEMENT, TYPE=C3D8, ELSET=%s' % elset)
        lines += ['%d, %s' % (eid, ', '.join(str(n) for n in conn))
                  for eid, conn, _ in self.elements]
        return lines


def id_lines(ids, per_line=12):
    ids = list(ids)
    return [', '.join(str(n) for n in ids[s:s + per_line]) for s in range(0, len(ids), per_line)]


def nset_cards(name, ids):
    return ['*NSET, NSET=%s' % name] + id_lines(ids)


def elset_cards(name, ids):
    return ['*ELSET, ELSET=%s' % name] + id_lines(ids)


def face_surface_cards(name, box, axis, side):
    """An element-face surface on a face of a box (its own element set NAME_EL)."""
    elements, label = box.face_elements(axis, side)
    return elset_cards(name + '_EL', elements) + \
        ['*SURFACE, NAME=%s, TYPE=ELEMENT' % name, '%s_EL, %s' % (name, label)]


def material_cards(name, elset, young, poisson):
    return ['*MATERIAL, NAME=%s' % name, '*ELASTIC', '%.12g, %.12g' % (young, poisson),
            '*SOLID SECTION, ELSET=%s, MATERIAL=%s' % (elset, name)]


def interaction_cards(name, normal_stiffness, mu=None, stick_stiffness=None):
    """*SURFACE INTERACTION with a linear pressure-overclosure slope E_n [stress/length] and,
    if mu is given, Coulomb friction with stick slope E_t (default E_n)."""
    lines = ['*SURFACE INTERACTION, NAME=%s' % name,
             '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR', '%.12g' % normal_stiffness]
    if mu is not None:
        lines += ['*FRICTION', '%.12g' % mu if stick_stiffness is None
                  else '%.12g, %.12g' % (mu, stick_stiffness)]
    return lines


def write_deck(path, lines):
    with open(path, 'w') as out:
        out.write('\n'.join(lines) + '\n')


def run_fcs3d(deck, *options):
    """Run $FCS3D on deck quietly, output next to it; exit 1 (test failure) if it fails."""
    return fcs_check.run_fcs3d(deck, *options)


# ---------------------------------------------------------------------------- .dat tables

DAT_HEADER = re.compile(r'^ (?P<title>.+?) for (?:set (?P<set>\S+)|all contact elements) '
                        r'and time\s*(?P<time>\S+)\s*$')


def read_dat(path):
    """Blocks of a CalculiX-layout .dat file (fcs3d's or ccx's): list of dicts title, set
    (None for contact blocks), time, rows (list of (integer keys, float values))."""
    blocks = []
    current = None
    with open(path, errors='replace') as dat:
        for line in dat:
            match = DAT_HEADER.match(line.rstrip('\n'))
            if match:
                current = dict(title=match.group('title').strip(), set=match.group('set'),
                               time=float(match.group('time')), rows=[])
                blocks.append(current)
                continue
            fields = line.split()
            if current is None or not fields:
                continue
            keys = []
            while fields and re.fullmatch(r'[+-]?\d+', fields[0]):
                keys.append(int(fields.pop(0)))
            try:
                values = [float(f) for f in fields]
            except ValueError:
                current = None
                continue
            current['rows'].append((tuple(keys), np.array(values)))
    return blocks


def totals(blocks, set_name):
    """(times, forces (n, 3)) of the 'total force' blocks of a node set, one per time (the
    first block of a repeated time)."""
    times, values = [], []
    for b in blocks:
        if b['title'].startswith('total force') and (b['set'] or '').upper() == set_name.upper():
            if times and abs(b['time'] - times[-1]) <= 1e-12 * max(1.0, abs(b['time'])):
                continue
            times.append(b['time'])
            values.append(b['rows'][0][1])
    return np.array(times), np.array(values)


def contact_tables(blocks, kind='contact stress'):
    """[(time, {slave node id: (p, t1, t2)})] of the *CONTACT PRINT blocks (CSTR: 'contact
    stress', CDIS: 'relative contact displacement'), each time once."""
    out = []
    for b in blocks:
        if not b['title'].startswith(kind):
            continue
        if out and out[-1][0] == b['time']:
            continue
        out.append((b['time'], {keys[0]: values for keys, values in b['rows']}))
    return out


# ---------------------------------------------------------------------------- .h5 results

STATUS = {0: 'open', 1: 'stick', 2: 'slip', 3: 'tied'}
OPEN, STICK, SLIP, TIED = 0, 1, 2, 3


def contact_frames(path, pair):
    """Frames of the contact grid 'contact_<pair>' in <job>.h5: list of dicts time, step,
    increment, x (current slave coordinates), and the fields status (int), gap, pressure,
    shear_magnitude, shear (n, 3), slip, slip_rate, mu."""
    import h5py
    frames = []
    with h5py.File(path, 'r') as h5:
        for name in sorted(h5['frames']):
            frame = h5['frames'][name]
            grid = frame['surfaces']['contact_' + pair]
            record = dict(time=float(frame.attrs['time']), step=int(frame.attrs['step']),
                          increment=int(frame.attrs['increment']), x=grid['coordinates'][()])
            for field, values in grid['nodal'].items():
                record[field] = values[()]
            record['status'] = np.rint(record['status']).astype(int)
            frames.append(record)
    return frames


def node_coordinates(path):
    """{node id: reference coordinates} from the mesh of <job>.h5."""
    import h5py
    with h5py.File(path, 'r') as h5:
        ids = h5['mesh/node_ids'][()]
        x = h5['mesh/coordinates'][()]
    return {int(n): x[i] for i, n in enumerate(ids)}


def save_csv(path, header, columns):
    data = np.column_stack(columns)
    np.savetxt(path, data, delimiter=',', header=','.join(header), comments='', fmt='%.9g')


def fail(text):
    fcs_check.fail(text)
