!> Unit test of the Dieterich-Ruina state evolution (fcs_rate_state_base, through fcs_rate_state
!> and fcs_rate_state_arcsinh): approach to steady state, the exact update against an
!> independent RK4 integration for piecewise-constant rates, a velocity step under rigid loading
!> against its closed form, Ruina's slip law with the paper's parameters (its steady state is
!> the paper's mu = 0.60 + (0.010 - 0.025) ln(V/0.001); a velocity step relaxes over the
!> characteristic slip L), and the limits V dt/D_c -> 0 and V = 0.
program test_fcs_friction_rate_state
  use fcs_kinds, only: dp
  use fcs_rate_state_base, only: rate_state_base_t, STATE_LAW_AGEING, STATE_LAW_SLIP, &
                                 ageing_state_update, slip_state_update
  use fcs_rate_state, only: rate_state_t
  use fcs_rate_state_arcsinh, only: rate_state_arcsinh_t
  use fcs_rate_dependent, only: rate_dependent_t, REGULARISATION_FLOOR
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite

  ! Parameters of the tests (mm, s): the paper's a and mu0, b > a (velocity weakening).
  real(dp), parameter :: MU0 = 0.6_dp, A = 0.010_dp, B = 0.015_dp, DC = 0.01_dp, V0 = 1.0e-3_dp
  real(dp), parameter :: VC = 1.0e-9_dp

  suite%name = 'fcs_friction_rate_state'
  call check_steady_state(suite)
  call check_against_rk4(suite)
  call check_velocity_step(suite)
  call check_limits(suite)
  call check_paper_slip_law(suite)
  call suite%report()

