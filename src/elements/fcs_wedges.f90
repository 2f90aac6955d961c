!> The wedge (pentahedron) element kinds as data: C3D6 (6 nodes, 2 points) and C3D15 (15
!> nodes, 9 points), with CalculiX's node order, integration rules, face numbering and
!> extrapolation.
!>
!> Nodes (CalculiX manual, section 6.2 on C3D6 and C3D15; shape6w.f, shape15w.f): corners
!> 1 (0,0,-1), 2 (1,0,-1), 3 (0,1,-1) and 4..6 the same at zeta = +1; mid-side nodes 7..9 on
!> edges 1-2, 2-3, 3-1, 10..12 on 4-5, 5-6, 6-4, 13..15 on 1-4, 2-5, 3-6. Basis: linear
!> triangle times linear in zeta (6 monomials), and the 15-node space: the quadratic triangle
!> times (1, zeta) plus (1, xi, eta) zeta^2.
!>
!> Faces S1..S5 (CalculiX e_c3d.f, array ifacew; as node sets the manual's "face 1: 1-2-3,
!> face 2: 4-5-6, face 3: 1-2-5-4, face 4: 2-3-6-5, face 5: 3-1-4-6"), listed so that the area
!> vector points out of the element: S1 1-3-2 (9-8-7), S2 4-5-6 (10-11-12), S3 1-2-5-4
!> (7-14-10-13), S4 2-3-6-5 (8-15-11-14), S5 4-6-3-1 (12-15-9-13).
!>
!> Rules (CalculiX gauss.f, e_c3d.f): C3D6 2 points (the centroid of the triangle at
!> zeta = -+1/sqrt(3)), C3D15 9 points (3-point triangle rule x 3 Gauss points); face loads:
!> C3D6 1 point on every face, C3D15 3 points on the triangles and 2x2 on the quadrilaterals.
!> Extrapolation (CalculiX extrapolate.f): C3D15 the least-squares fit of the 6-node field to
!> the 9 points (CalculiX's a9 table) at the corners, mid-side nodes the mean of their corners;
!> C3D6 the minimum-norm fit of the 6-node field to its 2 points, i.e. linear in zeta through
!> them (CalculiX's a2 table gives other values, see doc/architecture.md).
!>
!> gmsh (MSH 4.1 types 6 and 18; gmsh manual, "Node ordering", checked with gmsh 4.8.4): the
!> corners are in CalculiX's order; gmsh's mid-side nodes 7..15 lie on edges 1-2, 1-3, 1-4,
!> 2-3, 2-5, 3-6, 4-5, 4-6, 5-6.
module fcs_wedges
  use fcs_kinds, only: dp
  use fcs_element_kind, only: kind_definition_t, face_definition, TOPOLOGY_WEDGE, &
    FORMULATION_STANDARD, EXTRAPOLATE_FROM_CORNERS
  use fcs_face_kind, only: FACE_TRI3, FACE_TRI6, FACE_QUAD4, FACE_QUAD8
  use fcs_quadrature, only: wedge_rule, triangle_rule, gauss_square
  implicit none
  private
  public :: c3d6_definition, c3d15_definition

  !> Natural coordinates of the 15 nodes (the first 6 are the 6-node wedge's).
  real(dp), parameter :: WEDGE15_XI(3, 15) = reshape([ &
    0.0_dp, 0.0_dp, -1.0_dp, 1.0_dp, 0.0_dp, -1.0_dp, 0.0_dp, 1.0_dp, -1.0_dp, &
    0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, &
    0.5_dp, 0.0_dp, -1.0_dp, 0.5_dp, 0.5_dp, -1.0_dp, 0.0_dp, 0.5_dp, -1.0_dp, &
    0.5_dp, 0.0_dp, 1.0_dp, 0.5_dp, 0.5_dp, 1.0_dp, 0.0_dp, 0.5_dp, 1.0_dp, &
    0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp], [3, 15])

  !> Monomials of the 6-node wedge: 1, xi, eta, zeta, xi zeta, eta zeta.
  integer, parameter :: WEDGE6_TERMS(3, 6) = reshape([ &
    0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1], [3, 6])
  !> Monomials of the 15-node wedge.
  integer, parameter :: WEDGE15_TERMS(3, 15) = reshape([ &
    0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 1, 1, 0, 0, 2, 0, &
    0, 0, 1, 1, 0, 1, 0, 1, 1, 2, 0, 1, 1, 1, 1, 0, 2, 1, &
    0, 0, 2, 1, 0, 2, 0, 1, 2], [3, 15])

  !> Faces S1..S5: corners then mid-side nodes, 0-padded for the triangles (CalculiX ifacew).
  integer, parameter :: WEDGE_FACES(8, 5) = reshape([ &
    1, 3, 2, 9, 8, 7, 0, 0, &
    4, 5, 6, 10, 11, 12, 0, 0, &
    1, 2, 5, 4, 7, 14, 10, 13, &
    2, 3, 6, 5, 8, 15, 11, 14, &
    4, 6, 3, 1, 12, 15, 9, 13], [8, 5])

  !> gmsh position of each CalculiX node of the 15-node wedge.
  integer, parameter :: WEDGE15_GMSH(15) = [1, 2, 3, 4, 5, 6, 7, 10, 8, 13, 15, 14, 9, 11, 12]

contains

  !> C3D6: 6-node wedge, 2 points (CalculiX manual, C3D6).
  pure function c3d6_definition() result(def)
    type(kind_definition_t) :: def
    integer :: f
    def%name = 'C3D6'
    def%summary = '6-node wedge (2 points)'
    def%topology = TOPOLOGY_WEDGE
    def%n_corners = 6
    def%node_xi = WEDGE15_XI(:, 1:6)
    def%basis_terms = WEDGE6_TERMS
    def%corner_terms = WEDGE6_TERMS
    def%rule = wedge_rule(2)
    allocate (def%faces(5))
    do f = 1, 2
      def%faces(f) = face_definition(FACE_TRI3, WEDGE_FACES(1:3, f), triangle_rule(1))
    end do
    do f = 3, 5
      def%faces(f) = face_definition(FACE_QUAD4, WEDGE_FACES(1:4, f), gauss_square(1))
    end do
    def%extrapolation = EXTRAPOLATE_FROM_CORNERS
    def%formulation = FORMULATION_STANDARD
    def%gmsh_type = 6
    def%gmsh_order = WEDGE15_GMSH(1:6)
  end function c3d6_definition

  !> C3D15: 15-node wedge, 9 points (CalculiX manual, C3D15).
  pure function c3d15_definition() result(def)
    type(kind_definition_t) :: def
    integer :: f
    def%name = 'C3D15'
    def%summary = '15-node wedge (9 points)'
    def%topology = TOPOLOGY_WEDGE
    def%n_corners = 6
    def%node_xi = WEDGE15_XI
    def%basis_terms = WEDGE15_TERMS
    def%corner_terms = WEDGE6_TERMS
    def%rule = wedge_rule(9)
    allocate (def%faces(5))
    do f = 1, 2
      def%faces(f) = face_definition(FACE_TRI6, WEDGE_FACES(1:6, f), triangle_rule(3))
    end do
    do f = 3, 5
      def%faces(f) = face_definition(FACE_QUAD8, WEDGE_FACES(:, f), gauss_square(2))
    end do
    def%extrapolation = EXTRAPOLATE_FROM_CORNERS
    def%formulation = FORMULATION_STANDARD
    def%gmsh_type = 18
    def%gmsh_order = WEDGE15_GMSH
  end function c3d15_definition

end module fcs_wedges
