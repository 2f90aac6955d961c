"""Seeded fuzz test of the deck reader and the model checks (issue 9): good decks are mutated
(truncation, swapped fields, garbage numbers, huge or negative ids, missing includes, include
cycles, non-ASCII and control bytes, empty files, deleted or repeated lines, mangled
parameters, a very long line) and `fcs3d --check` is run on each. Every run must
  - end by itself within the time limit (no hang) and not by a signal (no crash), and print
    no Fortran runtime error or backtrace;
  - exit 0 (the mutation left a valid deck: possible for truncation, swaps and deletions) or 2
    (input error), never 1 or anything else;
  - when it exits 2, say where: a `file:line:` (or `file:` for whole-file problems) message;
  - for the mutations that can never leave a valid deck (missing include, include cycle,
    non-ASCII byte in a keyword or data line, empty file, a non-number in a numeric field, a
    node id beyond the integer range), exit 2.

Usage: deck_fuzz.py <work directory> [--seed N] [--per-deck N]
($FCS3D names the binary; the seed defaults to $FCS3D_TEST_SEED, else 20261121, and is printed.)
"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TESTS = os.path.normpath(os.path.join(HERE, '..', '..'))
FCS3D = os.environ['FCS3D']
TIME_LIMIT = 30.0
LOCATION = re.compile(r'[^ :\n]+:[0-9]+: |[^ :\n]+\.(inp|inc|msh): ')
CRASH = re.compile(r'Fortran runtime error|Backtrace|Segmentation|SIGSEGV|SIGFPE|'
                   r'internal error', re.IGNORECASE)
# Never a number (nor a name where a number is due: numeric fields of the base decks).
GARBAGE_NUMBERS = ['x', '1.2.3', '--5', '1e', 'e5', '0x10', 'nan', 'inf', '1e999', '-1e999',
                   '.', '+', '1d', '3..']
# Odd but possibly valid: two fields for one, a 40-digit real.
ODD_NUMBERS = ['1,5', '9' * 40, '-0', '1e-320']
HUGE_IDS = ['2147483648', '99999999999', '-2147483649', '1e3']
BAD_BYTES = [b'\xc3\xa9', b'\xb5', b'\x00', b'\x1b[31m', b'\x7f', b'\xff\xfe']


def base_decks():
    """(name, text, files it needs next to it) of the good decks the fuzzer starts from."""
    decks = []
    classic = os.path.join(TESTS, 'decks', 'classic')
    for name in sorted(os.listdir(classic)):
        if name.endswith('.inp'):
            extra = ['include_sets_mesh.inc'] if name == 'include_sets.inp' else []
            decks.append((name, open(os.path.join(classic, name), 'rb').read(),
                          [os.path.join(classic, e) for e in extra]))
    slide = open(os.path.join(TESTS, 'data', 'mpi', 'block_slide.inp'), 'rb').read()
    decks.append(('block_slide.inp', slide, []))
    rate = slide.replace(b'*FRICTION\n0.3, 1.e4\n',
                         b'*FRICTION, LAW=RATE DEPENDENT, MU0=0.6, A=0.01, B=0.025, V0=0.001, '
                         b'VC=1e-6, REGULARISATION=FLOOR, STICK SLOPE=1.e4\n'
                         b'*RESTART, WRITE, FREQUENCY=5\n*HISTORY, NAME=H\nCONTACT, '
                         b'UPPERBOTTOM-LOWERTOP\n*EVENT CATALOG, SLIP RATE=1e-3\n')
    decks.append(('block_rate.inp', rate, []))
    return decks


def lines_of(text):
    return text.split(b'\n')


def data_line_indices(lines):
    return [i for i, l in enumerate(lines)
            if l.strip() and not l.lstrip().startswith(b'*')]


def keyword_line_indices(lines):
    return [i for i, l in enumerate(lines)
            if l.lstrip().startswith(b'*') and not l.lstrip().startswith(b'**')]


def numeric_field_positions(lines):
    """(line, field) of every field that reads as a number, on data lines."""
    out = []
    for i in data_line_indices(lines):
        for j, field in enumerate(lines[i].split(b',')):
            if re.fullmatch(rb'\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*', field):
                out.append((i, j))
    return out


def replace_field(lines, i, j, value):
    fields = lines[i].split(b',')
    fields[j] = b' ' + value
    lines[i] = b','.join(fields)


# Each mutation returns (new text, must_fail, description) or None when it does not apply.
def truncate(rng, text, work):
    cut = rng.randrange(0, len(text))
    return text[:cut], False, 'truncated at byte %d' % cut


def swap_fields(rng, text, work):
    lines = lines_of(text)
    candidates = [i for i in data_line_indices(lines) if lines[i].count(b',') >= 1]
    if not candidates:
        return None
    i = rng.choice(candidates)
    fields = lines[i].split(b',')
    a, b = rng.sample(range(len(fields)), 2)
    fields[a], fields[b] = fields[b], fields[a]
    lines[i] = b','.join(fields)
    return b'\n'.join(lines), False, 'swapped fields %d and %d of line %d' % (a, b, i + 1)


def garbage_number(rng, text, work):
    lines = lines_of(text)
    positions = numeric_field_positions(lines)
    if not positions:
        return None
    i, j = rng.choice(positions)
    must_fail = rng.random() < 0.8
    value = rng.choice(GARBAGE_NUMBERS if must_fail else ODD_NUMBERS)
    replace_field(lines, i, j, value.encode())
    return b'\n'.join(lines), must_fail, 'field %d of line %d set to %r' % (j + 1, i + 1, value)


def huge_id(rng, text, work):
    lines = lines_of(text)
    node_lines = []
    in_node = False
    for i, l in enumerate(lines):
        s = l.strip().upper()
        if s.startswith(b'*'):
            in_node = s.startswith(b'*NODE') and not s.startswith(b'*NODE PRINT') \
                and not s.startswith(b'*NODE FILE')
            continue
        if in_node and s and not s.startswith(b'**'):
            node_lines.append(i)
    if not node_lines:
        return None
    i = rng.choice(node_lines)
    value = rng.choice(HUGE_IDS)
    replace_field(lines, i, 0, value.encode())
    lines[i] = lines[i].lstrip()
    return b'\n'.join(lines), True, 'node id of line %d set to %s' % (i + 1, value)


def missing_include(rng, text, work):
    lines = lines_of(text)
    at = rng.choice(keyword_line_indices(lines))
    lines.insert(at, b'*INCLUDE, INPUT=no_such_file_%d.inc' % rng.randrange(1000))
    return b'\n'.join(lines), True, 'include of a missing file before line %d' % (at + 1)


def include_cycle(rng, text, work):
    with open(os.path.join(work, 'cycle_a.inc'), 'wb') as f:
        f.write(b'** part of a cycle\n*INCLUDE, INPUT=cycle_b.inc\n')
    with open(os.path.join(work, 'cycle_b.inc'), 'wb') as f:
        f.write(b'*INCLUDE, INPUT=cycle_a.inc\n')
    lines = lines_of(text)
    at = rng.choice(keyword_line_indices(lines))
    lines.insert(at, b'*INCLUDE, INPUT=cycle_a.inc')
    return b'\n'.join(lines), True, 'include cycle before line %d' % (at + 1)


def bad_byte(rng, text, work):
    lines = lines_of(text)
    candidates = data_line_indices(lines) + keyword_line_indices(lines)
    i = rng.choice(candidates)
    pos = rng.randrange(0, len(lines[i]) + 1)
    byte = rng.choice(BAD_BYTES)
    lines[i] = lines[i][:pos] + byte + lines[i][pos:]
    return b'\n'.join(lines), True, 'bytes %r at column %d of line %d' % (byte, pos + 1, i + 1)


def empty(rng, text, work):
    return rng.choice([b'', b'\n\n', b'** only a comment\n', b'   \n']), True, 'empty deck'


def delete_line(rng, text, work):
    lines = lines_of(text)
    i = rng.randrange(len(lines))
    del lines[i]
    return b'\n'.join(lines), False, 'line %d deleted' % (i + 1)


def repeat_keyword(rng, text, work):
    lines = lines_of(text)
    i = rng.choice(keyword_line_indices(lines))
    lines.insert(i, lines[i])
    return b'\n'.join(lines), False, 'keyword line %d repeated' % (i + 1)


def mangle_parameter(rng, text, work):
    lines = lines_of(text)
    candidates = [i for i in keyword_line_indices(lines) if b'=' in lines[i]]
    if not candidates:
        return None
    i = rng.choice(candidates)
    parts = lines[i].split(b',')
    with_value = [k for k, p in enumerate(parts) if b'=' in p]
    k = rng.choice(with_value)
    name, value = parts[k].split(b'=', 1)
    parts[k] = rng.choice([name + b'=', name, b'=' + value, name + b'==' + value,
                           name + b'=' + value + b' extra', b' ' + value])
    lines[i] = b','.join(parts)
    return b'\n'.join(lines), False, 'parameter %d of line %d mangled' % (k + 1, i + 1)


def long_line(rng, text, work):
    lines = lines_of(text)
    i = rng.choice(data_line_indices(lines))
    lines[i] = lines[i] + b', 1' * 50000
    return b'\n'.join(lines), False, 'line %d made 150000 characters long' % (i + 1)


MUTATIONS = [truncate, swap_fields, garbage_number, huge_id, missing_include, include_cycle,
             bad_byte, empty, delete_line, repeat_keyword, mangle_parameter, long_line]


def run_case(work, name, text, extras, must_fail, description):
    """Problems of one mutated deck (empty list when it behaves)."""
    os.makedirs(work, exist_ok=True)
    for extra in extras:
        shutil.copy(extra, work)
    path = os.path.join(work, name)
    with open(path, 'wb') as f:
        f.write(text)
    try:
        run = subprocess.run([FCS3D, '--check', '-q', name], cwd=work, capture_output=True,
                             timeout=TIME_LIMIT)
    except subprocess.TimeoutExpired:
        return ['%s (%s): no answer within %g s (hang)' % (name, description, TIME_LIMIT)]
    output = (run.stdout + run.stderr).decode('utf-8', 'replace')
    problems = []
    if run.returncode < 0:
        problems.append('killed by signal %d' % -run.returncode)
    elif run.returncode not in (0, 2):
        problems.append('exit status %d (expected 0 or 2)' % run.returncode)
    if CRASH.search(output):
        problems.append('runtime error or backtrace in the output')
    if run.returncode == 2 and not LOCATION.search(output):
        problems.append('no file:line: location in the message')
    if must_fail and run.returncode == 0:
        problems.append('accepted, but this mutation can never give a valid deck')
    if problems:
        return ['%s (%s): %s; output: %s' % (name, description, '; '.join(problems),
                                              output.strip()[:300].replace('\n', ' | '))]
    return []


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('work')
    parser.add_argument('--seed', type=int,
                        default=int(os.environ.get('FCS3D_TEST_SEED', '20261121')))
    parser.add_argument('--per-deck', type=int, default=60)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    print('seed %d (FCS3D_TEST_SEED=%d reproduces this run)' % (args.seed, args.seed))
    failures, runs, refused, accepted = [], 0, 0, 0
    counts = {}
    for deck_name, text, extras in base_decks():
        for k in range(args.per_deck):
            mutation = MUTATIONS[k % len(MUTATIONS)]
            work = os.path.join(args.work, '%s_%03d' % (deck_name[:-4], k))
            os.makedirs(work, exist_ok=True)
            result = mutation(rng, text, work)
            if result is None:
                continue
            mutated, must_fail, description = result
            problems = run_case(work, deck_name, mutated, extras, must_fail, description)
            runs += 1
            counts[mutation.__name__] = counts.get(mutation.__name__, 0) + 1
            failures += problems
            if not problems:
                shutil.rmtree(work)
    print('%d mutated decks (%s)' % (runs, ', '.join('%s %d' % kv for kv in sorted(counts.items()))))
    for f in failures:
        print('FAIL ' + f)
    print('%d failed' % len(failures))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
