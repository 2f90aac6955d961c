!> Unit tests of the node-to-point contact element on master segments of gamma = 3, 4, 6 and 8
!> nodes (TRI3, QUAD4, TRI6, QUAD8; Xing, Mora & Makinouchi 2003, eqs. 6-9 with the segment's
!> own shape functions and metric):
!>   - the closed-form face shape functions (fcs_face_kind) against the kinds' polynomial bases,
!>     and their second derivatives against central differences of the first;
!>   - projection of a point built as x(xi0) + g n(xi0) on a distorted, curved segment (inside:
!>     Newton returns xi0 and g), on an edge (zero edge excess; the search takes it as inside)
!>     and outside (past a free edge: no contact point; past a shared edge: the clamped edge
!>     point);
!>   - the consistent tangent K_f = -dF/du against central differences of the return-mapping
!>     update, stick and slip, on each kind;
!>   - slave areas: the shares of a flat face sum to its area, TRI6 corners get none and QUAD8
!>     CalculiX's 1/100 and 24/100.
program test_fcs_contact_segments
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_test_assertions, only: test_suite_t
  use fcs_face_kind, only: face_kind_t, face_shape_functions, FACE_TRI3, FACE_TRI6, FACE_QUAD4, &
                           FACE_QUAD8
  use fcs_contact_geometry, only: segment_point_t, segment_point, project_to_segment, segment_centre
  use fcs_contact_search, only: closest_face, edge_excess, XI_TOLERANCE
  use fcs_contact_areas, only: face_node_areas
  use fcs_contact_element, only: contact_linear_t, contact_linearise, contact_update, &
                                 contact_update_t, contact_node_t, contact_params_t, &
                                 CONTACT_STICK, CONTACT_SLIP
  use fcs_friction_law, only: friction_derivatives_t
  use fcs_coulomb, only: coulomb_t
  implicit none
  type(test_suite_t) :: suite
  real(dp), parameter :: AREA = 0.7_dp, EN = 300.0_dp, ET = 200.0_dp, MU = 0.4_dp
  type(contact_params_t), parameter :: PARAMS = contact_params_t(AREA, EN, ET)
  type(coulomb_t), parameter :: COULOMB = coulomb_t(mu0=MU)
  integer, parameter :: KINDS(4) = [FACE_TRI3, FACE_QUAD4, FACE_TRI6, FACE_QUAD8]
  integer :: k, seed_size, seed_index
  suite%name = 'contact_segments'
  call random_seed(size=seed_size)
  call random_seed(put=[(7919 * seed_index + 104729, seed_index = 1, seed_size)])
  do k = 1, size(KINDS)
    call test_shape_functions(suite, KINDS(k))
    call test_projection(suite, KINDS(k))
    call test_tangent(suite, KINDS(k), CONTACT_STICK, 'stick')
    call test_tangent(suite, KINDS(k), CONTACT_SLIP, 'slip')
    call test_areas(suite, KINDS(k))
  end do
  call suite%report()

