"""Uniaxial stress with linear hardening against the closed form (plasticity_uniaxial.sh).

    uniaxial.py WORKDIR

Block: 2 x 2 x 2 C3D8 on the unit cube, symmetry conditions u_x = 0 on x = 0, u_y = 0 on
y = 0, u_z = 0 on z = 0, lateral faces free; the top z = 1 displaced by u_z = 0.01 a(t), a
rising from 0 to 1 over t in [0, 1] and falling to -1 at t = 2 (load, elastic unloading,
reverse yielding). E = 200000, nu = 0.3, initial yield stress s_y = 200, linear curves.
Every increment writes a frame; the checks read <job>.h5 at full precision.

Closed form (small strain, eps = u_top): uniaxial stress s along z, with the isotropic
radius R(alpha) = s_y + H_i alpha and the kinematic back stress b(alpha) = H_k alpha
(uniaxial terms; alpha = PEEQ), H = H_i + H_k:
  loading      s = s_y + E H / (E + H) (eps - s_y / E)           (the issue's formula)
  unloading    s = s_max - E (eps_max - eps), elastic, down to the reverse yield stress
               s_rev = b(alpha_max) - R(alpha_max)  (-s_max isotropic, s_max - 2 s_y kinematic)
  reversed     s = s_rev + E H / (E + H) (eps - eps_rev),  alpha grows by |ds| / H.
Cases: ISOTROPIC (H_i = 2000), KINEMATIC (H_k = 2000), COMBINED (*PLASTIC curve H_k = 2000,
*CYCLIC HARDENING H_i = 1000: monotonic slope H = 3000, as CalculiX reads the two curves).

Every point of every frame must match to 1e-10 of s_y (stresses; lateral and shear stresses
zero) and PEEQ to 1e-10 of s_y / H: the radial return of a proportional path with linear
hardening is exact for any increment, the elastoplastic tangent of a point on the surface
gives the exact lateral contraction, the R-minimum yield events end the elastic increments
exactly on the surface, and the unloading switch (elastic tangent for a point the increment
unloads) gives the elastic lateral contraction: what remains is round-off (measured 1e-13).

NLGEOM (*HYPOELASTIC, the rate form; ISOTROPIC, monotonic to 10 % engineering strain): with
fixed principal axes the Jaumann rate is the material rate and D_zz = d ln(l)/dt, so the rate
law integrates to the same curve in logarithmic strain and Cauchy stress: s = s_y + E H/(E + H) (ln(l/l0) - s_y/E).
The static-explicit increment is linear: each NLGEOM increment leaves an out-of-balance force
of second order in its strain increment de (the tangent of the start configuration against
the update on the mid-increment one), about E de^2, carried into and removed by the next
increment; the stresses printed carry the last one. With the default limits (MAX STRAIN
INCREMENT 2e-3, MAX PLASTIC STRAIN INCREMENT 1e-3) that is below 2e-3 of s_y (E de^2 / s_y
= 4e-3 for de = 2e-3); with limits four times smaller it must shrink by at least 4
(measured: 7.5e-4 of s_y over every increment, 4.0e-5 over every fourth increment of the
finer run; 1.2e-4 over all its increments, the first elastic increment's lateral stress), and
the end state must agree within 1e-4 of s_y (measured 1.2e-5).

NLGEOM with reversal (KINEMATIC and COMBINED, issue 18): stretched to 1.04 in a first step,
compressed to 0.99 in a second (PEEQ stays below 0.1, the end of the curves), every frame
against the closed form above evaluated along the logarithmic strain of the frames: the back
stress is co-rotated with the material (the Jaumann transport of doc/theory.md 1.4), so with
fixed axes it obeys the small-strain law in logarithmic strain as the stress does. Same
tolerance as the monotonic NLGEOM check (2e-3 of s_y, the carried out-of-balance force). A
back stress convected by the stretch (CalculiX's, doc/theory.md 2.8) would be off by about
int b d(ln l), 7e-3 of s_y at the end of the first step.

Every element kind (issue 18): the ISOTROPIC case, small strain, on the same cube cut into
each of C3D4, C3D6, C3D8R, C3D8I, C3D10, C3D15, C3D20, C3D20R (tests/tools/kind_meshes.py:
six tetrahedra or two wedges per cell, mid-side nodes on straight edges) with the same checks
at every integration point to 1e-10: the field is homogeneous, which every kind reproduces
exactly (C3D8R's hourglass force vanishes, C3D8I's modes stay zero).
"""
import os
import subprocess
import sys

