!> Unit test of the element-kind interface (fcs_element_kind, fcs_face_kind, fcs_quadrature,
!> fcs_element_basis, the kind data in fcs_hexahedra/fcs_tetrahedra/fcs_wedges and the
!> catalogue), for every kind:
!> - sizes, topology, rule, faces and gmsh type as CalculiX and gmsh define them;
!> - shape functions: partition of unity, derivatives summing to zero, N_a(x_b) = delta_ab,
!>   derivatives against central differences, and the values against the closed forms of the
!>   textbooks (an oracle independent of the monomial-and-Vandermonde construction);
!> - integration rule: weights sum to the reference volume, monomials of the claimed degree
!>   integrated exactly (and one of the next degree not), points as in CalculiX's gauss.f;
!> - isoparametric completeness: a linear field and its gradient reproduced on a distorted
!>   element; Jacobian checks (ratio 1 undistorted, positive distorted, negative inverted);
!> - faces: node lists (corners first, as CalculiX's manual lists them, mid-side nodes between
!>   their corners), outward area vectors, face areas, face shape functions equal to the
!>   volume ones restricted to the face, face rules exact to their degree;
!> - extrapolation reproducing linear fields (constant for one point, linear in zeta for C3D6,
!>   the 20-node field for C3D20) and agreeing with CalculiX's extrapolation tables;
!> - gmsh to CalculiX node order checked by geometry on gmsh's reference elements;
!> - C3D8I's incompatible modes and C3D8R's hourglass vectors;
!> - C3D8 against today's hex8 modules;
!> - the catalogue: lookup, the error listing the valid names, a test-only kind registered.
!> Tolerances: 1e-12 relative for identities that hold to round-off (tables of order 1,
!> fewer than 30 terms); 1e-8 for central differences with h = 1e-6 (truncation h^2 ~ 1e-12
!> times third derivatives of order 1, round-off 1e-16/h); CalculiX's tables to the digits they
!> print.
program test_fcs_element_kinds
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, EXIT_INPUT
  use fcs_test_assertions, only: test_suite_t
  use fcs_element_kind, only: element_kind_t, kind_definition_t, face_definition, &
    TOPOLOGY_HEXAHEDRON, TOPOLOGY_TETRAHEDRON, TOPOLOGY_WEDGE, FORMULATION_STANDARD, &
    FORMULATION_HOURGLASS, FORMULATION_INCOMPATIBLE_MODES, MAX_NODES, MAX_POINTS, &
    MAX_FACE_POINTS
  use fcs_element_catalogue, only: element_catalogue_t, ELEMENT_KIND_NAMES, builtin_definition
  use fcs_face_kind, only: FACE_TRI3, FACE_TRI6, FACE_QUAD4, FACE_QUAD8, MAX_FACE_NODES
  use fcs_quadrature, only: quadrature_rule_t, gauss_cube, gauss_square, gauss_line, &
    triangle_rule, tetrahedron_rule, wedge_rule
  use fcs_hex8_element, only: hex8_geometry_t, hex8_geometry, hex8_extrapolate
  use fcs_hex8_face, only: HEX8_FACE_LOCAL_NODES
  implicit none

  real(dp), parameter :: TIGHT = 1.0e-12_dp
  type(test_suite_t) :: suite
  type(element_catalogue_t) :: catalogue
  type(error_t), allocatable :: err
  integer :: k

  suite%name = 'fcs_element_kinds'
  call set_seed()
  call catalogue%init(err)
  call suite%check(.not. allocated(err), 'the catalogue builds')
  if (allocated(err)) then
    print '(a)', err%message
    call suite%report()
  end if
  call check_catalogue(suite, catalogue)
  call check_rules(suite)
  do k = 1, catalogue%size()
    associate (kind => catalogue%kinds(k))
      call check_sizes(suite, kind)
      call check_shape_functions(suite, kind)
      call check_closed_forms(suite, kind)
      call check_kind_rule(suite, kind)
      call check_completeness(suite, kind)
      call check_faces(suite, kind)
      call check_extrapolation(suite, kind)
      call check_gmsh_order(suite, kind)
      call check_formulation(suite, kind)
    end associate
  end do
  call check_calculix_tables(suite, catalogue)
  call check_against_hex8(suite, catalogue)
  call check_registration(suite, catalogue)
  call suite%report()