contains

  function kind_of(id) result(face)
    integer, intent(in) :: id
    type(face_kind_t) :: face
    type(error_t), allocatable :: err
    call face%init(id, err)
    if (allocated(err)) error stop 1
  end function kind_of

  !> A distorted, curved segment of kind id: the reference nodes mapped to a tilted, warped
  !> surface, the nodes moved off their regular places (mid-side nodes off the mid-points).
  function distorted_segment(id) result(xm)
    integer, intent(in) :: id
    real(dp), allocatable :: xm(:, :)
    type(face_kind_t) :: face
    real(dp) :: s, t
    integer :: a
    face = kind_of(id)
    allocate (xm(3, face%n_nodes))
    do a = 1, face%n_nodes
      s = face%node_st(1, a)
      t = face%node_st(2, a)
      xm(:, a) = [1.1_dp * s + 0.15_dp * t, 0.1_dp * s + 0.9_dp * t, 0.2_dp * s * t + 0.1_dp * s * s - 0.1_dp * t] + &
                 0.04_dp * [sin(3.0_dp * a), cos(5.0_dp * a), sin(7.0_dp * a)]
    end do
  end function distorted_segment

  !> A natural point well inside the segment, one on its first edge (nodes 1-2) and one past
  !> its second edge (nodes 2-3, by 0.3 of the span).
  subroutine sample_points(id, inside, on_edge, outside)
    integer, intent(in) :: id
    real(dp), intent(out) :: inside(2), on_edge(2), outside(2)
    if (id == FACE_TRI3 .or. id == FACE_TRI6) then
      inside = [0.3_dp, 0.25_dp]
      on_edge = [0.4_dp, 0.0_dp]
      outside = [0.6_dp, 0.55_dp]
    else
      inside = [0.2_dp, -0.3_dp]
      on_edge = [0.3_dp, -1.0_dp]
      outside = [1.3_dp, 0.1_dp]
    end if
  end subroutine sample_points

  subroutine test_shape_functions(suite, id)
    type(test_suite_t), intent(inout) :: suite
    integer, intent(in) :: id
    type(face_kind_t) :: face
    real(dp) :: st(2), m(8), dm(2, 8), ddm(3, 8), mb(8), dmb(2, 8), mp(8), dmp(2, 8), ddp(3, 8), &
                mm(8), dmm(2, 8), fd(3, 8)
    real(dp), parameter :: H = 1.0e-5_dp
    integer :: n
    face = kind_of(id)
    n = face%n_nodes
    st = [0.23_dp, 0.31_dp]
    call face_shape_functions(n, st, m, dm, ddm)
    call face%shape_values(st, mb(1:n))
    call face%shape_derivatives(st, dmb(:, 1:n))
    call suite%close_array(m(1:n), mb(1:n), 1.0e-13_dp, face%name // ' closed-form shape functions = basis')
    call suite%close_array(reshape(dm(:, 1:n), [2 * n]), reshape(dmb(:, 1:n), [2 * n]), 1.0e-13_dp, &
                           face%name // ' closed-form derivatives = basis')
    call suite%close_to(sum(m(1:n)), 1.0_dp, 1.0e-14_dp, face%name // ' partition of unity')
    call face_shape_functions(n, st + [H, 0.0_dp], mp, dmp, ddp)
    call face_shape_functions(n, st - [H, 0.0_dp], mm, dmm, ddp)
    fd(1, 1:n) = (dmp(1, 1:n) - dmm(1, 1:n)) / (2 * H)
    fd(3, 1:n) = (dmp(2, 1:n) - dmm(2, 1:n)) / (2 * H)
    call face_shape_functions(n, st + [0.0_dp, H], mp, dmp, ddp)
    call face_shape_functions(n, st - [0.0_dp, H], mm, dmm, ddp)
    fd(2, 1:n) = (dmp(2, 1:n) - dmm(2, 1:n)) / (2 * H)
    ! Central differences of quadratics are exact up to round-off ~1e-16/H.
    call suite%close_array(reshape(ddm(:, 1:n), [3 * n]), reshape(fd(:, 1:n), [3 * n]), 1.0e-8_dp, &
                           face%name // ' second derivatives = differences of the first')
  end subroutine test_shape_functions

  subroutine test_projection(suite, id)
    type(test_suite_t), intent(inout) :: suite
    integer, intent(in) :: id
    real(dp), allocatable :: xm(:, :)
    real(dp) :: inside(2), on_edge(2), outside(2), xs(3), gap, excess(4)
    type(segment_point_t) :: p0, p
    type(face_kind_t) :: face
    logical :: converged, free(4, 1)
    integer :: n, found
    integer, allocatable :: nodes(:, :)
    face = kind_of(id)
    n = face%n_nodes
    xm = distorted_segment(id)
    call sample_points(id, inside, on_edge, outside)
    ! Inside: the point x(xi0) - 0.05 n(xi0) projects back to xi0 with gap -0.05.
    p0 = segment_point(xm, inside)
    xs = p0%x - 0.05_dp * p0%normal
    call project_to_segment(xm, xs, segment_centre(n), p, gap, converged)
    call suite%check(converged, face%name // ' projection converges (inside)')
    call suite%close_array(p%xi, inside, 1.0e-10_dp, face%name // ' projection returns xi0 (inside)')
    call suite%close_to(gap, -0.05_dp, 1.0e-10_dp, face%name // ' gap = -0.05 (inside)')
    call suite%close_to(dot_product(xs - p%x, p%a(:, 1)), 0.0_dp, 1.0e-12_dp, face%name // &
                        ' x_s - x(xi) orthogonal to a_1', floor=1.0_dp)
    call suite%close_to(dot_product(xs - p%x, p%a(:, 2)), 0.0_dp, 1.0e-12_dp, face%name // &
                        ' x_s - x(xi) orthogonal to a_2', floor=1.0_dp)
    ! On an edge: zero edge excess there; the search takes the face (inside).
    allocate (nodes(n, 1))
    nodes(:, 1) = [(found, found = 1, n)]
    p0 = segment_point(xm, on_edge)
    xs = p0%x + 0.02_dp * p0%normal
    call project_to_segment(xm, xs, segment_centre(n), p, gap, converged)
    excess = edge_excess(p%xi, n)
    call suite%check(converged .and. abs(excess(1)) <= 1.0e-10_dp, face%name // ' on edge 1: excess 0')
    free = .true.
    call closest_face(nodes, xm, [1], xs, 1.0_dp, found, p, gap, free)
    call suite%check(found == 1 .and. abs(gap - 0.02_dp) <= 1.0e-10_dp, face%name // &
                     ' on an edge: inside the face, gap 0.02')
    ! Outside, past edge 2 by 0.3 of the span: no contact point past a free edge; past a
    ! shared edge (a convex kink) the clamped point on the edge.
    p0 = segment_point(xm, outside)
    xs = p0%x - 0.01_dp * p0%normal
    call project_to_segment(xm, xs, segment_centre(n), p, gap, converged)
    excess = edge_excess(p%xi, n)
    call suite%check(converged .and. excess(2) > 0.2_dp, face%name // ' outside: past edge 2')
    call closest_face(nodes, xm, [1], xs, 1.0_dp, found, p, gap, free, extend=.true.)
    call suite%check(found == 0, face%name // ' outside past a free edge: no contact point')
    free = .false.
    call closest_face(nodes, xm, [1], xs, 1.0_dp, found, p, gap, free)
    excess = edge_excess(p%xi, n)
    call suite%check(found == 1 .and. abs(excess(2)) <= 1.0e-12_dp .and. all(excess <= 1.0e-12_dp), &
                     face%name // ' outside past a shared edge: the clamped edge point')
    call suite%close_to(gap, dot_product(xs - p%x, p%normal), 1.0e-12_dp, face%name // &
                        ' clamped point: gap along its normal')
    call suite%check(XI_TOLERANCE < 1.0e-3_dp, 'edge tolerance is small')
  end subroutine test_projection

  !> Nodal forces after moving the 1 + gamma nodes by du (the stepper's update, eq. 5).
  function forces_after(xm, xs, xi0, ft0, status, du) result(f)
    real(dp), intent(in) :: xm(:, :), xs(3), xi0(2), ft0(2), du(:)
    integer, intent(in) :: status
    real(dp) :: f(size(du))
    real(dp) :: xm_new(3, size(xm, 2)), xs_new(3), gap, total(3)
    type(segment_point_t) :: p, p_old
    type(contact_update_t) :: u
    logical :: converged
    integer :: i
    xs_new = xs + du(1:3)
    xm_new = xm + reshape(du(4:), [3, size(xm, 2)])
    call project_to_segment(xm_new, xs_new, xi0, p, gap, converged)
    p_old = segment_point(xm_new, xi0)
    u = contact_update(p, gap, p_old, contact_node_t(status, 0.0_dp, ft0, 0.0_dp, 0.0_dp, 0.0_dp), &
                       PARAMS, COULOMB, 1.0_dp)
    total = u%normal_force * p%normal + u%friction(1) * p%e(:, 1) + u%friction(2) * p%e(:, 2)
    f(1:3) = total
    do i = 1, size(xm, 2)
      f(3 * i + 1:3 * i + 3) = -p%shape(i) * total
    end do
  end function forces_after

  subroutine test_tangent(suite, id, status, label)
    type(test_suite_t), intent(inout) :: suite
    integer, intent(in) :: id, status
    character(len=*), intent(in) :: label
    real(dp), allocatable :: xm(:, :), v(:), fd(:)
    real(dp) :: xs(3), gap, fn, ft(2), trial_norm, ft_returned(2), inside(2), on_edge(2), outside(2)
    real(dp), parameter :: EPS = 1.0e-6_dp
    type(segment_point_t) :: p
    type(contact_linear_t) :: lin
    type(friction_derivatives_t) :: fr
    type(face_kind_t) :: face
    logical :: converged
    integer :: nd
    face = kind_of(id)
    xm = distorted_segment(id)
    call sample_points(id, inside, on_edge, outside)
    p = segment_point(xm, inside)
    xs = p%x - 0.03_dp * p%normal
    call project_to_segment(xm, xs, segment_centre(face%n_nodes), p, gap, converged)
    fn = EN * AREA * (-gap)
    ft = [0.3_dp, -0.2_dp] * MU * fn
    if (status == CONTACT_SLIP) ft = [0.9_dp, -0.6_dp] * MU * fn
    trial_norm = norm2(ft)
    ft_returned = ft
    if (status == CONTACT_SLIP) ft_returned = MU * fn * ft / trial_norm
    fr%mu = MU
    call contact_linearise(reshape([xs, reshape(xm, [size(xm)])], [3, 1 + face%n_nodes]), p, gap, &
                           contact_node_t(status, fn, ft_returned, trial_norm, 0.0_dp, 0.0_dp), &
                           PARAMS, fr, 0.0_dp, lin)
    nd = 3 * (1 + face%n_nodes)
    call suite%equal_int(lin%n_dof, nd, face%name // ' element has 3 (1 + gamma) dofs')
    allocate (v(nd))
    call random_number(v)
    v = v - 0.5_dp
    fd = (forces_after(xm, xs, p%xi, ft, status, EPS * v) - forces_after(xm, xs, p%xi, ft, status, -EPS * v)) &
         / (2 * EPS)
    ! Central differences of a smooth map: truncation O(eps^2), round-off ~1e-16/eps; 1e-7.
    call suite%close_array(matmul(lin%stiffness(1:nd, 1:nd), v), -fd, 1.0e-7_dp, &
                           face%name // ' K_f = -dF/du, ' // label)
    call suite%check(all(lin%stiffness(nd + 1:, :) == 0.0_dp), face%name // ' no entries past its dofs')
  end subroutine test_tangent

  subroutine test_areas(suite, id)
    type(test_suite_t), intent(inout) :: suite
    integer, intent(in) :: id
    type(face_kind_t) :: face
    real(dp), allocatable :: xf(:, :), a(:)
    real(dp) :: area
    integer :: n
    face = kind_of(id)
    n = face%n_nodes
    ! A flat face: the reference nodes scaled by 2 and 3 (area 6 x the reference area).
    allocate (xf(3, n))
    xf(1, :) = 2.0_dp * face%node_st(1, :)
    xf(2, :) = 3.0_dp * face%node_st(2, :)
    xf(3, :) = 0.0_dp
    area = 6.0_dp * face%reference_area
    a = face_node_areas(xf)
    call suite%close_to(sum(a), area, 1.0e-13_dp, face%name // ' slave shares sum to the face area')
    select case (id)
    case (FACE_TRI6)
      call suite%close_array(a, [0.0_dp, 0.0_dp, 0.0_dp, area / 3, area / 3, area / 3], 1.0e-13_dp, &
                             'TRI6 shares: int M_k dA (corners 0, mid-sides 1/3)')
    case (FACE_QUAD8)
      call suite%close_array(a, area * [0.01_dp, 0.01_dp, 0.01_dp, 0.01_dp, 0.24_dp, 0.24_dp, 0.24_dp, &
                             0.24_dp], 1.0e-13_dp, 'QUAD8 shares: CalculiX 1/100 corners, 24/100 mid-sides')
    case default
      call suite%close_array(a, spread(area / n, 1, n), 1.0e-13_dp, face%name // ' shares: A/n on a parallelogram')
    end select
  end subroutine test_areas

end program test_fcs_contact_segments
