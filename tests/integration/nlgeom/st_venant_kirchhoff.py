"""*ELASTIC under NLGEOM is St Venant-Kirchhoff (doc/theory.md 2.10): closed forms.

    st_venant_kirchhoff.py            (writes the decks, runs $FCS3D, checks; run in a scratch dir)

St Venant-Kirchhoff: S = C : E with the Green-Lagrange strain E = (F^T F - I)/2, Cauchy stress
sigma = F S F^T / det F; *EL PRINT E prints E (reference axes) and ENER 1/2 S:E. Every case is a
block of 2 x 2 x 2 C3D8 on the unit cube, in default increments:

1. uniaxial: stretch lambda = 1.3 along x, the lateral faces free (symmetry planes x = 0,
   y = 0, z = 0). Uniaxial S (S22 = S33 = 0): E11 = (lambda^2 - 1)/2, S11 = E_young E11,
   E22 = E33 = -nu E11, lateral stretch mu = sqrt(1 + 2 E22), sigma11 = lambda S11 / mu^2.
   (The hypoelastic law gives sigma11 = E_young ln(lambda) (1 + ...) instead: 0.26 E against
   0.40 E here.)
2. simple shear x = X + gamma Y to gamma = 0.5, every node prescribed: sigma = F S F^T with
   S = lambda_L tr(E) I + 2 G E (J = 1).
3. stretch, then turn: step 1 F1 = diag(lambda, mu, mu) (every node prescribed, mu of case 1:
   a uniaxial S), step 2 F = R F1 with R a quarter turn about z (the displacements of the step
   go linearly to those of R F1: the path is not a rigid turn, but St Venant-Kirchhoff depends
   on F only). At the end sigma = R sigma1 R^T (sigma22 = sigma1_11) and E, in reference axes,
   is unchanged.
4. a rotated orthotropic block: *ELASTIC, TYPE=ENGINEERING CONSTANTS with an *ORIENTATION whose
   local axis 1 is global y; stretch lambda along y, the other faces free. In the reference
   material axes uniaxial S along 1: S11 = E1 E11, E22 = -nu12 E11, E33 = -nu13 E11; the
   lateral stretches along x (local 2) and z (local 3) are sqrt(1 + 2 E22) and sqrt(1 + 2 E33)
   (printed in global axes, GLOBAL=YES). The small-strain refusal of anisotropy under NLGEOM
   that this replaces (its axes do not turn: they stay in the reference configuration, as the
   Green-Lagrange strain's) was tests/decks/bad/elastic_aniso_nlgeom.inp.

The deformation is homogeneous, so every point has the same values; tolerance 1e-4 relative:
the equilibrium iterations leave an out-of-balance of that order of the nodal forces (case 1
and 4, where the lateral contraction is found), round-off where everything is prescribed.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fcs_check as fc  # noqa: E402

YOUNG = 1000.0
POISSON = 0.3
LAMBDA_L = YOUNG * POISSON / ((1.0 + POISSON) * (1.0 - 2.0 * POISSON))
SHEAR = YOUNG / (2.0 * (1.0 + POISSON))
STRETCH = 1.3
GAMMA = 0.5
TOLERANCE = 1e-4
#: ENGINEERING CONSTANTS E1, E2, E3, nu12, nu13, nu23, G12, G13, G23.
ORTHO = (2000.0, 800.0, 500.0, 0.25, 0.2, 0.3, 400.0, 300.0, 250.0)


def block_and_sets():
    block = fc.Block(nx=2, ny=2, nz=2)
    sets = {'X0': block.face(0, 0), 'X1': block.face(0, 1), 'Y0': block.face(1, 0),
            'Y1': block.face(1, 1), 'Z0': block.face(2, 0), 'Z1': block.face(2, 1)}
    return block, sets


def outputs(global_axes=''):
    return ['*NODE PRINT, NSET=ALL_NODES', 'U', '*EL PRINT, ELSET=ALL_ELEMENTS' + global_axes,
            'S, E, ENER']


def svk_cauchy(f, c):
    """sigma(F) (3 x 3) of St Venant-Kirchhoff with the 6 x 6 stiffness c (engineering shears)."""
    e = 0.5 * (f.T @ f - np.eye(3))
    s6 = c @ np.array([e[0, 0], e[1, 1], e[2, 2], 2 * e[0, 1], 2 * e[0, 2], 2 * e[1, 2]])
    s = np.array([[s6[0], s6[3], s6[4]], [s6[3], s6[1], s6[5]], [s6[4], s6[5], s6[2]]])
    return f @ s @ f.T / np.linalg.det(f), e, s


def isotropic_c():
    c = np.zeros((6, 6))
    c[0:3, 0:3] = LAMBDA_L
    for i in range(3):
        c[i, i] += 2 * SHEAR
        c[i + 3, i + 3] = SHEAR
    return c


def voigt(t):
    return np.array([t[0, 0], t[1, 1], t[2, 2], t[0, 1], t[0, 2], t[1, 2]])




def last_block(blocks, title):
    found = fc.blocks_of(blocks, title)
    if not found:
        fc.fail('no "%s" table' % title)
    return found[-1][3]


def compare(checker, case, what, rows, expected, scale):
    """Every row (point) against the expected Voigt values, relative to `scale`."""
    error = np.abs(rows - expected[None, :]).max() / scale
    checker.check(error <= TOLERANCE, '%s: %s at every point within %.0e (max error %.2e of '
                  'the scale %.4g)' % (case, what, TOLERANCE, error, scale))


def check_points(checker, case, job, sigma, e, s):
    blocks = fc.read_dat(job + '.dat')
    scale = np.abs(voigt(sigma)).max()
    compare(checker, case, 'Cauchy stress', last_block(blocks, 'stresses')[:, 2:8], voigt(sigma), scale)
    # The .dat prints tensor shear strains (CalculiX's exy = E12).
    compare(checker, case, 'Green-Lagrange strain', last_block(blocks, 'strains')[:, 2:8],
            voigt(e), np.abs(voigt(e)).max())
    energy = 0.5 * float(np.sum(s * e))
    compare(checker, case, 'ENER 1/2 S:E', last_block(blocks, 'internal energy')[:, 2:3],
            np.array([energy]), energy)
    return blocks


def displacement_of(blocks, node):
    rows = fc.blocks_of(blocks, 'displacements')[-1][3]
    return rows[rows[:, 0] == node][0, 1:4]


def uniaxial(checker):
    block, sets = block_and_sets()
    lines = ['*HEADING', 'St Venant-Kirchhoff uniaxial stretch (st_venant_kirchhoff.py)']
    lines += block.mesh_cards(sets) + fc.material_cards(YOUNG, POISSON, law='ELASTIC')
    lines += ['*STEP, NLGEOM', '*STATIC', '*BOUNDARY', 'X0, 1, 1, 0.', 'Y0, 2, 2, 0.',
              'Z0, 3, 3, 0.', 'X1, 1, 1, %.17g' % (STRETCH - 1.0)] + outputs() + ['*END STEP']
    fc.write_deck('uniaxial.inp', lines)
    fc.run_fcs3d('uniaxial.inp')
    e11 = 0.5 * (STRETCH ** 2 - 1.0)
    mu = math.sqrt(1.0 - 2.0 * POISSON * e11)
    f = np.diag([STRETCH, mu, mu])
    sigma, e, s = svk_cauchy(f, isotropic_c())
    checker.relative('uniaxial: sigma11 = lambda E e11 / mu^2', sigma[0, 0],
                     STRETCH * YOUNG * e11 / mu ** 2, 1e-12)
    blocks = check_points(checker, 'uniaxial', 'uniaxial', sigma, e, s)
    corner = block.ids[(2, 2, 2)]
    checker.relative('uniaxial: lateral displacement of the far corner = mu - 1',
                     displacement_of(blocks, corner)[1], mu - 1.0, TOLERANCE)


def simple_shear(checker):
    block = fc.Block(nx=2, ny=2, nz=2)
    heights = sorted(set(block.x[:, 1]))
    sets = {'LEVEL%d' % k: block.nodes_where(lambda x, y, z, h=h: abs(y - h) < 1e-12)
            for k, h in enumerate(heights)}
    lines = ['*HEADING', 'St Venant-Kirchhoff simple shear (st_venant_kirchhoff.py)']
    lines += block.mesh_cards(sets) + fc.material_cards(YOUNG, POISSON, law='ELASTIC')
    lines += ['*STEP, NLGEOM', '*STATIC', '*BOUNDARY', 'ALL_NODES, 2, 3, 0.']
    lines += ['LEVEL%d, 1, 1, %.17g' % (k, GAMMA * h) for k, h in enumerate(heights)]
    lines += outputs() + ['*END STEP']
    fc.write_deck('shear.inp', lines)
    fc.run_fcs3d('shear.inp')
    f = np.eye(3)
    f[0, 1] = GAMMA
    sigma, e, s = svk_cauchy(f, isotropic_c())
    check_points(checker, 'simple shear', 'shear', sigma, e, s)


def stretch_and_turn(checker):
    block, _ = block_and_sets()
    e11 = 0.5 * (STRETCH ** 2 - 1.0)
    mu = math.sqrt(1.0 - 2.0 * POISSON * e11)
    f1 = np.diag([STRETCH, mu, mu])
    turn = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    lines = ['*HEADING', 'St Venant-Kirchhoff stretch, then a quarter turn (st_venant_kirchhoff.py)']
    lines += block.mesh_cards({}) + fc.material_cards(YOUNG, POISSON, law='ELASTIC')
    for f in (f1, turn @ f1):
        lines += ['*STEP, NLGEOM', '*STATIC', '*BOUNDARY']
        for n, x in enumerate(block.x):
            u = f @ x - x
            lines += ['%d, %d, %d, %.17g' % (block.first_node + n, i + 1, i + 1, u[i]) for i in range(3)]
        lines += outputs() + ['*END STEP']
    fc.write_deck('turn.inp', lines)
    fc.run_fcs3d('turn.inp')
    sigma1, e, s = svk_cauchy(f1, isotropic_c())
    checker.check(abs(sigma1[1, 1]) <= 1e-12 * abs(sigma1[0, 0]), 'stretch: uniaxial stress')
    check_points(checker, 'stretch and turn', 'turn', turn @ sigma1 @ turn.T, e, s)


def rotated_orthotropic(checker):
    block, sets = block_and_sets()
    e1, e2, e3, nu12, nu13, nu23, g12, g13, g23 = ORTHO
    lines = ['*HEADING', 'St Venant-Kirchhoff rotated orthotropic block (st_venant_kirchhoff.py)']
    lines += block.mesh_cards(sets)
    lines += ['*ORIENTATION, NAME=TURNED, SYSTEM=RECTANGULAR', '0., 1., 0., -1., 0., 0.',
              '*MATERIAL, NAME=WOOD', '*ELASTIC, TYPE=ENGINEERING CONSTANTS',
              '%.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g' % ORTHO[:8], '%.17g' % g23,
              '*SOLID SECTION, ELSET=ALL_ELEMENTS, MATERIAL=WOOD, ORIENTATION=TURNED']
    lines += ['*STEP, NLGEOM', '*STATIC', '*BOUNDARY', 'X0, 1, 1, 0.', 'Y0, 2, 2, 0.',
              'Z0, 3, 3, 0.', 'Y1, 2, 2, %.17g' % (STRETCH - 1.0)] + outputs(', GLOBAL=YES') + \
        ['*END STEP']
    fc.write_deck('ortho.inp', lines)
    fc.run_fcs3d('ortho.inp')
    e11 = 0.5 * (STRETCH ** 2 - 1.0)
    mu_x = math.sqrt(1.0 - 2.0 * nu12 * e11)
    mu_z = math.sqrt(1.0 - 2.0 * nu13 * e11)
    f = np.diag([mu_x, STRETCH, mu_z])
    s_yy = e1 * e11
    sigma = np.zeros((3, 3))
    sigma[1, 1] = STRETCH * s_yy / (mu_x * mu_z)
    e = 0.5 * (f.T @ f - np.eye(3))
    s = np.zeros((3, 3))
    s[1, 1] = s_yy
    blocks = check_points(checker, 'rotated orthotropic', 'ortho', sigma, e, s)
    corner = block.ids[(2, 2, 2)]
    u = displacement_of(blocks, corner)
    checker.relative('rotated orthotropic: contraction along x (local 2, nu12)', u[0], mu_x - 1.0,
                     TOLERANCE)
    checker.relative('rotated orthotropic: contraction along z (local 3, nu13)', u[2], mu_z - 1.0,
                     TOLERANCE)


def main():
    checker = fc.Checker()
    uniaxial(checker)
    simple_shear(checker)
    stretch_and_turn(checker)
    rotated_orthotropic(checker)
    checker.finish()


if __name__ == '__main__':
    main()
