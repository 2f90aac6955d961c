"""Shared helpers of the FE-level friction tests (tests/integration/friction_*.sh,
tests/validate/friction_*.sh, tests/pending/friction_*.sh).

The model of all of them is a block-slider (units mm, s, MPa, N):

  * a base, one hexahedron [-1, 2] x [-1, 2] x [0, 0.5] (wider than the slider, so that the
    slider's nodes stay on its one top face however far they slide) whose eight nodes are all
    fixed: a rigid base, so that the four slave nodes see the same master geometry (a
    deformable base, even with E = 1e6, tilts its face under the friction load and makes the
    slave nodes' pressures differ by parts per million, enough to desynchronise their
    stick-slip cycles);
  * on it the slider, one hexahedron [0, 1]^2 x [0.5, 0.5 + H] (H = 0.01, E = 5e4, nu = 0.25,
    so its shear stiffness per unit area G / H = 2e6 MPa/mm). Thin, because the push at the
    top and the friction at the bottom make a couple T H that the contact pressure balances:
    the pressure differs between the front and back edges by about +-2 mu H / W (W = 1 the
    width), +-1.2 % here (+-12 % with H = 0.1, too much for the stability test, where k_c is
    proportional to the pressure);
  * node-to-point contact SLIDE: the slider's bottom (slave, 4 nodes of tributary area 0.25)
    on the base's top (master, one face), normal penalty E_n = 1e6 MPa/mm, *FRICTION with the
    law under test and an explicit STICK SLOPE E_t;
  * step 1 (1e-3 s): pressure sigma_n = 10 MPa on the slider's top, the driven nodes (set
    DRIVEN) held in x and y; later steps: DRIVEN moved in x by *BOUNDARY, TYPE=VELOCITY (y
    still held, z free under the pressure). DRIVEN is either the slider's top nodes (drive
    TOP, the block pushed at its top) or its bottom nodes, the slave nodes themselves (drive
    SLAVE): then the contact's stick spring E_t is the whole loading spring, the push acts in
    the contact plane (no couple, uniform pressure) and the four slave nodes are four identical
    spring-sliders (each node has its own stick spring and state), i.e. one.

Pushed at the top, the loading system of the frictional interface is a spring of stiffness per
unit area k = 1 / (1/E_t + H/G) (the contact's stick spring in series with the slider's shear)
driven at the load-point velocity: the spring-slider of Ruina (1983) with the block's own
stiffness. With E_t = 1e5 it is k = 9.52e4 MPa/mm, stiff (k / k_c > 1000 for the rate-and-state
parameters used), so that the slip rate follows the load rate; a small E_t gives a soft
spring whose stiffness is set by E_t (the slider's compliance H/G = 5e-7 mm/MPa is then a
correction of order E_t H/G, taken into account in k).

Outputs read: the history <job>_slider.csv (*HISTORY, FREQUENCY=1: CONTACT, SLIDE; NSET,
DRIVEN, RF; NSET, DRIVEN, U), the event catalog <job>_events.csv and the contact grid of
<job>.h5. Also: a quasi-static spring-slider integrator (classical RK4 of
the rate-and-state ODE), the oracle of the transient checks. numpy (h5py for the results).
"""
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'nlgeom'))
import fcs_check  # noqa: E402  (Checker, fail)

Checker = fcs_check.Checker
fail = fcs_check.fail

PAIR = 'SLIDE'
HISTORY = 'slider'
SIGMA_N = 10.0          # MPa, the pressure on the slider's top
AREA = 1.0              # mm^2, the slider's base
HEIGHT = 0.01           # mm
SLIDER_YOUNG = 5.0e4    # MPa
SLIDER_POISSON = 0.25
SLIDER_SHEAR = SLIDER_YOUNG / (2.0 * (1.0 + SLIDER_POISSON))   # 2e4 MPa
BASE_YOUNG = 1.0e6
NORMAL_STIFFNESS = 1.0e6   # MPa/mm
STEP1_PERIOD = 1.0e-3      # s

# The rate-and-state parameters of the steady-state, velocity-step and stability tests.
RS = dict(MU0=0.6, A=0.010, B=0.015, DC=1.0e-3, V0=1.0e-3, VC=1.0e-9)


def spring_stiffness(stick_slope, drive='TOP'):
    """Loading stiffness per unit area [MPa/mm] of the interface: E_t in series with the
    slider's shear stiffness G / H (drive TOP), or E_t alone (drive SLAVE)."""
    if drive == 'SLAVE':
        return stick_slope
    return 1.0 / (1.0 / stick_slope + HEIGHT / SLIDER_SHEAR)