import numpy as np

import plastic_common as pc

fc = pc.fc
YOUNG, POISSON, YIELD = 200000.0, 0.3, 200.0
TOP = 0.01
TOLERANCE = 1e-10
NLGEOM_STRAIN = 0.1
NLGEOM_TOLERANCE = 2e-3
NLGEOM_FINE = '*RMIN, MAX STRAIN INCREMENT=5e-4, MAX PLASTIC STRAIN INCREMENT=2.5e-4'
NLGEOM_REVERSAL = (0.04, -0.01)
CASES = {
    # name: (hardening, *PLASTIC curve, *CYCLIC HARDENING curve, H_i, H_k)
    'isotropic': ('ISOTROPIC', [(200.0, 0.0), (400.0, 0.1)], None, 2000.0, 0.0),
    'kinematic': ('KINEMATIC', [(200.0, 0.0), (400.0, 0.1)], None, 0.0, 2000.0),
    'combined': ('COMBINED', [(200.0, 0.0), (400.0, 0.1)], [(200.0, 0.0), (300.0, 0.1)],
                 1000.0, 2000.0),
}


def deck(path, case, nlgeom=False, rmin=None, frequency=1, kind='C3D8', reverse=None):
    hardening, curve, cyclic, _, _ = CASES[case]
    lines = ['*HEADING', 'uniaxial stress, %s hardening, %s (tests/integration/plasticity/uniaxial.py)'
             % (case, kind)]
    if kind == 'C3D8':
        block = fc.Block(nx=2, ny=2, nz=2)
        sets = {'X0': block.face(0, 0), 'Y0': block.face(1, 0), 'Z0': block.face(2, 0),
                'TOP': block.face(2, 1)}
        lines += block.mesh_cards(sets)
    else:
        lines += pc.kind_mesh_cards((1.0, 1.0, 1.0), (2, 2, 2), kind, {
            'X0': lambda x, y, z: x == 0.0, 'Y0': lambda x, y, z: y == 0.0,
            'Z0': lambda x, y, z: z == 0.0, 'TOP': lambda x, y, z: z == 1.0})
    # NLGEOM: the closed forms are the rate form's (logarithmic strain), *HYPOELASTIC's law.
    lines += pc.von_mises_cards(YOUNG, POISSON, curve, hardening, cyclic, hypoelastic=nlgeom)
    lines += ['*BOUNDARY', 'X0, 1, 1', 'Y0, 2, 2', 'Z0, 3, 3']
    if nlgeom:
        lines += ['*STEP, NLGEOM', '*STATIC', '0.05, 1.'] + ([rmin] if rmin else [])
        lines += ['*BOUNDARY', 'TOP, 3, 3, %r' % (NLGEOM_STRAIN if reverse is None else reverse[0])]
        if reverse is not None:
            lines += ['*NODE FILE, FREQUENCY=1', 'U', '*EL FILE, FREQUENCY=1', 'S, PEEQ', '*END STEP',
                      '*STEP, NLGEOM', '*STATIC', '0.05, 1.', '*BOUNDARY', 'TOP, 3, 3, %r' % reverse[1]]
    else:
        lines += fc.amplitude_card('PATH', [0.0, 1.0, 2.0], [0.0, 1.0, -1.0])
        lines += ['*STEP', '*STATIC', '0.02, 2., , 0.02', '*BOUNDARY, AMPLITUDE=PATH', 'TOP, 3, 3, %r' % TOP]
    lines += ['*NODE FILE, FREQUENCY=%d' % frequency, 'U', '*EL FILE, FREQUENCY=%d' % frequency,
              'S, PEEQ', '*END STEP']
    fc.write_deck(path, lines)


def closed_form(case, eps_path):
    """Stress and PEEQ along a strain path (a list of strains in time order): the closed
    form of the module docstring, evaluated step by step as the one-dimensional return of
    linear hardening (exact for any step: elastic up to |s - b| = R, then slope E H/(E + H))."""
    _, _, _, h_iso, h_kin = CASES[case]
    h = h_iso + h_kin
    stress, alpha = [], []
    s, a, back = 0.0, 0.0, 0.0
    previous = 0.0
    for eps in eps_path:
        d = eps - previous
        previous = eps
        # Elastic predictor, then the linear-hardening return in one dimension.
        trial = s + YOUNG * d
        radius = YIELD + h_iso * a
        f = abs(trial - back) - radius
        if f > 0.0:
            da = f / (YOUNG + h)
            sign = np.sign(trial - back)
            s = trial - YOUNG * da * sign
            back += h_kin * da * sign
            a += da
        else:
            s = trial
        stress.append(s)
        alpha.append(a)
    return np.array(stress), np.array(alpha)


