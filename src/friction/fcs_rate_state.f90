!> Dieterich-Ruina rate-and-state friction, logarithmic form (law RATE STATE):
!>
!>     mu = mu0 + a ln(V/V0) + b ln(V0 theta/D_c)                 for V >= V_c
!>     mu = mu0 + a ln(V_c/V0) + b ln(V0 theta/D_c) - a (1 - V/V_c)  for V < V_c
!>
!> (Dieterich 1979; Ruina 1983; method notes 3.1). The direct term a ln(V/V0) is singular at
!> V = 0; below the cut-off slip rate V_c = VC it is replaced by its tangent line at V_c, the
!> linear regularisation of PyLith's RateStateAgeing (`linear_slip_rate`, method notes 3.2):
!> value and slope a/V_c continuous at V_c, finite mu at rest. The state term is not
!> regularised. State theta [time] with the ageing or slip law (fcs_rate_state_base).
!> Steady state: theta = D_c/V, mu_ss = mu0 + (a - b) ln(V/V0) for V >= V_c.
module fcs_rate_state
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_derivatives_t
  use fcs_rate_state_base, only: rate_state_base_t
  implicit none
  private
  public :: rate_state_t

  !> The logarithmic Dieterich-Ruina law; cutoff_rate V_c > 0 [length/time] where the direct
  !> term turns linear (other parameters in rate_state_base_t).
  type, extends(rate_state_base_t) :: rate_state_t
    real(dp) :: cutoff_rate = 1.0_dp
  contains
    procedure :: evaluate => rate_state_evaluate
    procedure :: name => rate_state_name
  end type rate_state_t

contains

  !> mu, dmu/dV (a/V above V_c, a/V_c below) and dmu/dtheta = b/theta at slip rate V >= 0
  !> [length/time] and state theta > 0 [time] (module header; theta <= 0, which no state law
  !> produces from theta0 > 0, is read as the smallest positive number to stay finite).
  pure function rate_state_evaluate(this, pressure, rate, state) result(d)
    class(rate_state_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    real(dp) :: theta
    theta = max(state, tiny(state))
    d%mu = this%mu0 + this%b * log(this%v0 * theta / this%dc)
    d%dmu_dstate = this%b / theta
    if (rate >= this%cutoff_rate) then
      d%mu = d%mu + this%a * log(rate / this%v0)
      d%dmu_drate = this%a / rate
    else
      d%mu = d%mu + this%a * log(this%cutoff_rate / this%v0) &
             - this%a * (1.0_dp - rate / this%cutoff_rate)
      d%dmu_drate = this%a / this%cutoff_rate
    end if
  end function rate_state_evaluate

  pure function rate_state_name(this) result(name)
    class(rate_state_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'RATE STATE'
  end function rate_state_name

end module fcs_rate_state
