"""Drucker-Prager triaxial compression against the closed form (plasticity_drucker_prager.sh).

    triaxial.py WORKDIR

One C3D8 on the unit cube, symmetry conditions on x = 0, y = 0, z = 0. Step 1: a confining
pressure p_c on the faces x = 1, y = 1, z = 1 (*DSLOAD). Step 2: the top pushed down by 1 %
more (displacement control) with the lateral pressure held. E = 30000, nu = 0.25, linear
Drucker-Prager with beta = 30 degrees, hardening in compression sigma_c = 40 + 4000 eps_bar
(*DRUCKER PRAGER HARDENING, TYPE=COMPRESSION), associated (psi = 30) and non-associated
(psi = 10) flow, p_c = 0, 10, 20.

Closed form (p = -tr(sigma)/3, compression positive; axial stress s_a, lateral -p_c):
q = s_a - p_c, p = (s_a + 2 p_c)/3, and F = q - p tan(beta) - (1 - tan(beta)/3) sigma_c = 0 gives
    s_a = sigma_c(eps_bar) + p_c (1 + 2 tan(beta)/3) / (1 - tan(beta)/3)
(first yield at eps_bar = 0). The flow (D3) in triaxial compression has N_zz = -2/sqrt(6),
N_xx = N_yy = 1/sqrt(6): d eps_p,zz = -(1 - tan(psi)/3) dl = -d eps_bar, and the plastic volume
change tan(psi) dl: tr(eps_p) / eps_bar = tan(psi) / (1 - tan(psi)/3) (dilatancy). The path is
proportional (fixed N, linear hardening), so the return and the elastoplastic tangent are
exact: every increment must match within 1e-10 of sigma_c; the yield-event increment ends
on the yield stress of the closed form.

The non-associated tangent is unsymmetric: that case also runs with the SKYLINE and MUMPS
solvers (every solver takes the full, unsymmetric matrix), whose stresses must agree with
UMFPACK's to 1e-12.
"""
import math
import os
import sys

import numpy as np

import plastic_common as pc

fc = pc.fc
YOUNG, POISSON, BETA = 30000.0, 0.25, 30.0
SIGMA_C, HARDENING = 40.0, 4000.0
EXACT = 1e-10


def deck(path, psi, confining, solver='UMFPACK'):
    block = fc.Block()
    sets = {'X0': block.face(0, 0), 'Y0': block.face(1, 0), 'Z0': block.face(2, 0),
            'TOP': block.face(2, 1)}
    lines = ['*HEADING', 'Drucker-Prager triaxial compression, psi %g, p_c %g '
             '(tests/integration/plasticity/triaxial.py)' % (psi, confining)]
    lines += block.mesh_cards(sets)
    # The only element: face S4 is x = 1, S5 is y = 1, S2 is z = 1 (CalculiX numbering).
    lines += ['*SURFACE, NAME=OUTSIDE', '1, S2', '1, S4', '1, S5', '*SOLVER, TYPE=%s' % solver]
    lines += pc.drucker_prager_cards(YOUNG, POISSON, BETA, psi,
                                     [(SIGMA_C, 0.0), (SIGMA_C + HARDENING, 1.0)])
    lines += ['*BOUNDARY', 'X0, 1, 1', 'Y0, 2, 2', 'Z0, 3, 3']
    if confining > 0.0:
        lines += ['*STEP', '*STATIC', '1., 1.', '*DSLOAD', 'OUTSIDE, P, %r' % confining,
                  '*END STEP']
        start = -confining * (1.0 - 2.0 * POISSON) / YOUNG
    else:
        start = 0.0
    lines += ['*STEP', '*STATIC', '0.1, 1.', '*BOUNDARY', 'TOP, 3, 3, %r' % (start - 0.01),
              '*NODE FILE, FREQUENCY=1', 'U', '*EL FILE, FREQUENCY=1', 'S, PEEQ', '*END STEP']
    fc.write_deck(path, lines)


def check_case(work, psi, confining, checker, solver='UMFPACK'):
    name = 'triaxial_psi%g_pc%g_%s' % (psi, confining, solver.lower())
    job = os.path.join(work, name)
    deck(job + '.inp', psi, confining, solver)
    fc.run_fcs3d(job + '.inp')
    frames = pc.Frames(job + '.h5')
    records, _ = fc.read_increments(job + '.log')
    tb, tp = math.tan(math.radians(BETA)), math.tan(math.radians(psi))
    factor = (1.0 + 2.0 * tb / 3.0) / (1.0 - tb / 3.0)
    axial = -frames.stress[:, :, :, 2]
    peeq = frames.peeq
    label = 'psi %g, p_c %g' % (psi, confining)
    plastic = peeq > 0.0
    expected = SIGMA_C + HARDENING * peeq + confining * factor
    error = np.abs(axial - expected)[plastic].max() / SIGMA_C if plastic.any() else 1.0
    lateral = np.abs(frames.stress[1:, :, :, 0:2] + confining).max() / SIGMA_C
    checker.check(plastic.any() and error <= EXACT,
                  '%s: axial stress of every plastic point of every increment vs sigma_c(eps_bar) '
                  '+ p_c (1 + 2 tan(b)/3)/(1 - tan(b)/3) = %.6g at first yield: %.2e of sigma_c'
                  % (label, SIGMA_C + confining * factor, error))
    checker.check(lateral <= EXACT, '%s: lateral stress = -p_c: %.2e of sigma_c' % (label, lateral))
    first = next(k for k, r in enumerate(records) if r['limit'] == 'yield')
    at_yield = axial[first + 1]
    checker.check(np.abs(at_yield - (SIGMA_C + confining * factor)).max() <= EXACT * SIGMA_C and
                  peeq[first + 1].max() <= EXACT * SIGMA_C / YOUNG,
                  '%s: the yield-event increment (%d, %s) ends on the closed-form yield stress, '
                  'no plastic strain' % (label, records[first]['inc'], records[first]['entity']))
    volume = frames.plastic_strain[-1, :, :, 0:3].sum(axis=-1)
    ratio = volume / peeq[-1]
    checker.check(np.abs(ratio - tp / (1.0 - tp / 3.0)).max() <= 1e-9,
                  '%s: plastic volume change / eps_bar = %.9g = tan(psi)/(1 - tan(psi)/3)'
                  % (label, ratio.mean()))
    return frames


def main():
    pc.require_h5py()
    work = sys.argv[1]
    os.makedirs(work, exist_ok=True)
    checker = fc.Checker()
    for psi in (30.0, 10.0):
        for confining in (0.0, 10.0, 20.0):
            frames = check_case(work, psi, confining, checker)
    for solver in ('SKYLINE', 'MUMPS'):
        other = check_case(work, 10.0, 20.0, checker, solver)
        difference = np.abs(other.stress - frames.stress).max() / SIGMA_C
        checker.check(other.stress.shape == frames.stress.shape and difference <= 1e-12,
                      'non-associated (unsymmetric tangent): %s agrees with UMFPACK to %.1e of '
                      'sigma_c' % (solver, difference))
    checker.finish()


if __name__ == '__main__':
    main()
