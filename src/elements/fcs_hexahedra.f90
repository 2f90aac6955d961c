!> The hexahedral element kinds as data: C3D8, C3D8R, C3D8I (8 nodes) and C3D20, C3D20R (20
!> nodes), with CalculiX's node order, integration rules, face numbering and extrapolation.
!>
!> Nodes (CalculiX manual, section 6.2 on C3D8 and C3D20; shape8h.f, shape20h.f): corners
!> 1..4 at zeta = -1 counter-clockwise from (-1,-1), 5..8 the same at zeta = +1; mid-side nodes
!> 9..12 on edges 1-2, 2-3, 3-4, 4-1, 13..16 on 5-6, 6-7, 7-8, 8-5, 17..20 on 1-5, 2-6, 3-7,
!> 4-8. Basis: trilinear (1, xi, eta, zeta, xi eta, eta zeta, zeta xi, xi eta zeta) and the
!> 20-term serendipity space (Zienkiewicz, Taylor & Zhu 2005, serendipity family).
!>
!> Faces S1..S6 (CalculiX e_c3d.f, array ifaceq; as node sets the manual's "face 1: 1-2-3-4,
!> face 2: 5-8-7-6, face 3: 1-5-6-2, face 4: 2-6-7-3, face 5: 3-7-8-4, face 6: 4-8-5-1"), listed
!> so that the area vector points out of the element: S1 4-3-2-1 (11-10-9-12), S2 5-6-7-8
!> (13-14-15-16), S3 1-2-6-5 (9-18-13-17), S4 2-3-7-6 (10-19-14-18), S5 3-4-8-7 (11-20-15-19),
!> S6 4-1-5-8 (12-17-16-20).
!>
!> Rules (CalculiX e_c3d.f): C3D8 and C3D8I 2x2x2, C3D8R 1 point, C3D20 3x3x3, C3D20R 2x2x2;
!> face loads: 2x2 (C3D8, C3D8I, C3D20R), 1 point (C3D8R), 3x3 (C3D20).
!>
!> gmsh (MSH 4.1 types 5 and 17; gmsh manual, "Node ordering", checked with gmsh 4.8.4): the 8
!> corners are in CalculiX's order; gmsh's 20-node mid-side nodes 9..20 lie on edges 1-2, 1-4,
!> 1-5, 2-3, 2-6, 3-4, 3-7, 4-8, 5-6, 5-8, 6-7, 7-8.
module fcs_hexahedra
  use fcs_kinds, only: dp
  use fcs_element_kind, only: kind_definition_t, face_definition, TOPOLOGY_HEXAHEDRON, &
    FORMULATION_STANDARD, FORMULATION_HOURGLASS, FORMULATION_INCOMPATIBLE_MODES, &
    EXTRAPOLATE_FROM_CORNERS, EXTRAPOLATE_FROM_ALL_NODES
  use fcs_face_kind, only: FACE_QUAD4, FACE_QUAD8
  use fcs_quadrature, only: quadrature_rule_t, gauss_cube, gauss_square
  implicit none
  private
  public :: c3d8_definition, c3d8r_definition, c3d8i_definition, c3d20_definition, &
            c3d20r_definition

  !> Natural coordinates of the 20 nodes (the first 8 are the 8-node hexahedron's).
  real(dp), parameter :: HEX20_XI(3, 20) = reshape([ &
    -1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, &
    -1.0_dp, 1.0_dp, -1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp, &
    1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, &
    0.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, 0.0_dp, -1.0_dp, 0.0_dp, 1.0_dp, -1.0_dp, &
    -1.0_dp, 0.0_dp, -1.0_dp, 0.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, &
    0.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 0.0_dp, 1.0_dp, -1.0_dp, -1.0_dp, 0.0_dp, &
    1.0_dp, -1.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, -1.0_dp, 1.0_dp, 0.0_dp], [3, 20])

  !> Monomials (exponents of xi, eta, zeta): the first 8 span the trilinear basis, all 20 the
  !> serendipity basis.
  integer, parameter :: HEX20_TERMS(3, 20) = reshape([ &
    0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0, 0, 1, 1, 1, 0, 1, 1, 1, 1, &
    2, 0, 0, 0, 2, 0, 0, 0, 2, 2, 1, 0, 2, 0, 1, 1, 2, 0, 0, 2, 1, 1, 0, 2, 0, 1, 2, &
    2, 1, 1, 1, 2, 1, 1, 1, 2], [3, 20])

  !> Faces S1..S6: 4 corners then 4 mid-side nodes (CalculiX ifaceq).
  integer, parameter :: HEX_FACES(8, 6) = reshape([ &
    4, 3, 2, 1, 11, 10, 9, 12, &
    5, 6, 7, 8, 13, 14, 15, 16, &
    1, 2, 6, 5, 9, 18, 13, 17, &
    2, 3, 7, 6, 10, 19, 14, 18, &
    3, 4, 8, 7, 11, 20, 15, 19, &
    4, 1, 5, 8, 12, 17, 16, 20], [8, 6])

  !> gmsh position of each CalculiX node of the 20-node hexahedron.
  integer, parameter :: HEX20_GMSH(20) = [1, 2, 3, 4, 5, 6, 7, 8, 9, 12, 14, 10, 17, 19, 20, 18, &
                                          11, 13, 15, 16]

contains

  !> C3D8: 8-node hexahedron, 2x2x2 Gauss points (CalculiX manual, C3D8).
  pure function c3d8_definition() result(def)
    type(kind_definition_t) :: def
    def = hex8('C3D8', '8-node hexahedron, full integration (2x2x2 points)', gauss_cube(2), &
               gauss_square(2), FORMULATION_STANDARD)
  end function c3d8_definition

  !> C3D8R: 8-node hexahedron, one point with hourglass control (CalculiX manual, C3D8R).
  pure function c3d8r_definition() result(def)
    type(kind_definition_t) :: def
    def = hex8('C3D8R', '8-node hexahedron, reduced integration (1 point) with hourglass &
               &control', gauss_cube(1), gauss_square(1), FORMULATION_HOURGLASS)
  end function c3d8r_definition

  !> C3D8I: 8-node hexahedron with three incompatible modes, 2x2x2 points (CalculiX manual,
  !> C3D8I).
  pure function c3d8i_definition() result(def)
    type(kind_definition_t) :: def
    def = hex8('C3D8I', '8-node hexahedron with incompatible modes (2x2x2 points)', &
               gauss_cube(2), gauss_square(2), FORMULATION_INCOMPATIBLE_MODES)
  end function c3d8i_definition

  !> C3D20: 20-node hexahedron, 3x3x3 points; stresses extrapolated by a least-squares fit of
  !> the 20-node field to the 27 points (CalculiX's a27 table).
  pure function c3d20_definition() result(def)
    type(kind_definition_t) :: def
    def = hex20('C3D20', '20-node hexahedron, full integration (3x3x3 points)', gauss_cube(3), &
                gauss_square(3), EXTRAPOLATE_FROM_ALL_NODES)
    def%linear_temperature = .true.
  end function c3d20_definition

  !> C3D20R: 20-node hexahedron, 2x2x2 points.
  pure function c3d20r_definition() result(def)
    type(kind_definition_t) :: def
    def = hex20('C3D20R', '20-node hexahedron, reduced integration (2x2x2 points)', &
                gauss_cube(2), gauss_square(2), EXTRAPOLATE_FROM_CORNERS)
  end function c3d20r_definition

  !> An 8-node hexahedron with the given rules and formulation.
  pure function hex8(name, summary, rule, face_rule, formulation) result(def)
    character(len=*), intent(in) :: name, summary
    type(quadrature_rule_t), intent(in) :: rule, face_rule
    integer, intent(in) :: formulation
    type(kind_definition_t) :: def
    integer :: f
    def%name = name
    def%summary = summary
    def%topology = TOPOLOGY_HEXAHEDRON
    def%n_corners = 8
    def%node_xi = HEX20_XI(:, 1:8)
    def%basis_terms = HEX20_TERMS(:, 1:8)
    def%corner_terms = HEX20_TERMS(:, 1:8)
    def%rule = rule
    allocate (def%faces(6))
    do f = 1, 6
      def%faces(f) = face_definition(FACE_QUAD4, HEX_FACES(1:4, f), face_rule)
    end do
    def%extrapolation = EXTRAPOLATE_FROM_CORNERS
    def%formulation = formulation
    def%gmsh_type = 5
    def%gmsh_order = HEX20_GMSH(1:8)
  end function hex8

  !> A 20-node hexahedron with the given rules and extrapolation.
  pure function hex20(name, summary, rule, face_rule, extrapolation) result(def)
    character(len=*), intent(in) :: name, summary
    type(quadrature_rule_t), intent(in) :: rule, face_rule
    integer, intent(in) :: extrapolation
    type(kind_definition_t) :: def
    integer :: f
    def%name = name
    def%summary = summary
    def%topology = TOPOLOGY_HEXAHEDRON
    def%n_corners = 8
    def%node_xi = HEX20_XI
    def%basis_terms = HEX20_TERMS
    def%corner_terms = HEX20_TERMS(:, 1:8)
    def%rule = rule
    allocate (def%faces(6))
    do f = 1, 6
      def%faces(f) = face_definition(FACE_QUAD8, HEX_FACES(:, f), face_rule)
    end do
    def%extrapolation = extrapolation
    def%formulation = FORMULATION_STANDARD
    def%gmsh_type = 17
    def%gmsh_order = HEX20_GMSH
  end function hex20

end module fcs_hexahedra
