"""Shared helpers of the plasticity tests (tests/integration/plasticity_*.sh).

Decks on the blocks of ../nlgeom/fcs_check.py (C3D8), material cards of the plastic laws,
and the results of a run read at full precision from <job>.h5 (the .dat prints 7 digits, too
few for the closed-form checks at 1e-10): per frame the time, the integration-point stress
(fcs3d's Voigt order 11 22 33 12 13 23), PEEQ, and the nodal displacements. numpy, h5py.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'nlgeom'))
import fcs_check as fc  # noqa: E402,F401  (re-exported for the test scripts)

try:
    import h5py
except ImportError:
    h5py = None

#: Every element kind but C3D8 (which fcs_check.Block writes), for the tests that run each kind.
OTHER_KINDS = ['C3D4', 'C3D6', 'C3D8R', 'C3D8I', 'C3D10', 'C3D15', 'C3D20', 'C3D20R']


def kind_mesh_cards(size, cells, kind, node_sets):
    """*NODE (NSET=ALL_NODES), *ELEMENT (ELSET=ALL_ELEMENTS) and *NSET cards of the box
    [0, size] with `cells` hexahedral cells cut into elements of `kind` (tests/tools/
    kind_meshes.py: the corner ids are those of fcs_check.Block with the same cells; mid-side
    nodes follow). node_sets: name -> predicate(x, y, z) on the node coordinates."""
    sys.path.insert(0, os.path.join(HERE, '..', '..', 'tools'))
    import kind_meshes
    coords, hexes, _ = kind_meshes.hex_grid(list(cells), list(size), 0.0, np.random.default_rng(0))
    elements = kind_meshes.convert(coords, hexes, kind)
    lines = ['*NODE, NSET=ALL_NODES']
    lines += ['%d, %.17g, %.17g, %.17g' % (n, *x) for n, x in sorted(coords.items())]
    cards, _ = kind_meshes.element_cards(elements, 'ALL_ELEMENTS')
    lines += cards
    for name, predicate in node_sets.items():
        ids = [n for n, x in sorted(coords.items()) if predicate(*x)]
        lines.append('*NSET, NSET=%s' % name)
        for start in range(0, len(ids), 12):
            lines.append(', '.join(str(n) for n in ids[start:start + 12]))
    return lines


#: Position, in XDMF's Tensor6 order (xx xy xz yy yz zz) as stored, of fcs3d's Voigt
#: components xx yy zz xy xz yz.
FROM_XDMF = [0, 3, 5, 1, 2, 4]


def require_h5py():
    if h5py is None:
        print('h5py is not available to %s' % sys.executable)
        sys.exit(77)


def von_mises_cards(young, poisson, curve, hardening='ISOTROPIC', cyclic=None, bbar=False,
                    name='STEEL', elset='ALL_ELEMENTS', hypoelastic=False):
    """*MATERIAL with *ELASTIC (*HYPOELASTIC, the rate form under NLGEOM, with hypoelastic),
    *PLASTIC (curve: [(stress, plastic strain), ...]) and, for COMBINED, *CYCLIC HARDENING; the
    *SOLID SECTION on elset."""
    lines = ['*MATERIAL, NAME=%s' % name, '*HYPOELASTIC' if hypoelastic else '*ELASTIC',
             '%.17g, %.17g' % (young, poisson),
             '*PLASTIC, HARDENING=%s' % hardening]
    lines += ['%.17g, %.17g' % point for point in curve]
    if cyclic is not None:
        lines.append('*CYCLIC HARDENING')
        lines += ['%.17g, %.17g' % point for point in cyclic]
    section = '*SOLID SECTION, ELSET=%s, MATERIAL=%s' % (elset, name)
    if bbar:
        section += ', FORMULATION=BBAR'
    return lines + [section]


def drucker_prager_cards(young, poisson, beta, psi, curve, hardening_type='COMPRESSION',
                         bbar=False, name='ROCK', elset='ALL_ELEMENTS'):
    """*MATERIAL with *ELASTIC, *DRUCKER PRAGER (beta, K = 1, psi in degrees) and *DRUCKER
    PRAGER HARDENING; the *SOLID SECTION on elset."""
    lines = ['*MATERIAL, NAME=%s' % name, '*ELASTIC', '%.17g, %.17g' % (young, poisson),
             '*DRUCKER PRAGER', '%.17g, 1., %.17g' % (beta, psi),
             '*DRUCKER PRAGER HARDENING, TYPE=%s' % hardening_type]
    lines += ['%.17g, %.17g' % point for point in curve]
    section = '*SOLID SECTION, ELSET=%s, MATERIAL=%s' % (elset, name)
    if bbar:
        section += ', FORMULATION=BBAR'
    return lines + [section]


class Frames:
    """The frames of <job>.h5: times (n), stress (n, ne, 8, 6) in fcs3d's Voigt order,
    peeq (n, ne, 8), plastic_strain (n, ne, 8, 6: tensor components, Voigt order), displacement (n, nodes, 3) and reference coordinates (nodes, 3);
    node_ids to find nodes by id."""

    def __init__(self, path):
        require_h5py()
        with h5py.File(path, 'r') as f:
            names = sorted(f['frames'])
            self.times = np.array([f['frames'][n].attrs['time'] for n in names])
            self.stress = np.array([f['frames'][n]['integration_points/stress'][()][..., FROM_XDMF]
                                    for n in names])
            self.peeq = np.array([f['frames'][n]['integration_points/PEEQ'][()][..., 0]
                                  for n in names])
            self.plastic_strain = np.array([f['frames'][n]['integration_points/PE'][()][..., FROM_XDMF]
                                            for n in names])
            self.displacement = np.array([f['frames'][n]['nodal/displacement'][()]
                                          for n in names])
            self.force = np.array([f['frames'][n]['nodal/force'][()] for n in names])
            self.node_ids = list(f['mesh/node_ids'][()])
            self.x = f['mesh/coordinates'][()]

    def node(self, node_id):
        return self.node_ids.index(node_id)