def stick_slope_for(k, drive='TOP'):
    """The E_t that gives the loading stiffness k per unit area (inverse of spring_stiffness)."""
    if drive == 'SLAVE':
        return k
    return 1.0 / (1.0 / k - HEIGHT / SLIDER_SHEAR)


def friction_card(law, stick_slope, **parameters):
    """*FRICTION, LAW=..., the parameters in the given order, STICK SLOPE=."""
    items = ['LAW=%s' % law] + ['%s=%s' % (name.replace('_', ' '), _text(value))
                                for name, value in parameters.items()]
    items.append('STICK SLOPE=%s' % _text(stick_slope))
    return '*FRICTION, ' + ', '.join(items)


def _text(value):
    return value if isinstance(value, str) else '%.12g' % value


def slider_deck(path, friction, steps, title='block-slider', restart=None, catalog=None,
                contact_file=0, rmin=None, drive='TOP', node_histories=False):
    """Write the block-slider deck. friction: the *FRICTION card (friction_card). steps: list
    of dicts for steps 2, 3, ...: velocity [mm/s] of the driven nodes in x, period [s], and
    optionally initial, min, max (the *STATIC increments). restart: *RESTART, WRITE
    parameters (text) or None. catalog: *EVENT CATALOG parameters (text) or None.
    contact_file: *CONTACT FILE frequency in the sliding steps (0: step ends only). rmin: text
    of an *RMIN card's parameters for every sliding step, or None. drive: TOP or SLAVE (the
    nodes moved, module doc string). node_histories: also the history of RF of each driven
    node (node sets N<id>, columns N<id>_RF1..3): with drive SLAVE, -RF_x of a slave node is
    its friction force."""
    lines = ['*HEADING', '%s (tests/integration/friction/friction_common.py)' % title,
             '*NODE, NSET=ALL_NODES']
    base = [(-1, -1, 0), (2, -1, 0), (2, 2, 0), (-1, 2, 0),
            (-1, -1, 0.5), (2, -1, 0.5), (2, 2, 0.5), (-1, 2, 0.5)]
    top = 0.5 + HEIGHT
    slider = [(0, 0, 0.5), (1, 0, 0.5), (1, 1, 0.5), (0, 1, 0.5),
              (0, 0, top), (1, 0, top), (1, 1, top), (0, 1, top)]
    lines += ['%d, %.17g, %.17g, %.17g' % (i + 1, *p) for i, p in enumerate(base)]
    lines += ['%d, %.17g, %.17g, %.17g' % (i + 11, *p) for i, p in enumerate(slider)]
    lines += ['*ELEMENT, TYPE=C3D8, ELSET=BASE', '1, 1, 2, 3, 4, 5, 6, 7, 8',
              '*ELEMENT, TYPE=C3D8, ELSET=SLIDER', '2, 11, 12, 13, 14, 15, 16, 17, 18',
              '*NSET, NSET=BASE_NODES', '1, 2, 3, 4, 5, 6, 7, 8', '*NSET, NSET=TOP',
              '15, 16, 17, 18',
              '*NSET, NSET=DRIVEN', '15, 16, 17, 18' if drive == 'TOP' else '11, 12, 13, 14',
              '*SURFACE, NAME=MASTER', 'BASE, S2', '*SURFACE, NAME=SLAVE', 'SLIDER, S1',
              '*SURFACE, NAME=LOADED', 'SLIDER, S2',
              '*MATERIAL, NAME=BASE_MAT', '*ELASTIC', '%.17g, 0.3' % BASE_YOUNG,
              '*MATERIAL, NAME=SLIDER_MAT', '*ELASTIC',
              '%.17g, %.17g' % (SLIDER_YOUNG, SLIDER_POISSON),
              '*SOLID SECTION, ELSET=BASE, MATERIAL=BASE_MAT',
              '*SOLID SECTION, ELSET=SLIDER, MATERIAL=SLIDER_MAT',
              '*SURFACE INTERACTION, NAME=FRICTION_UNDER_TEST',
              '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR', '%.17g' % NORMAL_STIFFNESS,
              friction,
              '*CONTACT PAIR, INTERACTION=FRICTION_UNDER_TEST, NAME=%s' % PAIR, 'SLAVE, MASTER',
              '*HISTORY, NAME=%s, FREQUENCY=1' % HISTORY, 'CONTACT, %s' % PAIR,
              'NSET, DRIVEN, RF', 'NSET, DRIVEN, U']
    if node_histories:
        driven = [15, 16, 17, 18] if drive == 'TOP' else [11, 12, 13, 14]
        at = lines.index('*HISTORY, NAME=%s, FREQUENCY=1' % HISTORY)
        lines[at:at] = [card for n in driven for card in ('*NSET, NSET=N%d' % n, '%d' % n)]
        lines += ['NSET, N%d, RF' % n for n in driven]
    if catalog:
        lines.append('*EVENT CATALOG, %s' % catalog)
    if restart:
        lines.append('*RESTART, WRITE, %s' % restart)
    lines += ['*BOUNDARY', 'BASE_NODES, 1, 3',
              '*STEP, NAME=PRESS', '*STATIC', '%.17g, %.17g' % (STEP1_PERIOD / 10, STEP1_PERIOD),
              '*BOUNDARY', 'DRIVEN, 1, 2', '*DSLOAD', 'LOADED, P, %.17g' % SIGMA_N, '*END STEP']
    for number, step in enumerate(steps, start=2):
        period = step['period']
        static = '%.17g, %.17g, %.17g, %.17g' % (step.get('initial', period / 1000.0), period,
                                                  step.get('min', 1.0e-9),
                                                  step.get('max', period / 100.0))
        lines += ['*STEP, NAME=SLIDE %d' % number, '*STATIC', static]
        if rmin:
            lines.append('*RMIN, %s' % rmin)
        lines += ['*BOUNDARY, TYPE=VELOCITY', 'DRIVEN, 1, 1, %.17g' % step['velocity']]
        if contact_file:
            lines += ['*CONTACT FILE, FREQUENCY=%d' % contact_file, 'CDIS, CSTR']
        lines.append('*END STEP')
    with open(path, 'w') as out:
        out.write('\n'.join(lines) + '\n')


