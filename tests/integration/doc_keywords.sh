#!/bin/sh
# The documentation matches the code's keyword table:
#   1. doc/deck_reference.md is exactly what `fcs3d --list-keywords --markdown` prints (the
#      reference is generated from the table the reader uses; `make doc` regenerates it);
#   2. every keyword of the table has its section in the reference, and every section is a
#      keyword of the table;
#   3. every *KEYWORD named in README.md and doc/**/*.md is one the code accepts (or a
#      CalculiX keyword the text says fcs3d does not take: listed in ALLOWED below).
# By hand: FCS3D=$PWD/bin/fcs3d sh tests/integration/doc_keywords.sh
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
"$FCS3D" --list-keywords --markdown > generated.md || { echo "fcs3d --list-keywords failed"; exit 1; }
if ! cmp -s generated.md "$root/doc/deck_reference.md"; then
  echo "doc/deck_reference.md differs from fcs3d --list-keywords --markdown (run make doc):"
  diff "$root/doc/deck_reference.md" generated.md | head -20
  exit 1
fi
"$FCS3D" --list-keywords > keywords.txt || exit 1
"${PYTHON:-/usr/bin/python3}" - "$root" <<'PY'
import glob
import os
import re
import sys

root = sys.argv[1]
table = set()
for line in open('keywords.txt'):
    m = re.match(r'^\*([A-Z][A-Z ]*[A-Z])\s\s', line)
    if m:
        table.add(m.group(1))
sections = set(re.findall(r'^## \*([A-Z][A-Z ]*)$', open('generated.md').read(), re.M))
failures = []
if table != sections:
    failures.append('keywords without a section: %s; sections without a keyword: %s'
                    % (sorted(table - sections), sorted(sections - table)))
# CalculiX keywords the documentation names as not accepted (and the misspelt or unknown ones
# the user guide gives as examples of the unknown-keyword rule), and words that only look like
# keywords (e.g. "*2" in formulas is not matched: keywords start with a letter).
ALLOWED = {'KEYWORD', 'DYNAMIC', 'FRICTION', 'PLASTIC', 'EQUATION', 'COUPLING', 'KINEMATIC', 'USER MATERIAL',
           'CONTACT OUTPUT', 'NODE OUTPUT', 'ELEMENT OUTPUT', 'OUTPUT', 'CONTROLS', 'VISCO',
           'BUCKLE', 'FREQUENCY', 'HEAT TRANSFER', 'COUPLED TEMPERATURE-DISPLACEMENT',
           'DLOAD', 'GAP', 'SPRING', 'MPC', 'ORIENTATION', 'SHELL SECTION', 'BEAM SECTION',
           'CONTACT DAMPING', 'CLEARANCE', 'INITIAL CONDITIONS', 'TEMPERATURE', 'EXPANSION',
           'CONDUCTIVITY', 'SPECIFIC HEAT', 'CHANGE FRICTION', 'MODEL CHANGE', 'NODAL THICKNESS',
           'MODAL DYNAMIC', 'STEADY STATE DYNAMICS', 'COMPLEX FREQUENCY', 'ELECTROMAGNETICS',
           'GREEN', 'SENSITIVITY', 'SUBSTRUCTURE GENERATE', 'NO ANALYSIS', 'CFD', 'TRANSFORM',
           'UNCOUPLED TEMPERATURE-DISPLACEMENT', 'CHANGE SURFACE BEHAVIOR', 'CYCLIC SYMMETRY MODEL',
           'SUBMODEL', 'PRE-TENSION SECTION', 'CHANGE SOLID SECTION', 'RIGID BODY',
           'NODEE', 'PART', 'GEOSTATIC', 'SOLID SECTON', 'MEMBRANE'}
docs = [p for p in [os.path.join(root, 'README.md')] if os.path.exists(p)] + glob.glob(os.path.join(root, 'doc', '**', '*.md'),
                                                      recursive=True)
for path in docs:
    if os.path.basename(path) == 'deck_reference.md':
        continue
    text = open(path, encoding='utf-8').read()
    for m in re.finditer(r'`\*([A-Z][A-Z \n]*?[A-Z])(?=[,`])', text):
        name = ' '.join(m.group(1).split())
        if name not in table and name not in ALLOWED:
            line = text.count('\n', 0, m.start()) + 1
            failures.append('%s:%d: *%s is not a keyword fcs3d accepts'
                            % (os.path.relpath(path, root), line, name))
for f in failures:
    print('FAIL ' + f)
print('%d keywords in the table, %d sections in the reference, %d documents checked, %d problem(s)'
      % (len(table), len(sections), len(docs), len(failures)))
sys.exit(1 if failures else 0)
PY
