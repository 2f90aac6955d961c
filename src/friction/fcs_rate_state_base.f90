!> What the Dieterich-Ruina rate-and-state laws (RATE STATE, RATE STATE ARCSINH) share: their
!> parameters, the state variable theta [time], its initial value and its exact evolution over
!> an increment at constant slip rate.
!>
!> State laws (method notes 3.1):
!>   AGEING (Dieterich 1979, J. Geophys. Res. 84:2161; Ruina 1983):  dtheta/dt = 1 - V theta/D_c
!>   SLIP   (Ruina 1983, J. Geophys. Res. 88:10359):   dtheta/dt = -(V theta/D_c) ln(V theta/D_c)
!> Both have the steady state theta_ss = D_c/V. At constant V over dt, with x = V dt/D_c:
!>   ageing:  theta(dt) = theta e^{-x} + (D_c/V)(1 - e^{-x})  (PyLith RateStateAgeing, notes 3.2),
!>            evaluated as theta e^{-x} + dt (1 - e^{-x})/x, which has no cancellation as x -> 0
!>            and gives theta + dt at V = 0 (healing at rest);
!>   slip:    ln(V theta/D_c) decays as e^{-x}, i.e. theta(dt) = theta exp(psi (e^{-x} - 1)) with
!>            psi = ln(V theta/D_c); theta is unchanged at V = 0.
module fcs_rate_state_base
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_law_t
  implicit none
  private
  public :: rate_state_base_t, STATE_LAW_AGEING, STATE_LAW_SLIP
  public :: ageing_state_update, slip_state_update

  !> Dieterich's ageing law dtheta/dt = 1 - V theta/D_c.
  integer, parameter :: STATE_LAW_AGEING = 1
  !> Ruina's slip law dtheta/dt = -(V theta/D_c) ln(V theta/D_c).
  integer, parameter :: STATE_LAW_SLIP = 2

  !> Parameters of a Dieterich-Ruina law: mu0 [-] friction at steady sliding at v0; a, b [-]
  !> direct and evolution effects; dc characteristic slip [length]; v0 reference slip rate
  !> [length/time]; theta0 initial state [time]; state_law STATE_LAW_AGEING or STATE_LAW_SLIP.
  type, abstract, extends(friction_law_t) :: rate_state_base_t
    real(dp) :: mu0 = 0.0_dp
    real(dp) :: a = 0.0_dp
    real(dp) :: b = 0.0_dp
    real(dp) :: dc = 1.0_dp
    real(dp) :: v0 = 1.0_dp
    real(dp) :: theta0 = 1.0_dp
    integer :: state_law = STATE_LAW_AGEING
  contains
    procedure :: n_state => rate_state_n_state
    procedure :: initial_state => rate_state_initial_state
    procedure :: evolve_state => rate_state_evolve_state
    procedure :: state_change => rate_state_state_change
    procedure :: characteristic_slip => rate_state_characteristic_slip
    procedure :: rate_dependent => always_rate_dependent
  end type rate_state_base_t

contains

  !> One state variable, theta [time].
  pure integer function rate_state_n_state(this)
    class(rate_state_base_t), intent(in) :: this
    rate_state_n_state = 1
  end function rate_state_n_state

  !> theta0 [time], as the factory set it (THETA0, or D_c/VINIT).
  pure real(dp) function rate_state_initial_state(this)
    class(rate_state_base_t), intent(in) :: this
    rate_state_initial_state = this%theta0
  end function rate_state_initial_state

  !> theta [time] after slipping at constant rate V >= 0 [length/time] for dt >= 0 [time],
  !> exact for the chosen state law (module header).
  pure real(dp) function rate_state_evolve_state(this, state, rate, dt) result(new_state)
    class(rate_state_base_t), intent(in) :: this
    real(dp), intent(in) :: state, rate, dt
    select case (this%state_law)
    case (STATE_LAW_SLIP)
      new_state = slip_state_update(state, rate, dt, this%dc)
    case default
      new_state = ageing_state_update(state, rate, dt, this%dc)
    end select
  end function rate_state_evolve_state

  !> Exact solution of the ageing law dtheta/dt = 1 - V theta/D_c at constant V over dt
  !> (Dieterich 1979; PyLith RateStateAgeing, method notes 3.2):
  !> theta e^{-x} + dt (1 - e^{-x})/x with x = V dt/D_c, -> theta + dt for x -> 0.
  !> theta [time], rate V [length/time], dt [time], dc [length].
  pure real(dp) function ageing_state_update(theta, rate, dt, dc) result(new_theta)
    real(dp), intent(in) :: theta, rate, dt, dc
    real(dp) :: x, decay_minus_one, relaxation
    x = rate * dt / dc
    decay_minus_one = exp_minus_one(-x)
    if (x > 0.0_dp) then
      relaxation = -decay_minus_one / x
    else
      relaxation = 1.0_dp
    end if
    new_theta = theta * (1.0_dp + decay_minus_one) + dt * relaxation
  end function ageing_state_update

  !> Exact solution of the slip law at constant V over dt (Ruina 1983): psi = ln(V theta/D_c)
  !> obeys dpsi/dt = -(V/D_c) psi, so theta(dt) = theta exp(psi (e^{-x} - 1)), x = V dt/D_c;
  !> theta is unchanged at V = 0. theta [time], rate [length/time], dt [time], dc [length].
  pure real(dp) function slip_state_update(theta, rate, dt, dc) result(new_theta)
    real(dp), intent(in) :: theta, rate, dt, dc
    real(dp) :: psi
    if (rate <= 0.0_dp .or. dt <= 0.0_dp) then
      new_theta = theta
      return
    end if
    psi = log(rate) + log(max(theta, tiny(theta))) - log(dc)
    new_theta = theta * exp(psi * exp_minus_one(-rate * dt / dc))
  end function slip_state_update

  !> L = D_c [length].
  pure real(dp) function rate_state_characteristic_slip(this) result(length)
    class(rate_state_base_t), intent(in) :: this
    length = this%dc
  end function rate_state_characteristic_slip

  !> e^x - 1 without cancellation for small |x| (Kahan's trick: (u - 1) x / ln u with u = e^x;
  !> Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., sec. 1.14.1).
  pure real(dp) function exp_minus_one(x) result(y)
    real(dp), intent(in) :: x
    real(dp) :: u
    u = exp(x)
    if (u == 1.0_dp) then
      y = x
    else if (u - 1.0_dp == -1.0_dp) then
      y = -1.0_dp
    else
      y = (u - 1.0_dp) * x / log(u)
    end if
  end function exp_minus_one

  !> |ln(theta_new / theta_old)|: the change of the state's contribution b ln(theta) to mu,
  !> in units of b.
  pure real(dp) function rate_state_state_change(this, old, new) result(change)
    class(rate_state_base_t), intent(in) :: this
    real(dp), intent(in) :: old, new
    change = 0.0_dp
    if (old > 0.0_dp .and. new > 0.0_dp) change = abs(log(new / old))
  end function rate_state_state_change

  !> mu depends on the slip rate.
  pure logical function always_rate_dependent(this)
    class(rate_state_base_t), intent(in) :: this
    always_rate_dependent = .true.
  end function always_rate_dependent

end module fcs_rate_state_base
