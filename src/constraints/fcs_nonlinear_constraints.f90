!> CalculiX's nonlinear multi-point constraints (*MPC PLANE, STRAIGHT, MEANROT; *RIGID BODY)
!> under NLGEOM: each is a scalar equation g(x) = 0 between current positions x = X + u (and
!> the rotation vector of a rigid body's rotation node), as in ccx 2.20's `nonlinmpc.f` and
!> `umpc_mean_rot.f` (doc/theory.md 6.2.3):
!>
!>   PLANE     g = (x_p - x_a) . ((x_b - x_a) x (x_c - x_a))                          (N1)
!>   STRAIGHT  g = r_i e_j - r_j e_i,   r = x_p - x_a, e = x_b - x_a                  (N2)
!>   RIGID     g = x_p,i - x_ref,i - (C(w) (X_p - X_ref))_i,  w = u_rot,
!>             C(w) = cos|w| I + sin|w|/|w| [w x] + (1 - cos|w|)/|w|^2 w w^T          (N3)
!>   MEANROT   g = sum_k asin(a . (p_k x q_k) / (|p_k| |q_k|)) - N u_m,1,              (N4)
!>             p_k, q_k the initial and current positions of member k relative to the
!>             members' centroid, projected on the plane normal to the axis a (the
!>             coordinates of the last node m, whose first displacement is the angle)
!>
!> Each constraint owns one linear equation (its linearisation, terms in a fixed order, the
!> first the dependent one): `relinearise` writes the gradient of g at the current state into
!> the coefficients and rebuilds the elimination u = T u_I from them (fcs_linear_constraints,
!> (L1)-(L2)); `project` moves the dependent degrees of freedom of an increment so that every
!> g is zero again (Newton on each dependent term, sweeps until the changes are at
!> round-off): the constraints hold exactly at every state the stepper computes forces on,
!> and T spans the tangent space of the constraint manifold there, so equilibrium T^T R = 0
!> is that of the nonlinear constraints (ccx re-linearises each iteration with an
!> inhomogeneous term instead; the converged states are the same).
module fcs_nonlinear_constraints
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  use fcs_diagnostics, only: format_location
  use fcs_linear_constraints, only: linear_equation_t, constraint_map_t
  implicit none
  private
  public :: nonlinear_constraint_t, nonlinear_set_t, constraint_gradient, rotation_matrix, &
            rotation_derivative
  public :: CONSTRAINT_PLANE, CONSTRAINT_STRAIGHT, CONSTRAINT_RIGID, CONSTRAINT_MEAN_ROTATION

  integer, parameter :: CONSTRAINT_PLANE = 1, CONSTRAINT_STRAIGHT = 2, CONSTRAINT_RIGID = 3, &
                        CONSTRAINT_MEAN_ROTATION = 4
  !> Largest number of projection sweeps; a sweep whose largest change is below
  !> PROJECTION_TOLERANCE times the model's size ends them.
  integer, parameter :: MAX_SWEEPS = 30
  real(dp), parameter :: PROJECTION_TOLERANCE = 1.0e-14_dp
  !> The dependent term of a constraint must keep at least this fraction of the largest
  !> coefficient at its node (a PLANE or STRAIGHT turned by about 90 degrees loses it: ccx
  !> then moves the dependent term to another direction, fcs3d stops).
  real(dp), parameter :: DEPENDENT_FRACTION = 1.0e-2_dp

  !> One nonlinear constraint: its kind, its nodes (PLANE p, a, b, c; STRAIGHT p, a, b;
  !> RIGID p, ref, rot; MEANROT the members, then the angle node), the equation of the
  !> model it owns, and its data (RIGID: the direction i and X_p - X_ref; STRAIGHT: the
  !> directions i and j; MEANROT: the unit axis).
  type :: nonlinear_constraint_t
    integer :: kind = 0
    integer :: equation = 0
    integer, allocatable :: nodes(:)
    integer :: direction = 0
    integer :: along = 0
    real(dp) :: vector(3) = 0.0_dp
  end type nonlinear_constraint_t

  !> The nonlinear constraints of a run with their current linearisations (a copy of the
  !> model's equations whose coefficients follow the geometry).
  type :: nonlinear_set_t
    type(nonlinear_constraint_t), allocatable :: constraints(:)
    type(linear_equation_t), allocatable :: equations(:)
    !> The model's size (largest extent of the nodes), the scale of the projection tolerance.
    real(dp) :: length = 1.0_dp
  contains
    procedure :: init => set_init
    procedure :: active => set_active
    procedure :: relinearise => set_relinearise
    procedure :: project => set_project
  end type nonlinear_set_t

contains

  !> Keep the constraints and a copy of the equations; x0(3, n_nodes) the initial
  !> coordinates (the size of the model).
  subroutine set_init(this, constraints, equations, x0)
    class(nonlinear_set_t), intent(inout) :: this
    type(nonlinear_constraint_t), intent(in) :: constraints(:)
    type(linear_equation_t), intent(in) :: equations(:)
    real(dp), intent(in) :: x0(:, :)
    integer :: i
    this%constraints = constraints
    this%equations = equations
    this%length = 1.0_dp
    if (size(x0, 2) > 0) then
      this%length = 0.0_dp
      do i = 1, 3
        this%length = max(this%length, maxval(x0(i, :)) - minval(x0(i, :)))
      end do
      if (this%length <= 0.0_dp) this%length = 1.0_dp
    end if
  end subroutine set_init

  pure logical function set_active(this)
    class(nonlinear_set_t), intent(in) :: this
    set_active = .false.
    if (allocated(this%constraints)) set_active = size(this%constraints) > 0
  end function set_active

  !> The coefficients of every constraint's equation from the gradient of g at the state
  !> (x0 initial coordinates, u displacements, both (3, n_nodes)), then `map` rebuilt from all
  !> equations (n_nodes, node_id, frame, transformed as for constraint_map_t%init).
  subroutine set_relinearise(this, x0, u, map, n_nodes, node_id, frame, transformed, err)
    class(nonlinear_set_t), intent(inout) :: this
    real(dp), intent(in) :: x0(:, :), u(:, :)
    type(constraint_map_t), intent(inout) :: map
    integer, intent(in) :: n_nodes, node_id(:)
    real(dp), intent(in) :: frame(:, :, :)
    logical, intent(in) :: transformed(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: gradient(:, :)
    real(dp) :: g
    integer :: k, t
    do k = 1, size(this%constraints)
      associate (c => this%constraints(k))
        call constraint_gradient(c, x0, u, g, gradient)
        associate (terms => this%equations(c%equation)%terms)
          do t = 1, size(terms)
            terms(t)%coefficient = gradient(terms(t)%dof, findloc(c%nodes, terms(t)%node, 1))
          end do
          if (abs(terms(1)%coefficient) < DEPENDENT_FRACTION * &
              maxval(abs(gradient(:, findloc(c%nodes, terms(1)%node, 1))))) then
            call fatal_error(err, format_location(this%equations(c%equation)%loc, &
              this%equations(c%equation)%origin // ': the coefficient of its dependent term ' // &
              '(direction ' // achar(iachar('0') + terms(1)%dof) // ') has nearly vanished with ' // &
              'the rotation of the constraint; fcs3d keeps the dependent term of a nonlinear ' // &
              'constraint fixed (CalculiX moves it to another direction): rotations of a PLANE ' // &
              'or STRAIGHT MPC near 90 degrees are not supported'))
            return
          end if
        end associate
      end associate
    end do
    call map%init(this%equations, n_nodes, node_id, err, frame, transformed)
  end subroutine set_relinearise

  !> Move the dependent degrees of freedom of the increment du (3 n_nodes, from the state
  !> x0 + u_start) so that every constraint holds at x0 + u_start + du: a Newton step on each
  !> constraint's dependent term, u_d <- u_d - g / (dg/du_d), in sweeps over the constraints
  !> until the largest change is at round-off (one sweep is exact for a constraint linear in
  !> its dependent term; more resolve cascades and MEANROT's asin).
  subroutine set_project(this, x0, u_start, du)
    class(nonlinear_set_t), intent(in) :: this
    real(dp), intent(in) :: x0(:, :), u_start(:, :)
    real(dp), intent(inout) :: du(:)
    real(dp), allocatable :: u(:, :), gradient(:, :)
    real(dp) :: g, change, largest
    integer :: sweep, k, node, dof
    u = u_start + reshape(du, shape(u_start))
    do sweep = 1, MAX_SWEEPS
      largest = 0.0_dp
      do k = 1, size(this%constraints)
        associate (c => this%constraints(k))
          node = this%equations(c%equation)%terms(1)%node
          dof = this%equations(c%equation)%terms(1)%dof
          call constraint_gradient(c, x0, u, g, gradient)
          associate (slope => gradient(dof, findloc(c%nodes, node, 1)))
            if (slope == 0.0_dp) cycle
            change = -g / slope
          end associate
          u(dof, node) = u(dof, node) + change
          largest = max(largest, abs(change))
        end associate
      end do
      if (largest <= PROJECTION_TOLERANCE * this%length) exit
    end do
    du = reshape(u - u_start, shape(du))
  end subroutine set_project

  !> g of constraint c at the state x0 + u, and its gradient dg/du (3, size(c%nodes)) at
  !> its nodes ((N1)-(N4)).
  subroutine constraint_gradient(c, x0, u, g, gradient)
    type(nonlinear_constraint_t), intent(in) :: c
    real(dp), intent(in) :: x0(:, :), u(:, :)
    real(dp), intent(out) :: g
    real(dp), allocatable, intent(out) :: gradient(:, :)
    allocate (gradient(3, size(c%nodes)))
    gradient = 0.0_dp
    select case (c%kind)
    case (CONSTRAINT_PLANE)
      call plane_gradient(c, x0, u, g, gradient)
    case (CONSTRAINT_STRAIGHT)
      call straight_gradient(c, x0, u, g, gradient)
    case (CONSTRAINT_RIGID)
      call rigid_gradient(c, u, g, gradient)
    case (CONSTRAINT_MEAN_ROTATION)
      call mean_rotation_gradient(c, x0, u, g, gradient)
    case default
      g = 0.0_dp
    end select
  end subroutine constraint_gradient

  !> (N1) with n = e1 x e2, e1 = x_b - x_a, e2 = x_c - x_a, r = x_p - x_a:
  !> dg/du_p = n, dg/du_b = e2 x r, dg/du_c = r x e1, dg/du_a = -(the sum of the others).
  pure subroutine plane_gradient(c, x0, u, g, gradient)
    type(nonlinear_constraint_t), intent(in) :: c
    real(dp), intent(in) :: x0(:, :), u(:, :)
    real(dp), intent(out) :: g, gradient(:, :)
    real(dp) :: xp(3), xa(3), xb(3), xc(3), n(3), r(3), e1(3), e2(3)
    xp = x0(:, c%nodes(1)) + u(:, c%nodes(1))
    xa = x0(:, c%nodes(2)) + u(:, c%nodes(2))
    xb = x0(:, c%nodes(3)) + u(:, c%nodes(3))
    xc = x0(:, c%nodes(4)) + u(:, c%nodes(4))
    e1 = xb - xa
    e2 = xc - xa
    r = xp - xa
    n = cross(e1, e2)
    g = dot_product(r, n)
    gradient(:, 1) = n
    gradient(:, 3) = cross(e2, r)
    gradient(:, 4) = cross(r, e1)
    gradient(:, 2) = -(gradient(:, 1) + gradient(:, 3) + gradient(:, 4))
  end subroutine plane_gradient

  !> (N2) for directions i = c%direction, j = c%along.
  pure subroutine straight_gradient(c, x0, u, g, gradient)
    type(nonlinear_constraint_t), intent(in) :: c
    real(dp), intent(in) :: x0(:, :), u(:, :)
    real(dp), intent(out) :: g, gradient(:, :)
    real(dp) :: r(3), e(3)
    integer :: i, j
    i = c%direction
    j = c%along
    r = x0(:, c%nodes(1)) + u(:, c%nodes(1)) - x0(:, c%nodes(2)) - u(:, c%nodes(2))
    e = x0(:, c%nodes(3)) + u(:, c%nodes(3)) - x0(:, c%nodes(2)) - u(:, c%nodes(2))
    g = r(i) * e(j) - r(j) * e(i)
    gradient(i, 1) = e(j)
    gradient(j, 1) = -e(i)
    gradient(j, 3) = r(i)
    gradient(i, 3) = -r(j)
    gradient(:, 2) = -(gradient(:, 1) + gradient(:, 3))
  end subroutine straight_gradient

  !> (N3): dg/du_p = e_i, dg/du_ref = -e_i, dg/dw_k = -(dC/dw_k (X_p - X_ref))_i.
  pure subroutine rigid_gradient(c, u, g, gradient)
    type(nonlinear_constraint_t), intent(in) :: c
    real(dp), intent(in) :: u(:, :)
    real(dp), intent(out) :: g, gradient(:, :)
    real(dp) :: rotation(3, 3), derivative(3, 3)
    integer :: i
    i = c%direction
    rotation = rotation_matrix(u(:, c%nodes(3)))
    derivative = rotation_derivative(u(:, c%nodes(3)), c%vector)
    g = u(i, c%nodes(1)) - u(i, c%nodes(2)) - (dot_product(rotation(i, :), c%vector) - c%vector(i))
    gradient(i, 1) = 1.0_dp
    gradient(i, 2) = -1.0_dp
    gradient(:, 3) = -derivative(i, :)
  end subroutine rigid_gradient

  !> (N4), as ccx's umpc_mean_rot: with s_k = a . (p_k x q_k) / (|p_k| |q_k|) and
  !> b_k = a x p_k, d asin(s_k) / d q_k = (b_k / (|p_k| |q_k|) - s_k q_k / |q_k|^2) /
  !> sqrt(1 - s_k^2), and q_k moves with u_l by (delta_kl - 1/N) (the centroid moves too).
  !> Members within sqrt(1e-10) of the mean distance from the axis through the centroid
  !> are left out, as in ccx.
  pure subroutine mean_rotation_gradient(c, x0, u, g, gradient)
    type(nonlinear_constraint_t), intent(in) :: c
    real(dp), intent(in) :: x0(:, :), u(:, :)
    real(dp), intent(out) :: g, gradient(:, :)
    real(dp) :: centre_x(3), centre_u(3), p(3), q(3), b(3), s, spread_x, dq(3), total(3), a(3)
    integer :: n, k
    n = size(c%nodes) - 1
    a = c%vector
    centre_x = 0.0_dp
    centre_u = 0.0_dp
    do k = 1, n
      centre_x = centre_x + x0(:, c%nodes(k))
      centre_u = centre_u + u(:, c%nodes(k))
    end do
    centre_x = centre_x / n
    centre_u = centre_u / n
    spread_x = 0.0_dp
    do k = 1, n
      spread_x = spread_x + sum((x0(:, c%nodes(k)) - centre_x)**2)
    end do
    spread_x = spread_x / n
    g = 0.0_dp
    total = 0.0_dp
    do k = 1, n
      p = x0(:, c%nodes(k)) - centre_x
      q = p + u(:, c%nodes(k)) - centre_u
      p = p - dot_product(p, a) * a
      q = q - dot_product(q, a) * a
      if (dot_product(p, p) < 1.0e-10_dp * spread_x) cycle
      b = cross(a, p)
      s = dot_product(q, b) / (norm2(p) * norm2(q))
      g = g + asin(s)
      dq = (b / (norm2(p) * norm2(q)) - s * q / dot_product(q, q)) / sqrt(1.0_dp - s * s)
      gradient(:, k) = dq
      total = total + dq
    end do
    do k = 1, n
      gradient(:, k) = gradient(:, k) - total / n
    end do
    g = g - n * u(1, c%nodes(n + 1))
    gradient(1, n + 1) = -real(n, dp)
  end subroutine mean_rotation_gradient

  !> Rodrigues' rotation matrix C(w) of the rotation vector w (N3).
  pure function rotation_matrix(w) result(rotation)
    real(dp), intent(in) :: w(3)
    real(dp) :: rotation(3, 3)
    real(dp) :: c1, c2, c3
    integer :: i
    call rotation_factors(w, c1, c2, c3)
    rotation = c2 * skew(w)
    do i = 1, 3
      rotation(:, i) = rotation(:, i) + c3 * w * w(i)
      rotation(i, i) = rotation(i, i) + c1
    end do
  end function rotation_matrix

  !> d(C(w) r) / dw (3, 3): column k the derivative with respect to w_k. With t = |w|,
  !> C r = c1 r + c2 (w x r) + c3 w (w . r), dc1/dw = -c2 w, dc2/dw = c5 w, dc3/dw = c6 w,
  !> c5 = (t cos t - sin t) / t^3, c6 = (t sin t - 2 (1 - cos t)) / t^4 (their series below
  !> t = 1e-2, where the closed forms lose digits).
  pure function rotation_derivative(w, r) result(derivative)
    real(dp), intent(in) :: w(3), r(3)
    real(dp) :: derivative(3, 3)
    real(dp) :: c1, c2, c3, c5, c6, t, wr, wxr(3), e(3)
    integer :: k
    call rotation_factors(w, c1, c2, c3)
    t = norm2(w)
    if (t < 1.0e-2_dp) then
      c5 = -1.0_dp / 3.0_dp + t**2 / 30.0_dp - t**4 / 840.0_dp
      c6 = -1.0_dp / 12.0_dp + t**2 / 180.0_dp - t**4 / 6720.0_dp
    else
      c5 = (t * cos(t) - sin(t)) / t**3
      c6 = (t * sin(t) - 2.0_dp * (1.0_dp - cos(t))) / t**4
    end if
    wr = dot_product(w, r)
    wxr = cross(w, r)
    do k = 1, 3
      e = 0.0_dp
      e(k) = 1.0_dp
      derivative(:, k) = -c2 * w(k) * r + c5 * w(k) * wxr + c2 * cross(e, r) + &
                         c6 * w(k) * wr * w + c3 * (e * wr + w * r(k))
    end do
  end function rotation_derivative

  !> c1 = cos t, c2 = sin t / t, c3 = (1 - cos t) / t^2 of t = |w| (series for small t).
  pure subroutine rotation_factors(w, c1, c2, c3)
    real(dp), intent(in) :: w(3)
    real(dp), intent(out) :: c1, c2, c3
    real(dp) :: t
    t = norm2(w)
    c1 = cos(t)
    if (t < 1.0e-2_dp) then
      c2 = 1.0_dp - t**2 / 6.0_dp + t**4 / 120.0_dp
      c3 = 0.5_dp - t**2 / 24.0_dp + t**4 / 720.0_dp
    else
      c2 = sin(t) / t
      c3 = (1.0_dp - cos(t)) / t**2
    end if
  end subroutine rotation_factors

  !> [w x]: the matrix of the cross product w x.
  pure function skew(w) result(m)
    real(dp), intent(in) :: w(3)
    real(dp) :: m(3, 3)
    m = reshape([0.0_dp, w(3), -w(2), -w(3), 0.0_dp, w(1), w(2), -w(1), 0.0_dp], [3, 3])
  end function skew

  pure function cross(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross

end module fcs_nonlinear_constraints
