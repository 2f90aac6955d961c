!> The element-kind interface: one type, `element_kind_t`, that every solid element kind
!> (C3D4 ... C3D20R) is an instance of, built from a `kind_definition_t` - the data that
!> describes the kind, as Elmer's `elements.def` does: the natural coordinates of its nodes,
!> the monomials of its basis, its integration rule, its faces. The element loops never know
!> which kind they run: they ask the kind for its numbers of nodes and points, its tables at
!> the integration points and its faces.
!>
!> What a kind provides (all tables are computed once, by `init`):
!> - `n_nodes`, `n_corners`, `topology`, `name` (CalculiX's element type name);
!> - shape functions and natural derivatives at any natural point (`shape_values`,
!>   `shape_derivatives`), and at the integration points as tables (`point_values(a, q)`,
!>   `point_derivatives(i, a, q)`, with `point_xi(:, q)` and `weight(q)`); `point_gradients`
!>   turns the table into spatial gradients and det J for nodal coordinates x(3, n_nodes)
!>   without allocating (the hot path);
!> - faces S1..Sn in CalculiX's numbering (`faces(f)`: a face kind, its element nodes - corner
!>   nodes first, then mid-side nodes, ordered so that the area vector points out of the
!>   element - and the face integration rule CalculiX uses for loads on that face);
!> - the extrapolation matrix from integration points to nodes (`extrapolation(a, q)`), built
!>   the way CalculiX's `extrapolate.f` extrapolates (see `EXTRAPOLATE_*`);
!> - the natural points at which det J must be positive (`check_xi`: the integration points
!>   and the nodes) and `min_jacobian_ratio`;
!> - for C3D8I the incompatible modes' natural derivatives at the integration points, for
!>   C3D8R the hourglass base vectors;
!> - the gmsh node order (`gmsh_type`, `gmsh_order`).
!>
!> Voigt order and sign conventions are the element loops' business, not the kind's.
!> Node ordering is CalculiX's (= Abaqus's) for every kind; natural coordinates: hexahedra
!> [-1, 1]^3, tetrahedra 0 <= xi, eta, zeta, xi + eta + zeta <= 1, wedges the triangle
!> 0 <= xi, eta, xi + eta <= 1 times zeta in [-1, 1] (CalculiX shape8h.f, shape20h.f,
!> shape4tet.f, shape10tet.f, shape6w.f, shape15w.f; CalculiX manual, section 6.2).
module fcs_element_kind
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error, add_context
  use fcs_element_basis, only: polynomial_basis_t, solve_linear_system
  use fcs_face_kind, only: face_kind_t, face_shape_nodes, MAX_FACE_NODES
  use fcs_quadrature, only: quadrature_rule_t, gauss_cube
  implicit none
  private
  public :: element_kind_t, element_face_t, kind_definition_t, face_definition_t
  public :: face_definition, spatial_gradients, determinant3
  public :: TOPOLOGY_HEXAHEDRON, TOPOLOGY_TETRAHEDRON, TOPOLOGY_WEDGE, TOPOLOGY_NAMES
  public :: FORMULATION_STANDARD, FORMULATION_HOURGLASS, FORMULATION_INCOMPATIBLE_MODES
  public :: EXTRAPOLATE_FROM_CORNERS, EXTRAPOLATE_FROM_ALL_NODES
  public :: KERNEL_TABLES, KERNEL_HEX8
  public :: MAX_NODES, MAX_POINTS, MAX_FACES, MAX_FACE_POINTS, MAX_CHECK_POINTS

  !> Upper bounds over all kinds, for fixed-size work arrays in the element loops.
  integer, parameter :: MAX_NODES = 20, MAX_POINTS = 27, MAX_FACES = 6, MAX_FACE_POINTS = 9
  integer, parameter :: MAX_CHECK_POINTS = MAX_POINTS + MAX_NODES

  !> Topologies (reference domains).
  integer, parameter :: TOPOLOGY_HEXAHEDRON = 1, TOPOLOGY_TETRAHEDRON = 2, TOPOLOGY_WEDGE = 3
  character(len=11), parameter :: TOPOLOGY_NAMES(3) = [character(len=11) :: &
    'hexahedron', 'tetrahedron', 'wedge']

  !> What the element loops do beyond B^T C B at the integration points.
  !> FORMULATION_HOURGLASS: one-point rule with hourglass control (C3D8R: Flanagan &
  !> Belytschko 1981, IJNME 17, 679-706, as CalculiX's shape8hr.f, hgstiffness.f);
  !> FORMULATION_INCOMPATIBLE_MODES: three extra modes 1 - xi_m^2 whose gradients use the
  !> Jacobian at the element centre and are condensed out (C3D8I: Wilson, Taylor, Doherty &
  !> Ghaboussi 1973; Taylor, Beresford & Wilson 1976; CalculiX's shape8hu.f).
  integer, parameter :: FORMULATION_STANDARD = 1, FORMULATION_HOURGLASS = 2
  integer, parameter :: FORMULATION_INCOMPATIBLE_MODES = 3

  !> How integration-point values are extrapolated to the nodes (CalculiX extrapolate.f):
  !> EXTRAPOLATE_FROM_CORNERS: the field of the linear (corner) basis fitted to the point values
  !> - interpolating when there are as many points as corners (C3D8, C3D8I, C3D20R, C3D10:
  !> CalculiX's a8 and a4 tables), least squares when there are more (C3D15: CalculiX's a9
  !> table), minimum norm when fewer (1 point: constant, as CalculiX for C3D8R and C3D4; C3D6:
  !> linear in zeta - CalculiX's own a2 table differs, see doc/architecture.md) - evaluated at
  !> the corners; each mid-side node takes the mean of its two corners.
  !> EXTRAPOLATE_FROM_ALL_NODES: least-squares fit of the full basis (C3D20, 27 points to 20
  !> nodes: CalculiX's a27 table).
  integer, parameter :: EXTRAPOLATE_FROM_CORNERS = 1, EXTRAPOLATE_FROM_ALL_NODES = 2

  !> How the element loops (fcs_element_loops) compute a kind: KERNEL_TABLES, from this
  !> type's tables (any kind); KERNEL_HEX8, with the hand-written kernels of the 8-node
  !> hexahedron (fcs_hex8_element, fcs_hex8_shape, fcs_hex8_face: C3D8, the results of the
  !> code before the element interface bit for bit, its face node lists starting at node 1 as
  !> fcs_hex8_face's HEX8_FACE_LOCAL_NODES).
  integer, parameter :: KERNEL_TABLES = 1, KERNEL_HEX8 = 2

  !> A face of a kind as data: its face kind, its element nodes (CalculiX order) and the rule
  !> CalculiX integrates loads on it with.
  type :: face_definition_t
    !> FACE_TRI3, FACE_TRI6, FACE_QUAD4 or FACE_QUAD8.
    integer :: shape = 0
    integer, allocatable :: nodes(:)
    type(quadrature_rule_t) :: rule
  end type face_definition_t

  !> An element kind as data: what a catalogue entry supplies.
  type :: kind_definition_t
    !> CalculiX's element type name (C3D8 ...).
    character(len=:), allocatable :: name
    !> One line for the documentation.
    character(len=:), allocatable :: summary
    integer :: topology = 0
    integer :: n_corners = 0
    !> node_xi(:, a): natural coordinates of node a (corners first, CalculiX order).
    real(dp), allocatable :: node_xi(:, :)
    !> basis_terms(:, k): exponents of monomial k of the shape functions.
    integer, allocatable :: basis_terms(:, :)
    !> corner_terms(:, k): monomials of the linear basis on the corners (extrapolation).
    integer, allocatable :: corner_terms(:, :)
    type(quadrature_rule_t) :: rule
    !> faces(f): face Sf.
    type(face_definition_t), allocatable :: faces(:)
    integer :: extrapolation = EXTRAPOLATE_FROM_CORNERS
    !> Temperatures at the integration points from the linear (corner) basis fitted to the
    !> element's interpolation, as CalculiX takes them for C3D20 (build_temperature_table).
    logical :: linear_temperature = .false.
    integer :: formulation = FORMULATION_STANDARD
    !> gmsh MSH element type (0: none); gmsh_order(a): position in gmsh's node list of
    !> CalculiX node a.
    integer :: gmsh_type = 0
    integer, allocatable :: gmsh_order(:)
  end type kind_definition_t

  !> Face Sf of an element kind: a face kind plus its element nodes and its load integration
  !> rule with the face shape functions tabulated at the rule's points.
  type, extends(face_kind_t) :: element_face_t
    !> nodes(k), k = 1..n_nodes: the element's local node that is face node k.
    integer :: nodes(MAX_FACE_NODES) = 0
    integer :: n_points = 0
    !> Integration points (s, t) and weights of the face rule.
    real(dp), allocatable :: point_st(:, :)
    real(dp), allocatable :: weight(:)
    !> point_values(k, q) = M_k and point_derivatives(alpha, k, q) = dM_k/ds_alpha at point q.
    real(dp), allocatable :: point_values(:, :)
    real(dp), allocatable :: point_derivatives(:, :, :)
  end type element_face_t

  !> An element kind, ready for the element loops. Components are read-only after `init`.
  type :: element_kind_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: summary
    integer :: topology = 0
    integer :: n_nodes = 0
    integer :: n_corners = 0
    !> Number of integration points of the kind's rule.
    integer :: n_points = 0
    integer :: n_faces = 0
    integer :: formulation = 0
    integer :: extrapolation_method = 0
    !> The element loops' implementation: KERNEL_TABLES, or KERNEL_HEX8 for the catalogue's
    !> C3D8 (set by element_catalogue_t%init).
    integer :: kernel = KERNEL_TABLES
    !> Volume of the reference domain (8, 1/6, 1).
    real(dp) :: reference_volume = 0.0_dp
    character(len=:), allocatable :: rule_name
    !> Total degree the integration rule integrates exactly.
    integer :: rule_degree = -1
    type(polynomial_basis_t) :: basis
    !> node_xi(:, a): natural coordinates of node a.
    real(dp), allocatable :: node_xi(:, :)
    !> edge_corners(:, a): the two corners of mid-side node a (0 for corners).
    integer, allocatable :: edge_corners(:, :)
    !> Integration points and weights.
    real(dp), allocatable :: point_xi(:, :)
    real(dp), allocatable :: weight(:)
    !> point_values(a, q) = N_a, point_derivatives(i, a, q) = dN_a/dxi_i at point q.
    real(dp), allocatable :: point_values(:, :)
    real(dp), allocatable :: point_derivatives(:, :, :)
    !> Nodal values = matmul(point values, transpose(extrapolation)): extrapolation(a, q).
    real(dp), allocatable :: extrapolation(:, :)
    !> Temperature at point q from nodal temperatures T_a: sum_a temperature_values(a, q) T_a
    !> (point_values, or for a kind with linear_temperature the projected table).
    real(dp), allocatable :: temperature_values(:, :)
    !> Natural points where det J must be positive: the integration points, then the nodes.
    integer :: n_check = 0
    real(dp), allocatable :: check_xi(:, :)
    real(dp), allocatable :: check_derivatives(:, :, :)
    type(element_face_t), allocatable :: faces(:)
    !> C3D8I: mode_derivatives(i, m, q) = dP_m/dxi_i at point q of the incompatible modes
    !> P_m = 1 - xi_m^2, m = 1..3 (to be mapped with the Jacobian at the centre, from
    !> centre_derivatives(i, a) = dN_a/dxi_i at xi = 0).
    integer :: n_modes = 0
    real(dp), allocatable :: mode_derivatives(:, :, :)
    real(dp), allocatable :: centre_derivatives(:, :)
    !> C3D8R: hourglass base vectors hourglass_base(a, k) = eta zeta, xi zeta, xi eta,
    !> xi eta zeta at node a (Flanagan & Belytschko 1981, the Gamma vectors).
    integer :: n_hourglass = 0
    real(dp), allocatable :: hourglass_base(:, :)
    !> C3D8R: mean_derivatives(i, a, p) = dN_a/dxi_i at the 2x2x2 Gauss points p (weights 1),
    !> which integrate the element volume and the mean gradient (1/V) int grad N_a dV of a
    !> trilinear hexahedron exactly (Flanagan & Belytschko 1981, eqs. 15-16: integrands of
    !> degree at most 3 in each natural coordinate).
    real(dp), allocatable :: mean_derivatives(:, :, :)
    integer :: gmsh_type = 0
    integer, allocatable :: gmsh_order(:)
  contains
    procedure :: init => kind_init
    procedure :: free => kind_free
    procedure :: shape_values => kind_shape_values
    procedure :: shape_derivatives => kind_shape_derivatives
    procedure :: point_gradients => kind_point_gradients
    procedure :: gradients => kind_gradients
    procedure :: jacobian => kind_jacobian
    procedure :: volume => kind_volume
    procedure :: min_jacobian_ratio => kind_min_jacobian_ratio
    procedure :: extrapolate => kind_extrapolate
    procedure :: face_xi => kind_face_xi
  end type element_kind_t

contains

  !> A face definition (for the catalogue's data).
  pure function face_definition(shape, nodes, rule) result(face)
    integer, intent(in) :: shape
    integer, intent(in) :: nodes(:)
    type(quadrature_rule_t), intent(in) :: rule
    type(face_definition_t) :: face
    face%shape = shape
    face%nodes = nodes
    face%rule = rule
  end function face_definition

  !> Build the kind described by `def`: check the data, the basis, the tables at the
  !> integration and check points, the faces, the extrapolation matrix and the extra tables
  !> of its formulation. An inconsistent definition is an internal error naming the kind.
  subroutine kind_init(this, def, err)
    class(element_kind_t), intent(inout) :: this
    type(kind_definition_t), intent(in) :: def
    type(error_t), allocatable, intent(out) :: err
    call this%free()
    call check_definition(def, err)
    if (allocated(err)) then
      if (allocated(def%name)) call add_context(err, 'element kind ' // def%name)
      return
    end if
    call this%basis%init(def%node_xi, def%basis_terms, err)
    if (allocated(err)) then
      call add_context(err, 'element kind ' // def%name)
      return
    end if
    this%name = def%name
    this%summary = def%summary
    this%topology = def%topology
    this%n_nodes = size(def%node_xi, 2)
    this%n_corners = def%n_corners
    this%formulation = def%formulation
    this%extrapolation_method = def%extrapolation
    this%node_xi = def%node_xi
    this%gmsh_type = def%gmsh_type
    if (allocated(def%gmsh_order)) this%gmsh_order = def%gmsh_order
    select case (def%topology)
    case (TOPOLOGY_HEXAHEDRON)
      this%reference_volume = 8.0_dp
    case (TOPOLOGY_TETRAHEDRON)
      this%reference_volume = 1.0_dp / 6.0_dp
    case (TOPOLOGY_WEDGE)
      this%reference_volume = 1.0_dp
    end select
    call tabulate_points(this, def%rule)
    call find_edge_corners(this, err)
    if (.not. allocated(err)) call build_faces(this, def, err)
    if (.not. allocated(err)) call build_extrapolation(this, def, err)
    if (.not. allocated(err)) call build_temperature_table(this, def, err)
    if (.not. allocated(err)) call build_formulation_tables(this, err)
    if (allocated(err)) then
      call add_context(err, 'element kind ' // def%name)
      call this%free()
    end if
  end subroutine kind_init

  !> Forget the kind.
  subroutine kind_free(this)
    class(element_kind_t), intent(inout) :: this
    type(element_kind_t) :: empty
    ! Every component back to its default (allocatable ones deallocated by the assignment).
    select type (this)
    type is (element_kind_t)
      this = empty
    end select
  end subroutine kind_free

  !> Shape function values n(a) = N_a(xi), a = 1..n_nodes, at any natural point.
  pure subroutine kind_shape_values(this, xi, n)
    class(element_kind_t), intent(in) :: this
    real(dp), intent(in) :: xi(3)
    real(dp), intent(out) :: n(:)
    call this%basis%values(xi, n)
  end subroutine kind_shape_values

  !> Natural derivatives dn(i, a) = dN_a/dxi_i at any natural point.
  pure subroutine kind_shape_derivatives(this, xi, dn)
    class(element_kind_t), intent(in) :: this
    real(dp), intent(in) :: xi(3)
    real(dp), intent(out) :: dn(:, :)
    call this%basis%derivatives(xi, dn)
  end subroutine kind_shape_derivatives

  !> At integration point q, for nodal coordinates x(3, n_nodes): spatial gradients
  !> grad(j, a) = dN_a/dx_j and det J (from the tabulated natural derivatives; no allocation).
  !> grad is zero where det J = 0; the caller checks det.
  pure subroutine kind_point_gradients(this, q, x, grad, det)
    class(element_kind_t), intent(in) :: this
    integer, intent(in) :: q
    real(dp), intent(in) :: x(:, :)
    real(dp), intent(out) :: grad(:, :)
    real(dp), intent(out) :: det
    call spatial_gradients(this%point_derivatives(:, :, q), x, grad, det)
  end subroutine kind_point_gradients

  !> Spatial gradients grad(j, a) and det J at any natural point xi.
  pure subroutine kind_gradients(this, xi, x, grad, det)
    class(element_kind_t), intent(in) :: this
    real(dp), intent(in) :: xi(3)
    real(dp), intent(in) :: x(:, :)
    real(dp), intent(out) :: grad(:, :)
    real(dp), intent(out) :: det
    real(dp) :: dn(3, MAX_NODES)
    call this%basis%derivatives(xi, dn)
    call spatial_gradients(dn(:, 1:this%n_nodes), x, grad, det)
  end subroutine kind_gradients

  !> Jacobian J(i, j) = dx_i/dxi_j at natural point xi for nodal coordinates x(3, n_nodes).
  pure function kind_jacobian(this, xi, x) result(jac)
    class(element_kind_t), intent(in) :: this
    real(dp), intent(in) :: xi(3)
    real(dp), intent(in) :: x(:, :)
    real(dp) :: jac(3, 3)
    real(dp) :: dn(3, MAX_NODES)
    call this%basis%derivatives(xi, dn)
    jac = jacobian_of(dn(:, 1:this%n_nodes), x)
  end function kind_jacobian

  !> Volume sum_q det J_q w_q of the element with nodal coordinates x(3, n_nodes) by the kind's
  !> rule (exact for elements whose det J the rule integrates: all affine elements, and the
  !> trilinear hexahedron with 2x2x2 points).
  pure real(dp) function kind_volume(this, x) result(volume)
    class(element_kind_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :)
    integer :: q
    volume = 0.0_dp
    do q = 1, this%n_points
      volume = volume + determinant3(jacobian_of(this%point_derivatives(:, :, q), x)) * &
               this%weight(q)
    end do
  end function kind_volume

  !> Smallest det J over the check points (integration points and nodes) divided by the mean
  !> det J (volume / reference volume): 1 for an undistorted (affine) element, <= 0 for an
  !> inverted or folded one.
  pure real(dp) function kind_min_jacobian_ratio(this, x) result(ratio)
    class(element_kind_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :)
    real(dp) :: volume, smallest
    integer :: c
    volume = this%volume(x)
    smallest = huge(1.0_dp)
    do c = 1, this%n_check
      smallest = min(smallest, determinant3(jacobian_of(this%check_derivatives(:, :, c), x)))
    end do
    if (abs(volume) <= tiny(1.0_dp)) then
      ratio = -1.0_dp
    else
      ratio = smallest / (abs(volume) / this%reference_volume)
    end if
  end function kind_min_jacobian_ratio

  !> Nodal values node_values(:, a), a = 1..n_nodes, from values at the integration points
  !> point_values(:, q), q = 1..n_points (any number of components).
  pure subroutine kind_extrapolate(this, point_values, node_values)
    class(element_kind_t), intent(in) :: this
    real(dp), intent(in) :: point_values(:, :)
    real(dp), intent(out) :: node_values(:, :)
    integer :: a, q
    do a = 1, this%n_nodes
      node_values(:, a) = 0.0_dp
      do q = 1, this%n_points
        node_values(:, a) = node_values(:, a) + this%extrapolation(a, q) * point_values(:, q)
      end do
    end do
  end subroutine kind_extrapolate

  !> Element natural coordinates of the point (s, t) of face f.
  pure function kind_face_xi(this, f, st) result(xi)
    class(element_kind_t), intent(in) :: this
    integer, intent(in) :: f
    real(dp), intent(in) :: st(2)
    real(dp) :: xi(3)
    real(dp) :: m(MAX_FACE_NODES)
    integer :: k
    call this%faces(f)%shape_values(st, m)
    xi = 0.0_dp
    do k = 1, this%faces(f)%n_nodes
      xi = xi + m(k) * this%node_xi(:, this%faces(f)%nodes(k))
    end do
  end function kind_face_xi

  !> Spatial gradients grad(j, a) = sum_i dn(i, a) (J^-1)(i, j) and det J from natural
  !> derivatives dn(3, n) and nodal coordinates x(3, n) (only the first n columns of x and
  !> grad are used). grad is zero if det J = 0.
  pure subroutine spatial_gradients(dn, x, grad, det)
    real(dp), intent(in) :: dn(:, :), x(:, :)
    real(dp), intent(out) :: grad(:, :)
    real(dp), intent(out) :: det
    real(dp) :: jac(3, 3), inv(3, 3)
    integer :: a, n
    n = size(dn, 2)
    jac = jacobian_of(dn, x)
    det = determinant3(jac)
    if (det == 0.0_dp) then
      grad(:, 1:n) = 0.0_dp
      return
    end if
    inv(1, 1) = jac(2, 2) * jac(3, 3) - jac(2, 3) * jac(3, 2)
    inv(1, 2) = jac(1, 3) * jac(3, 2) - jac(1, 2) * jac(3, 3)
    inv(1, 3) = jac(1, 2) * jac(2, 3) - jac(1, 3) * jac(2, 2)
    inv(2, 1) = jac(2, 3) * jac(3, 1) - jac(2, 1) * jac(3, 3)
    inv(2, 2) = jac(1, 1) * jac(3, 3) - jac(1, 3) * jac(3, 1)
    inv(2, 3) = jac(1, 3) * jac(2, 1) - jac(1, 1) * jac(2, 3)
    inv(3, 1) = jac(2, 1) * jac(3, 2) - jac(2, 2) * jac(3, 1)
    inv(3, 2) = jac(1, 2) * jac(3, 1) - jac(1, 1) * jac(3, 2)
    inv(3, 3) = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
    inv = inv / det
    do a = 1, n
      grad(1, a) = dn(1, a) * inv(1, 1) + dn(2, a) * inv(2, 1) + dn(3, a) * inv(3, 1)
      grad(2, a) = dn(1, a) * inv(1, 2) + dn(2, a) * inv(2, 2) + dn(3, a) * inv(3, 2)
      grad(3, a) = dn(1, a) * inv(1, 3) + dn(2, a) * inv(2, 3) + dn(3, a) * inv(3, 3)
    end do
  end subroutine spatial_gradients

  !> Determinant of a 3x3 matrix.
  pure real(dp) function determinant3(a) result(det)
    real(dp), intent(in) :: a(3, 3)
    det = a(1, 1) * (a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)) &
        - a(1, 2) * (a(2, 1) * a(3, 3) - a(2, 3) * a(3, 1)) &
        + a(1, 3) * (a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1))
  end function determinant3

  !> J(i, j) = sum_a x(i, a) dn(j, a) over the n = size(dn, 2) nodes.
  pure function jacobian_of(dn, x) result(jac)
    real(dp), intent(in) :: dn(:, :), x(:, :)
    real(dp) :: jac(3, 3)
    integer :: a, j
    jac = 0.0_dp
    do a = 1, size(dn, 2)
      do j = 1, 3
        jac(:, j) = jac(:, j) + x(:, a) * dn(j, a)
      end do
    end do
  end function jacobian_of

  !> Check the sizes and ranges of a definition.
  subroutine check_definition(def, err)
    type(kind_definition_t), intent(in) :: def
    type(error_t), allocatable, intent(out) :: err
    integer :: n, f, a
    if (.not. allocated(def%name)) then
      call fatal_error(err, 'element kind without a name')
      return
    end if
    if (.not. (allocated(def%node_xi) .and. allocated(def%basis_terms) .and. &
               allocated(def%corner_terms) .and. allocated(def%faces) .and. &
               allocated(def%summary))) then
      call fatal_error(err, 'incomplete definition')
      return
    end if
    n = size(def%node_xi, 2)
    if (size(def%node_xi, 1) /= 3 .or. n < 1 .or. n > MAX_NODES) then
      call fatal_error(err, 'node coordinates must be (3, n) with n <= 20')
    else if (def%topology < 1 .or. def%topology > size(TOPOLOGY_NAMES)) then
      call fatal_error(err, 'unknown topology')
    else if (def%n_corners < 1 .or. def%n_corners > n .or. &
             size(def%corner_terms, 2) /= def%n_corners .or. size(def%corner_terms, 1) /= 3) then
      call fatal_error(err, 'corner nodes and corner monomials do not match')
    else if (def%rule%n < 1 .or. def%rule%n > MAX_POINTS .or. def%rule%dimension /= 3) then
      call fatal_error(err, 'no three-dimensional integration rule of 1..27 points')
    else if (size(def%faces) < 1 .or. size(def%faces) > MAX_FACES) then
      call fatal_error(err, 'an element kind has 1..6 faces')
    else if (def%extrapolation /= EXTRAPOLATE_FROM_CORNERS .and. &
             def%extrapolation /= EXTRAPOLATE_FROM_ALL_NODES) then
      call fatal_error(err, 'unknown extrapolation method')
    end if
    if (allocated(err)) return
    do f = 1, size(def%faces)
      associate (face => def%faces(f))
        if (face_shape_nodes(face%shape) == 0 .or. .not. allocated(face%nodes)) then
          call fatal_error(err, 'face ' // int_text(f) // ': unknown face kind')
        else if (size(face%nodes) /= face_shape_nodes(face%shape)) then
          call fatal_error(err, 'face ' // int_text(f) // ': wrong number of nodes')
        else if (any(face%nodes < 1) .or. any(face%nodes > n)) then
          call fatal_error(err, 'face ' // int_text(f) // ': node outside the element')
        else if (face%rule%n < 1 .or. face%rule%n > MAX_FACE_POINTS .or. &
                 face%rule%dimension /= 2) then
          call fatal_error(err, 'face ' // int_text(f) // ': no two-dimensional rule of 1..9 points')
        end if
      end associate
      if (allocated(err)) return
    end do
    if (def%gmsh_type /= 0) then
      if (.not. allocated(def%gmsh_order)) then
        call fatal_error(err, 'gmsh type without a node order')
        return
      end if
      if (size(def%gmsh_order) /= n) then
        call fatal_error(err, 'gmsh node order of the wrong length')
        return
      end if
      do a = 1, n
        if (count(def%gmsh_order == a) /= 1) then
          call fatal_error(err, 'gmsh node order is not a permutation')
          return
        end if
      end do
    end if
  end subroutine check_definition

  !> Integration points, weights and the shape-function tables there; the check points.
  subroutine tabulate_points(this, rule)
    type(element_kind_t), intent(inout) :: this
    type(quadrature_rule_t), intent(in) :: rule
    integer :: q, n
    n = this%n_nodes
    this%n_points = rule%n
    this%rule_name = rule%name
    this%rule_degree = rule%degree
    this%point_xi = rule%points
    this%weight = rule%weights
    allocate (this%point_values(n, rule%n), this%point_derivatives(3, n, rule%n))
    do q = 1, rule%n
      call this%basis%values(rule%points(:, q), this%point_values(:, q))
      call this%basis%derivatives(rule%points(:, q), this%point_derivatives(:, :, q))
    end do
    this%n_check = rule%n + n
    allocate (this%check_xi(3, this%n_check), this%check_derivatives(3, n, this%n_check))
    this%check_xi(:, 1:rule%n) = rule%points
    this%check_xi(:, rule%n + 1:) = this%node_xi
    do q = 1, this%n_check
      call this%basis%derivatives(this%check_xi(:, q), this%check_derivatives(:, :, q))
    end do
  end subroutine tabulate_points

  !> For each mid-side node, the two corners it lies midway between (unique for every kind).
  subroutine find_edge_corners(this, err)
    type(element_kind_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer :: a, b, c, found
    allocate (this%edge_corners(2, this%n_nodes))
    this%edge_corners = 0
    do a = this%n_corners + 1, this%n_nodes
      found = 0
      do b = 1, this%n_corners
        do c = b + 1, this%n_corners
          if (all(abs(0.5_dp * (this%node_xi(:, b) + this%node_xi(:, c)) - this%node_xi(:, a)) &
                  < 1.0e-12_dp)) then
            found = found + 1
            this%edge_corners(:, a) = [b, c]
          end if
        end do
      end do
      if (found /= 1) then
        call fatal_error(err, 'node ' // int_text(a) // ' is not the midpoint of one pair of corners')
        return
      end if
    end do
  end subroutine find_edge_corners

  !> The faces: face kind, nodes, rule and the face shape functions at the rule's points.
  subroutine build_faces(this, def, err)
    type(element_kind_t), intent(inout) :: this
    type(kind_definition_t), intent(in) :: def
    type(error_t), allocatable, intent(out) :: err
    integer :: f, q, nf
    this%n_faces = size(def%faces)
    allocate (this%faces(this%n_faces))
    do f = 1, this%n_faces
      associate (face => this%faces(f), fdef => def%faces(f))
        call face%init(fdef%shape, err)
        if (allocated(err)) return
        nf = face%n_nodes
        face%nodes(1:nf) = fdef%nodes
        face%n_points = fdef%rule%n
        face%point_st = fdef%rule%points
        face%weight = fdef%rule%weights
        allocate (face%point_values(nf, face%n_points), face%point_derivatives(2, nf, face%n_points))
        do q = 1, face%n_points
          call face%shape_values(fdef%rule%points(:, q), face%point_values(:, q))
          call face%shape_derivatives(fdef%rule%points(:, q), face%point_derivatives(:, :, q))
        end do
      end associate
    end do
  end subroutine build_faces

  !> The extrapolation matrix (see EXTRAPOLATE_*): E = pinv(M) for the fitting matrix M(q, b) of
  !> the chosen basis at the integration points, mid-side rows the mean of their corners' rows
  !> when fitting the corner basis.
  subroutine build_extrapolation(this, def, err)
    type(element_kind_t), intent(inout) :: this
    type(kind_definition_t), intent(in) :: def
    type(error_t), allocatable, intent(out) :: err
    type(polynomial_basis_t) :: corner_basis
    real(dp), allocatable :: fit(:, :), inverse(:, :)
    integer :: q, a
    logical :: ok
    allocate (this%extrapolation(this%n_nodes, this%n_points))
    if (def%extrapolation == EXTRAPOLATE_FROM_ALL_NODES) then
      fit = transpose(this%point_values)
      call pseudo_inverse(fit, inverse, ok)
      if (.not. ok) then
        call fatal_error(err, 'the integration points do not determine the nodal values')
        return
      end if
      this%extrapolation = inverse
      return
    end if
    call corner_basis%init(def%node_xi(:, 1:def%n_corners), def%corner_terms, err)
    if (allocated(err)) return
    allocate (fit(this%n_points, this%n_corners))
    do q = 1, this%n_points
      call corner_basis%values(this%point_xi(:, q), fit(q, :))
    end do
    call pseudo_inverse(fit, inverse, ok)
    if (.not. ok) then
      call fatal_error(err, 'the integration points do not determine the corner values')
      return
    end if
    this%extrapolation(1:this%n_corners, :) = inverse
    do a = this%n_corners + 1, this%n_nodes
      this%extrapolation(a, :) = 0.5_dp * (inverse(this%edge_corners(1, a), :) + &
                                           inverse(this%edge_corners(2, a), :))
    end do
  end subroutine build_extrapolation

  !> The point temperatures' table. A kind with linear_temperature takes at its points the
  !> L2 projection (over its own integration rule) of the interpolated nodal temperatures onto
  !> the linear basis on its corners:
  !>
  !>     T_q = sum_c L_c(xi_q) tc_c,   tc = M^-1 B T,   M_cd = sum_p w_p L_c L_d,
  !>     B_ca = sum_p w_p L_c N_a                                                        (TT1)
  !>
  !> (L: corner basis, N: the kind's shape functions, at the points p). A quadratic
  !> temperature field would give a quadratic thermal strain, which the element's linear
  !> strain field cannot follow (spurious stresses); CalculiX's lintemp.f makes the same
  !> "trilinear approximation to the quadratic interpolation" for C3D20 (its 20 x 27 table
  !> equals (TT1) to its 9 printed digits). Other kinds interpolate with their shape functions.
  subroutine build_temperature_table(this, def, err)
    type(element_kind_t), intent(inout) :: this
    type(kind_definition_t), intent(in) :: def
    type(error_t), allocatable, intent(out) :: err
    type(polynomial_basis_t) :: corner_basis
    real(dp), allocatable :: corner(:, :), mass(:, :), rhs(:, :)
    integer :: q, c
    logical :: ok
    this%temperature_values = this%point_values
    if (.not. def%linear_temperature) return
    call corner_basis%init(def%node_xi(:, 1:def%n_corners), def%corner_terms, err)
    if (allocated(err)) return
    allocate (corner(this%n_corners, this%n_points))
    do q = 1, this%n_points
      call corner_basis%values(this%point_xi(:, q), corner(:, q))
    end do
    mass = matmul(corner, transpose(corner) * spread(this%weight, 2, this%n_corners))
    rhs = matmul(corner, transpose(this%point_values) * spread(this%weight, 2, this%n_nodes))
    call solve_linear_system(mass, rhs, ok)
    if (.not. ok) then
      call fatal_error(err, 'the corner basis is singular on the integration rule')
      return
    end if
    do q = 1, this%n_points
      do c = 1, this%n_nodes
        this%temperature_values(c, q) = dot_product(corner(:, q), rhs(:, c))
      end do
    end do
  end subroutine build_temperature_table

  !> Moore-Penrose inverse X (c x r) of a full-rank m (r x c): (m^T m)^-1 m^T when r >= c
  !> (least squares), m^T (m m^T)^-1 when r < c (minimum norm).
  subroutine pseudo_inverse(m, x, ok)
    real(dp), intent(in) :: m(:, :)
    real(dp), allocatable, intent(out) :: x(:, :)
    logical, intent(out) :: ok
    real(dp), allocatable :: normal(:, :), rhs(:, :)
    if (size(m, 1) >= size(m, 2)) then
      normal = matmul(transpose(m), m)
      rhs = transpose(m)
      call solve_linear_system(normal, rhs, ok)
      x = rhs
    else
      normal = matmul(m, transpose(m))
      rhs = m
      call solve_linear_system(normal, rhs, ok)
      x = transpose(rhs)
    end if
  end subroutine pseudo_inverse

  !> Tables of the formulation: incompatible modes (C3D8I) or hourglass base vectors (C3D8R).
  subroutine build_formulation_tables(this, err)
    type(element_kind_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    type(quadrature_rule_t) :: exact_rule
    integer :: q, m, a
    real(dp) :: xi(3)
    select case (this%formulation)
    case (FORMULATION_STANDARD)
      continue
    case (FORMULATION_INCOMPATIBLE_MODES)
      if (this%topology /= TOPOLOGY_HEXAHEDRON) then
        call fatal_error(err, 'incompatible modes need a hexahedron')
        return
      end if
      this%n_modes = 3
      allocate (this%mode_derivatives(3, 3, this%n_points), this%centre_derivatives(3, this%n_nodes))
      this%mode_derivatives = 0.0_dp
      do q = 1, this%n_points
        do m = 1, 3
          this%mode_derivatives(m, m, q) = -2.0_dp * this%point_xi(m, q)
        end do
      end do
      call this%basis%derivatives([0.0_dp, 0.0_dp, 0.0_dp], this%centre_derivatives)
    case (FORMULATION_HOURGLASS)
      if (this%topology /= TOPOLOGY_HEXAHEDRON .or. this%n_nodes /= 8) then
        call fatal_error(err, 'hourglass control needs an 8-node hexahedron')
        return
      end if
      this%n_hourglass = 4
      allocate (this%hourglass_base(8, 4))
      do a = 1, 8
        xi = this%node_xi(:, a)
        this%hourglass_base(a, :) = [xi(2) * xi(3), xi(1) * xi(3), xi(1) * xi(2), &
                                     xi(1) * xi(2) * xi(3)]
      end do
      exact_rule = gauss_cube(2)
      allocate (this%mean_derivatives(3, 8, exact_rule%n))
      do q = 1, exact_rule%n
        call this%basis%derivatives(exact_rule%points(:, q), this%mean_derivatives(:, :, q))
      end do
    case default
      call fatal_error(err, 'unknown formulation')
    end select
  end subroutine build_formulation_tables

  !> A positive integer as text.
  pure function int_text(n) result(text)
    integer, intent(in) :: n
    character(len=:), allocatable :: text
    character(len=12) :: buffer
    write (buffer, '(i0)') n
    text = trim(buffer)
  end function int_text

end module fcs_element_kind
