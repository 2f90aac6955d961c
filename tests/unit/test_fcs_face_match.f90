!> Unit tests of fcs_face_match on a small mixed mesh: two C3D8 sharing a face (a 2 x 1 x 1
!> block), and a C3D6 wedge with a C3D4 tetrahedron on its top triangle. Quadrilaterals and
!> triangles in any rotation or direction, shared faces chosen by the given face's
!> orientation, repeated faces, faces on no element face, and a search limited to some
!> elements.
program test_fcs_face_match
  use fcs_mesh, only: mesh_t
  use fcs_element_catalogue, only: element_catalogue_t
  use fcs_element_loops, only: mesh_kinds
  use fcs_error, only: error_t
  use fcs_face_match, only: match_faces, face_corner_count
  use fcs_kinds, only: dp
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  type(element_catalogue_t) :: catalogue
  type(error_t), allocatable :: err
  type(mesh_t) :: mesh
  integer :: corners(4, 12), n_corners(12), k
  integer, allocatable :: element(:), face(:), matches(:)
  logical :: duplicate

  suite%name = 'fcs_face_match'
  call catalogue%init(err)
  call suite%check(.not. allocated(err), 'element catalogue')
  call mesh%init(mesh_kinds(catalogue))
  do k = 1, 19
    call mesh%add_node(k, [real(k, dp), 0.0_dp, 0.0_dp], duplicate)
  end do
  ! Nodes 1..12: hexahedron 1 spans x 0..1, hexahedron 2 x 1..2, sharing S4 of 1 = S6 of 2.
  call mesh%add_element(1, [1, 5, 6, 2, 3, 7, 8, 4], duplicate, mesh%find_kind('C3D8'))
  call mesh%add_element(2, [5, 9, 10, 6, 7, 11, 12, 8], duplicate, mesh%find_kind('C3D8'))
  ! Wedge 13..18 (S1 13-15-14 at the bottom, S2 16-17-18 on top), tetrahedron on its top
  ! (S1 16-18-17 is the wedge's S2, the other way round).
  call mesh%add_element(3, [13, 14, 15, 16, 17, 18], duplicate, mesh%find_kind('C3D6'))
  call mesh%add_element(4, [16, 17, 18, 19], duplicate, mesh%find_kind('C3D4'))
  call suite%check(face_corner_count(3) == 3 .and. face_corner_count(6) == 3 .and. &
    face_corner_count(4) == 4 .and. face_corner_count(8) == 4, 'corners of 3-, 6-, 4-, 8-node faces')

  corners = 0
  n_corners = [4, 4, 4, 4, 4, 4, 4, 3, 3, 3, 3, 3]
  corners(:, 1) = mesh%face_nodes(1, 1)
  corners(:, 2) = cshift(mesh%face_nodes(2, 4), 2)
  corners(:, 3) = mesh%face_nodes(2, 3)
  corners(:, 3) = corners([4, 3, 2, 1], 3)
  corners(:, 4) = mesh%face_nodes(1, 4)
  corners(:, 5) = mesh%face_nodes(2, 6)
  corners(:, 6) = [1, 5, 10, 12]
  corners(:, 7) = corners(:, 1)
  corners(1:3, 8) = [16, 17, 18]
  corners(1:3, 9) = [18, 17, 16]
  corners(1:3, 10) = [14, 13, 15]
  corners(1:3, 11) = [18, 19, 17]
  corners(1:3, 12) = [1, 5, 6]
  call match_faces(mesh, 1, 4, corners, n_corners, element, face, matches)
  call suite%check(all(matches == [1, 1, 1, 2, 2, 0, 1, 2, 2, 1, 1, 0]), 'number of faces found')
  call suite%check(element(1) == 1 .and. face(1) == 1, 'S1 of hexahedron 1')
  call suite%check(element(2) == 2 .and. face(2) == 4, 'S4 of hexahedron 2, rotated quad')
  call suite%check(element(3) == 2 .and. face(3) == 3, 'S3 of hexahedron 2, reversed quad')
  call suite%check(element(4) == 1 .and. face(4) == 4, 'shared quad, normal out of hexahedron 1')
  call suite%check(element(5) == 2 .and. face(5) == 6, 'shared quad, normal out of hexahedron 2')
  call suite%check(element(6) == 0 .and. face(6) == 0, 'quad on no face')
  call suite%check(element(7) == 1 .and. face(7) == 1, 'repeated quad')
  call suite%check(element(8) == 3 .and. face(8) == 2, 'shared triangle, normal out of the wedge (S2)')
  call suite%check(element(9) == 4 .and. face(9) == 1, 'shared triangle, normal out of the tetrahedron (S1)')
  call suite%check(element(10) == 3 .and. face(10) == 1, 'S1 of the wedge, reversed and rotated')
  call suite%check(element(11) == 4 .and. face(11) == 3, 'S3 of the tetrahedron, rotated')
  call suite%check(element(12) == 0, 'triangle on three corners of a quad face: no face')

  call match_faces(mesh, 2, 3, corners, n_corners, element, face, matches)
  call suite%check(all(matches == [0, 1, 1, 1, 1, 0, 0, 1, 1, 1, 0, 0]), 'search among elements 2..3 only')
  call suite%check(element(4) == 2 .and. face(4) == 6, 'shared quad with one element searched')
  call match_faces(mesh, 1, 4, corners(:, 1:0), n_corners(1:0), element, face, matches)
  call suite%equal_int(size(matches), 0, 'no faces')
  do k = 1, 5
    corners(:, 1) = 0
    corners(1:size(mesh%face_nodes(3, k)), 1) = mesh%face_nodes(3, k)
    n_corners(1) = face_corner_count(size(mesh%face_nodes(3, k)))
    call match_faces(mesh, 3, 3, corners(:, 1:1), n_corners(1:1), element, face, matches)
    call suite%check(face(1) == k, 'every face of the wedge')
  end do
  call suite%report()
end program test_fcs_face_match
