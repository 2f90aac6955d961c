"""Thermal strain closed forms (issue 17, item 3), for tests/integration/thermal_bar.sh.

A bar 0 <= x <= L = 4, 0 <= y, z <= 1 of 8 x 2 x 2 C3D8 elements, on rollers on the planes
x = 0, y = 0, z = 0 (symmetry planes), heated uniformly from T0 to T:
  - free (x = L free): the thermal strain alpha dT in every direction and no stress,
    u_x(L) = alpha dT L, u_y(y = 1) = alpha dT;
  - clamped (u_x = 0 at x = L too): sigma_xx = -E alpha dT, sigma_yy = sigma_zz = 0, the
    lateral strain (1 + nu) alpha dT, and the reaction on the clamped end -E alpha dT A (the
    wall pushes back).
With *EXPANSION and *ELASTIC tables over temperature (linear between the rows, constant beyond
them, secant alpha from ZERO as CalculiX), the clamped stress at temperature T is
  sigma_xx = -E(T) (alpha(T) (T - Z) - alpha(T0) (T0 - Z)),
whatever path the temperature took (CalculiX's total form sigma = C(T) eps_el, which the
rate form reproduces exactly: doc/theory.md 2.5); step 2 reaches its end temperature through
an amplitude that starts below the end of step 1; step 3 (*TEMPERATURE, OP=NEW) returns every
node to its initial temperature and the stress to 0.

Every field is homogeneous, which trilinear elements represent exactly: the tolerance is
round-off, 1e-9 relative to E alpha dT (the equilibrium iterations stop at 1e-3 of the force
scale, but a homogeneous thermal load is balanced exactly by the first solve: the trial
solution is exact for a linear problem, and the secant update makes it exact for the tables).
"""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import datfile  # noqa: E402

FCS3D = os.environ.get('FCS3D', 'fcs3d')
L, NX, NY, NZ = 4.0, 8, 2, 2
E, NU, ALPHA, ZERO, T0, T1 = 200000.0, 0.3, 1.2e-5, 20.0, 20.0, 120.0
TOL = 1e-9


def mesh():
    """*NODE and *ELEMENT lines and node sets of the bar."""
    def nid(i, j, k):
        return 1 + i + (NX + 1) * (j + (NY + 1) * k)
    lines = ['*NODE, NSET=NALL']
    for k in range(NZ + 1):
        for j in range(NY + 1):
            for i in range(NX + 1):
                lines.append('%d, %.6f, %.6f, %.6f' % (nid(i, j, k), L * i / NX, j / NY, k / NZ))
    lines.append('*ELEMENT, TYPE=C3D8, ELSET=EALL')
    e = 0
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                e += 1
                n = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                     nid(i, j + 1, k + 1)]
                lines.append('%d, %s' % (e, ', '.join(map(str, n))))

    def nset(name, pick):
        members = [nid(i, j, k) for k in range(NZ + 1) for j in range(NY + 1)
                   for i in range(NX + 1) if pick(i, j, k)]
        out = ['*NSET, NSET=' + name]
        for c in range(0, len(members), 8):
            out.append(', '.join(map(str, members[c:c + 8])))
        return out
    lines += nset('X0', lambda i, j, k: i == 0)
    lines += nset('XL', lambda i, j, k: i == NX)
    lines += nset('Y0', lambda i, j, k: j == 0)
    lines += nset('Y1', lambda i, j, k: j == NY)
    lines += nset('Z0', lambda i, j, k: k == 0)
    return lines


def deck(clamped, tables=False, restart=False, yield_stress=None):
    lines = ['*HEADING', 'thermal bar, %s' % ('clamped' if clamped else 'free')] + mesh()
    lines += ['*INITIAL CONDITIONS, TYPE=TEMPERATURE', 'NALL, %g' % T0]
    lines += ['*MATERIAL, NAME=STEEL', '*ELASTIC']
    if tables:
        lines += ['200000., 0.3, 0.', '100000., 0.3, 200.']
        lines += ['*EXPANSION, ZERO=%g' % ZERO, '1.e-5, 0.', '2.e-5, 200.']
    else:
        lines += ['%g, %g' % (E, NU), '*EXPANSION, ZERO=%g' % ZERO, '%g' % ALPHA]
    if yield_stress is not None:
        lines += ['*PLASTIC', '%g, 0.' % yield_stress]
    lines += ['*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL']
    lines += ['*BOUNDARY', 'X0, 1, 1', 'Y0, 2, 2', 'Z0, 3, 3']
    if clamped:
        lines += ['XL, 1, 1']
    if restart:
        lines += ['*RESTART, WRITE, FREQUENCY=1, GENERATIONS=8']
    lines += ['*AMPLITUDE, NAME=HALF', '0., 0.5, 1., 1.']
    steps = [('*TEMPERATURE', 'NALL, %g' % T1)]
    if tables:
        steps.append(('*TEMPERATURE, AMPLITUDE=HALF', 'NALL, 200.'))
        steps.append(('*TEMPERATURE, OP=NEW', 'X0, %g' % T0))
    for keyword, data in steps:
        lines += ['*STEP', '*STATIC', '0.25, 1., 1.e-5, 0.25', keyword, data,
                  '*NODE PRINT, NSET=NALL', 'U, NT', '*NODE PRINT, NSET=XL, TOTALS=ONLY', 'RF',
                  '*EL PRINT, ELSET=EALL', 'S, E' + (', PEEQ' if yield_stress else ''),
                  '*END STEP']
    return '\n'.join(lines) + '\n'


