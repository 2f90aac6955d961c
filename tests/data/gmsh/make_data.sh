#!/bin/sh
# Regenerate the gmsh test meshes of tests/unit/test_fcs_gmsh_reader.f90 and of the bad
# decks tests/decks/bad/mesh_*.inp (gmsh 4.8.4).
# Run from this directory: sh make_data.sh. The .msh files are committed; this script records
# how each was made. sparse.msh is written by hand (sparse node tags, blocks out of order,
# parametric coordinates) and is not regenerated.
set -e
mesh() { gmsh -3 "$@" > /dev/null; }

# Good files: the same mesh as text and binary; text with CRLF line ends; no physical groups
# (gmsh then saves every element); physical surfaces but no physical volume, saved with
# Mesh.SaveAll = 1 (all hexahedra are used).
mesh -format msh41 cube.geo -o cube_ascii.msh
mesh -format msh41 -bin cube.geo -o cube_binary.msh
sed 's/$/\r/' cube_ascii.msh > cube_crlf.msh
mesh -format msh41 -bin -setnumber groups 0 cube.geo -o cube_nogroups.msh
mesh -format msh41 -save_all -setnumber volume_group 0 cube.geo -o cube_saveall_surfaces.msh
# Tetrahedra (4 C3D4, then 4 C3D10), and the box of kinds.geo as hexahedra + prisms, first
# order as binary (C3D8 + C3D6), second order as text (C3D20 + C3D15, 6-node triangles and
# 8-node quadrangles on the physical surfaces).
mesh -format msh41 tet.geo -o tet4.msh
mesh -format msh41 -order 2 tet.geo -o tet10.msh
mesh -format msh41 -bin -setnumber shape 3 kinds.geo -o mixed8_binary.msh
mesh -format msh41 -order 2 -setnumber Mesh.SecondOrderIncomplete 1 -setnumber shape 3 kinds.geo \
  -o mixed20.msh

# Files fcs3d must reject.
mesh -format msh22 cube.geo -o bad_v22.msh
mesh -format msh41 -part 2 cube.geo -o bad_partitioned.msh
mesh -format msh41 -setnumber volume_group 0 cube.geo -o bad_no_hexahedra.msh
mesh -format msh41 -order 2 -setnumber shape 2 kinds.geo -o bad_quad9.msh   # complete 2nd order
mesh -format msh41 -order 2 -setnumber groups 0 cube.geo -o bad_hex27.msh     # no groups: hex27 read
sed 's/^2 3 7 1 5 $/2 3 1 7 5 /' tet4.msh > bad_inverted_tet.msh              # tetrahedron 2 inverted
sed 's/^3 1 6 11 2 17 19 18 5 12 7 $/3 1 6 11 2 17 19 18 5 12 99 /' tet10.msh > bad_missing_node_tet10.msh
head -n 60 cube_ascii.msh > bad_truncated.msh                      # cut inside $Nodes
head -n 122 cube_ascii.msh > bad_truncated_elements.msh            # cut inside $Elements
head -c 2500 cube_binary.msh > bad_truncated_binary.msh            # cut inside $Nodes
sed 's/^8 1 12 16 5 $/8 1 12 16 6 /' cube_ascii.msh > bad_quad.msh  # quad 8 off every face
sed 's/^2 0.4999999999986921 0$/2 0.49999x 0/' cube_ascii.msh > bad_number.msh
sed 's/^12 1 9 17 12 5 13 18 16 $/12 1 9 17 12 5 13 18 99 /' cube_ascii.msh > bad_missing_node.msh
printf 'this is not a mesh\n' > bad_not_msh.msh
