!> The tetrahedral element kinds as data: C3D4 (4 nodes, 1 point) and C3D10 (10 nodes, 4
!> points), with CalculiX's node order, integration rules, face numbering and extrapolation.
!>
!> Nodes (CalculiX manual, section 6.2 on C3D4 and C3D10; shape4tet.f, shape10tet.f): corners
!> 1 (0,0,0), 2 (1,0,0), 3 (0,1,0), 4 (0,0,1); mid-side nodes 5..10 on edges 1-2, 2-3, 3-1,
!> 1-4, 2-4, 3-4. Basis: linear, and the complete quadratic (10 monomials).
!>
!> Faces S1..S4 (CalculiX e_c3d.f, array ifacet; as node sets the manual's "face 1: 1-2-3,
!> face 2: 1-4-2, face 3: 2-4-3, face 4: 3-4-1"), listed so that the area vector points out of
!> the element: S1 1-3-2 (7-6-5), S2 1-2-4 (5-9-8), S3 2-3-4 (6-10-9), S4 1-4-3 (8-10-7).
!>
!> Rules (CalculiX e_c3d.f): C3D4 1 point, C3D10 4 points; face loads 1 point (C3D4) and 3
!> points (C3D10). Extrapolation (CalculiX extrapolate.f): C3D4 constant; C3D10 the linear
!> field through the 4 points (CalculiX's a4 table) at the corners, mid-side nodes the mean of
!> their corners.
!>
!> gmsh (MSH 4.1 types 4 and 11; gmsh manual, "Node ordering", checked with gmsh 4.8.4): the
!> corners are in CalculiX's order; gmsh's mid-side nodes 5..10 lie on edges 1-2, 2-3, 3-1,
!> 4-1, 4-3, 4-2 (CalculiX's nodes 9 and 10 are swapped).
module fcs_tetrahedra
  use fcs_kinds, only: dp
  use fcs_element_kind, only: kind_definition_t, face_definition, TOPOLOGY_TETRAHEDRON, &
    FORMULATION_STANDARD, EXTRAPOLATE_FROM_CORNERS
  use fcs_face_kind, only: FACE_TRI3, FACE_TRI6
  use fcs_quadrature, only: tetrahedron_rule, triangle_rule
  implicit none
  private
  public :: c3d4_definition, c3d10_definition

  !> Natural coordinates of the 10 nodes (the first 4 are the 4-node tetrahedron's).
  real(dp), parameter :: TET10_XI(3, 10) = reshape([ &
    0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
    0.0_dp, 0.0_dp, 1.0_dp, 0.5_dp, 0.0_dp, 0.0_dp, 0.5_dp, 0.5_dp, 0.0_dp, &
    0.0_dp, 0.5_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.5_dp, 0.5_dp, 0.0_dp, 0.5_dp, &
    0.0_dp, 0.5_dp, 0.5_dp], [3, 10])

  !> Monomials: the first 4 span the linear basis, all 10 the quadratic one.
  integer, parameter :: TET10_TERMS(3, 10) = reshape([ &
    0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0, 0, 0, 2, 0, 0, 0, 2, 1, 1, 0, 0, 1, 1, &
    1, 0, 1], [3, 10])

  !> Faces S1..S4: 3 corners then 3 mid-side nodes (CalculiX ifacet).
  integer, parameter :: TET_FACES(6, 4) = reshape([ &
    1, 3, 2, 7, 6, 5, &
    1, 2, 4, 5, 9, 8, &
    2, 3, 4, 6, 10, 9, &
    1, 4, 3, 8, 10, 7], [6, 4])

  !> gmsh position of each CalculiX node of the 10-node tetrahedron.
  integer, parameter :: TET10_GMSH(10) = [1, 2, 3, 4, 5, 6, 7, 8, 10, 9]

contains

  !> C3D4: 4-node tetrahedron, 1 point (CalculiX manual, C3D4).
  pure function c3d4_definition() result(def)
    type(kind_definition_t) :: def
    integer :: f
    def%name = 'C3D4'
    def%summary = '4-node tetrahedron (1 point)'
    def%topology = TOPOLOGY_TETRAHEDRON
    def%n_corners = 4
    def%node_xi = TET10_XI(:, 1:4)
    def%basis_terms = TET10_TERMS(:, 1:4)
    def%corner_terms = TET10_TERMS(:, 1:4)
    def%rule = tetrahedron_rule(1)
    allocate (def%faces(4))
    do f = 1, 4
      def%faces(f) = face_definition(FACE_TRI3, TET_FACES(1:3, f), triangle_rule(1))
    end do
    def%extrapolation = EXTRAPOLATE_FROM_CORNERS
    def%formulation = FORMULATION_STANDARD
    def%gmsh_type = 4
    def%gmsh_order = TET10_GMSH(1:4)
  end function c3d4_definition

  !> C3D10: 10-node tetrahedron, 4 points (CalculiX manual, C3D10).
  pure function c3d10_definition() result(def)
    type(kind_definition_t) :: def
    integer :: f
    def%name = 'C3D10'
    def%summary = '10-node tetrahedron (4 points)'
    def%topology = TOPOLOGY_TETRAHEDRON
    def%n_corners = 4
    def%node_xi = TET10_XI
    def%basis_terms = TET10_TERMS
    def%corner_terms = TET10_TERMS(:, 1:4)
    def%rule = tetrahedron_rule(4)
    allocate (def%faces(4))
    do f = 1, 4
      def%faces(f) = face_definition(FACE_TRI6, TET_FACES(:, f), triangle_rule(3))
    end do
    def%extrapolation = EXTRAPOLATE_FROM_CORNERS
    def%formulation = FORMULATION_STANDARD
    def%gmsh_type = 11
    def%gmsh_order = TET10_GMSH
  end function c3d10_definition

end module fcs_tetrahedra