def run(directory, job, text):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, job + '.inp'), 'w') as f:
        f.write(text)
    p = subprocess.run([FCS3D, '-q', job + '.inp'], cwd=directory, capture_output=True,
                       text=True, timeout=600)
    if p.returncode != 0:
        print('%s: fcs3d exit %d: %s' % (job, p.returncode, p.stderr))
        return None
    return datfile.read_blocks(os.path.join(directory, job + '.dat'))


def last(blocks, kind, time):
    found = [b for b in blocks if b.kind == kind and abs(b.time - time) < 1e-9]
    return found[-1]


class Checker:
    def __init__(self):
        self.failures = 0

    def close(self, what, value, expected, scale):
        error = abs(value - expected) / scale
        ok = error <= TOL
        print('%-62s %14.7e expected %14.7e  rel. error %.1e  %s' % (
            what, value, expected, error, 'ok' if ok else 'FAIL'))
        if not ok:
            self.failures += 1


def check_free(c, blocks):
    dt = T1 - T0
    strain = ALPHA * dt
    u = last(blocks, 'displacements', 1.0)
    nt = last(blocks, 'temperatures', 1.0)
    s = last(blocks, 'stresses', 1.0).values()
    e = last(blocks, 'strains', 1.0).values()
    ux = max(v[0] for v in u.rows.values())
    uy = max(v[1] for v in u.rows.values())
    c.close('free: largest u_x (= alpha dT L)', ux, strain * L, strain * L)
    c.close('free: largest u_y (= alpha dT)', uy, strain, strain * L)
    c.close('free: largest |stress| (= 0)', abs(s).max(), 0.0, E * strain)
    c.close('free: strain exx at every point (= alpha dT)', e[:, 0].min(), strain, strain)
    c.close('free: strain eyy at every point (= alpha dT)', e[:, 1].max(), strain, strain)
    c.close('free: NT at every node (= T)', min(v[0] for v in nt.rows.values()), T1, T1)


def check_clamped(c, blocks):
    dt = T1 - T0
    sigma = -E * ALPHA * dt
    u = last(blocks, 'displacements', 1.0)
    s = last(blocks, 'stresses', 1.0).values()
    rf = last(blocks, 'total', 1.0).values()
    c.close('clamped: sxx, largest (= -E alpha dT)', s[:, 0].max(), sigma, abs(sigma))
    c.close('clamped: sxx, smallest (= -E alpha dT)', s[:, 0].min(), sigma, abs(sigma))
    c.close('clamped: largest |syy|, |szz| (= 0)', abs(s[:, 1:3]).max(), 0.0, abs(sigma))
    c.close('clamped: u_y(y = 1) (= (1 + nu) alpha dT)', max(v[1] for v in u.rows.values()),
            (1 + NU) * ALPHA * dt, ALPHA * dt)
    c.close('clamped: total reaction on x = L (= -E alpha dT A)', rf[0][0], -E * ALPHA * dt,
            E * ALPHA * dt)


def table(points, t):
    (t_a, v_a), (t_b, v_b) = points
    w = min(max((t - t_a) / (t_b - t_a), 0.0), 1.0)
    return v_a + w * (v_b - v_a)


def check_tables(c, blocks):
    youngs = [(0.0, 200000.0), (200.0, 100000.0)]
    alpha = [(0.0, 1e-5), (200.0, 2e-5)]
    for time, temperature in [(1.0, T1), (2.0, 200.0)]:
        expected = -table(youngs, temperature) * (
            table(alpha, temperature) * (temperature - ZERO) - table(alpha, T0) * (T0 - ZERO))
        s = last(blocks, 'stresses', time).values()
        c.close('tables: sxx at T = %g (= -E(T) (a(T)(T-Z) - a(T0)(T0-Z)))' % temperature,
                s[:, 0].min(), expected, abs(expected))
        c.close('tables: sxx spread at T = %g' % temperature, s[:, 0].max() - s[:, 0].min(),
                0.0, abs(expected))
        nt = last(blocks, 'temperatures', time)
        c.close('tables: NT at time %g' % time, max(v[0] for v in nt.rows.values()),
                temperature, temperature)
    # Step 3, OP=NEW: every node back to its initial temperature, the stress back to 0.
    s = last(blocks, 'stresses', 3.0).values()
    c.close('tables: OP=NEW, |sxx| back at T0 (= 0)', abs(s[:, 0]).max(), 0.0, 360.0)
    nt = last(blocks, 'temperatures', 3.0)
    c.close('tables: OP=NEW, largest NT (= T0)', max(v[0] for v in nt.rows.values()), T0, T0)


