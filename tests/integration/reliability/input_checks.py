"""A deck means what it says (issue 15, items 7, 8, 10, 11; items 5 and 6 are bad decks in
tests/decks/bad/: between_steps_*, after_last_step_*, static_negative_*, include_directory).

  - Tabs and byte-order marks are accepted (item 10): the stick-slip deck with every keyword
    line and comment indented by a tab, a line holding only a tab, tabs between the fields of
    the data lines, and a UTF-8 byte-order mark at the start of the deck and of an included
    file passes --check with the same echo as the plain deck.
  - Definitions between steps stay allowed: an *AMPLITUDE between the two steps.
  - *INCLUDE of a FIFO without a writer is refused at once (it used to block for ever); the
    deck given as a directory or as /dev/zero, and a *MESH file that is a directory, are
    refused as such, not as "empty" files (items 7, 11).
  - `--restart ""` and `-o ""` are refused (item 8); they used to start a fresh run (pushing
    out the killed run's checkpoints) or write next to the deck.
  - A checkpoint that is a directory, an empty file or (when not root) unreadable is named as
    such, not "truncated or damaged?" (item 11).
  - An inverted hexahedron of a gmsh mesh is reported at its line of the .msh file (item 11).
  - An input error of a run (not only --check) is written to job.log with the exit status
    (item 11: the user guide says the log is always written).
Every refusal must be exit status 2 with the text named; none may take longer than 30 s.
Usage: input_checks.py <work directory>
"""
import os
import sys

import reliability_common as r

GMSH_INVERTED = """$MeshFormat
4.1 0 8
$EndMeshFormat
$Nodes
1 8 1 8
3 1 0 8
1
2
3
4
5
6
7
8
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
$EndNodes
$Elements
1 1 1 1
3 1 5 1
1 5 6 7 8 1 2 3 4
$EndElements
"""
#: Line of the element record above (1-based).
GMSH_ELEMENT_LINE = 27

MESH_DECK = """*MESH, FILE={mesh}
*ELSET, ELSET=EALL
1
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*STEP
*STATIC
*BOUNDARY
1, 1, 3
*END STEP
"""


def refused(where, args, texts, what, not_empty=False):
    status, _, stderr = r.run(where, *args, timeout=30)
    first = stderr.strip().splitlines()[0] if stderr.strip() else ''
    print('%s: exit status %s: %s' % (what, status, first[:200]))
    r.check(status == 2, '%s: exit status %s, expected 2' % (what, status))
    for text in texts:
        r.check(text in stderr, '%s: the message lacks "%s": %s' % (what, text, stderr))
    if not_empty:
        r.check('empty' not in stderr, '%s: the message still says "empty": %s' % (what, stderr))
    return stderr


def tabs_and_marks(work):
    plain = r.fresh_dir(os.path.join(work, 'plain'))
    text = r.rc.deck_text(steps=2)
    with open(os.path.join(plain, 'job.inp'), 'w') as f:
        f.write(text)
    status, _, stderr = r.run(plain, '--check', 'job.inp')
    r.check(status == 0, 'plain deck: --check exit status %s: %s' % (status, stderr))
    tabbed = r.fresh_dir(os.path.join(work, 'tabs'))
    lines = []
    for line in text.splitlines():
        if line.startswith('*'):
            lines.append('\t' + line)
        elif line[:1].isdigit():
            lines.append(line.replace(', ', ',\t'))
        else:
            lines.append(line)
    split = len(lines) // 2
    with open(os.path.join(tabbed, 'job.inp'), 'wb') as f:
        f.write(b'\xef\xbb\xbf' + '\n'.join(lines[:split] + ['\t', '\t** a comment after a tab',
                                                              '*INCLUDE, INPUT=rest.inc'])
                .encode() + b'\n')
    with open(os.path.join(tabbed, 'rest.inc'), 'wb') as f:
        f.write(b'\xef\xbb\xbf' + '\n'.join(lines[split:]).encode() + b'\n')
    status, _, stderr = r.run(tabbed, '--check', 'job.inp')
    print('tabs and byte-order marks: --check exit status %s' % status)
    r.check(status == 0, 'tabs and byte-order marks: exit status %s: %s' % (status, stderr))
    echo = [l for l in r.read(os.path.join(tabbed, 'job.echo')).splitlines()
            if not l.startswith('** ')]
    plain_echo = [l for l in r.read(os.path.join(plain, 'job.echo')).splitlines()
                  if not l.startswith('** ')]
    r.check(echo == plain_echo, 'tabs and byte-order marks: the echo differs from the plain '
            'deck\'s')
    between = r.fresh_dir(os.path.join(work, 'amplitude_between_steps'))
    at = text.index('*STEP', text.index('*END STEP'))
    with open(os.path.join(between, 'job.inp'), 'w') as f:
        f.write(text[:at] + '*AMPLITUDE, NAME=LATER\n0., 0., 1., 1.\n' + text[at:])
    status, _, stderr = r.run(between, '--check', 'job.inp')
    r.check(status == 0, '*AMPLITUDE between steps: exit status %s: %s' % (status, stderr))


