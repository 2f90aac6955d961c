!> Linear slip-weakening friction (law SLIP WEAKENING):
!>
!>     mu(delta) = mu_s - (mu_s - mu_k) min(delta / D_c, 1)
!>
!> with the accumulated slip delta [length] as the state variable, mu_s = MU0, mu_k = MUK <= mu_s
!> and the slip-weakening distance D_c = DC [length] (Ida 1972, J. Geophys. Res. 77:3796;
!> Andrews 1976, J. Geophys. Res. 81:5679). The state starts at 0 and grows by V dt per increment.
module fcs_slip_weakening
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  implicit none
  private
  public :: slip_weakening_t

  !> Linear slip weakening; mu0 = static, mu_kinetic = residual coefficient [-],
  !> dc = slip-weakening distance [length].
  type, extends(friction_law_t) :: slip_weakening_t
    real(dp) :: mu0 = 0.0_dp
    real(dp) :: mu_kinetic = 0.0_dp
    real(dp) :: dc = 1.0_dp
  contains
    procedure :: evaluate => slip_weakening_evaluate
    procedure :: name => slip_weakening_name
    procedure :: n_state => slip_weakening_n_state
    procedure :: evolve_state => slip_weakening_evolve_state
    procedure :: state_change => slip_weakening_state_change
  end type slip_weakening_t

contains

  !> mu(delta) and dmu/d(delta) = -(mu0 - muk)/D_c for delta < D_c, 0 beyond (the one-sided
  !> slope past the kink at delta = D_c); the state is the slip delta [length].
  pure function slip_weakening_evaluate(this, pressure, rate, state) result(d)
    class(slip_weakening_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    if (state < this%dc) then
      d%mu = this%mu0 - (this%mu0 - this%mu_kinetic) * state / this%dc
      d%dmu_dstate = -(this%mu0 - this%mu_kinetic) / this%dc
    else
      d%mu = this%mu_kinetic
    end if
  end function slip_weakening_evaluate

  pure function slip_weakening_name(this) result(name)
    class(slip_weakening_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'SLIP WEAKENING'
  end function slip_weakening_name

  !> One state variable: the accumulated slip.
  pure integer function slip_weakening_n_state(this)
    class(slip_weakening_t), intent(in) :: this
    slip_weakening_n_state = 1
  end function slip_weakening_n_state

  !> Slip after slipping at rate V [length/time] for dt [time]: delta + V dt (exact).
  pure real(dp) function slip_weakening_evolve_state(this, state, rate, dt) result(new_state)
    class(slip_weakening_t), intent(in) :: this
    real(dp), intent(in) :: state, rate, dt
    new_state = state + rate * dt
  end function slip_weakening_evolve_state

  !> Slip over the increment in units of DC.
  pure real(dp) function slip_weakening_state_change(this, old, new) result(change)
    class(slip_weakening_t), intent(in) :: this
    real(dp), intent(in) :: old, new
    change = abs(new - old) / this%dc
  end function slip_weakening_state_change

end module fcs_slip_weakening