def check_small_strain(work, case, checker, kind='C3D8'):
    job = os.path.join(work, 'uniaxial_' + case + ('' if kind == 'C3D8' else '_' + kind))
    deck(job + '.inp', case, kind=kind)
    fc.run_fcs3d(job + '.inp')
    frames = pc.Frames(job + '.h5')
    records, _ = fc.read_increments(job + '.log')
    top = frames.node(fc.Block(nx=2, ny=2, nz=2).face(2, 1)[0])
    eps = frames.displacement[:, top, 2]
    expected_stress, expected_peeq = closed_form(case, eps)
    _, _, _, h_iso, h_kin = CASES[case]
    h = h_iso + h_kin
    s = frames.stress
    stress_error = np.abs(s[:, :, :, 2] - expected_stress[:, None, None]).max() / YIELD
    lateral = np.abs(s[:, :, :, [0, 1, 3, 4, 5]]).max() / YIELD
    peeq_error = np.abs(frames.peeq - expected_peeq[:, None, None]).max() / (YIELD / h)
    if kind != 'C3D8':
        case_label = '%s %s' % (kind, case)
    else:
        case_label = case
    label = '%s: %d increments' % (case_label, len(records))
    checker.check(stress_error <= TOLERANCE, '%s: s_zz at every point of every increment vs the '
                  'closed form: %.2e of s_y (tolerance %.0e)' % (label, stress_error, TOLERANCE))
    checker.check(lateral <= TOLERANCE, '%s: lateral and shear stresses zero: %.2e of s_y'
                  % (case_label, lateral))
    checker.check(peeq_error <= TOLERANCE, '%s: PEEQ vs the closed form: %.2e of s_y / H'
                  % (case_label, peeq_error))
    checker.check(abs(eps[-1] + TOP) <= 1e-12 and eps.max() >= TOP * (1 - 1e-12),
                  '%s: the path reaches +%g and ends at -%g' % (case_label, TOP, TOP))
    # Elastic unloading: the frames after the peak up to the reverse yield point lie on a line
    # of slope E through (eps_max, s_max).
    peak = int(np.argmax(eps))
    s_max = s[peak, 0, 0, 2]
    reverse = (CASES[case][4] * expected_peeq[peak] - (YIELD + h_iso * expected_peeq[peak]))
    unloading = [k for k in range(peak + 1, len(eps)) if s[k, 0, 0, 2] > reverse + 1e-9 * YIELD]
    slope_error = max(abs(s[k, 0, 0, 2] - (s_max - YOUNG * (eps[peak] - eps[k]))) / YIELD
                      for k in unloading) if unloading else 1.0
    checker.check(len(unloading) >= 2 and slope_error <= TOLERANCE,
                  '%s: elastic unloading over %d increments with slope E: %.2e of s_y'
                  % (case_label, len(unloading), slope_error))
    # Reverse yield on the closed-form stress b - R (isotropic -s_max, kinematic s_max - 2 s_y),
    # reached by an increment limited by a yield event.
    yield_incs = [r for r in records if r['limit'] == 'yield']
    # (No plastic strain yet at the landing: PEEQ as at the peak up to round-off, 1e-12 relative;
    # an increment that crossed the surface would add plastic strain of order its strain.)
    at_reverse = [k for k in range(peak + 1, len(eps)) if abs(s[k, 0, 0, 2] - reverse) <=
                  TOLERANCE * YIELD and abs(frames.peeq[k, 0, 0] - frames.peeq[peak, 0, 0]) <=
                  1e-12 * frames.peeq[peak, 0, 0]]
    checker.check(len(yield_incs) >= 2 and len(at_reverse) == 1,
                  '%s: first yield and reverse yield at %.6g (= b - R) end increments limited '
                  'by yield events (%d yield-limited increments, the log names %s)'
                  % (case_label, reverse, len(yield_incs), yield_incs[0]['entity'] if yield_incs else '-'))
    text = open(job + '.log').read()
    checker.check(' switches ' in text, '%s: the first unloading increment switches the '
                  'unloading points to the elastic tangent (log "switches")' % case_label)


