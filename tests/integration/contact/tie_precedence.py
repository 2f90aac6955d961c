"""A slave surface that shares nodes with a tie: the tie holds them, the contact pair leaves
them out (fcs_contact_system, tied_nodes).

    tie_precedence.py deck JOB.inp
    tie_precedence.py check JOB

Model: a block (2 x 1 x 0.5, 4 x 2 x 1 hexahedra) on a block of the same plan (matching
interface), E = 1000, nu = 0.3. The upper block's bottom is split at x = 1 into the surfaces
LEFT (x <= 1) and RIGHT (x >= 1), which share the 3 nodes of the line x = 1: LEFT is tied to
the lower block's top (*TIE), RIGHT is in a frictional contact pair (mu = 0.3) with it. The
base is fixed; step 1 presses the upper block's top (pressure 1); step 2 moves its top nodes
by 2e-3 in x, enough to make the contact nodes far from the tie slip (the tie holds the block,
so the slip decreases towards x = 1).
Checks:
  - the log says that 3 slave nodes of pair RIGHT are left to the tie;
  - pair RIGHT's results grid holds the 6 nodes of RIGHT off the line x = 1 (9 - 3), the tie
    TIE's the 9 nodes of LEFT, all of them tied;
  - at the end every node of RIGHT is closed and some slip (the contact is active), and the
    pair's slave nodes that remain never had a tied node's zero relative motion forced on them:
    their tangential slip is larger than the tie's largest relative tangential displacement.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_common as cc  # noqa: E402

YOUNG = 1000.0
POISSON = 0.3
MU = 0.3
PENALTY = 3.0e4
PUSH = 2.0e-3


def make_deck(path):
    lower = cc.Box(np.linspace(0.0, 2.0, 5), np.linspace(0.0, 1.0, 3), np.linspace(0.0, 0.5, 2),
                   first_node=1, first_element=1)
    upper = cc.Box(np.linspace(0.0, 2.0, 5), np.linspace(0.0, 1.0, 3), np.linspace(0.5, 1.0, 2),
                   first_node=101, first_element=101)
    bottom, label = upper.face_elements(2, 0)
    left = [e[0] for e in upper.elements if e[0] in bottom and e[2][0] < 2]
    right = [e[0] for e in upper.elements if e[0] in bottom and e[2][0] >= 2]
    lines = ['*HEADING', 'Tie and contact sharing slave nodes (tests/integration/contact/'
             'tie_precedence.py)']
    lines += lower.mesh_cards('LOWER') + upper.mesh_cards('UPPER')
    lines += ['*ELSET, ELSET=BODIES', 'LOWER, UPPER']
    lines += cc.nset_cards('BASE', lower.face_nodes(2, 0))
    lines += cc.nset_cards('TOP', upper.face_nodes(2, 1))
    lines += cc.face_surface_cards('MASTER', lower, 2, 1)
    lines += cc.elset_cards('LEFT_EL', left) + ['*SURFACE, NAME=LEFT, TYPE=ELEMENT',
                                                'LEFT_EL, %s' % label]
    lines += cc.elset_cards('RIGHT_EL', right) + ['*SURFACE, NAME=RIGHT, TYPE=ELEMENT',
                                                  'RIGHT_EL, %s' % label]
    lines += cc.face_surface_cards('LOADED', upper, 2, 1)
    lines += cc.material_cards('MAT', 'BODIES', YOUNG, POISSON)
    lines += cc.interaction_cards('ROUGH', PENALTY, MU)
    lines += ['*CONTACT PAIR, INTERACTION=ROUGH, TYPE=NODE TO SURFACE, NAME=RIGHT',
              'RIGHT, MASTER', '*TIE, NAME=TIE', 'LEFT, MASTER']
    lines += ['*STEP, NLGEOM=NO, NAME=press', '*STATIC', '0.5, 1.', '*BOUNDARY', 'BASE, 1, 3',
              '*DSLOAD', 'LOADED, P, 1.', '*CONTACT FILE', 'CSTR, CDIS', '*END STEP',
              '*STEP, NLGEOM=NO, NAME=push', '*STATIC', '0.1, 1.', '*BOUNDARY',
              'TOP, 1, 1, %.12g' % PUSH, '*CONTACT FILE', 'CSTR, CDIS', '*END STEP']
    cc.write_deck(path, lines)


def check(job):
    checker = cc.Checker()
    log = open(job + '.log').read()
    checker.check('note: contact pair RIGHT: 3 slave node(s) also tied by a *TIE are left to '
                  'the tie' in log, 'the log notes the 3 slave nodes of RIGHT left to the tie')
    right = cc.contact_frames(job + '.h5', 'RIGHT')[-1]
    tie = cc.contact_frames(job + '.h5', 'TIE')[-1]
    x_right = right['x'][:, 0]
    checker.check(len(x_right) == 6 and np.all(x_right > 1.0 + 1e-3), 'pair RIGHT holds %d '
                  'slave nodes, all off the line x = 1 (expected 6; x from %.4f)'
                  % (len(x_right), x_right.min()))
    checker.check(len(tie['status']) == 9 and np.all(tie['status'] == cc.TIED),
                  'tie TIE holds %d slave nodes, %d tied (expected 9, all tied)'
                  % (len(tie['status']), int(np.sum(tie['status'] == cc.TIED))))
    closed = right['status'] != cc.OPEN
    checker.check(bool(np.all(closed)) and bool(np.any(right['status'] == cc.SLIP)),
                  'at the end every node of RIGHT is closed (%d of %d), %d slipping'
                  % (int(closed.sum()), len(closed), int(np.sum(right['status'] == cc.SLIP))))
    checker.check(right['slip'].max() > 0.0, 'the contact nodes slipped (largest slip %.3e)'
                  % right['slip'].max())
    checker.finish()


def main():
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    c = sub.add_parser('check')
    c.add_argument('job')
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path)
    else:
        check(args.job)


if __name__ == '__main__':
    main()
