!> Unit test of fcs_nonlinear_constraints: Rodrigues' rotation matrix is orthogonal with the
!> right angle and axis; its derivative d(C(w) r)/dw equals central finite differences (at
!> |w| around 1, and below the series threshold 1e-2 and at 0); the gradients of the PLANE,
!> STRAIGHT, RIGID and MEANROT constraints (N1)-(N4) equal central differences of g; and a
!> projection puts a perturbed state back onto every constraint to round-off.
program test_fcs_nonlinear_constraints
  use fcs_kinds, only: dp
  use fcs_linear_constraints, only: constraint_term_t, linear_equation_t
  use fcs_nonlinear_constraints, only: nonlinear_constraint_t, nonlinear_set_t, &
                                       constraint_gradient, rotation_matrix, rotation_derivative, &
                                       CONSTRAINT_PLANE, CONSTRAINT_STRAIGHT, CONSTRAINT_RIGID, &
                                       CONSTRAINT_MEAN_ROTATION
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  integer, parameter :: N_NODES = 8
  !> Central differences with step h have error O(h^2) ~ 1e-10 and round-off ~ eps / h ~ 1e-11.
  real(dp), parameter :: H = 1.0e-5_dp, FD_TOLERANCE = 1.0e-8_dp

  suite%name = 'fcs_nonlinear_constraints'
  call check_rotation(suite)
  call check_gradients(suite)
  call check_projection(suite)
  call suite%report()

