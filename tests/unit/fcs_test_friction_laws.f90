!> Friction laws used only by the tests, and the shared finite-difference check of a law's
!> derivatives (`check_derivatives`). The laws: a smooth rate-dependent law
!> mu = mu0 + c ln(1 + V/v_ref), strengthening (c > 0) or weakening (c < 0); and TEST LINEAR
!> RATE, mu = MU0 + A V/V0, with its registry entry (`test_linear_rate_entry`) so that a test
!> can add it to the friction registry the way a new law is added
!> (doc/architecture.md, "How to add a friction law").
module fcs_test_friction_laws
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  use fcs_friction_factory, only: friction_def_t, friction_law_entry_t, friction_law_entry
  use fcs_test_assertions, only: test_suite_t
  implicit none
  private
  public :: log_rate_law_t, test_linear_rate_t, test_linear_rate_entry, check_derivatives
  public :: FD_STEP, FD_TOLERANCE

  ! Finite-difference tolerance. The central difference with step h = 1e-5 x has truncation
  ! error ~ (h/x)^2 x^2 |mu'''|/(6 |mu'|) ~ 1e-10 relative for the logarithmic and exponential
  ! forms at the points used, and rounding error ~ eps |mu| / (h |mu'|) <~ 1e-8 relative
  ! (worst: the static-kinetic law well past its decay, where |mu'| << |mu|/V); 1e-6 leaves
  ! two orders of margin and still catches any wrong factor or sign.
  real(dp), parameter :: FD_TOLERANCE = 1.0e-6_dp
  ! Relative finite-difference step.
  real(dp), parameter :: FD_STEP = 1.0e-5_dp

  !> mu = MU0 + A V/V0: the test-only law registered as TEST LINEAR RATE.
  type, extends(friction_law_t) :: test_linear_rate_t
    real(dp) :: mu0 = 0.0_dp
    real(dp) :: a = 0.0_dp
    real(dp) :: v0 = 1.0_dp
  contains
    procedure :: evaluate => linear_rate_evaluate
    procedure :: name => linear_rate_name
    procedure :: rate_dependent => linear_rate_rate_dependent
  end type test_linear_rate_t

  type, extends(friction_law_t) :: log_rate_law_t
    real(dp) :: mu0 = 0.4_dp
    real(dp) :: c = 0.02_dp
    real(dp) :: v_ref = 1.0e-2_dp
  contains
    procedure :: evaluate => log_rate_evaluate
    procedure :: name => log_rate_name
  end type log_rate_law_t

contains

  pure function log_rate_evaluate(this, pressure, rate, state) result(d)
    class(log_rate_law_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    d%mu = this%mu0 + this%c * log(1.0_dp + rate / this%v_ref)
    d%dmu_drate = this%c / (this%v_ref + rate)
  end function log_rate_evaluate

  pure function log_rate_name(this) result(name)
    class(log_rate_law_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'LOG RATE (test)'
  end function log_rate_name

  pure function linear_rate_evaluate(this, pressure, rate, state) result(d)
    class(test_linear_rate_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    d%mu = this%mu0 + this%a * rate / this%v0
    d%dmu_drate = this%a / this%v0
  end function linear_rate_evaluate

  pure function linear_rate_name(this) result(name)
    class(test_linear_rate_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'TEST LINEAR RATE'
  end function linear_rate_name

  pure logical function linear_rate_rate_dependent(this)
    class(test_linear_rate_t), intent(in) :: this
    linear_rate_rate_dependent = this%a /= 0.0_dp
  end function linear_rate_rate_dependent

  !> The registry entry of TEST LINEAR RATE: MU0, A, V0 required, RATE UPDATE optional
  !> (EXPLICIT by default, as RATE DEPENDENT).
  function test_linear_rate_entry() result(entry)
    type(friction_law_entry_t) :: entry
    entry = friction_law_entry('TEST LINEAR RATE', 'MU0, A, V0', 'RATE UPDATE', .true., &
                               new_test_linear_rate)
  end function test_linear_rate_entry

  !> The constructor the entry registers: the law from a checked definition.
  subroutine new_test_linear_rate(def, law)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    allocate (law, source=test_linear_rate_t(mu0=def%mu0, a=def%a, v0=def%v0))
  end subroutine new_test_linear_rate

  !> Compare the analytic derivatives of `law` at (pressure, rate, state) with central
  !> differences with relative steps FD_STEP (steps FD_STEP * rate_scale, FD_STEP * state_scale
  !> where the argument is 0). At rate = 0 the rate difference is the one-sided second-order
  !> formula (-3 f(0) + 4 f(h) - f(2h)) / (2h), also O(h^2). A difference carries a rounding
  !> error ~ eps |mu| / h, so derivatives are compared relative to max(|expected|, 1e-3 |mu|/x)
  !> (x the argument or its scale): a zero derivative is then checked to ~1e-9 |mu|/x, and no
  !> non-zero derivative of these laws at the points used is below that floor.
  subroutine check_derivatives(suite, law, pressure, rate, state, rate_scale, state_scale, what)
    type(test_suite_t), intent(inout) :: suite
    class(friction_law_t), intent(in) :: law
    real(dp), intent(in) :: pressure, rate, state, rate_scale, state_scale
    character(len=*), intent(in) :: what
    type(friction_derivatives_t) :: d
    real(dp) :: h, fd, x
    character(len=64) :: where
    write (where, '(a,es10.3,a,es10.3)') ' at V=', rate, ' state=', state
    d = law%evaluate(pressure, rate, state)
    call suite%check(d%mu == d%mu .and. abs(d%mu) < huge(1.0_dp), what // ': finite mu' // trim(where))
    call suite%check(d%mu == law%mu(pressure, rate, state), what // ': mu() = evaluate()%mu')
    x = max(abs(pressure), 1.0_dp)
    h = FD_STEP * x
    fd = (law%mu(pressure + h, rate, state) - law%mu(pressure - h, rate, state)) / (2.0_dp * h)
    call suite%close_to(d%dmu_dpressure, fd, FD_TOLERANCE, what // ': dmu/dp' // trim(where), &
                        floor=1.0e-3_dp * abs(d%mu) / x)
    x = merge(rate, rate_scale, rate > 0.0_dp)
    h = FD_STEP * x
    if (rate > 0.0_dp) then
      fd = (law%mu(pressure, rate + h, state) - law%mu(pressure, rate - h, state)) / (2.0_dp * h)
    else
      fd = (-3.0_dp * law%mu(pressure, rate, state) + 4.0_dp * law%mu(pressure, rate + h, state) &
            - law%mu(pressure, rate + 2.0_dp * h, state)) / (2.0_dp * h)
    end if
    call suite%close_to(d%dmu_drate, fd, FD_TOLERANCE, what // ': dmu/dV' // trim(where), &
                        floor=1.0e-3_dp * abs(d%mu) / x)
    x = merge(abs(state), state_scale, state /= 0.0_dp)
    h = FD_STEP * x
    fd = (law%mu(pressure, rate, state + h) - law%mu(pressure, rate, state - h)) / (2.0_dp * h)
    call suite%close_to(d%dmu_dstate, fd, FD_TOLERANCE, what // ': dmu/dstate' // trim(where), &
                        floor=1.0e-3_dp * abs(d%mu) / x)
  end subroutine check_derivatives

end module fcs_test_friction_laws
