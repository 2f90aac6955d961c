"""Every *HYPERELASTIC form and *HYPERFOAM against CalculiX 2.20 (doc/theory.md 2.11).

    calculix_hyperelastic.py [--work DIR]      (needs ccx; exit 77 without it)

A 2 x 2 x 2 C3D8 block on the unit cube (symmetry planes x = 0, y = 0, z = 0) is stretched
to 1.4 along x, the lateral faces free, under NLGEOM, through ccx (20 increments of 0.05) and
fcs3d (its defaults), for each form with constants of order one (every C_ij, mu_i, alpha_i,
D_i of the form nonzero, so that a constant read into the wrong place shows): YEOH,
POLYNOMIAL N=2 and N=3 (a pair of lines), REDUCED POLYNOMIAL N=2, MOONEY-RIVLIN with D1 = 0
(ccx's default D1), NEO HOOKE with a temperature column, ARRUDA-BOYCE, OGDEN N=3 (a pair of
lines) and HYPERFOAM N=3 (a pair of lines). (HYPERFOAM N=1 is left out: ccx 2.20 stops without a
message in the first iteration of such a block, whatever the constants;
tests/integration/nlgeom_hyperelastic.sh checks fcs3d's against the closed form.)

Asserted: the reaction force on the face x = 1 and every nodal displacement agree within
1e-4, relative to the force and to the largest displacement (the deformation is homogeneous, so
both codes find the same F; what is left is their equilibrium tolerances; measured 2e-5 at
most).
"""
import argparse
import os
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'integration', 'nlgeom'))
import fcs_check as fc  # noqa: E402

TOLERANCE = 1e-4
FORMS = [
    ('yeoh', ['*HYPERELASTIC, YEOH', '0.4, -0.02, 0.005, 0.2, 0.5, 1.']),
    ('polynomial2', ['*HYPERELASTIC, POLYNOMIAL, N=2', '0.4, 0.1, 0.02, -0.01, 0.005, 0.2, 0.5']),
    ('polynomial3', ['*HYPERELASTIC, POLYNOMIAL, N=3',
                     '0.4, 0.1, 0.02, -0.01, 0.005, 0.003, 0.002, -0.001', '0.0005, 0.2, 0.5, 1.']),
    ('reduced2', ['*HYPERELASTIC, REDUCED POLYNOMIAL, N=2', '0.4, 0.03, 0.2, 0.5']),
    ('mooney_default_d', ['*HYPERELASTIC, MOONEY-RIVLIN', '0.4, 0.1, 0.']),
    ('neo_hooke_temperature', ['*HYPERELASTIC, NEO HOOKE', '0.5, 0.1, 20.']),
    ('arruda_boyce', ['*HYPERELASTIC, ARRUDA-BOYCE', '0.8, 2.5, 0.2']),
    ('ogden3', ['*HYPERELASTIC, OGDEN, N=3', '0.6, 2.5, 0.02, -2., 0.01, 4., 0.2, 0.5', '1.']),
    ('hyperfoam3', ['*HYPERFOAM, N=3', '0.2, 6., 0.01, -2., 0.02, 3., 0.1, 0.2', '0.05']),
]


def deck(name, cards):
    block = fc.Block(nx=2, ny=2, nz=2)
    sets = {'X0': block.face(0, 0), 'X1': block.face(0, 1), 'Y0': block.face(1, 0),
            'Z0': block.face(2, 0)}
    lines = ['*HEADING', 'hyperelastic form %s (calculix_hyperelastic.py)' % name]
    lines += block.mesh_cards(sets) + ['*MATERIAL, NAME=RUBBER'] + cards
    lines += ['*SOLID SECTION, ELSET=ALL_ELEMENTS, MATERIAL=RUBBER', '*STEP, NLGEOM, INC=1000',
              '*STATIC', '0.05, 1.', '*BOUNDARY', 'X0, 1, 1, 0.', 'Y0, 2, 2, 0.', 'Z0, 3, 3, 0.',
              'X1, 1, 1, 0.4', '*NODE PRINT, NSET=X1', 'RF', '*NODE PRINT, NSET=ALL_NODES', 'U',
              '*END STEP']
    return lines


def run(program, work, name, lines):
    directory = os.path.join(work, program, name)
    os.makedirs(directory, exist_ok=True)
    fc.write_deck(os.path.join(directory, name + '.inp'), lines)
    command = ['ccx', name] if program == 'ccx' else [os.environ.get('FCS3D', 'fcs3d'), '-q',
                                                        name + '.inp']
    p = subprocess.run(command, cwd=directory, capture_output=True, text=True, timeout=600,
                       env=dict(os.environ, OMP_NUM_THREADS='1'))
    if p.returncode != 0:
        fc.fail('%s failed on %s: %s' % (program, name, p.stdout[-400:] + p.stderr[-400:]))
    blocks = fc.read_dat(os.path.join(directory, name + '.dat'))
    forces = fc.blocks_of(blocks, 'forces', 'X1')
    displacements = fc.blocks_of(blocks, 'displacements', 'ALL_NODES')
    if not forces or not displacements:
        fc.fail('%s wrote no final tables for %s' % (program, name))
    return forces[-1][3][:, 1].sum(), displacements[-1][3][:, 1:4]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--work', default='calculix_hyperelastic')
    args = parser.parse_args()
    if shutil.which('ccx') is None:
        print('ccx (Debian package calculix-ccx) not installed')
        return 77
    checker = fc.Checker()
    for name, cards in FORMS:
        lines = deck(name, cards)
        force_ccx, u_ccx = run('ccx', args.work, name, lines)
        force_fcs, u_fcs = run('fcs3d', args.work, name, lines)
        checker.relative('%s: reaction force, fcs3d against ccx' % name, force_fcs, force_ccx,
                         TOLERANCE)
        error = np.abs(u_fcs - u_ccx).max() / np.abs(u_ccx).max()
        checker.check(error <= TOLERANCE, '%s: nodal displacements within %.0e of the largest '
                      '(max difference %.2e)' % (name, TOLERANCE, error))
    checker.finish()
    return 0


if __name__ == '__main__':
    sys.exit(main())