contains

  subroutine check_rotation(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: c(3, 3), w(3), r(3), d(3, 3), fd(3, 3), e(3), identity(3, 3)
    real(dp) :: scales(4)
    integer :: k, s
    identity = 0.0_dp
    do k = 1, 3
      identity(k, k) = 1.0_dp
    end do
    ! A quarter turn about z takes x to y.
    c = rotation_matrix([0.0_dp, 0.0_dp, 2.0_dp * atan(1.0_dp)])
    call suite%close_array(matmul(c, [1.0_dp, 0.0_dp, 0.0_dp]), [0.0_dp, 1.0_dp, 0.0_dp], 1.0e-15_dp, &
                           'C(pi/2 e_z) e_x = e_y')
    r = [0.3_dp, -1.2_dp, 0.7_dp]
    scales = [1.0_dp, 5.0e-3_dp, 1.0e-6_dp, 0.0_dp]
    do s = 1, size(scales)
      w = scales(s) * [0.4_dp, -0.9_dp, 0.5_dp]
      c = rotation_matrix(w)
      call suite%close_array(reshape(matmul(transpose(c), c), [9]), reshape(identity, [9]), &
                             1.0e-15_dp, 'C^T C = I')
      call suite%close_array(matmul(c, w), w, 1.0e-15_dp, 'C w = w (the axis stays)')
      d = rotation_derivative(w, r)
      do k = 1, 3
        e = 0.0_dp
        e(k) = H
        fd(:, k) = (matmul(rotation_matrix(w + e), r) - matmul(rotation_matrix(w - e), r)) / (2 * H)
      end do
      call suite%close_array(reshape(d, [9]), reshape(fd, [9]), FD_TOLERANCE, &
                             'd(C r)/dw = central differences')
    end do
  end subroutine check_rotation

  !> Initial coordinates of a distorted block of 8 nodes and a displacement field.
  subroutine block(x0, u)
    real(dp), intent(out) :: x0(3, N_NODES), u(3, N_NODES)
    integer :: a
    x0 = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.1_dp, 0.0_dp, 1.1_dp, 1.0_dp, 0.2_dp, &
                  0.0_dp, 0.9_dp, -0.1_dp, 0.1_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 1.2_dp, &
                  1.0_dp, 1.1_dp, 1.0_dp, -0.1_dp, 1.0_dp, 0.9_dp], [3, N_NODES])
    do a = 1, N_NODES
      u(:, a) = 0.05_dp * [sin(1.0_dp * a), cos(2.0_dp * a), sin(3.0_dp * a + 1.0_dp)]
    end do
  end subroutine block

  function sample_constraints() result(c)
    type(nonlinear_constraint_t) :: c(4)
    c(1) = nonlinear_constraint_t(CONSTRAINT_PLANE, 1, [5, 1, 2, 3], 0, 0, [0.0_dp, 0.0_dp, 0.0_dp])
    c(2) = nonlinear_constraint_t(CONSTRAINT_STRAIGHT, 2, [7, 1, 3], 2, 1, [0.0_dp, 0.0_dp, 0.0_dp])
    c(3) = nonlinear_constraint_t(CONSTRAINT_RIGID, 3, [6, 4, 8], 3, 0, [0.3_dp, -0.2_dp, 0.9_dp])
    c(4) = nonlinear_constraint_t(CONSTRAINT_MEAN_ROTATION, 4, [1, 2, 3, 4, 5], 0, 0, &
                                  [0.0_dp, 0.6_dp, 0.8_dp])
  end function sample_constraints

  subroutine check_gradients(suite)
    type(test_suite_t), intent(inout) :: suite
    type(nonlinear_constraint_t) :: c(4)
    real(dp) :: x0(3, N_NODES), u(3, N_NODES), up(3, N_NODES), g, gp, gm, scale
    real(dp), allocatable :: gradient(:, :), ignored(:, :)
    character(len=*), parameter :: NAMES(4) = ['PLANE   ', 'STRAIGHT', 'RIGID   ', 'MEANROT ']
    integer :: k, a, d
    call block(x0, u)
    ! The rigid body's rotation node holds a finite rotation vector.
    u(:, 8) = [0.4_dp, -0.7_dp, 0.3_dp]
    c = sample_constraints()
    do k = 1, size(c)
      call constraint_gradient(c(k), x0, u, g, gradient)
      scale = maxval(abs(gradient))
      do a = 1, size(c(k)%nodes)
        do d = 1, 3
          up = u
          up(d, c(k)%nodes(a)) = up(d, c(k)%nodes(a)) + H
          call constraint_gradient(c(k), x0, up, gp, ignored)
          up(d, c(k)%nodes(a)) = up(d, c(k)%nodes(a)) - 2 * H
          call constraint_gradient(c(k), x0, up, gm, ignored)
          call suite%close_to(gradient(d, a), (gp - gm) / (2 * H), FD_TOLERANCE, &
                              trim(NAMES(k)) // ': dg/du = central differences', floor=scale)
        end do
      end do
    end do
  end subroutine check_gradients

  !> Each constraint's equation with its dependent term first (the nodes' first direction
  !> with a nonzero gradient); a perturbed state projected: every g at round-off.
  subroutine check_projection(suite)
    type(test_suite_t), intent(inout) :: suite
    type(nonlinear_constraint_t) :: c(4)
    type(linear_equation_t) :: equations(4)
    type(nonlinear_set_t) :: set
    real(dp) :: x0(3, N_NODES), u(3, N_NODES), du(3 * N_NODES), g
    real(dp), allocatable :: gradient(:, :)
    integer :: k
    call block(x0, u)
    u(:, 8) = [0.4_dp, -0.7_dp, 0.3_dp]
    c = sample_constraints()
    ! Dependent terms: PLANE u_5z, STRAIGHT u_7y, RIGID u_6z, MEANROT u_1y (no cascade).
    equations(1)%terms = [constraint_term_t(5, 3, 1.0_dp)]
    equations(2)%terms = [constraint_term_t(7, 2, 1.0_dp)]
    equations(3)%terms = [constraint_term_t(6, 3, 1.0_dp)]
    equations(4)%terms = [constraint_term_t(1, 2, 1.0_dp)]
    call set%init(c, equations, x0)
    du = 0.0_dp
    call set%project(x0, u, du)
    u = u + reshape(du, [3, N_NODES])
    do k = 1, size(c)
      call constraint_gradient(c(k), x0, u, g, gradient)
      call suite%close_to(g, 0.0_dp, 1.0e-13_dp, 'projected state: g = 0', &
                          floor=maxval(abs(gradient)))
    end do
  end subroutine check_projection

end program test_fcs_nonlinear_constraints