def run(deck, *options, check=True):
    """Run $FCS3D quietly on deck (output next to it); a failure fails the test."""
    binary = os.environ.get('FCS3D')
    if not binary:
        fail('FCS3D is not set')
    result = subprocess.run([binary, '-q', *options, deck], capture_output=True, text=True,
                            cwd=os.path.dirname(os.path.abspath(deck)))
    if check and result.returncode != 0:
        fail('fcs3d %s exited with status %d:\n%s%s' % (deck, result.returncode,
                                                        result.stdout, result.stderr))
    return result


def read_csv(path):
    """A CSV with a header line as a dict of column name -> numpy array."""
    if not os.path.exists(path):
        fail('%s was not written' % path)
    with open(path) as f:
        header = f.readline().strip().split(',')
    data = np.loadtxt(path, delimiter=',', skiprows=1, ndmin=2)
    if data.size == 0:
        return {name: np.zeros(0) for name in header}
    return {name: data[:, i] for i, name in enumerate(header)}


class History:
    """The slider history of a job: time t, friction from the contact (mu = mean shear /
    mean pressure of the closed slave nodes), the apparent friction the loading system feels
    (mu_rf = |RF_x| / (sigma_n A), RF of the driven nodes), slip rate (largest), mean slip,
    counts, load-point displacement u."""

    def __init__(self, job):
        h = read_csv(job + '_' + HISTORY + '.csv')
        self.raw = h
        self.t = h['time']
        p = PAIR
        self.pressure = h[p + '_PRESSURE_MEAN']
        self.shear = h[p + '_SHEAR_MEAN']
        with np.errstate(invalid='ignore', divide='ignore'):
            self.mu = np.where(self.pressure > 0, self.shear / np.where(self.pressure > 0,
                                                                          self.pressure, 1), 0)
            self.mu_rf = np.abs(h['DRIVEN_RF1']) / (SIGMA_N * AREA)
        self.rate = h[p + '_RATE_MAX']
        self.slip = h[p + '_SLIP_MEAN']
        self.n_slip = h[p + '_SLIP']
        self.u = h['DRIVEN_U1']
        self.normal_force = h[p + '_FN']


def read_events(job):
    """The event catalog <job>_events.csv as a dict of columns (empty arrays if no event)."""
    return read_csv(job + '_events.csv')


