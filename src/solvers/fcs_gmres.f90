!> Restarted GMRES(m) with right preconditioning: Y. Saad and M. H. Schultz, "GMRES: a
!> generalized minimal residual algorithm for solving nonsymmetric linear systems", SIAM J. Sci.
!> Stat. Comput. 7(3), 856-869, 1986; Y. Saad, "Iterative Methods for Sparse Linear Systems",
!> 2nd ed., SIAM 2003, Algorithm 9.5 (right-preconditioned GMRES), with the preconditioned
!> vectors z_j = M^-1 v_j kept as in Algorithm 9.6 (flexible GMRES) so that the update
!> x = x0 + Z y needs no further solve.
!>
!> Right preconditioning minimises the true residual |b - A x|, so the stopping test is on
!> the quantity the caller asks for. The Arnoldi basis is orthogonalised by modified
!> Gram-Schmidt, the Hessenberg matrix reduced by Givens rotations (Saad 2003, section 6.5.3),
!> whose last right-hand-side entry is the residual norm of the current iterate. At the end of
!> each cycle the residual is recomputed from its definition, and that one decides convergence.
!>
!> The operator and the preconditioner come from an extension of `krylov_operator_t`; every
!> vector is held whole on every process (a distributed operator sums its product over the
!> processes, `fcs_factor_reuse`), so the arithmetic here is the same everywhere.
module fcs_gmres
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  implicit none
  private
  public :: krylov_operator_t, gmres_settings_t, gmres_result_t, gmres_solve
  public :: GMRES_CONVERGED, GMRES_TOO_SLOW, GMRES_ITERATION_LIMIT, GMRES_NOT_RUN

  !> Outcomes: the residual reached the tolerance; the rate of convergence so far could not
  !> reach it within the iteration limit (stagnation included); the limit was reached.
  integer, parameter :: GMRES_NOT_RUN = 0, GMRES_CONVERGED = 1, GMRES_TOO_SLOW = 2, &
                        GMRES_ITERATION_LIMIT = 3

  !> A linear operator A and a preconditioner M^-1 (an approximate inverse of A).
  type, abstract :: krylov_operator_t
  contains
    procedure(apply_interface), deferred :: apply
    procedure(precondition_interface), deferred :: precondition
  end type krylov_operator_t

  abstract interface
    !> y = A x.
    subroutine apply_interface(this, x, y)
      import :: krylov_operator_t, dp
      class(krylov_operator_t), intent(inout) :: this
      real(dp), intent(in) :: x(:)
      real(dp), intent(out) :: y(:)
    end subroutine apply_interface

    !> z = M^-1 v.
    subroutine precondition_interface(this, v, z, err)
      import :: krylov_operator_t, dp, error_t
      class(krylov_operator_t), intent(inout) :: this
      real(dp), intent(in) :: v(:)
      real(dp), intent(out) :: z(:)
      type(error_t), allocatable, intent(out) :: err
    end subroutine precondition_interface
  end interface

  !> When to stop.
  type :: gmres_settings_t
    !> Converged when |b - A x| <= tolerance |b|.
    real(dp) :: tolerance = 1.0e-10_dp
    !> Iterations per cycle (m) and in all (each one a product and a preconditioner solve).
    integer :: restart = 20
    integer :: max_iterations = 40
    !> From this iteration on, the solve is given up as soon as the mean reduction of the
    !> residual per iteration so far, continued, would not reach the tolerance within
    !> max_iterations (a slowly converging or stagnating solve stops early).
    integer :: rate_check_from = 4
  end type gmres_settings_t

  !> What a solve did.
  type :: gmres_result_t
    integer :: outcome = GMRES_NOT_RUN
    integer :: iterations = 0
    !> |b - A x| / |b| of the solution returned (0 for b = 0).
    real(dp) :: residual_ratio = 0.0_dp
  end type gmres_result_t

