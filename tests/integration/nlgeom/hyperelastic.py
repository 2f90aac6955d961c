"""*HYPERELASTIC and *HYPERFOAM under NLGEOM (doc/theory.md 2.11): uniaxial stretch, closed form.

    hyperelastic.py            (writes the decks, runs $FCS3D, checks; run in a scratch dir)

A block of 2 x 2 x 2 C3D8 on the unit cube, in default increments, is stretched to lambda = 1.5
along x, the lateral faces free (symmetry planes x = 0, y = 0, z = 0): F = diag(lambda, mu, mu)
with the lateral stretch mu where sigma_22 = 0. The principal Cauchy stresses of an isotropic
energy W(lambda_1, lambda_2, lambda_3) are sigma_a = lambda_a / J dW/dlambda_a (Holzapfel 2000,
eq. 6.74); W is coded here from the ccx manual's formulas (*HYPERELASTIC, *HYPERFOAM) and
differentiated by central differences (step 1e-6: error ~1e-11 relative), mu found by bisection
on sigma_22(mu) = 0 (to 1e-14). The reaction force on the face x = 1 (sum of RF over its nodes)
is then sigma_11 mu^2 (the current area of the unit face), and the far corner moves by
(lambda - 1, mu - 1, mu - 1). Three materials:

1. MOONEY-RIVLIN C10 = 0.4, C01 = 0.1, D1 = 0.2 (compressible: initial Poisson's ratio 0.42);
2. OGDEN, N=2 mu = 0.6, 0.02, alpha = 2.5, -2, D1 = D2 = 0: the defaults D_i = (0.1/mu_0)^i
   (mu_0 = mu_1 + mu_2) that ccx substitutes, so mu_0 / K_0 = 1/20, nearly incompressible;
3. HYPERFOAM, N=1 mu = 0.2, alpha = 6, nu = 0.1 (a compressible foam).

Restart: the Ogden run writes a checkpoint every 5 increments (*RESTART, WRITE); a copy of the
job restarted from the middle one of its checkpoints (with the .dat and .h5 the run had written) ends with
the one-go run's .dat byte for byte and every dataset and attribute of its .h5 bit for bit
(restart_common.compare_h5; skipped without h5py): the hyperelastic stress is a function of F
alone, so the checkpoint needs no state of its own.

Tolerance 1e-4 relative: the deformation is homogeneous (each point sees the same F, whatever
the increments), so the only error is the out-of-balance the equilibrium iterations leave, of
order 1e-5 of the nodal forces (doc/theory.md 6.8); the closed form itself is exact to 1e-10.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fcs_check as fc  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'restart'))

STRETCH = 1.5
TOLERANCE = 1e-4


def mooney_rivlin(l):
    c10, c01, d1 = 0.4, 0.1, 0.2
    j = l[0] * l[1] * l[2]
    lb2 = (j ** (-2.0 / 3.0)) * np.asarray(l) ** 2
    i1, i2 = lb2.sum(), lb2[0] * lb2[1] + lb2[1] * lb2[2] + lb2[0] * lb2[2]
    return c10 * (i1 - 3) + c01 * (i2 - 3) + (j - 1) ** 2 / d1


OGDEN_MU, OGDEN_ALPHA = (0.6, 0.02), (2.5, -2.0)


def ogden(l):
    mu0 = sum(OGDEN_MU)
    d = (0.1 / mu0, (0.1 / mu0) ** 2)
    j = l[0] * l[1] * l[2]
    lb = j ** (-1.0 / 3.0) * np.asarray(l)
    w = sum(2 * m / a ** 2 * ((lb ** a).sum() - 3) for m, a in zip(OGDEN_MU, OGDEN_ALPHA))
    return w + sum((j - 1) ** (2 * (i + 1)) / d[i] for i in range(2))


def hyperfoam(l):
    mu, alpha, nu = 0.2, 6.0, 0.1
    beta = nu / (1 - 2 * nu)
    j = l[0] * l[1] * l[2]
    return 2 * mu / alpha ** 2 * ((np.asarray(l) ** alpha).sum() - 3 + (j ** (-alpha * beta) - 1) / beta)


MATERIALS = [('mooney_rivlin', ['*HYPERELASTIC, MOONEY-RIVLIN', '0.4, 0.1, 0.2'], mooney_rivlin),
             ('ogden', ['*HYPERELASTIC, OGDEN, N=2', '0.6, 2.5, 0.02, -2., 0., 0.'], ogden),
             ('hyperfoam', ['*HYPERFOAM, N=1', '0.2, 6., 0.1'], hyperfoam)]


def principal_stresses(energy, l):
    """sigma_a = lambda_a / J dW/dlambda_a, central differences."""
    h = 1e-6
    j = l[0] * l[1] * l[2]
    out = []
    for a in range(3):
        up, down = list(l), list(l)
        up[a] += h
        down[a] -= h
        out.append(l[a] / j * (energy(up) - energy(down)) / (2 * h))
    return out


def lateral_stretch(energy):
    """mu in (0.3, 1] with sigma_22(lambda, mu, mu) = 0, by bisection."""
    low, high = 0.3, 1.0
    for _ in range(200):
        mid = 0.5 * (low + high)
        if principal_stresses(energy, [STRETCH, mid, mid])[1] > 0:
            high = mid
        else:
            low = mid
        if high - low < 1e-14:
            break
    return 0.5 * (low + high)


def main():
    checker = fc.Checker()
    block = fc.Block(nx=2, ny=2, nz=2)
    sets = {'X0': block.face(0, 0), 'X1': block.face(0, 1), 'Y0': block.face(1, 0),
            'Z0': block.face(2, 0)}
    corner = block.ids[(2, 2, 2)]
    for name, cards, energy in MATERIALS:
        lines = ['*HEADING', 'Hyperelastic uniaxial stretch, %s (hyperelastic.py)' % name]
        lines += block.mesh_cards(sets) + ['*MATERIAL, NAME=RUBBER'] + cards
        lines += ['*SOLID SECTION, ELSET=ALL_ELEMENTS, MATERIAL=RUBBER']
        if name == 'ogden':
            lines += ['*RESTART, WRITE, FREQUENCY=5, GENERATIONS=100']
        lines += ['*STEP, NLGEOM', '*STATIC', '*BOUNDARY', 'X0, 1, 1, 0.', 'Y0, 2, 2, 0.',
                  'Z0, 3, 3, 0.', 'X1, 1, 1, %.17g' % (STRETCH - 1.0),
                  '*NODE PRINT, NSET=X1', 'RF', '*NODE PRINT, NSET=ALL_NODES', 'U', '*END STEP']
        fc.write_deck(name + '.inp', lines)
        fc.run_fcs3d(name + '.inp')
        mu = lateral_stretch(energy)
        sigma = principal_stresses(energy, [STRETCH, mu, mu])
        blocks = fc.read_dat(name + '.dat')
        forces = fc.blocks_of(blocks, 'forces', 'X1')
        if not forces:
            fc.fail('%s: no forces table for set X1' % name)
        total = forces[-1][3][:, 1].sum()
        checker.relative('%s: reaction force on x = 1 = sigma_11 mu^2 (lateral stretch %.6f)'
                         % (name, mu), total, sigma[0] * mu ** 2, TOLERANCE)
        rows = fc.blocks_of(blocks, 'displacements', 'ALL_NODES')[-1][3]
        u = rows[rows[:, 0] == corner][0, 1:4]
        checker.relative('%s: lateral displacement of the far corner = mu - 1' % name, u[1],
                         mu - 1.0, TOLERANCE)
    check_restart(checker)
    checker.finish()


def check_restart(checker):
    """The Ogden job restarted from a checkpoint half-way ends as the one-go run."""
    import filecmp
    import glob
    import shutil
    try:
        import h5py  # noqa: F401
    except ImportError:
        print('skip restart: h5py not available')
        return
    import restart_common as rc
    os.makedirs('restarted', exist_ok=True)
    for name in ('ogden.inp', 'ogden.dat', 'ogden.h5'):
        shutil.copy(name, os.path.join('restarted', name))
    # The middle one of the checkpoints kept (ogden.rst.<n>.h5, n counting back in time).
    kept = sorted(glob.glob('ogden.rst.*.h5'), key=lambda n: int(n.split('.')[2]))
    if not kept:
        fc.fail('restart: the Ogden run wrote no checkpoints')
    shutil.copy(kept[len(kept) // 2], os.path.join('restarted', 'checkpoint.h5'))
    print('restart from %s (of %d kept)' % (kept[len(kept) // 2], len(kept)))
    os.chdir('restarted')
    fc.run_fcs3d('ogden.inp', '--restart', 'checkpoint.h5')
    os.chdir('..')
    checker.check(filecmp.cmp('ogden.dat', os.path.join('restarted', 'ogden.dat'), shallow=False),
                  'restart from a checkpoint: ogden.dat byte for byte')
    problems = rc.compare_h5('ogden.h5', os.path.join('restarted', 'ogden.h5'))
    checker.check(not problems, 'restart from a checkpoint: ogden.h5 bit for bit%s'
                  % ('' if not problems else ': ' + '; '.join(problems[:3])))


if __name__ == '__main__':
    main()
