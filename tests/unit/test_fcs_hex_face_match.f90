!> Unit tests of fcs_hex_face_match on two hexahedra sharing a face (a 2 x 1 x 1 block):
!> boundary quads in any rotation or direction, the shared face chosen by the quad's
!> orientation, repeated quads, and quads on no face.
program test_fcs_hex_face_match
  use fcs_hex8_face, only: HEX8_FACE_LOCAL_NODES
  use fcs_hex_face_match, only: match_quads_to_hex_faces
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  !> Nodes 1..12: x = 0, 1, 2 (columns of 4); hexahedron 1 spans x 0..1, hexahedron 2 x 1..2,
  !> both in C3D8 order, sharing face S4 of hexahedron 1 = face S6 of hexahedron 2.
  integer, parameter :: HEXAHEDRA(8, 2) = reshape([1, 5, 6, 2, 3, 7, 8, 4, &
    5, 9, 10, 6, 7, 11, 12, 8], [8, 2])
  integer :: quads(4, 7), k
  integer, allocatable :: hexahedron(:), face(:), matches(:)

  suite%name = 'fcs_hex_face_match'
  quads(:, 1) = HEXAHEDRA(HEX8_FACE_LOCAL_NODES(:, 1), 1)
  quads(:, 2) = cshift(HEXAHEDRA(HEX8_FACE_LOCAL_NODES(:, 4), 2), 2)
  quads(:, 3) = HEXAHEDRA(HEX8_FACE_LOCAL_NODES([4, 3, 2, 1], 3), 2)
  quads(:, 4) = HEXAHEDRA(HEX8_FACE_LOCAL_NODES(:, 4), 1)
  quads(:, 5) = HEXAHEDRA(HEX8_FACE_LOCAL_NODES(:, 6), 2)
  quads(:, 6) = [1, 5, 10, 12]
  quads(:, 7) = quads(:, 1)
  call match_quads_to_hex_faces(HEX8_FACE_LOCAL_NODES, HEXAHEDRA, quads, hexahedron, face, matches)
  call suite%check(all(matches == [1, 1, 1, 2, 2, 0, 1]), 'number of faces found per quad')
  call suite%check(hexahedron(1) == 1 .and. face(1) == 1, 'S1 of hexahedron 1')
  call suite%check(hexahedron(2) == 2 .and. face(2) == 4, 'S4 of hexahedron 2, rotated quad')
  call suite%check(hexahedron(3) == 2 .and. face(3) == 3, 'S3 of hexahedron 2, reversed quad')
  call suite%check(hexahedron(4) == 1 .and. face(4) == 4, 'shared face, normal out of hexahedron 1')
  call suite%check(hexahedron(5) == 2 .and. face(5) == 6, 'shared face, normal out of hexahedron 2')
  call suite%check(hexahedron(6) == 0 .and. face(6) == 0, 'quad on no face')
  call suite%check(hexahedron(7) == 1 .and. face(7) == 1, 'repeated quad')
  call match_quads_to_hex_faces(HEX8_FACE_LOCAL_NODES, HEXAHEDRA, quads(:, 1:0), hexahedron, face, matches)
  call suite%equal_int(size(matches), 0, 'no quads')
  do k = 1, 6
    quads(:, 1) = HEXAHEDRA(HEX8_FACE_LOCAL_NODES(:, k), 1)
    call match_quads_to_hex_faces(HEX8_FACE_LOCAL_NODES, HEXAHEDRA(:, 1:1), quads(:, 1:1), hexahedron, face, matches)
    call suite%check(face(1) == k, 'every face of one hexahedron')
  end do
  call suite%report()
end program test_fcs_hex_face_match
