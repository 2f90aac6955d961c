#!/bin/sh
# Block sliding by increment size (contact issue, test 1; `make validate`): the partial-slip
# block of tests/integration/contact_block_sliding.sh with the default increments and with
# caps of 0.05 .. 0.005 of the step, and the soft-stick variant. Rewrites
# doc/validation/contact_block_sliding.{md,png,csv} (the load-displacement curve of the test
# configuration in the CSV). Requires the 1 % of the test with caps 0.01 and 0.005.
# contact/studies.py sliding. About 1 minute.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, matplotlib' 2>/dev/null || { echo "numpy/matplotlib not available"; exit 77; }
"$py" "$here/tests/integration/contact/studies.py" sliding --work "$PWD/sliding" \
  --markdown "$here/doc/validation/contact_block_sliding.md" \
  --png "$here/doc/validation/contact_block_sliding.png" \
  --csv "$here/doc/validation/contact_block_sliding.csv"
