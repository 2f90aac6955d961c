#!/bin/sh
# Hertz line contact with C3D10 meshes on three meshes (issue 16, "Hertz contact with C3D10
# or C3D20R meshes and quadratic/triangular master segments, peak pressure within 5 % on the
# finest mesh"; `make validate`): tests/integration/contact_hertz_c3d10.sh with hc = 0.2,
# 0.1, 0.05 (5, 10, 20 elements per contact half-width a = 1). Requires on the finest mesh
# the peak nodal pressure, the fitted p0 and the fitted half-width within 5 % of Hertz and the
# contact edge bracketed; prints the convergence table (doc/validation/contact.md section 9).
# About 15 minutes of CPU, most of it on the finest mesh.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy/h5py missing"; exit 77; }
command -v gmsh >/dev/null 2>&1 || { echo "gmsh (Debian package gmsh) not installed"; exit 77; }
export FCS3D_TEST_DATA=${FCS3D_TEST_DATA:-$here/tests/data}
contact=$here/tests/integration/contact
fail=0
echo "| hc | a/hc | p_max/p0 - 1 | p0_fit/p0 - 1 | a_fit/a - 1 | edge bracket |"
echo "|---|---|---|---|---|---|"
for hc in 0.2 0.1 0.05; do
  job=hertz_c3d10_$hc
  "$py" "$contact/hertz.py" mesh $job.msh --hc $hc || exit 1
  "$py" "$contact/hertz_tet.py" deck $job.inp --mesh $job.msh --hc $hc || exit 1
  "$FCS3D" -q $job.inp || { echo "fcs3d failed on $job.inp"; fail=1; continue; }
  if [ "$hc" = 0.05 ]; then
    "$py" "$contact/hertz_tet.py" check $job --hc $hc --tolerance 0.05 > $job.check || fail=1
  else
    "$py" "$contact/hertz_tet.py" check $job --hc $hc --tolerance 1 > $job.check
  fi
  grep -v '^summary' $job.check
  sed -n 's/^summary hertz C3D10 hc \([^:]*\): a\/hc \([^,]*\), p_max\/p0 - 1 = \([^,]*\), p0_fit\/p0 - 1 = \([^,]*\), a_fit\/a - 1 = \([^,]*\), edge bracket \(.*\) vs a .*/| \1 | \2 | \3 | \4 | \5 | \6 |/p' $job.check
done
exit $fail