def nlgeom_errors(work, name, rmin, frequency):
    """Largest |s_zz - curve| and lateral stress over the frames (every `frequency`
    increments: a frame costs more than an increment here), the end error, increments."""
    job = os.path.join(work, name)
    deck(job + '.inp', 'isotropic', nlgeom=True, rmin=rmin, frequency=frequency)
    fc.run_fcs3d(job + '.inp')
    frames = pc.Frames(job + '.h5')
    records, _ = fc.read_increments(job + '.log')
    top = frames.node(fc.Block(nx=2, ny=2, nz=2).face(2, 1)[0])
    log_strain = np.log(1.0 + frames.displacement[:, top, 2])
    h = CASES['isotropic'][3]
    expected = np.where(log_strain * YOUNG <= YIELD, YOUNG * log_strain,
                        YIELD + YOUNG * h / (YOUNG + h) * (log_strain - YIELD / YOUNG))
    error = np.abs(frames.stress[:, :, :, 2] - expected[:, None, None]).max(axis=(1, 2)) / YIELD
    lateral = np.abs(frames.stress[:, :, :, [0, 1, 3, 4, 5]]).max(axis=(1, 2, 3)) / YIELD
    return max(error.max(), lateral.max()), max(error[-1], lateral[-1]), len(records)


def check_nlgeom_reversal(work, case, checker):
    """KINEMATIC or COMBINED at NLGEOM, stretched to 1 + NLGEOM_REVERSAL[0] and compressed to
    1 + NLGEOM_REVERSAL[1]: every frame's s_zz (and lateral stresses) against the closed form
    along the frames' logarithmic strain."""
    job = os.path.join(work, 'uniaxial_nlgeom_' + case)
    deck(job + '.inp', case, nlgeom=True, reverse=NLGEOM_REVERSAL)
    fc.run_fcs3d(job + '.inp')
    frames = pc.Frames(job + '.h5')
    top = frames.node(fc.Block(nx=2, ny=2, nz=2).face(2, 1)[0])
    log_strain = np.log(1.0 + frames.displacement[:, top, 2])
    expected, _ = closed_form(case, log_strain)
    error = np.abs(frames.stress[:, :, :, 2] - expected[:, None, None]).max() / YIELD
    lateral = np.abs(frames.stress[:, :, :, [0, 1, 3, 4, 5]]).max() / YIELD
    reached = abs(log_strain[-1] - np.log(1 + NLGEOM_REVERSAL[1])) < 1e-12
    checker.check(max(error, lateral) <= NLGEOM_TOLERANCE and reached,
                  'NLGEOM %s, stretched to %g and compressed to %g (%d frames): Cauchy s_zz vs '
                  'the closed form in logarithmic strain, and the lateral stresses, within %.2e '
                  'of s_y (tolerance %.0e)' % (case, 1 + NLGEOM_REVERSAL[0], 1 + NLGEOM_REVERSAL[1],
                                              len(log_strain), max(error, lateral), NLGEOM_TOLERANCE))


def check_nlgeom(work, checker):
    default, _, n_default = nlgeom_errors(work, 'uniaxial_nlgeom', None, 1)
    fine, end, n_fine = nlgeom_errors(work, 'uniaxial_nlgeom_fine', NLGEOM_FINE, 4)
    checker.check(default <= NLGEOM_TOLERANCE, 'NLGEOM to %g %% engineering strain, default limits '
                  '(%d increments): Cauchy s_zz vs the curve in logarithmic strain, and the lateral '
                  'stresses, within %.2e of s_y (tolerance %.0e)'
                  % (100 * NLGEOM_STRAIN, n_default, default, NLGEOM_TOLERANCE))
    checker.check(fine <= default / 4.0, 'NLGEOM, limits / 4 (%d increments): %.2e of s_y, %.1f times '
                  'smaller (at least 4)' % (n_fine, fine, default / fine))
    checker.check(end <= 1e-4, 'NLGEOM, limits / 4: end state within %.2e of s_y (tolerance 1e-4)' % end)


def main():
    pc.require_h5py()
    work = sys.argv[1]
    os.makedirs(work, exist_ok=True)
    checker = fc.Checker()
    for case in CASES:
        check_small_strain(work, case, checker)
    check_nlgeom(work, checker)
    for case in ('kinematic', 'combined'):
        check_nlgeom_reversal(work, case, checker)
    for kind in pc.OTHER_KINDS:
        check_small_strain(work, 'isotropic', checker, kind)
    checker.finish()


if __name__ == '__main__':
    main()