contains

  !> Solve A x = b from x = 0. `x` is the last iterate whatever the outcome; `err` only
  !> carries a failed preconditioner solve.
  subroutine gmres_solve(op, b, x, settings, result, err)
    class(krylov_operator_t), intent(inout) :: op
    real(dp), intent(in) :: b(:)
    real(dp), intent(out) :: x(:)
    type(gmres_settings_t), intent(in) :: settings
    type(gmres_result_t), intent(out) :: result
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: r(:)
    real(dp) :: b_norm, beta
    logical :: give_up
    x = 0.0_dp
    b_norm = norm2(b)
    if (b_norm == 0.0_dp) then
      result%outcome = GMRES_CONVERGED
      return
    end if
    r = b
    beta = b_norm
    do
      call gmres_cycle(op, r, beta, b_norm, settings, x, result, give_up, err)
      if (allocated(err)) return
      call op%apply(x, r)
      r = b - r
      beta = norm2(r)
      result%residual_ratio = beta / b_norm
      if (result%residual_ratio <= settings%tolerance) then
        result%outcome = GMRES_CONVERGED
        return
      else if (give_up) then
        result%outcome = GMRES_TOO_SLOW
        return
      else if (result%iterations >= settings%max_iterations) then
        result%outcome = GMRES_ITERATION_LIMIT
        return
      end if
    end do
  end subroutine gmres_solve

  !> One cycle of at most `restart` Arnoldi steps from the residual r (norm beta) of x;
  !> adds the cycle's correction to x. `give_up` when the rate test fails.
  subroutine gmres_cycle(op, r, beta, b_norm, settings, x, result, give_up, err)
    class(krylov_operator_t), intent(inout) :: op
    real(dp), intent(in) :: r(:), beta, b_norm
    type(gmres_settings_t), intent(in) :: settings
    real(dp), intent(inout) :: x(:)
    type(gmres_result_t), intent(inout) :: result
    logical, intent(out) :: give_up
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: v(:, :), z(:, :), h(:, :), g(:), c(:), s(:), y(:)
    real(dp) :: estimate, next_norm
    integer :: m, j, steps
    m = max(1, min(settings%restart, settings%max_iterations - result%iterations))
    allocate (v(size(r), m + 1), z(size(r), m), h(m + 1, m), g(m + 1), c(m), s(m))
    h = 0.0_dp
    g = 0.0_dp
    g(1) = beta
    v(:, 1) = r / beta
    give_up = .false.
    steps = 0
    do j = 1, m
      call op%precondition(v(:, j), z(:, j), err)
      if (allocated(err)) return
      call op%apply(z(:, j), v(:, j + 1))
      call orthogonalise(v, j, h(1:j + 1, j))
      next_norm = h(j + 1, j)
      call rotate(h(1:j + 1, j), c, s, g, j)
      steps = j
      result%iterations = result%iterations + 1
      estimate = abs(g(j + 1)) / b_norm
      if (estimate <= settings%tolerance .or. next_norm == 0.0_dp) exit
      give_up = too_slow(estimate, result%iterations, settings)
      if (give_up .or. result%iterations >= settings%max_iterations) exit
      v(:, j + 1) = v(:, j + 1) / next_norm
    end do
    y = back_substitute(h(1:steps, 1:steps), g(1:steps))
    x = x + matmul(z(:, 1:steps), y)
  end subroutine gmres_cycle

  !> Modified Gram-Schmidt: orthogonalise v(:, j+1) = A z_j against v(:, 1:j); the
  !> coefficients and the remaining norm go to the Hessenberg column h(1:j+1) (the vector is
  !> left unnormalised).
  pure subroutine orthogonalise(v, j, h)
    real(dp), intent(inout) :: v(:, :)
    integer, intent(in) :: j
    real(dp), intent(out) :: h(:)
    integer :: i
    do i = 1, j
      h(i) = dot_product(v(:, j + 1), v(:, i))
      v(:, j + 1) = v(:, j + 1) - h(i) * v(:, i)
    end do
    h(j + 1) = norm2(v(:, j + 1))
  end subroutine orthogonalise

  !> Apply the rotations 1..j-1 to the new Hessenberg column h(1:j+1), then the rotation j
  !> that zeroes h(j+1), also to the right-hand side g (Saad 2003, section 6.5.3).
  pure subroutine rotate(h, c, s, g, j)
    real(dp), intent(inout) :: h(:), c(:), s(:), g(:)
    integer, intent(in) :: j
    real(dp) :: upper, radius
    integer :: i
    do i = 1, j - 1
      upper = c(i) * h(i) + s(i) * h(i + 1)
      h(i + 1) = -s(i) * h(i) + c(i) * h(i + 1)
      h(i) = upper
    end do
    radius = hypot(h(j), h(j + 1))
    if (radius == 0.0_dp) then
      c(j) = 1.0_dp
      s(j) = 0.0_dp
    else
      c(j) = h(j) / radius
      s(j) = h(j + 1) / radius
    end if
    h(j) = radius
    h(j + 1) = 0.0_dp
    g(j + 1) = -s(j) * g(j)
    g(j) = c(j) * g(j)
  end subroutine rotate

  !> y with R y = g, R upper triangular (the rotated Hessenberg matrix); a zero diagonal
  !> (a breakdown with a singular operator) leaves its component zero.
  pure function back_substitute(r, g) result(y)
    real(dp), intent(in) :: r(:, :), g(:)
    real(dp) :: y(size(g))
    integer :: i
    do i = size(g), 1, -1
      y(i) = g(i) - dot_product(r(i, i + 1:), y(i + 1:))
      if (r(i, i) /= 0.0_dp) then
        y(i) = y(i) / r(i, i)
      else
        y(i) = 0.0_dp
      end if
    end do
  end function back_substitute

  !> True when, from `rate_check_from` iterations on, the mean reduction per iteration so far
  !> (estimate^(1/k) after k iterations) would need more than max_iterations in all to reach
  !> the tolerance.
  pure logical function too_slow(estimate, k, settings)
    real(dp), intent(in) :: estimate
    integer, intent(in) :: k
    type(gmres_settings_t), intent(in) :: settings
    real(dp) :: log_rate
    too_slow = .false.
    if (k < settings%rate_check_from) return
    if (estimate >= 1.0_dp) then
      too_slow = .true.
      return
    end if
    log_rate = log(estimate) / k
    too_slow = log(settings%tolerance) / log_rate > real(settings%max_iterations, dp)
  end function too_slow

end module fcs_gmres