contains

  !> The law `kind` (1: log form, 2: arcsinh) with state law `state_law` and initial state
  !> theta0.
  subroutine make_law(kind, state_law, theta0, law)
    integer, intent(in) :: kind, state_law
    real(dp), intent(in) :: theta0
    class(rate_state_base_t), allocatable, intent(out) :: law
    if (kind == 1) then
      allocate (law, source=rate_state_t(mu0=MU0, a=A, b=B, dc=DC, v0=V0, theta0=theta0, &
                                         state_law=state_law, cutoff_rate=VC))
    else
      allocate (law, source=rate_state_arcsinh_t(mu0=MU0, a=A, b=B, dc=DC, v0=V0, &
                                                 theta0=theta0, state_law=state_law))
    end if
  end subroutine make_law

  pure real(dp) function steady_mu(rate)
    real(dp), intent(in) :: rate
    steady_mu = MU0 + (A - B) * log(rate / V0)
  end function steady_mu

  !> Slide at V = 1e-2 mm/s from the steady state of V/100 for 40 D_c of slip in 400 steps:
  !> theta -> D_c/V and mu -> mu_ss(V). The remaining transient is e^-40 ~ 4e-18 of the initial
  !> offset (ageing) or of ln(100) (slip law), and the arcsinh form differs from the log form
  !> by O(e^-120); 1e-6 is the brief's tolerance, met with a wide margin.
  subroutine check_steady_state(suite)
    type(test_suite_t), intent(inout) :: suite
    class(rate_state_base_t), allocatable :: law
    real(dp), parameter :: rate = 1.0e-2_dp
    real(dp) :: theta, dt
    integer :: kind, state_law, step
    character(len=40) :: what
    dt = 0.1_dp * DC / rate
    do kind = 1, 2
      do state_law = STATE_LAW_AGEING, STATE_LAW_SLIP
        write (what, '(a,i0,a,i0)') 'steady state: form ', kind, ', state law ', state_law
        call make_law(kind, state_law, DC / (rate / 100.0_dp), law)
        theta = law%initial_state()
        do step = 1, 400
          theta = law%evolve_state(theta, rate, dt)
        end do
        call suite%close_to(theta, DC / rate, 1.0e-6_dp, trim(what) // ': theta = DC/V')
        call suite%close_to(law%mu(0.0_dp, rate, theta), steady_mu(rate), 1.0e-6_dp, &
                            trim(what) // ': mu = mu_ss(V)')
      end do
    end do
  end subroutine check_steady_state

  !> Right-hand side of the state ODE (method notes 3.1).
  pure real(dp) function state_rate(state_law, theta, rate)
    integer, intent(in) :: state_law
    real(dp), intent(in) :: theta, rate
    if (state_law == STATE_LAW_AGEING) then
      state_rate = 1.0_dp - rate * theta / DC
    else if (rate > 0.0_dp) then
      state_rate = -(rate * theta / DC) * log(rate * theta / DC)
    else
      state_rate = 0.0_dp
    end if
  end function state_rate

  !> Classical fourth-order Runge-Kutta over `duration` in n equal steps at constant rate.
  pure real(dp) function rk4(state_law, theta0, rate, duration, n) result(theta)
    integer, intent(in) :: state_law, n
    real(dp), intent(in) :: theta0, rate, duration
    real(dp) :: h, k1, k2, k3, k4
    integer :: i
    h = duration / n
    theta = theta0
    do i = 1, n
      k1 = state_rate(state_law, theta, rate)
      k2 = state_rate(state_law, theta + 0.5_dp * h * k1, rate)
      k3 = state_rate(state_law, theta + 0.5_dp * h * k2, rate)
      k4 = state_rate(state_law, theta + h * k3, rate)
      theta = theta + h * (k1 + 2.0_dp * k2 + 2.0_dp * k3 + k4) / 6.0_dp
    end do
  end function rk4

  !> A sequence of piecewise-constant rates (including a hold at V = 0 and jumps of up to two
  !> decades), each over 0.3-5 D_c of slip: the exact update after each piece against RK4 with
  !> 20000 steps per piece. The stiffest rate is (V/D_c)(1 + |ln(V theta/D_c)|) <~ 6 V/D_c, so
  !> h times it is <~ 1.5e-3 and RK4's global error ~ (1.5e-3)^4 ~ 5e-12 relative, plus
  !> ~ 20000 eps of rounding ~ 4e-12: the brief's 1e-8 relative is a safe bound for both.
  subroutine check_against_rk4(suite)
    type(test_suite_t), intent(inout) :: suite
    class(rate_state_base_t), allocatable :: law
    real(dp), parameter :: rates(8) = [1.0e-3_dp, 1.0e-1_dp, 1.0e-5_dp, 0.0_dp, 3.0e-2_dp, &
                                       1.0e-3_dp, 2.0e-4_dp, 5.0e-2_dp]
    real(dp), parameter :: slips(8) = [1.0_dp, 5.0_dp, 0.3_dp, 0.0_dp, 2.0_dp, 0.7_dp, 3.0_dp, 0.5_dp]
    real(dp) :: theta_exact, theta_rk4, duration
    integer :: state_law, piece
    character(len=60) :: what
    do state_law = STATE_LAW_AGEING, STATE_LAW_SLIP
      call make_law(1, state_law, DC / 1.0e-3_dp, law)
      theta_exact = law%initial_state()
      theta_rk4 = theta_exact
      do piece = 1, size(rates)
        if (rates(piece) > 0.0_dp) then
          duration = slips(piece) * DC / rates(piece)
        else
          duration = 5.0_dp
        end if
        theta_exact = law%evolve_state(theta_exact, rates(piece), duration)
        theta_rk4 = rk4(state_law, theta_rk4, rates(piece), duration, 20000)
        write (what, '(a,i0,a,i0,a,es8.1)') 'RK4: state law ', state_law, ', piece ', piece, &
          ', V =', rates(piece)
        call suite%close_to(theta_exact, theta_rk4, 1.0e-8_dp, trim(what))
      end do
    end do
  end subroutine check_against_rk4

  !> Velocity step V1 -> V2 = 10 V1 from steady state at V1 under rigid loading (method notes
  !> 3.1): the direct effect A ln 10 at once, then theta(delta) = D_c/V2 + (D_c/V1 - D_c/V2)
  !> e^{-delta/D_c} (ageing) or theta = (D_c/V2) exp(ln(10) e^{-delta/D_c}) (slip), checked at
  !> delta = D_c and 3 D_c, and the new steady state (A - B) ln 10 after 30 D_c. Each D_c is
  !> covered in 50 increments, so the exact updates compose; the closed forms agree to
  !> rounding (~1e-14), 1e-12 is the tolerance. The arcsinh form's direct effect differs
  !> from A ln 10 by O(x^-2) ~ e^-120 (x = V z ~ e^60).
  subroutine check_velocity_step(suite)
    type(test_suite_t), intent(inout) :: suite
    class(rate_state_base_t), allocatable :: law
    real(dp), parameter :: v1 = 1.0e-3_dp, v2 = 1.0e-2_dp
    real(dp) :: theta, closed, dt, mu1
    integer :: kind, state_law, step
    character(len=48) :: what
    dt = DC / (50.0_dp * v2)
    do kind = 1, 2
      do state_law = STATE_LAW_AGEING, STATE_LAW_SLIP
        write (what, '(a,i0,a,i0)') 'velocity step: form ', kind, ', state law ', state_law
        call make_law(kind, state_law, DC / v1, law)
        theta = law%initial_state()
        mu1 = law%mu(0.0_dp, v1, theta)
        call suite%close_to(mu1, steady_mu(v1), 1.0e-12_dp, trim(what) // ': mu_ss(V1)')
        call suite%close_to(law%mu(0.0_dp, v2, theta) - mu1, A * log(10.0_dp), 1.0e-12_dp, &
                            trim(what) // ': direct effect A ln 10')
        do step = 1, 30 * 50
          theta = law%evolve_state(theta, v2, dt)
          if (step == 50 .or. step == 150) then
            closed = closed_theta(state_law, v1, v2, step * v2 * dt)
            call suite%close_to(theta, closed, 1.0e-12_dp, trim(what) // ': theta(delta)')
            call suite%close_to(law%mu(0.0_dp, v2, theta), law%mu(0.0_dp, v2, closed), &
                                1.0e-12_dp, trim(what) // ': mu(delta)')
          end if
        end do
        ! After 30 D_c the transient is e^-30 ~ 1e-13 of B ln 10 for ageing; for the slip law
        ! ln(10) e^-30 in ln(theta): both well inside 1e-9 absolute on (A - B) ln 10 ~ 0.01.
        call suite%close_to(law%mu(0.0_dp, v2, theta) - mu1, (A - B) * log(10.0_dp), 1.0e-9_dp, &
                            trim(what) // ': steady change (A - B) ln 10')
      end do
    end do
  end subroutine check_velocity_step

  pure real(dp) function closed_theta(state_law, v1, v2, slip) result(theta)
    integer, intent(in) :: state_law
    real(dp), intent(in) :: v1, v2, slip
    if (state_law == STATE_LAW_AGEING) then
      theta = DC / v2 + (DC / v1 - DC / v2) * exp(-slip / DC)
    else
      theta = (DC / v2) * exp(log(v2 / v1) * exp(-slip / DC))
    end if
  end function closed_theta

  !> Small V dt/D_c: the ageing update against its Taylor expansion theta (1 - x + x^2/2) +
  !> dt (1 - x/2 + x^2/6), with x = 1e-9, 1e-12, 1e-300 (cancellation in the naive
  !> (D_c/V)(1 - e^-x) would lose 9-16 digits or give 0/0; the expansion's error is O(x^3));
  !> V = 0: theta + dt (ageing, healing at rest) and unchanged (slip law); dt = 0: unchanged.
  subroutine check_limits(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: xs(3) = [1.0e-9_dp, 1.0e-12_dp, 1.0e-300_dp]
    real(dp) :: theta, dt, rate, x, expected
    integer :: i
    theta = 7.0_dp
    dt = 3.0_dp
    do i = 1, size(xs)
      x = xs(i)
      rate = x * DC / dt
      expected = theta * (1.0_dp - x + 0.5_dp * x**2) + dt * (1.0_dp - 0.5_dp * x + x**2 / 6.0_dp)
      ! Tolerance: a few ulps of a sum of two O(1) terms.
      call suite%close_to(ageing_state_update(theta, rate, dt, DC), expected, 1.0e-15_dp, &
                          'ageing update, small V dt/DC')
    end do
    call suite%check(ageing_state_update(theta, 0.0_dp, dt, DC) == theta + dt, &
                     'ageing update at V = 0: theta + dt')
    call suite%check(slip_state_update(theta, 0.0_dp, dt, DC) == theta, &
                     'slip update at V = 0: unchanged')
    call suite%check(ageing_state_update(theta, 1.0_dp, 0.0_dp, DC) == theta, &
                     'ageing update over dt = 0: unchanged')
    call suite%check(slip_state_update(theta, 1.0_dp, 0.0_dp, DC) == theta, &
                     'slip update over dt = 0: unchanged')
    ! Steady state is a fixed point of both updates (to rounding).
    call suite%close_to(ageing_state_update(DC / 0.2_dp, 0.2_dp, 1.0e3_dp, DC), DC / 0.2_dp, &
                        1.0e-14_dp, 'ageing update: steady state is fixed')
    call suite%close_to(slip_state_update(DC / 0.2_dp, 0.2_dp, 1.0e3_dp, DC), DC / 0.2_dp, &
                        1.0e-14_dp, 'slip update: steady state is fixed')
    ! Very long hold-free slip: no overflow or NaN, theta -> D_c/V.
    call suite%close_to(ageing_state_update(1.0e6_dp, 1.0_dp, 1.0e6_dp, DC), DC, 1.0e-14_dp, &
                        'ageing update, V dt/DC = 1e8')
    call suite%close_to(slip_state_update(1.0e6_dp, 1.0_dp, 1.0e6_dp, DC), DC, 1.0e-14_dp, &
                        'slip update, V dt/DC = 1e8')
  end subroutine check_limits

  !> RATE STATE with STATE LAW=SLIP (Ruina 1983) and the paper's parameters (Xing et al. 2003,
  !> sec. 4: MU0 = 0.60, A = 0.010, B = 0.025, V0 = 0.001 mm/s) and L = D_c = 0.05 mm.
  !> 1. At steady state theta = L/V its mu is the paper's law, RATE DEPENDENT's
  !>    mu_ss = MU0 + (A - B) ln(V/V0), for V from 1e-6 to 100 mm/s (the same formula: 1e-14).
  !> 2. Velocity step V1 = 1e-3 -> V2 = 1e-1 mm/s from steady state, in increments of L/20 of
  !>    slip: with psi = ln(V theta/L), the slip law gives dpsi/d(delta) = -psi/L at constant V,
  !>    so psi = ln(V2/V1) e^{-delta/L} and
  !>      mu(delta) = mu_ss(V2) + B ln(V2/V1) e^{-delta/L},
  !>    the exponential approach over L (Ruina 1983, eq. 8 integrated). Checked at delta = L/2,
  !>    L, 2 L, 5 L and 20 L; the exact update composes, so rounding (1e-13 after 400
  !>    increments) is all that separates them: tolerance 1e-12.
  subroutine check_paper_slip_law(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: PAPER_MU0 = 0.60_dp, PAPER_A = 0.010_dp, PAPER_B = 0.025_dp
    real(dp), parameter :: PAPER_V0 = 1.0e-3_dp, L = 0.05_dp
    real(dp), parameter :: rates(5) = [1.0e-6_dp, 1.0e-4_dp, 1.0e-3_dp, 1.0_dp, 100.0_dp]
    real(dp), parameter :: v1 = 1.0e-3_dp, v2 = 1.0e-1_dp
    integer, parameter :: checked(5) = [10, 20, 40, 100, 400]
    type(rate_state_t) :: law
    type(rate_dependent_t) :: paper
    real(dp) :: theta, dt, closed, mu_ss2
    integer :: i, step
    character(len=60) :: what
    law = rate_state_t(mu0=PAPER_MU0, a=PAPER_A, b=PAPER_B, dc=L, v0=PAPER_V0, theta0=L / v1, &
                       state_law=STATE_LAW_SLIP, cutoff_rate=1.0e-12_dp)
    paper = rate_dependent_t(mu0=PAPER_MU0, a=PAPER_A, b=PAPER_B, v0=PAPER_V0, &
                             cutoff_rate=1.0e-12_dp, regularisation=REGULARISATION_FLOOR)
    do i = 1, size(rates)
      write (what, '(a,es8.1,a)') 'slip law, paper: steady state at V =', rates(i), ' mm/s'
      call suite%close_to(law%mu(0.0_dp, rates(i), L / rates(i)), paper%mu(0.0_dp, rates(i), 0.0_dp), &
                          1.0e-14_dp, trim(what))
    end do
    mu_ss2 = PAPER_MU0 + (PAPER_A - PAPER_B) * log(v2 / PAPER_V0)
    theta = law%initial_state()
    dt = L / (20.0_dp * v2)
    step = 0
    do i = 1, size(checked)
      do while (step < checked(i))
        theta = law%evolve_state(theta, v2, dt)
        step = step + 1
      end do
      closed = mu_ss2 + PAPER_B * log(v2 / v1) * exp(-step * v2 * dt / L)
      write (what, '(a,f5.2,a)') 'slip law, paper: velocity step, mu at ', step / 20.0_dp, ' L'
      call suite%close_to(law%mu(0.0_dp, v2, theta), closed, 1.0e-12_dp, trim(what))
    end do
  end subroutine check_paper_slip_law

end program test_fcs_friction_rate_state
