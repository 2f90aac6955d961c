!> The abstract friction law mu(f_n, V, phi) of Xing, Mora & Makinouchi (2003, eqs. 3 and 6):
!> the friction coefficient as a function of the normal contact pressure f_n, the slip rate V
!> and a state variable phi, with the derivatives the consistent tangent of eq. (6) needs,
!> and the evolution of the state over an increment.
!>
!> Units are the deck's: pressure [stress], slip rate [length/time], state as the law defines
!> it (theta [time] for Dieterich-Ruina laws). Laws without state ignore phi (n_state() = 0).
module fcs_friction_law
  use fcs_kinds, only: dp
  implicit none
  private
  public :: friction_law_t, friction_derivatives_t

  !> mu and its partial derivatives at one point.
  type :: friction_derivatives_t
    real(dp) :: mu = 0.0_dp
    real(dp) :: dmu_dpressure = 0.0_dp
    real(dp) :: dmu_drate = 0.0_dp
    real(dp) :: dmu_dstate = 0.0_dp
  end type friction_derivatives_t

  type, abstract :: friction_law_t
    !> How the slip rate enters an increment (the deck's RATE UPDATE). Implicit (.false.): mu
    !> at the end-of-increment rate, solved in the return mapping, with the rate term in the
    !> tangent (eq. 6). Explicit (.true.): mu at the rate of the previous increment, known at
    !> the start, so that each increment is a rate-independent cone (the static-explicit
    !> treatment of Xing et al. 2003, sec. 2: states at the start of the increment, changes
    !> limited by the R-minimum). The explicit form is the one that stays well posed when mu
    !> falls with the rate at once (the state-less velocity-weakening law of the fault-bend
    !> model: doc/theory.md, "Explicit slip rate").
    logical :: explicit_rate = .false.
    !> Which velocity the law's V is (the deck's VELOCITY). .false. (SLIP): the plastic slip
    !> rate, the irreversible slip of an increment over its duration. .true. (RELATIVE): the
    !> literal reading of Xing et al. (2003, eq. 3), V = u~dot_eq = sqrt(u~dot_m u~dot_m), the
    !> norm of the total relative tangential velocity between slave and master, elastic (stick)
    !> part included: in stick V = |df_t/dt| / (E_t A), not 0 (doc/friction.md, "VELOCITY").
    logical :: relative_velocity = .false.
  contains
    procedure(evaluate_interface), deferred :: evaluate
    procedure(name_interface), deferred :: name
    procedure :: n_state => friction_law_n_state
    procedure :: initial_state => friction_law_initial_state
    procedure :: evolve_state => friction_law_evolve_state
    procedure :: state_change => friction_law_state_change
    procedure :: characteristic_slip => friction_law_characteristic_slip
    procedure :: rate_dependent => friction_law_rate_dependent
    procedure :: mu => friction_law_mu
  end type friction_law_t

  abstract interface
    !> mu and its derivatives for pressure p >= 0, slip rate v >= 0 and state phi.
    pure function evaluate_interface(this, pressure, rate, state) result(d)
      import :: friction_law_t, friction_derivatives_t, dp
      class(friction_law_t), intent(in) :: this
      real(dp), intent(in) :: pressure, rate, state
      type(friction_derivatives_t) :: d
    end function evaluate_interface

    pure function name_interface(this) result(name)
      import :: friction_law_t
      class(friction_law_t), intent(in) :: this
      character(len=:), allocatable :: name
    end function name_interface
  end interface

contains

  !> The friction coefficient alone.
  pure real(dp) function friction_law_mu(this, pressure, rate, state) result(mu)
    class(friction_law_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    d = this%evaluate(pressure, rate, state)
    mu = d%mu
  end function friction_law_mu

  !> Number of state variables (0 or 1); laws with state override.
  pure integer function friction_law_n_state(this)
    class(friction_law_t), intent(in) :: this
    friction_law_n_state = 0
  end function friction_law_n_state

  !> Initial value of the state variable (0 for laws without state).
  pure real(dp) function friction_law_initial_state(this)
    class(friction_law_t), intent(in) :: this
    friction_law_initial_state = 0.0_dp
  end function friction_law_initial_state

  !> State after slipping at constant rate `rate` for time `dt` (unchanged without state).
  pure real(dp) function friction_law_evolve_state(this, state, rate, dt) result(new_state)
    class(friction_law_t), intent(in) :: this
    real(dp), intent(in) :: state, rate, dt
    new_state = state
  end function friction_law_evolve_state

  !> A dimensionless measure of how much the state changed from `old` to `new`, for the
  !> R-minimum step control (0 for laws without state).
  pure real(dp) function friction_law_state_change(this, old, new) result(change)
    class(friction_law_t), intent(in) :: this
    real(dp), intent(in) :: old, new
    change = 0.0_dp
  end function friction_law_state_change

  !> The slip over which the law's state follows a change of slip rate [length] (L = D_c of
  !> the Dieterich-Ruina laws), for the R-minimum limit MAX SLIP INCREMENT; 0: none.
  pure real(dp) function friction_law_characteristic_slip(this) result(length)
    class(friction_law_t), intent(in) :: this
    length = 0.0_dp
  end function friction_law_characteristic_slip

  !> Whether mu depends on the slip rate (the R-minimum rate limits apply only then).
  pure logical function friction_law_rate_dependent(this)
    class(friction_law_t), intent(in) :: this
    friction_law_rate_dependent = .false.
  end function friction_law_rate_dependent

end module fcs_friction_law
