#!/usr/bin/python3
"""Compare two runs of the contact benchmark deck (tests/bench/contact_deck.py) through their
*HISTORY of the pushed top (NSET TOP, RF and U, written as <job>_<history>.csv):

    history_compare.py REFERENCE.csv OTHER.csv [--mu 0.3] [--after PUSH]

T = RF_x(TOP), N = -RF_z(TOP), push = u_x(TOP), step 2 only (time > 1). Prints T/(mu N) - 1 at
the end of each run, the largest T/(mu N) of each, and the largest abs(T_other - T_reference)
/ (mu N) over the reference's output points (OTHER interpolated linearly in the push), over the
whole push and, with --after, from that push on. Prints figures; asserts nothing."""
import argparse

import numpy as np


def step2(path):
    data = np.genfromtxt(path, delimiter=',', names=True)
    keep = data['time'] > 1.0
    return data['TOP_U1'][keep], data['TOP_RF1'][keep], -data['TOP_RF3'][keep]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('reference')
    parser.add_argument('other')
    parser.add_argument('--mu', type=float, default=0.3)
    parser.add_argument('--after', type=float)
    args = parser.parse_args()
    u_ref, t_ref, n_ref = step2(args.reference)
    u_oth, t_oth, n_oth = step2(args.other)
    mu = args.mu
    for name, t, n in (('reference', t_ref, n_ref), ('other', t_oth, n_oth)):
        print('%-9s: %d points, T/(mu N) - 1 at the end %+.3e, largest T/(mu N) %.6f'
              % (name, len(t), t[-1] / (mu * n[-1]) - 1.0, np.max(t / (mu * n))))
    diff = np.abs(np.interp(u_ref, u_oth, t_oth) - t_ref) / (mu * n_ref)
    k = int(np.argmax(diff))
    print('largest abs(T_other - T_reference)/(mu N): %.3e at push %.4g' % (diff[k], u_ref[k]))
    if args.after is not None:
        late = u_ref >= args.after
        k = int(np.argmax(np.where(late, diff, -1.0)))
        print('  from push %g on: %.3e at push %.4g' % (args.after, diff[k], u_ref[k]))


if __name__ == '__main__':
    main()