def not_files(work):
    where = r.fresh_dir(os.path.join(work, 'not_files'))
    text = r.rc.deck_text(steps=1)
    fifo = os.path.join(where, 'pipe.inc')
    os.mkfifo(fifo)
    at = text.index('*STEP')
    with open(os.path.join(where, 'fifo.inp'), 'w') as f:
        f.write(text[:at] + '*INCLUDE, INPUT=pipe.inc\n' + text[at:])
    refused(where, ['--check', 'fifo.inp'], ['fifo.inp:', '"pipe.inc" is a FIFO (named pipe)'],
            '*INCLUDE of a FIFO', not_empty=True)
    os.makedirs(os.path.join(where, 'deck_dir'), exist_ok=True)
    refused(where, ['--check', 'deck_dir'], ['deck_dir: cannot read the deck: "deck_dir" is a '
                                             'directory'], 'the deck is a directory',
            not_empty=True)
    refused(where, ['--check', '-o', '.', '/dev/zero'], ['"/dev/zero" is a character device'],
            'the deck is /dev/zero', not_empty=True)
    os.makedirs(os.path.join(where, 'mesh_dir'), exist_ok=True)
    with open(os.path.join(where, 'mesh_dir.inp'), 'w') as f:
        f.write(MESH_DECK.format(mesh='mesh_dir'))
    refused(where, ['--check', 'mesh_dir.inp'], ['mesh_dir.inp:1: *MESH:',
                                                 'is a directory, not a gmsh mesh file'],
            '*MESH of a directory', not_empty=True)


def empty_options(work):
    where = r.fresh_dir(os.path.join(work, 'empty_options'))
    r.rc.write_deck(os.path.join(where, 'job.inp'), steps=1)
    refused(where, ['--restart', '', 'job.inp'], ['option --restart needs a value, got an '
                                                  'empty string'], '--restart ""')
    refused(where, ['-o', '', 'job.inp'], ['option -o needs a value, got an empty string'],
            '-o ""')
    r.check(not os.path.exists(os.path.join(where, 'job.log')), 'an empty option still wrote '
            'job.log')


def checkpoints(work):
    where = r.fresh_dir(os.path.join(work, 'checkpoints'))
    r.rc.write_deck(os.path.join(where, 'job.inp'), steps=1)
    os.makedirs(os.path.join(where, 'dir.rst.h5'), exist_ok=True)
    refused(where, ['--restart', 'dir.rst.h5', 'job.inp'], ['dir.rst.h5', 'it is a directory, '
                                                             'not a checkpoint file'],
            'a checkpoint that is a directory', not_empty=True)
    open(os.path.join(where, 'empty.rst.h5'), 'w').close()
    refused(where, ['--restart', 'empty.rst.h5', 'job.inp'], ['the file is empty (0 bytes)'],
            'an empty checkpoint')
    if os.geteuid() != 0:
        path = os.path.join(where, 'locked.rst.h5')
        with open(path, 'w') as f:
            f.write('x')
        os.chmod(path, 0)
        refused(where, ['--restart', 'locked.rst.h5', 'job.inp'], ['cannot be read'],
                'an unreadable checkpoint')
    else:
        print('running as root: every file is readable, the unreadable checkpoint is not tried')


def gmsh_inverted(work):
    where = r.fresh_dir(os.path.join(work, 'gmsh_inverted'))
    with open(os.path.join(where, 'mesh.msh'), 'w') as f:
        f.write(GMSH_INVERTED)
    with open(os.path.join(where, 'job.inp'), 'w') as f:
        f.write(MESH_DECK.format(mesh='mesh.msh'))
    refused(where, ['--check', 'job.inp'], ['mesh.msh:%d: element 1 is inverted' %
                                            GMSH_ELEMENT_LINE], 'an inverted gmsh hexahedron')


def log_of_input_errors(work):
    where = r.fresh_dir(os.path.join(work, 'log'))
    text = r.rc.deck_text(steps=1).replace('*STATIC\n0.1, 1.', '*STATIC\n0.1, 1., -1e-3')
    with open(os.path.join(where, 'job.inp'), 'w') as f:
        f.write(text)
    stderr = refused(where, ['job.inp'], ['minimum time increment must be positive'],
                     'an input error of a run')
    log = r.read(os.path.join(where, 'job.log')) if os.path.exists(
        os.path.join(where, 'job.log')) else ''
    r.check('minimum time increment must be positive' in log and
            log.rstrip().endswith('exit status 2 (bad input)'),
            'job.log does not record the input error: %r' % log[-300:])


def main():
    work = sys.argv[1]
    tabs_and_marks(work)
    not_files(work)
    empty_options(work)
    checkpoints(work)
    gmsh_inverted(work)
    log_of_input_errors(work)
    r.finish('input_checks')


if __name__ == '__main__':
    main()