contains

  ! ---------------------------------------------------------------- helpers

  subroutine set_seed()
    integer :: n, i
    integer, allocatable :: seed(:)
    call random_seed(size=n)
    allocate (seed(n))
    seed = [(20240 + 37 * i, i = 1, n)]
    call random_seed(put=seed)
  end subroutine set_seed

  !> A random natural point strictly inside the reference domain of `topology`.
  function random_point(topology) result(xi)
    integer, intent(in) :: topology
    real(dp) :: xi(3), u(3)
    do
      call random_number(u)
      select case (topology)
      case (TOPOLOGY_HEXAHEDRON)
        xi = 1.8_dp * u - 0.9_dp
        return
      case (TOPOLOGY_TETRAHEDRON)
        xi = 0.05_dp + 0.9_dp * u
        if (sum(xi) < 0.95_dp) return
      case default
        xi(1:2) = 0.05_dp + 0.9_dp * u(1:2)
        xi(3) = 1.8_dp * u(3) - 0.9_dp
        if (xi(1) + xi(2) < 0.95_dp) return
      end select
    end do
  end function random_point

  !> A random point (s, t) strictly inside a triangle (3 or 6 nodes) or a square.
  function random_face_point(n_corners) result(st)
    integer, intent(in) :: n_corners
    real(dp) :: st(2), u(2)
    do
      call random_number(u)
      if (n_corners == 4) then
        st = 1.8_dp * u - 0.9_dp
        return
      end if
      st = 0.05_dp + 0.9_dp * u
      if (sum(st) < 0.95_dp) return
    end do
  end function random_face_point

  !> Nodal coordinates of a distorted element: an affine image of the reference element,
  !> corners moved by up to 0.04 and mid-side nodes by up to 0.02 (curved edges), det J > 0.
  function distorted(kind) result(x)
    type(element_kind_t), intent(in) :: kind
    real(dp) :: x(3, kind%n_nodes)
    real(dp), parameter :: map(3, 3) = reshape([1.2_dp, -0.1_dp, 0.05_dp, 0.2_dp, 0.9_dp, &
      -0.2_dp, 0.1_dp, 0.15_dp, 1.1_dp], [3, 3])
    real(dp) :: noise(3, kind%n_nodes)
    integer :: a
    call random_number(noise)
    noise = 2.0_dp * noise - 1.0_dp
    do a = 1, kind%n_nodes
      x(:, a) = matmul(map, kind%node_xi(:, a)) + [0.3_dp, -0.2_dp, 0.5_dp]
      x(:, a) = x(:, a) + merge(0.04_dp, 0.02_dp, a <= kind%n_corners) * noise(:, a)
    end do
  end function distorted

  !> Exact integral of xi^i eta^j zeta^k over the reference domain of `topology`.
  pure real(dp) function exact_volume_integral(topology, e) result(value)
    integer, intent(in) :: topology, e(3)
    select case (topology)
    case (TOPOLOGY_HEXAHEDRON)
      value = line_integral(e(1)) * line_integral(e(2)) * line_integral(e(3))
    case (TOPOLOGY_TETRAHEDRON)
      value = factorial(e(1)) * factorial(e(2)) * factorial(e(3)) / factorial(sum(e) + 3)
    case default
      value = factorial(e(1)) * factorial(e(2)) / factorial(e(1) + e(2) + 2) * line_integral(e(3))
    end select
  end function exact_volume_integral

  !> Exact integral of s^i t^j over the reference square (n_corners = 4) or triangle.
  pure real(dp) function exact_face_integral(n_corners, e) result(value)
    integer, intent(in) :: n_corners, e(2)
    if (n_corners == 4) then
      value = line_integral(e(1)) * line_integral(e(2))
    else
      value = factorial(e(1)) * factorial(e(2)) / factorial(e(1) + e(2) + 2)
    end if
  end function exact_face_integral

  !> Integral of x^i over [-1, 1].
  pure real(dp) function line_integral(i) result(value)
    integer, intent(in) :: i
    value = merge(2.0_dp / (i + 1), 0.0_dp, mod(i, 2) == 0)
  end function line_integral

  pure real(dp) function factorial(n) result(value)
    integer, intent(in) :: n
    integer :: i
    value = 1.0_dp
    do i = 2, n
      value = value * i
    end do
  end function factorial

  !> Sum over a rule of the monomial with exponents e.
  pure real(dp) function rule_sum(points, weights, e) result(value)
    real(dp), intent(in) :: points(:, :), weights(:)
    integer, intent(in) :: e(:)
    integer :: q
    value = 0.0_dp
    do q = 1, size(weights)
      value = value + weights(q) * product(points(:, q)**e)
    end do
  end function rule_sum

  pure function cross(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross

  function label(kind, what) result(text)
    type(element_kind_t), intent(in) :: kind
    character(len=*), intent(in) :: what
    character(len=:), allocatable :: text
    text = kind%name // ': ' // what
  end function label

  function face_label(kind, f, what) result(text)
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: f
    character(len=*), intent(in) :: what
    character(len=:), allocatable :: text
    character(len=8) :: number
    write (number, '(a,i0)') 'S', f
    text = kind%name // ' ' // trim(number) // ': ' // what
  end function face_label

  ! ---------------------------------------------------------------- catalogue

  subroutine check_catalogue(suite, catalogue)
    type(test_suite_t), intent(inout) :: suite
    type(element_catalogue_t), intent(in) :: catalogue
    type(error_t), allocatable :: err
    integer :: index
    call suite%equal_int(catalogue%size(), 9, 'nine built-in kinds')
    call suite%check(catalogue%names() == 'C3D4, C3D6, C3D8, C3D8R, C3D8I, C3D10, C3D15, C3D20, &
                     &C3D20R', 'names in catalogue order: ' // catalogue%names())
    do index = 1, size(ELEMENT_KIND_NAMES)
      call suite%equal_int(catalogue%find(ELEMENT_KIND_NAMES(index)), index, &
                           'find ' // trim(ELEMENT_KIND_NAMES(index)))
    end do
    call catalogue%lookup('  c3d20r ', index, err)
    call suite%check(.not. allocated(err) .and. index == 9, 'lookup ignores case and blanks')
    call catalogue%lookup('C3D27', index, err)
    call suite%check(allocated(err) .and. index == 0, 'unknown name is an error')
    if (allocated(err)) then
      call suite%equal_int(err%exit_code, EXIT_INPUT, 'unknown name is an input error')
      call suite%check(err%message == 'unknown element type "C3D27"; expected one of C3D4, &
                       &C3D6, C3D8, C3D8R, C3D8I, C3D10, C3D15, C3D20, C3D20R', &
                       'message lists the valid names: ' // err%message)
    end if
    call suite%equal_int(catalogue%find_gmsh(4), catalogue%find('C3D4'), 'gmsh type 4')
    call suite%equal_int(catalogue%find_gmsh(5), catalogue%find('C3D8'), 'gmsh type 5')
    call suite%equal_int(catalogue%find_gmsh(6), catalogue%find('C3D6'), 'gmsh type 6')
    call suite%equal_int(catalogue%find_gmsh(11), catalogue%find('C3D10'), 'gmsh type 11')
    call suite%equal_int(catalogue%find_gmsh(17), catalogue%find('C3D20'), 'gmsh type 17')
    call suite%equal_int(catalogue%find_gmsh(18), catalogue%find('C3D15'), 'gmsh type 18')
    call suite%equal_int(catalogue%find_gmsh(1), 0, 'gmsh line type: none')
  end subroutine check_catalogue

  !> A test-only kind registered through the catalogue (the recipe of doc/architecture.md):
  !> C3D8's data with a 3x3x3 rule and 3x3 face rules; then a duplicate and a broken one.
  subroutine check_registration(suite, catalogue)
    type(test_suite_t), intent(inout) :: suite
    type(element_catalogue_t), intent(inout) :: catalogue
    type(kind_definition_t) :: def
    type(element_kind_t) :: unnamed
    type(error_t), allocatable :: err
    logical :: found
    integer :: f, index
    call builtin_definition('C3D8', def, found)
    call suite%check(found, 'builtin_definition C3D8')
    def%name = 'TEST8X27'
    def%summary = 'test-only 8-node hexahedron with 3x3x3 points'
    def%rule = gauss_cube(3)
    do f = 1, 6
      def%faces(f)%rule = gauss_square(3)
    end do
    call catalogue%add(def, err)
    call suite%check(.not. allocated(err), 'test-only kind registered')
    index = catalogue%find('test8x27')
    call suite%equal_int(index, 10, 'test-only kind found')
    if (index == 10) then
      call suite%equal_int(catalogue%kinds(index)%n_points, 27, 'test-only kind: 27 points')
      call suite%equal_int(catalogue%kinds(index)%faces(3)%n_points, 9, &
                           'test-only kind: 9 face points')
      call check_shape_functions(suite, catalogue%kinds(index))
      call check_completeness(suite, catalogue%kinds(index))
      call check_extrapolation(suite, catalogue%kinds(index))
      call suite%check(index_of(catalogue%names(), 'TEST8X27') > 0, 'names list it')
    end if
    call catalogue%add(def, err)
    call suite%check(allocated(err), 'a name defined twice is refused')
    if (allocated(err)) call suite%check(index_of(err%message, 'already defined') > 0, &
                                         'duplicate: ' // err%message)
    def%name = 'BROKEN'
    def%faces(1) = face_definition(FACE_QUAD4, [1, 2, 3, 9], gauss_square(2))
    call catalogue%add(def, err)
    call suite%check(allocated(err), 'a face node outside the element is refused')
    if (allocated(err)) call suite%check(err%message == 'element kind BROKEN: face 1: node &
                                         &outside the element', 'broken: ' // err%message)
    deallocate (def%name)
    call catalogue%add(def, err)
    call suite%check(allocated(err), 'a kind without a name is refused')
    call unnamed%init(def, err)
    call suite%check(allocated(err) .and. unnamed%n_nodes == 0, 'init refuses a kind without a name')
    call suite%equal_int(catalogue%size(), 10, 'refused kinds are not added')
  end subroutine check_registration

  pure integer function index_of(text, part) result(i)
    character(len=*), intent(in) :: text, part
    i = index(text, part)
  end function index_of

  ! ---------------------------------------------------------------- rules

  !> The rules as CalculiX's gauss.f lists them (values printed with 15 digits there).
  subroutine check_rules(suite)
    type(test_suite_t), intent(inout) :: suite
    type(quadrature_rule_t) :: rule
    real(dp), parameter :: CCX = 1.0e-14_dp
    rule = tetrahedron_rule(4)
    call suite%close_to(rule%points(1, 1), 0.138196601125011_dp, CCX, 'gauss3d5 a')
    call suite%close_to(rule%points(1, 2), 0.585410196624968_dp, CCX, 'gauss3d5 b')
    call suite%close_to(rule%weights(4), 0.041666666666667_dp, CCX, 'weight3d5')
    rule = wedge_rule(2)
    call suite%close_to(rule%points(3, 1), -0.577350269189626_dp, CCX, 'gauss3d7 zeta')
    call suite%close_to(rule%points(1, 2), 0.333333333333333_dp, CCX, 'gauss3d7 xi')
    call suite%close_to(rule%weights(2), 0.5_dp, CCX, 'weight3d7')
    rule = wedge_rule(9)
    call suite%close_to(rule%points(1, 2), 0.666666666666667_dp, CCX, 'gauss3d8 point 2 xi')
    call suite%close_to(rule%points(3, 9), 0.774596669241483_dp, CCX, 'gauss3d8 point 9 zeta')
    call suite%close_to(rule%weights(1), 0.092592592592593_dp, CCX, 'weight3d8(1)')
    call suite%close_to(rule%weights(5), 0.148148148148148_dp, CCX, 'weight3d8(5)')
    rule = gauss_cube(3)
    call suite%close_to(rule%points(1, 2), 0.0_dp, CCX, 'gauss3d3 point 2 xi', floor=1.0_dp)
    call suite%close_to(rule%points(2, 4), 0.0_dp, CCX, 'gauss3d3 point 4 eta', floor=1.0_dp)
    call suite%close_to(rule%points(1, 3), 0.774596669241483_dp, CCX, 'gauss3d3 point 3 xi')
    call suite%close_to(rule%weights(1), 0.171467764060357_dp, CCX, 'weight3d3(1)')
    call suite%close_to(rule%weights(14), 0.702331961591221_dp, CCX, 'weight3d3(14)')
    rule = gauss_cube(2)
    call suite%close_array(rule%points(:, 3), [-1.0_dp, 1.0_dp, -1.0_dp] * 0.577350269189626_dp, &
                           CCX, 'gauss3d2 point 3')
    rule = gauss_square(3)
    call suite%close_to(rule%weights(5), 0.790123456790123_dp, CCX, 'weight2d3(5)')
    rule = triangle_rule(3)
    call suite%close_array(rule%points(:, 3), [0.166666666666667_dp, 0.666666666666667_dp], &
                           CCX, 'gauss2d5 point 3')
    rule = gauss_line(4)
    call suite%equal_int(rule%n, 0, 'no 4-point line rule')
  end subroutine check_rules

  !> The kind's rule: weights sum to the reference volume, monomials exact to the claimed
  !> degree (for tensor rules per coordinate, for wedges in zeta), the next degree not exact.
  subroutine check_kind_rule(suite, kind)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    integer :: i, j, l, worst_exponent(3)
    real(dp) :: error, worst
    call suite%close_to(sum(kind%weight), kind%reference_volume, TIGHT, label(kind, 'sum of weights'))
    worst = 0.0_dp
    do i = 0, 5
      do j = 0, 5
        do l = 0, 5
          if (.not. claimed(kind, [i, j, l])) cycle
          error = abs(rule_sum(kind%point_xi, kind%weight, [i, j, l]) - &
                      exact_volume_integral(kind%topology, [i, j, l]))
          if (error > worst) then
            worst = error
            worst_exponent = [i, j, l]
          end if
        end do
      end do
    end do
    call suite%check(worst < TIGHT, label(kind, 'rule exact to its degree'))
    if (worst >= TIGHT) print '(a,3i2,es10.2)', '  worst monomial ', worst_exponent, worst
    ! x^(degree + 1) is not integrated exactly: the claimed degree is the rule's.
    i = kind%rule_degree + 1
    call suite%check(abs(rule_sum(kind%point_xi, kind%weight, [i, 0, 0]) - &
                         exact_volume_integral(kind%topology, [i, 0, 0])) > 1.0e-6_dp, &
                     label(kind, 'next degree not exact'))
  end subroutine check_kind_rule

  !> Whether the kind's rule claims to integrate monomial e exactly.
  pure logical function claimed(kind, e)
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: e(3)
    integer :: per_direction
    select case (kind%topology)
    case (TOPOLOGY_HEXAHEDRON)
      claimed = all(e <= kind%rule_degree)
    case (TOPOLOGY_TETRAHEDRON)
      claimed = sum(e) <= kind%rule_degree
    case default
      per_direction = merge(3, 5, kind%n_points == 2)
      claimed = e(1) + e(2) <= kind%rule_degree .and. e(3) <= per_direction
    end select
  end function claimed

  ! ---------------------------------------------------------------- sizes

  !> Counts as CalculiX defines the kinds (manual section 6.2, e_c3d.f, gauss.f).
  subroutine check_sizes(suite, kind)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    integer :: expected(5), face_points(6), topology, formulation, f
    select case (kind%name)
    case ('C3D4')
      expected = [4, 4, 1, 4, 4]
      face_points = 1
      topology = TOPOLOGY_TETRAHEDRON
    case ('C3D6')
      expected = [6, 6, 2, 5, 6]
      face_points = 1
      topology = TOPOLOGY_WEDGE
    case ('C3D8', 'C3D8I')
      expected = [8, 8, 8, 6, 5]
      face_points = 4
      topology = TOPOLOGY_HEXAHEDRON
    case ('C3D8R')
      expected = [8, 8, 1, 6, 5]
      face_points = 1
      topology = TOPOLOGY_HEXAHEDRON
    case ('C3D10')
      expected = [10, 4, 4, 4, 11]
      face_points = 3
      topology = TOPOLOGY_TETRAHEDRON
    case ('C3D15')
      expected = [15, 6, 9, 5, 18]
      face_points = [3, 3, 4, 4, 4, 0]
      topology = TOPOLOGY_WEDGE
    case ('C3D20')
      expected = [20, 8, 27, 6, 17]
      face_points = 9
      topology = TOPOLOGY_HEXAHEDRON
    case ('C3D20R')
      expected = [20, 8, 8, 6, 17]
      face_points = 4
      topology = TOPOLOGY_HEXAHEDRON
    case default
      call suite%check(.false., 'unexpected kind ' // kind%name)
      return
    end select
    formulation = FORMULATION_STANDARD
    if (kind%name == 'C3D8R') formulation = FORMULATION_HOURGLASS
    if (kind%name == 'C3D8I') formulation = FORMULATION_INCOMPATIBLE_MODES
    call suite%equal_int(kind%n_nodes, expected(1), label(kind, 'nodes'))
    call suite%equal_int(kind%n_corners, expected(2), label(kind, 'corners'))
    call suite%equal_int(kind%n_points, expected(3), label(kind, 'integration points'))
    call suite%equal_int(kind%n_faces, expected(4), label(kind, 'faces'))
    call suite%equal_int(kind%gmsh_type, expected(5), label(kind, 'gmsh type'))
    call suite%equal_int(kind%topology, topology, label(kind, 'topology'))
    call suite%equal_int(kind%formulation, formulation, label(kind, 'formulation'))
    call suite%equal_int(kind%n_check, kind%n_points + kind%n_nodes, label(kind, 'check points'))
    call suite%check(kind%n_nodes <= MAX_NODES .and. kind%n_points <= MAX_POINTS, &
                     label(kind, 'within the MAX_ bounds'))
    do f = 1, kind%n_faces
      call suite%equal_int(kind%faces(f)%n_points, face_points(f), &
                           face_label(kind, f, 'face integration points'))
      call suite%check(kind%faces(f)%n_points <= MAX_FACE_POINTS .and. &
                       kind%faces(f)%n_nodes <= MAX_FACE_NODES, face_label(kind, f, 'bounds'))
    end do
  end subroutine check_sizes

  ! ---------------------------------------------------------------- shape functions

  subroutine check_shape_functions(suite, kind)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    real(dp), parameter :: h = 1.0e-6_dp
    real(dp) :: xi(3), n(MAX_NODES), dn(3, MAX_NODES), plus(MAX_NODES), minus(MAX_NODES)
    real(dp) :: worst_unity, worst_sum, worst_delta, worst_fd, worst_table
    integer :: trial, a, i, q
    real(dp) :: step(3)
    worst_unity = 0.0_dp
    worst_sum = 0.0_dp
    worst_fd = 0.0_dp
    do trial = 1, 20
      xi = random_point(kind%topology)
      call kind%shape_values(xi, n)
      call kind%shape_derivatives(xi, dn)
      worst_unity = max(worst_unity, abs(sum(n(1:kind%n_nodes)) - 1.0_dp))
      do i = 1, 3
        worst_sum = max(worst_sum, abs(sum(dn(i, 1:kind%n_nodes))))
        step = 0.0_dp
        step(i) = h
        call kind%shape_values(xi + step, plus)
        call kind%shape_values(xi - step, minus)
        worst_fd = max(worst_fd, maxval(abs((plus(1:kind%n_nodes) - minus(1:kind%n_nodes)) / &
                                            (2.0_dp * h) - dn(i, 1:kind%n_nodes))))
      end do
    end do
    call suite%check(worst_unity < TIGHT, label(kind, 'partition of unity'))
    call suite%check(worst_sum < 1.0e-11_dp, label(kind, 'derivatives sum to zero'))
    call suite%check(worst_fd < 1.0e-8_dp, label(kind, 'derivatives against central differences'))
    worst_delta = 0.0_dp
    do a = 1, kind%n_nodes
      call kind%shape_values(kind%node_xi(:, a), n)
      n(a) = n(a) - 1.0_dp
      worst_delta = max(worst_delta, maxval(abs(n(1:kind%n_nodes))))
    end do
    call suite%check(worst_delta < TIGHT, label(kind, 'N_a(x_b) = delta_ab'))
    worst_table = 0.0_dp
    do q = 1, kind%n_points
      call kind%shape_values(kind%point_xi(:, q), n)
      call kind%shape_derivatives(kind%point_xi(:, q), dn)
      worst_table = max(worst_table, maxval(abs(n(1:kind%n_nodes) - kind%point_values(:, q))), &
                        maxval(abs(dn(:, 1:kind%n_nodes) - kind%point_derivatives(:, :, q))))
    end do
    call suite%check(worst_table < TIGHT, label(kind, 'tables at the points'))
  end subroutine check_shape_functions

  !> The shape functions against their closed forms (Zienkiewicz, Taylor & Zhu 2005; Dhondt
  !> 2004; the same formulas as CalculiX's shape*.f), at random points.
  subroutine check_closed_forms(suite, kind)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    real(dp) :: xi(3), n(MAX_NODES), expected(MAX_NODES), worst
    integer :: trial
    worst = 0.0_dp
    do trial = 1, 20
      xi = random_point(kind%topology)
      call kind%shape_values(xi, n)
      expected(1:kind%n_nodes) = closed_form(kind, xi)
      worst = max(worst, maxval(abs(n(1:kind%n_nodes) - expected(1:kind%n_nodes))))
    end do
    call suite%check(worst < TIGHT, label(kind, 'shape functions equal their closed forms'))
  end subroutine check_closed_forms

  function closed_form(kind, xi) result(n)
    type(element_kind_t), intent(in) :: kind
    real(dp), intent(in) :: xi(3)
    real(dp) :: n(kind%n_nodes)
    real(dp) :: l(4), s(3), z
    integer :: a, edges(2, 9), c
    select case (kind%topology)
    case (TOPOLOGY_HEXAHEDRON)
      do a = 1, kind%n_nodes
        s = kind%node_xi(:, a)
        if (kind%n_nodes == 8) then
          n(a) = 0.125_dp * product(1.0_dp + s * xi)
        else if (a <= 8) then
          n(a) = 0.125_dp * product(1.0_dp + s * xi) * (sum(s * xi) - 2.0_dp)
        else
          c = minloc(abs(s), 1)
          n(a) = 0.25_dp * (1.0_dp - xi(c)**2) * product(1.0_dp + s * xi, mask=[1, 2, 3] /= c)
        end if
      end do
    case (TOPOLOGY_TETRAHEDRON)
      l = [1.0_dp - sum(xi), xi(1), xi(2), xi(3)]
      if (kind%n_nodes == 4) then
        n = l
      else
        edges(:, 1:6) = reshape([1, 2, 2, 3, 3, 1, 1, 4, 2, 4, 3, 4], [2, 6])
        n(1:4) = l * (2.0_dp * l - 1.0_dp)
        do a = 1, 6
          n(4 + a) = 4.0_dp * l(edges(1, a)) * l(edges(2, a))
        end do
      end if
    case default
      l(1:3) = [1.0_dp - xi(1) - xi(2), xi(1), xi(2)]
      z = xi(3)
      if (kind%n_nodes == 6) then
        n(1:3) = 0.5_dp * l(1:3) * (1.0_dp - z)
        n(4:6) = 0.5_dp * l(1:3) * (1.0_dp + z)
      else
        n(1:3) = 0.5_dp * l(1:3) * (1.0_dp - z) * (2.0_dp * l(1:3) - 2.0_dp - z)
        n(4:6) = 0.5_dp * l(1:3) * (1.0_dp + z) * (2.0_dp * l(1:3) - 2.0_dp + z)
        edges(:, 1:3) = reshape([1, 2, 2, 3, 3, 1], [2, 3])
        do a = 1, 3
          n(6 + a) = 2.0_dp * l(edges(1, a)) * l(edges(2, a)) * (1.0_dp - z)
          n(9 + a) = 2.0_dp * l(edges(1, a)) * l(edges(2, a)) * (1.0_dp + z)
          n(12 + a) = l(a) * (1.0_dp - z * z)
        end do
      end if
    end select
  end function closed_form

  ! ---------------------------------------------------------------- geometry

  !> Isoparametric completeness on a distorted element: u = c + g.x interpolated exactly, its
  !> gradient exactly g, at random points and at the integration points; Jacobian checks.
  subroutine check_completeness(suite, kind)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    real(dp), parameter :: c = 0.7_dp, g(3) = [0.3_dp, -1.1_dp, 0.45_dp]
    real(dp) :: x(3, kind%n_nodes), u(kind%n_nodes), xi(3), n(MAX_NODES), grad(3, MAX_NODES)
    real(dp) :: det, point(3), worst_value, worst_gradient, mirrored(3, kind%n_nodes)
    integer :: trial, a, q
    x = distorted(kind)
    do a = 1, kind%n_nodes
      u(a) = c + dot_product(g, x(:, a))
    end do
    worst_value = 0.0_dp
    worst_gradient = 0.0_dp
    do trial = 1, 10
      xi = random_point(kind%topology)
      call kind%shape_values(xi, n)
      point = matmul(x, n(1:kind%n_nodes))
      worst_value = max(worst_value, abs(dot_product(n(1:kind%n_nodes), u) - c - dot_product(g, point)))
      call kind%gradients(xi, x, grad, det)
      worst_gradient = max(worst_gradient, maxval(abs(matmul(grad(:, 1:kind%n_nodes), u) - g)))
    end do
    do q = 1, kind%n_points
      call kind%point_gradients(q, x, grad, det)
      worst_gradient = max(worst_gradient, maxval(abs(matmul(grad(:, 1:kind%n_nodes), u) - g)))
      call suite%check(det > 0.0_dp, label(kind, 'det J > 0 at an integration point'))
    end do
    call suite%check(worst_value < TIGHT, label(kind, 'linear field interpolated exactly'))
    call suite%check(worst_gradient < 1.0e-11_dp, label(kind, 'linear field gradient exact'))
    call suite%close_to(kind%min_jacobian_ratio(kind%node_xi), 1.0_dp, TIGHT, &
                        label(kind, 'Jacobian ratio of the reference element'))
    call suite%close_to(kind%volume(kind%node_xi), kind%reference_volume, TIGHT, &
                        label(kind, 'volume of the reference element'))
    call suite%check(kind%min_jacobian_ratio(x) > 0.5_dp, label(kind, 'distorted element accepted'))
    mirrored = x
    mirrored(1, :) = -mirrored(1, :)
    call suite%check(kind%min_jacobian_ratio(mirrored) < 0.0_dp, &
                     label(kind, 'inverted element refused'))
    call suite%close_array(reshape(kind%jacobian(random_point(kind%topology), kind%node_xi), [9]), &
                           reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, &
                                    0.0_dp, 1.0_dp], [9]), TIGHT, &
                           label(kind, 'Jacobian of the reference element'))
  end subroutine check_completeness

  ! ---------------------------------------------------------------- faces

  !> The corner nodes of face f as the CalculiX manual lists them (section 6.2).
  function manual_face_corners(kind, f) result(nodes)
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: f
    integer, allocatable :: nodes(:)
    integer, parameter :: HEX(4, 6) = reshape([1, 2, 3, 4, 5, 8, 7, 6, 1, 5, 6, 2, 2, 6, 7, 3, &
                                               3, 7, 8, 4, 4, 8, 5, 1], [4, 6])
    integer, parameter :: TET(3, 4) = reshape([1, 2, 3, 1, 4, 2, 2, 4, 3, 3, 4, 1], [3, 4])
    integer, parameter :: WEDGE(4, 5) = reshape([1, 2, 3, 0, 4, 5, 6, 0, 1, 2, 5, 4, 2, 3, 6, 5, &
                                                 3, 1, 4, 6], [4, 5])
    select case (kind%topology)
    case (TOPOLOGY_HEXAHEDRON)
      nodes = HEX(:, f)
    case (TOPOLOGY_TETRAHEDRON)
      nodes = TET(:, f)
    case default
      nodes = pack(WEDGE(:, f), WEDGE(:, f) > 0)
    end select
  end function manual_face_corners

  subroutine check_faces(suite, kind)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    integer :: f
    do f = 1, kind%n_faces
      call check_face_nodes(suite, kind, f)
      call check_face_geometry(suite, kind, f)
      call check_face_restriction(suite, kind, f)
      call check_face_rule(suite, kind, f)
    end do
  end subroutine check_faces

  !> Node list: right count and kind, distinct, corners first (the corners of the manual's
  !> face, in the same cycle), mid-side node k between face corners k and k+1.
  subroutine check_face_nodes(suite, kind, f)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: f
    integer :: nf, nc, k, expected_id
    integer, allocatable :: nodes(:), manual(:)
    logical :: distinct, midpoints, same_cycle
    associate (face => kind%faces(f))
      nf = face%n_nodes
      nc = face%n_corners
      nodes = face%nodes(1:nf)
      if (nc == 4) then
        expected_id = merge(FACE_QUAD8, FACE_QUAD4, kind%n_nodes > kind%n_corners)
      else
        expected_id = merge(FACE_TRI6, FACE_TRI3, kind%n_nodes > kind%n_corners)
      end if
      call suite%equal_int(face%id, expected_id, face_label(kind, f, 'face kind'))
      distinct = .true.
      do k = 1, nf
        distinct = distinct .and. count(nodes == nodes(k)) == 1
      end do
      call suite%check(distinct .and. all(nodes >= 1) .and. all(nodes <= kind%n_nodes), &
                       face_label(kind, f, 'distinct element nodes'))
      call suite%check(all(nodes(1:nc) <= kind%n_corners) .and. all(nodes(nc + 1:) > kind%n_corners), &
                       face_label(kind, f, 'corners first'))
      ! The manual's cycle of corners, read either way round, starting anywhere (the manual
      ! gives node sets; their orientation varies, the outward check is geometric).
      manual = manual_face_corners(kind, f)
      same_cycle = .false.
      do k = 0, nc - 1
        same_cycle = same_cycle .or. all(nodes(1:nc) == cshift(manual, k)) .or. &
                     all(nodes(1:nc) == cshift(manual(nc:1:-1), k))
      end do
      call suite%check(same_cycle, face_label(kind, f, 'corners are the manual''s face'))
      midpoints = .true.
      do k = 1, nf - nc
        midpoints = midpoints .and. all(abs(kind%node_xi(:, nodes(nc + k)) - 0.5_dp * &
          (kind%node_xi(:, nodes(k)) + kind%node_xi(:, nodes(mod(k, nc) + 1)))) < TIGHT)
      end do
      call suite%check(midpoints, face_label(kind, f, 'mid-side nodes between their corners'))
    end associate
  end subroutine check_face_nodes

  !> Outward area vectors at the face points of a distorted element; face area on the
  !> reference element (flat faces: the polygon area of the corners).
  subroutine check_face_geometry(suite, kind, f)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: f
    real(dp) :: x(3, kind%n_nodes), centre(3), n(MAX_NODES), a(3), m(MAX_FACE_NODES), xf(3)
    real(dp) :: area, polygon(3), corners(3, 4)
    logical :: outward
    integer :: q, nf, nc, k
    associate (face => kind%faces(f))
      nf = face%n_nodes
      nc = face%n_corners
      x = distorted(kind)
      call kind%shape_values(sum(kind%node_xi(:, 1:kind%n_corners), 2) / kind%n_corners, n)
      centre = matmul(x, n(1:kind%n_nodes))
      outward = .true.
      do q = 1, face%n_points
        a = face%area_vector(x(:, face%nodes(1:nf)), face%point_st(:, q))
        call face%shape_values(face%point_st(:, q), m)
        xf = matmul(x(:, face%nodes(1:nf)), m(1:nf))
        outward = outward .and. dot_product(a, xf - centre) > 0.0_dp
      end do
      call suite%check(outward, face_label(kind, f, 'area vector points outward'))
      area = 0.0_dp
      do q = 1, face%n_points
        a = face%area_vector(kind%node_xi(:, face%nodes(1:nf)), face%point_st(:, q))
        area = area + norm2(a) * face%weight(q)
      end do
      corners(:, 1:nc) = kind%node_xi(:, face%nodes(1:nc))
      polygon = 0.0_dp
      do k = 1, nc
        polygon = polygon + cross(corners(:, k), corners(:, mod(k, nc) + 1))
      end do
      call suite%close_to(area, 0.5_dp * norm2(polygon), TIGHT, face_label(kind, f, 'face area'))
    end associate
  end subroutine check_face_geometry

  !> On the face, the volume shape functions of the face nodes equal the face shape functions
  !> and the others vanish.
  subroutine check_face_restriction(suite, kind, f)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: f
    real(dp) :: st(2), n(MAX_NODES), m(MAX_FACE_NODES), worst
    logical :: on_face(MAX_NODES)
    integer :: trial, nf, k
    associate (face => kind%faces(f))
      nf = face%n_nodes
      on_face = .false.
      on_face(face%nodes(1:nf)) = .true.
      worst = 0.0_dp
      do trial = 1, 10
        st = random_face_point(face%n_corners)
        call kind%shape_values(kind%face_xi(f, st), n)
        call face%shape_values(st, m)
        do k = 1, nf
          worst = max(worst, abs(n(face%nodes(k)) - m(k)))
        end do
        worst = max(worst, maxval(abs(n(1:kind%n_nodes)), mask=.not. on_face(1:kind%n_nodes)))
      end do
      call suite%check(worst < TIGHT, face_label(kind, f, 'face shape functions restrict the &
                       &volume ones'))
    end associate
  end subroutine check_face_restriction

  !> Face rule exact for the face polynomials: triangles to the rule's degree (1 or 2),
  !> squares per coordinate to 2n - 1; face tables consistent.
  subroutine check_face_rule(suite, kind, f)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: f
    integer :: i, j, n_line, degree
    real(dp) :: worst, m(MAX_FACE_NODES), dm(2, MAX_FACE_NODES), table
    integer :: q
    associate (face => kind%faces(f))
      call suite%close_to(sum(face%weight), face%reference_area, TIGHT, &
                          face_label(kind, f, 'face weights sum to the reference area'))
      worst = 0.0_dp
      if (face%n_corners == 4) then
        n_line = nint(sqrt(real(face%n_points, dp)))
        do i = 0, 2 * n_line - 1
          do j = 0, 2 * n_line - 1
            worst = max(worst, abs(rule_sum(face%point_st, face%weight, [i, j]) - &
                                   exact_face_integral(4, [i, j])))
          end do
        end do
      else
        degree = merge(1, 2, face%n_points == 1)
        do i = 0, degree
          do j = 0, degree - i
            worst = max(worst, abs(rule_sum(face%point_st, face%weight, [i, j]) - &
                                   exact_face_integral(3, [i, j])))
          end do
        end do
      end if
      call suite%check(worst < TIGHT, face_label(kind, f, 'face rule exact to its degree'))
      table = 0.0_dp
      do q = 1, face%n_points
        call face%shape_values(face%point_st(:, q), m)
        call face%shape_derivatives(face%point_st(:, q), dm)
        table = max(table, maxval(abs(m(1:face%n_nodes) - face%point_values(:, q))), &
                    maxval(abs(dm(:, 1:face%n_nodes) - face%point_derivatives(:, :, q))))
      end do
      call suite%check(table < TIGHT, face_label(kind, f, 'face tables'))
    end associate
  end subroutine check_face_rule

  ! ---------------------------------------------------------------- extrapolation

  !> Rows sum to one; linear fields reproduced at the nodes (one point: constants; C3D6:
  !> fields linear in zeta, its two points lying on the wedge's axis); C3D20: fields of its
  !> own basis (a quadratic serendipity field).
  subroutine check_extrapolation(suite, kind)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    real(dp) :: g(3), at_points(1, MAX_POINTS), at_nodes(1, MAX_NODES), expected(MAX_NODES)
    integer :: q, a
    call suite%close_array(sum(kind%extrapolation, 2), [(1.0_dp, a = 1, kind%n_nodes)], TIGHT, &
                           label(kind, 'extrapolation rows sum to one'))
    g = [0.4_dp, -0.25_dp, 0.9_dp]
    if (kind%n_points == 1) g = 0.0_dp
    if (kind%name == 'C3D6') g(1:2) = 0.0_dp
    do q = 1, kind%n_points
      at_points(1, q) = 1.5_dp + dot_product(g, kind%point_xi(:, q))
    end do
    do a = 1, kind%n_nodes
      expected(a) = 1.5_dp + dot_product(g, kind%node_xi(:, a))
    end do
    call kind%extrapolate(at_points(:, 1:kind%n_points), at_nodes)
    call suite%close_array(at_nodes(1, 1:kind%n_nodes), expected(1:kind%n_nodes), TIGHT, &
                           label(kind, 'extrapolation reproduces linear fields'))
    if (kind%name /= 'C3D20') return
    do q = 1, kind%n_points
      at_points(1, q) = quadratic(kind%point_xi(:, q))
    end do
    do a = 1, kind%n_nodes
      expected(a) = quadratic(kind%node_xi(:, a))
    end do
    call kind%extrapolate(at_points(:, 1:kind%n_points), at_nodes)
    call suite%close_array(at_nodes(1, 1:kind%n_nodes), expected(1:kind%n_nodes), 1.0e-11_dp, &
                           label(kind, 'extrapolation reproduces serendipity fields'))
  end subroutine check_extrapolation

  pure real(dp) function quadratic(xi)
    real(dp), intent(in) :: xi(3)
    quadratic = 1.0_dp + xi(1)**2 - 0.5_dp * xi(2) * xi(3) + 0.3_dp * xi(1)**2 * xi(2) - &
                0.7_dp * xi(1) * xi(2) * xi(3)**2
  end function quadratic

  !> Entries of CalculiX's extrapolation tables (extrapolate.f: a8, a4, a9, a27, printed there
  !> with 4 or 5 digits): node 1 from point 1 and a mid-side or far entry.
  subroutine check_calculix_tables(suite, catalogue)
    type(test_suite_t), intent(inout) :: suite
    type(element_catalogue_t), intent(in) :: catalogue
    real(dp), parameter :: DIGITS5 = 6.0e-6_dp, DIGITS4 = 6.0e-4_dp
    associate (c3d8 => catalogue%kinds(catalogue%find('C3D8')), &
               c3d10 => catalogue%kinds(catalogue%find('C3D10')), &
               c3d15 => catalogue%kinds(catalogue%find('C3D15')), &
               c3d20 => catalogue%kinds(catalogue%find('C3D20')), &
               c3d20r => catalogue%kinds(catalogue%find('C3D20R')))
      call suite%close_to(c3d8%extrapolation(1, 1), 2.549_dp, DIGITS4, 'ccx a8(1,1)', floor=1.0_dp)
      call suite%close_to(c3d8%extrapolation(1, 8), -0.04904_dp, DIGITS5, 'ccx a8(1,8)', floor=1.0_dp)
      call suite%close_to(c3d8%extrapolation(1, 2), -0.683_dp, DIGITS4, 'ccx a8(1,2)', floor=1.0_dp)
      call suite%close_array(reshape(c3d20r%extrapolation(1:8, :), [64]), &
                             reshape(c3d8%extrapolation, [64]), TIGHT, &
                             'C3D20R corners extrapolate as C3D8')
      call suite%close_to(c3d10%extrapolation(1, 1), 1.92705_dp, DIGITS5, 'ccx a4(1,1)', floor=1.0_dp)
      call suite%close_to(c3d10%extrapolation(1, 2), -0.30902_dp, DIGITS5, 'ccx a4(1,2)', floor=1.0_dp)
      call suite%close_to(c3d15%extrapolation(1, 1), 1.63138_dp, DIGITS5, 'ccx a9(1,1)', floor=1.0_dp)
      call suite%close_to(c3d15%extrapolation(4, 1), -0.52027_dp, DIGITS5, 'ccx a9(4,1)', floor=1.0_dp)
      call suite%close_to(c3d15%extrapolation(1, 4), 0.55556_dp, DIGITS5, 'ccx a9(1,4)', floor=1.0_dp)
      call suite%close_to(c3d20%extrapolation(1, 1), 2.37499_dp, DIGITS5, 'ccx a27(1,1)', floor=1.0_dp)
      call suite%close_to(c3d20%extrapolation(9, 1), 0.32628_dp, DIGITS5, 'ccx a27(9,1)', floor=1.0_dp)
      call suite%close_to(c3d20%extrapolation(7, 1), 0.11575_dp, DIGITS5, 'ccx a27(7,1)', floor=1.0_dp)
    end associate
  end subroutine check_calculix_tables

  ! ---------------------------------------------------------------- gmsh

  !> gmsh's reference nodes (gmsh manual, "Node ordering"; the coordinates of single elements
  !> meshed by gmsh 4.8.4) permuted by gmsh_order land on CalculiX's nodes.
  subroutine check_gmsh_order(suite, kind)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    real(dp), parameter :: HEX(3, 20) = reshape([ &
      -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1, &
      0, -1, -1, -1, 0, -1, -1, -1, 0, 1, 0, -1, 1, -1, 0, 0, 1, -1, 1, 1, 0, -1, 1, 0, &
      0, -1, 1, -1, 0, 1, 1, 0, 1, 0, 1, 1], [3, 20])
    real(dp), parameter :: TET(3, 10) = reshape([ &
      0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, &
      0.5_dp, 0.0_dp, 0.0_dp, 0.5_dp, 0.5_dp, 0.0_dp, 0.0_dp, 0.5_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.5_dp, &
      0.0_dp, 0.5_dp, 0.5_dp, 0.5_dp, 0.0_dp, 0.5_dp], [3, 10])
    real(dp), parameter :: PRISM(3, 15) = reshape([ &
      0.0_dp, 0.0_dp, -1.0_dp, 1.0_dp, 0.0_dp, -1.0_dp, 0.0_dp, 1.0_dp, -1.0_dp, &
      0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, &
      0.5_dp, 0.0_dp, -1.0_dp, 0.0_dp, 0.5_dp, -1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
      0.5_dp, 0.5_dp, -1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
      0.5_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.5_dp, 1.0_dp, 0.5_dp, 0.5_dp, 1.0_dp], [3, 15])
    real(dp) :: gmsh(3, MAX_NODES)
    integer :: a
    logical :: permutation
    select case (kind%topology)
    case (TOPOLOGY_HEXAHEDRON)
      gmsh(:, 1:20) = HEX
    case (TOPOLOGY_TETRAHEDRON)
      gmsh(:, 1:10) = TET
    case default
      gmsh(:, 1:15) = PRISM
    end select
    permutation = size(kind%gmsh_order) == kind%n_nodes
    do a = 1, kind%n_nodes
      permutation = permutation .and. count(kind%gmsh_order == a) == 1
    end do
    call suite%check(permutation, label(kind, 'gmsh order is a permutation'))
    if (.not. permutation) return
    call suite%check(all(abs(gmsh(:, kind%gmsh_order) - kind%node_xi) < TIGHT), &
                     label(kind, 'gmsh nodes land on CalculiX''s'))
  end subroutine check_gmsh_order

  ! ---------------------------------------------------------------- formulations

  subroutine check_formulation(suite, kind)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: kind
    real(dp) :: expected(3, 3), centre(3, MAX_NODES), gram(4, 4)
    integer :: q, m, i
    logical :: ok
    select case (kind%formulation)
    case (FORMULATION_INCOMPATIBLE_MODES)
      call suite%equal_int(kind%n_modes, 3, label(kind, 'three incompatible modes'))
      ok = .true.
      do q = 1, kind%n_points
        expected = 0.0_dp
        do m = 1, 3
          expected(m, m) = -2.0_dp * kind%point_xi(m, q)
        end do
        ok = ok .and. all(abs(kind%mode_derivatives(:, :, q) - expected) < TIGHT)
      end do
      call suite%check(ok, label(kind, 'mode derivatives d(1 - xi_m^2)/dxi_i'))
      call kind%shape_derivatives([0.0_dp, 0.0_dp, 0.0_dp], centre)
      call suite%check(all(abs(kind%centre_derivatives - centre(:, 1:8)) < TIGHT), &
                       label(kind, 'derivatives at the centre'))
    case (FORMULATION_HOURGLASS)
      call suite%equal_int(kind%n_hourglass, 4, label(kind, 'four hourglass vectors'))
      ok = all(abs(sum(kind%hourglass_base, 1)) < TIGHT)
      do i = 1, 3
        ok = ok .and. all(abs(matmul(kind%node_xi(i, :), kind%hourglass_base)) < TIGHT)
      end do
      call suite%check(ok, label(kind, 'hourglass vectors orthogonal to linear fields'))
      gram = matmul(transpose(kind%hourglass_base), kind%hourglass_base)
      call suite%close_array(reshape(gram, [16]), reshape(8.0_dp * identity4(), [16]), TIGHT, &
                             label(kind, 'hourglass vectors orthogonal, length sqrt(8)'))
    case default
      call suite%check(kind%n_modes == 0 .and. kind%n_hourglass == 0, label(kind, 'no extra tables'))
    end select
  end subroutine check_formulation

  pure function identity4() result(id)
    real(dp) :: id(4, 4)
    integer :: i
    id = 0.0_dp
    do i = 1, 4
      id(i, i) = 1.0_dp
    end do
  end function identity4

  ! ---------------------------------------------------------------- today's hex8

  !> C3D8 through the kind interface agrees with today's hex8 modules: gradients and volume
  !> weights at the 8 points, extrapolation, and the face node sets of HEX8_FACE_LOCAL_NODES
  !> (same outward cycle; fcs_mesh starts S1 at node 1, CalculiX at node 4).
  subroutine check_against_hex8(suite, catalogue)
    type(test_suite_t), intent(inout) :: suite
    type(element_catalogue_t), intent(in) :: catalogue
    type(hex8_geometry_t) :: geo
    real(dp) :: x(3, 8), grad(3, MAX_NODES), det, values(2, 8), node_values(2, MAX_NODES)
    logical :: ok, same_cycle
    integer :: q, f, k
    associate (c3d8 => catalogue%kinds(catalogue%find('C3D8')))
      x = distorted(c3d8)
      call hex8_geometry(x, geo, ok)
      call suite%check(ok, 'hex8_geometry accepts the distorted element')
      do q = 1, 8
        call c3d8%point_gradients(q, x, grad, det)
        call suite%close_array(reshape(grad(:, 1:8), [24]), reshape(geo%grad(:, :, q), [24]), &
                               TIGHT, 'C3D8 gradients = hex8_geometry')
        call suite%close_to(det * c3d8%weight(q), geo%dv(q), TIGHT, 'C3D8 det J w = hex8 dv')
      end do
      call random_number(values)
      call c3d8%extrapolate(values, node_values)
      call suite%close_array(reshape(node_values(:, 1:8), [16]), &
                             reshape(hex8_extrapolate(values), [16]), TIGHT, &
                             'C3D8 extrapolation = hex8_extrapolate')
      do f = 1, 6
        same_cycle = .false.
        do k = 0, 3
          same_cycle = same_cycle .or. all(c3d8%faces(f)%nodes(1:4) == &
                                           cshift(HEX8_FACE_LOCAL_NODES(:, f), k))
        end do
        call suite%check(same_cycle, face_label(c3d8, f, 'same cycle as HEX8_FACE_LOCAL_NODES'))
      end do
    end associate
  end subroutine check_against_hex8

end program test_fcs_element_kinds