def contact_fields(job, field):
    """(times, values (n_frames, n_slaves)) of a field of the contact grid of <job>.h5."""
    import h5py
    with h5py.File(job + '.h5', 'r') as h5:
        times, values = [], []
        for name in sorted(h5['frames'], key=lambda n: float(h5['frames'][n].attrs['time'])):
            frame = h5['frames'][name]
            grid = frame['surfaces']['contact_' + PAIR]['nodal']
            if field not in grid:
                return None, None
            times.append(float(frame.attrs['time']))
            values.append(np.ravel(grid[field][()]))
    return np.array(times), np.array(values)


def contact_field_names(job):
    """Names of the fields of the contact grid in the last frame of <job>.h5."""
    import h5py
    with h5py.File(job + '.h5', 'r') as h5:
        last = sorted(h5['frames'], key=lambda n: float(h5['frames'][n].attrs['time']))[-1]
        return sorted(h5['frames'][last]['surfaces']['contact_' + PAIR]['nodal'])


# ------------------------------------------------------------------ the oracle: spring-slider

def mu_steady(v, p=RS):
    """mu_ss(V) = MU0 + (A - B) ln(V/V0)."""
    return p['MU0'] + (p['A'] - p['B']) * math.log(v / p['V0'])


def mu_rate_state(v, theta, p=RS):
    """mu = MU0 + A ln(V/V0) + B ln(V0 theta/DC) (V above the cut-off)."""
    return p['MU0'] + p['A'] * math.log(v / p['V0']) + p['B'] * math.log(p['V0'] * theta / p['DC'])


def theta_rate(v, theta, state_law, p=RS):
    """dtheta/dt of the ageing (Dieterich) or slip (Ruina) law."""
    x = v * theta / p['DC']
    if state_law == 'AGEING':
        return 1.0 - x
    return -x * math.log(x)


def spring_slider(k, load_rate, v_start, theta_start, duration, state_law, p=RS, sigma=SIGMA_N,
                  steps=200000, record_every=10, v_stop=None):
    """Quasi-static spring-slider with rate-and-state friction, integrated independently of
    fcs3d by classical RK4 with a fixed step: the spring k [MPa/mm] (per unit area) between the
    load point (velocity load_rate(t) [mm/s], t from the start) and the slider, whose shear
    stress k (delta_lp - delta) = sigma mu(V, theta) (Ruina 1983). Differentiating,
        d ln V / dt = [k (V_lp - V) / sigma - B dtheta/dt / theta] / A,
        d theta / dt = 1 - V theta / DC  (AGEING)  or  -(V theta/DC) ln(V theta/DC)  (SLIP),
    integrated in y = (ln V, ln theta) for accuracy over decades. Returns arrays t, V, theta,
    mu, slip (every record_every steps). v_stop: stop (after recording) once V exceeds it
    (below k_c the quasi-static V grows without bound in finite time)."""
    h = duration / steps

    def rhs(t, y):
        v, theta = math.exp(y[0]), math.exp(y[1])
        dtheta = theta_rate(v, theta, state_law, p)
        dlnv = (k * (load_rate(t) - v) / sigma - p['B'] * dtheta / theta) / p['A']
        return dlnv, dtheta / theta

    y = [math.log(v_start), math.log(theta_start)]
    t = 0.0
    slip = 0.0
    out = [(t, v_start, theta_start, mu_rate_state(v_start, theta_start, p), 0.0)]
    for i in range(steps):
        k1 = rhs(t, y)
        y2 = [y[j] + 0.5 * h * k1[j] for j in range(2)]
        k2 = rhs(t + 0.5 * h, y2)
        y3 = [y[j] + 0.5 * h * k2[j] for j in range(2)]
        k3 = rhs(t + 0.5 * h, y3)
        y4 = [y[j] + h * k3[j] for j in range(2)]
        k4 = rhs(t + h, y4)
        v_before = math.exp(y[0])
        y = [y[j] + h / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]) for j in range(2)]
        t += h
        slip += 0.5 * h * (v_before + math.exp(y[0]))
        stop = v_stop is not None and math.exp(y[0]) > v_stop
        if (i + 1) % record_every == 0 or stop:
            v, theta = math.exp(y[0]), math.exp(y[1])
            out.append((t, v, theta, mu_rate_state(v, theta, p), slip))
        if stop:
            break
    a = np.array(out)
    return a[:, 0], a[:, 1], a[:, 2], a[:, 3], a[:, 4]


def critical_stiffness(p=RS, sigma=SIGMA_N):
    """k_c = sigma_n (B - A) / DC (Ruina 1983; method notes 3.1) [MPa/mm]."""
    return sigma * (p['B'] - p['A']) / p['DC']