def check_restart(c, work):
    """The tables deck with a checkpoint after every increment, restarted from the one in the
    middle of step 2 (bar.rst.7.h5: after increment 3 of 4 of step 2, the one with the
    amplitude; newer are 7 checkpoints of step 3 and of the ends of steps 2, 3), gives the one-go
    outputs bit for bit (restart_common.compare_runs: job.h5, job.dat, XDMF frames)."""
    import shutil
    sys.path.insert(0, os.path.join(HERE, '..', 'integration', 'restart'))
    import restart_common as rc
    reference = os.path.join(work, 'restart_reference')
    if run(reference, 'bar', deck(True, True, restart=True)) is None:
        c.failures += 1
        return
    restarted = os.path.join(work, 'restarted')
    os.makedirs(restarted, exist_ok=True)
    for name in os.listdir(reference):
        shutil.copy(os.path.join(reference, name), restarted)
    print('restart from bar.rst.7.h5: step %d, increment %d, time %g, step time %g' %
          rc.checkpoint_info(os.path.join(restarted, 'bar.rst.7.h5')))
    p = subprocess.run([FCS3D, '-q', 'bar.inp', '--restart', 'bar.rst.7.h5'], cwd=restarted,
                       capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        print('restart: fcs3d exit %d: %s' % (p.returncode, p.stderr))
        c.failures += 1
        return
    problems = rc.compare_h5(os.path.join(reference, 'bar.h5'), os.path.join(restarted, 'bar.h5'))
    problems += rc.compare_files(reference, restarted, ['bar.dat'])
    problems += rc.compare_xdmf(os.path.join(reference, 'bar.xdmf'),
                                os.path.join(restarted, 'bar.xdmf'))
    for problem in problems[:20]:
        print('  restart: ' + problem)
    print('restart: bar.h5 (every dataset and attribute, NT included), bar.dat and the XDMF '
          'frames %s the one-go run' % ('differ from' if problems else 'identical to'))
    if problems:
        c.failures += 1


def check_plastic(c, work):
    """The clamped bar of von Mises steel, perfectly plastic at sigma_y = 100 < E alpha dT:
    the R-minimum control sees the thermal load and ends an increment where the bar yields
    (alpha (T - T0) E = sigma_y: step time (sigma_y / (E alpha)) / dT), then
    sigma_xx = -sigma_y and PEEQ = alpha dT - sigma_y / E at the end (uniaxial stress, the
    axial plastic strain takes up what the elastic strain cannot)."""
    sigma_y = 100.0
    directory = os.path.join(work, 'plastic')
    blocks = run(directory, 'bar', deck(True, yield_stress=sigma_y))
    if blocks is None:
        c.failures += 1
        return
    s = last(blocks, 'stresses', 1.0).values()
    peeq = last(blocks, 'equivalent', 1.0).values()
    expected = ALPHA * (T1 - T0) - sigma_y / E
    c.close('plastic: sxx, smallest (= -sigma_y)', s[:, 0].min(), -sigma_y, sigma_y)
    c.close('plastic: sxx, largest (= -sigma_y)', s[:, 0].max(), -sigma_y, sigma_y)
    c.close('plastic: PEEQ (= alpha dT - sigma_y / E)', peeq[:, 0].max(), expected, expected)
    with open(os.path.join(directory, 'bar.log')) as f:
        log = f.read()
    t_yield = sigma_y / (E * ALPHA) / (T1 - T0)
    times = [float(line.split()[5]) for line in log.splitlines()
             if line.startswith('inc ') and 'limit yield' in line]
    if len(times) != 1:
        print('plastic: expected one increment limited by yield in bar.log, found %d  FAIL'
              % len(times))
        c.failures += 1
        return
    # The log prints the time with 10 significant digits.
    error = abs(times[0] - t_yield)
    print('plastic: increment ended by the yield event at step time %.10g, expected %.10g '
          '(alpha (T - T0) E = sigma_y)  %s' % (times[0], t_yield, 'ok' if error < 1e-9 else 'FAIL'))
    if error >= 1e-9:
        c.failures += 1


def main():
    work = sys.argv[1] if len(sys.argv) > 1 else '.'
    c = Checker()
    check_restart(c, work)
    check_plastic(c, work)
    for name, clamped, tables, check in [('free', False, False, check_free),
                                         ('clamped', True, False, check_clamped),
                                         ('tables', True, True, check_tables)]:
        blocks = run(os.path.join(work, name), 'bar', deck(clamped, tables))
        if blocks is None:
            c.failures += 1
            continue
        check(c, blocks)
    print('%d failure(s)' % c.failures)
    return 1 if c.failures else 0


if __name__ == '__main__':
    sys.exit(main())
