#!/bin/sh
# Generate Makefile dependencies between Fortran objects from their `module`, `submodule` and
# `use` lines (a submodule depends on its parent module).
# Usage: tools/gen_deps.sh BUILD_DIR file.f90 ... > deps.mk
# Each file's object is BUILD_DIR/<basename>.o; a file that uses module m depends on the object
# of the file that defines m. Only modules defined in the given files count (library modules
# such as hdf5 or iso_c_binding are ignored).
build=$1
shift
awk -v build="$build" '
function objof(path,   n, parts, base) {
  n = split(path, parts, "/"); base = parts[n]; sub(/\.[fF]90$/, "", base)
  return build "/" base ".o"
}
FNR == 1 { file = FILENAME; files[file] = 1 }
{
  line = tolower($0); sub(/!.*/, "", line)
  if (match(line, /^[ \t]*module[ \t]+[a-z0-9_]+[ \t]*$/)) {
    split(line, w, /[ \t]+/); name = (w[1] == "" ? w[3] : w[2])
    if (name != "procedure") provider[name] = file
  }
  if (match(line, /^[ \t]*submodule[ \t]*\([ \t]*[a-z0-9_]+/)) {
    parent = line; sub(/^[ \t]*submodule[ \t]*\([ \t]*/, "", parent); sub(/[ \t:)].*$/, "", parent)
    uses[file] = uses[file] " " parent
  }
  if (match(line, /^[ \t]*use[ \t,]/)) {
    rest = line; sub(/^[ \t]*use[ \t]*(,[ \t]*(non_)?intrinsic[ \t]*::)?[ \t]*/, "", rest)
    sub(/[ \t]*::[ \t]*/, "", rest); split(rest, w, /[ \t,]/)
    uses[file] = uses[file] " " w[1]
  }
}
END {
  for (f in files) {
    n = split(uses[f], list, " ")
    for (i = 1; i <= n; i++) {
      m = list[i]
      if (m in provider && provider[m] != f) {
        key = objof(f) ": " objof(provider[m])
        if (!(key in seen)) { seen[key] = 1; print key }
      }
    }
  }
}' "$@" | sort
