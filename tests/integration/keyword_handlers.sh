#!/bin/sh
# Step 2 of "How to add a keyword" (doc/architecture.md): every keyword of the table that
# `fcs3d --list-keywords` prints has its case in `dispatch` of src/input/fcs_model_builder.f90
# (a keyword without one would reach the builder's "no handler" internal error), and every
# case there is a keyword of the table. *INCLUDE is the one exception: the deck lexer
# (src/input/fcs_deck_lexer.f90) expands it before the builder sees the cards, which this
# test also checks.
# By hand: FCS3D=$PWD/bin/fcs3d sh tests/integration/keyword_handlers.sh
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
"$FCS3D" --list-keywords > keywords.txt || { echo "fcs3d --list-keywords failed"; exit 1; }
"${PYTHON:-/usr/bin/python3}" - "$root" <<'PY'
import re
import sys

root = sys.argv[1]
table = set()
for line in open('keywords.txt'):
    m = re.match(r'^\*([A-Z][A-Z ]*[A-Z])\s\s', line)
    if m:
        table.add(m.group(1))
source = open(root + '/src/input/fcs_model_builder.f90').read()
start = source.find('  subroutine dispatch(')
end = source.find('  end subroutine dispatch')
if start < 0 or end < start:
    print('FAIL: no subroutine dispatch in fcs_model_builder.f90')
    sys.exit(1)
body = re.sub(r'&\s*\n\s*', ' ', source[start:end])  # join continuation lines
first_select = body[:body.find('case default')]
cases = set()
for labels in re.findall(r'^\s*case \((.*)\)\s*$', first_select, re.M):
    cases.update(re.findall(r"'([A-Z][A-Z ]*)'", labels))
LEXER = {'INCLUDE'}
failures = []
if len(table) < 40 or len(cases) < 40:
    failures.append('too few keywords read (table %d, dispatch %d): the parsing here is stale'
                    % (len(table), len(cases)))
missing = table - cases - LEXER
if missing:
    failures.append('keywords of the table without a case in dispatch: %s' % sorted(missing))
extra = cases - table
if extra:
    failures.append('cases in dispatch that are not keywords of the table: %s' % sorted(extra))
lexer = open(root + '/src/input/fcs_deck_lexer.f90').read()
for name in LEXER:
    if name not in table:
        failures.append('*%s is no longer in the table: drop it from LEXER' % name)
    if "'" + name + "'" not in lexer:
        failures.append('the lexer no longer handles *%s' % name)
if failures:
    print('FAIL: ' + '\n      '.join(failures))
    sys.exit(1)
print('keyword handlers: %d keywords, %d handled by dispatch, %s by the lexer'
      % (len(table), len(cases), ', '.join(sorted(LEXER))))
PY
