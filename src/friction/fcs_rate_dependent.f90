!> Steady-state rate-dependent friction, the law of the fault-bend model (law RATE DEPENDENT):
!>
!>     mu_ss(V) = mu0 + (a - b) ln(V / V0)
!>
!> Xing, Mora & Makinouchi (2003, sec. 4): "mu = 0.60 + (0.010 - 0.025) ln(V/0.001), dphi/dt = 0",
!> i.e. Ruina's (1983) additive-state law with the state at steady state (method notes 3.1).
!> No state variable.
!>
!> mu_ss is singular as V -> 0, so below a cut-off slip rate V_c = VC the law is regularised, by
!> the user's choice (method notes 3.4):
!>   FLOOR:  mu = mu_ss(max(V, V_c)): constant below V_c (static level mu_ss(V_c)), with a jump
!>           of dmu/dV from (a - b)/V_c to 0 at V_c;
!>   LINEAR: mu = mu_ss(V_c) - (a - b)(1 - V/V_c) for V < V_c: the linear tail of PyLith's
!>           RateStateAgeing (method notes 3.2) applied to the steady-state law; value and slope
!>           are continuous at V_c and mu(0) = mu_ss(V_c) - (a - b).
module fcs_rate_dependent
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  implicit none
  private
  public :: rate_dependent_t, REGULARISATION_FLOOR, REGULARISATION_LINEAR

  !> Regularisation below V_c: mu held at mu_ss(V_c).
  integer, parameter :: REGULARISATION_FLOOR = 1
  !> Regularisation below V_c: linear in V with the slope of mu_ss at V_c.
  integer, parameter :: REGULARISATION_LINEAR = 2

  !> mu0 [-] friction at the reference rate; a, b [-] (only a - b matters); v0 reference slip
  !> rate and cutoff_rate V_c > 0 [length/time]; regularisation REGULARISATION_FLOOR or _LINEAR.
  type, extends(friction_law_t) :: rate_dependent_t
    real(dp) :: mu0 = 0.0_dp
    real(dp) :: a = 0.0_dp
    real(dp) :: b = 0.0_dp
    real(dp) :: v0 = 1.0_dp
    real(dp) :: cutoff_rate = 1.0_dp
    integer :: regularisation = REGULARISATION_LINEAR
  contains
    procedure :: evaluate => rate_dependent_evaluate
    procedure :: name => rate_dependent_name
    procedure :: rate_dependent => always_rate_dependent
  end type rate_dependent_t

contains

  !> mu and dmu/dV at slip rate V >= 0 [length/time] (Xing et al. 2003, sec. 4; regularised
  !> below V_c as in the module header). At V = V_c the branch V >= V_c is used.
  pure function rate_dependent_evaluate(this, pressure, rate, state) result(d)
    class(rate_dependent_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    real(dp) :: slope
    slope = this%a - this%b
    if (rate >= this%cutoff_rate) then
      d%mu = this%mu0 + slope * log(rate / this%v0)
      d%dmu_drate = slope / rate
    else
      d%mu = this%mu0 + slope * log(this%cutoff_rate / this%v0)
      if (this%regularisation == REGULARISATION_LINEAR) then
        d%mu = d%mu - slope * (1.0_dp - rate / this%cutoff_rate)
        d%dmu_drate = slope / this%cutoff_rate
      end if
    end if
  end function rate_dependent_evaluate

  pure function rate_dependent_name(this) result(name)
    class(rate_dependent_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'RATE DEPENDENT'
  end function rate_dependent_name

  !> mu depends on the slip rate.
  pure logical function always_rate_dependent(this)
    class(rate_dependent_t), intent(in) :: this
    always_rate_dependent = .true.
  end function always_rate_dependent

end module fcs_rate_dependent
