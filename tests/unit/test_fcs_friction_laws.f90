!> Unit test of the friction laws (fcs_coulomb, fcs_static_kinetic, fcs_slip_weakening,
!> fcs_rate_dependent, fcs_rate_state, fcs_rate_state_arcsinh): every analytic derivative
!> against central finite differences at several points (both sides of the cut-off rate V_c of
!> the regularised laws, and V = 0), continuity of mu and dmu/dV at V_c, and the paper's law
!> against the table of method notes 1.9.
program test_fcs_friction_laws
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  use fcs_coulomb, only: coulomb_t
  use fcs_static_kinetic, only: static_kinetic_t
  use fcs_slip_weakening, only: slip_weakening_t
  use fcs_rate_dependent, only: rate_dependent_t, REGULARISATION_FLOOR, REGULARISATION_LINEAR
  use fcs_rate_state_base, only: STATE_LAW_AGEING, STATE_LAW_SLIP
  use fcs_rate_state, only: rate_state_t
  use fcs_rate_state_arcsinh, only: rate_state_arcsinh_t
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_friction_laws, only: check_derivatives
  implicit none
  type(test_suite_t) :: suite

  suite%name = 'fcs_friction_laws'
  call check_coulomb(suite)
  call check_static_kinetic(suite)
  call check_slip_weakening(suite)
  call check_rate_dependent(suite)
  call check_rate_state(suite)
  call check_rate_state_arcsinh(suite)
  call check_paper_law(suite)
  call suite%report()

contains

  subroutine check_coulomb(suite)
    type(test_suite_t), intent(inout) :: suite
    type(coulomb_t) :: law
    law = coulomb_t(mu0=0.6_dp)
    call check_derivatives(suite, law, 10.0_dp, 1.0e-3_dp, 0.0_dp, 1.0_dp, 1.0_dp, 'COULOMB')
    call check_derivatives(suite, law, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 'COULOMB')
    call suite%check(law%mu(5.0_dp, 3.0_dp, 0.0_dp) == 0.6_dp, 'COULOMB: mu = MU0')
    call suite%equal_int(law%n_state(), 0, 'COULOMB: no state')
  end subroutine check_coulomb

  subroutine check_static_kinetic(suite)
    type(test_suite_t), intent(inout) :: suite
    type(static_kinetic_t) :: law
    integer :: i
    real(dp), parameter :: rates(4) = [1.0e-3_dp, 0.05_dp, 0.1_dp, 0.5_dp]
    law = static_kinetic_t(mu0=0.6_dp, mu_kinetic=0.4_dp, decay=10.0_dp)
    do i = 1, size(rates)
      call check_derivatives(suite, law, 10.0_dp, rates(i), 0.0_dp, 0.1_dp, 1.0_dp, 'STATIC KINETIC')
    end do
    call check_derivatives(suite, law, 10.0_dp, 0.0_dp, 0.0_dp, 0.1_dp, 1.0_dp, 'STATIC KINETIC')
    ! Closed forms: mu(0) = MU0 exactly; mu(1/DECAY) = MUK + (MU0 - MUK)/e to round-off.
    call suite%close_to(law%mu(0.0_dp, 0.0_dp, 0.0_dp), 0.6_dp, 1.0e-15_dp, 'STATIC KINETIC: mu(0)')
    call suite%close_to(law%mu(0.0_dp, 0.1_dp, 0.0_dp), 0.4_dp + 0.2_dp * exp(-1.0_dp), 1.0e-15_dp, &
                        'STATIC KINETIC: mu(1/DECAY)')
    call suite%equal_int(law%n_state(), 0, 'STATIC KINETIC: no state')
  end subroutine check_static_kinetic

  subroutine check_slip_weakening(suite)
    type(test_suite_t), intent(inout) :: suite
    type(slip_weakening_t) :: law
    integer :: i
    real(dp), parameter :: slips(4) = [0.0_dp, 0.3_dp, 0.99_dp, 1.7_dp]
    law = slip_weakening_t(mu0=0.6_dp, mu_kinetic=0.4_dp, dc=1.0_dp)
    ! The slip 0 point straddles the start of weakening only on the unphysical side (slip < 0
    ! continues the same line), so the central difference is still exact there.
    do i = 1, size(slips)
      call check_derivatives(suite, law, 10.0_dp, 1.0e-3_dp, slips(i), 1.0_dp, 1.0_dp, &
                             'SLIP WEAKENING')
    end do
    call suite%equal_int(law%n_state(), 1, 'SLIP WEAKENING: one state')
    call suite%check(law%initial_state() == 0.0_dp, 'SLIP WEAKENING: initial slip 0')
    call suite%close_to(law%evolve_state(0.25_dp, 0.5_dp, 1.5_dp), 1.0_dp, 1.0e-15_dp, &
                        'SLIP WEAKENING: slip + V dt')
    call suite%close_to(law%mu(0.0_dp, 0.0_dp, 0.5_dp), 0.5_dp, 1.0e-15_dp, &
                        'SLIP WEAKENING: mu at DC/2')
    call suite%close_to(law%mu(0.0_dp, 0.0_dp, 5.0_dp), 0.4_dp, 1.0e-15_dp, &
                        'SLIP WEAKENING: mu beyond DC = MUK')
  end subroutine check_slip_weakening

  !> Both regularisations: derivatives at points on both sides of V_c and at V = 0;
  !> continuity of mu at V_c (both) and of dmu/dV (LINEAR; FLOOR has the documented jump).
  subroutine check_rate_dependent(suite)
    type(test_suite_t), intent(inout) :: suite
    type(rate_dependent_t) :: law
    real(dp), parameter :: vc = 1.0e-6_dp
    integer :: k, i
    real(dp) :: rates(6)
    character(len=:), allocatable :: what
    type(friction_derivatives_t) :: below, above
    rates = [0.3_dp * vc, vc * (1.0_dp - 1.0e-3_dp), vc * (1.0_dp + 1.0e-3_dp), 10.0_dp * vc, &
             1.0e-3_dp, 0.1_dp]
    do k = 1, 2
      law = rate_dependent_t(mu0=0.6_dp, a=0.010_dp, b=0.025_dp, v0=1.0e-3_dp, cutoff_rate=vc, &
                             regularisation=merge(REGULARISATION_FLOOR, REGULARISATION_LINEAR, k == 1))
      what = 'RATE DEPENDENT ' // trim(merge('FLOOR ', 'LINEAR', k == 1))
      do i = 1, size(rates)
        call check_derivatives(suite, law, 10.0_dp, rates(i), 0.0_dp, vc, 1.0_dp, what)
      end do
      call check_derivatives(suite, law, 10.0_dp, 0.0_dp, 0.0_dp, vc, 1.0_dp, what)
      ! Continuity at V_c: a relative offset of 1e-14 in V changes mu by |a-b| 1e-14 ~ 1e-16;
      ! 1e-13 allows the rounding of the two branches' logarithms.
      below = law%evaluate(10.0_dp, vc * (1.0_dp - 1.0e-14_dp), 0.0_dp)
      above = law%evaluate(10.0_dp, vc, 0.0_dp)
      call suite%close_to(below%mu, above%mu, 1.0e-13_dp, what // ': mu continuous at VC')
      if (k == 2) then
        call suite%close_to(below%dmu_drate, above%dmu_drate, 1.0e-12_dp, &
                            what // ': dmu/dV continuous at VC')
        call suite%close_to(law%mu(0.0_dp, 0.0_dp, 0.0_dp), above%mu + 0.015_dp, 1.0e-14_dp, &
                            what // ': mu(0) = mu_ss(VC) - (A - B)')
      else
        call suite%check(below%dmu_drate == 0.0_dp .and. above%dmu_drate < 0.0_dp, &
                         what // ': slope jumps from 0 to (A-B)/VC at VC')
        call suite%close_to(law%mu(0.0_dp, 0.0_dp, 0.0_dp), above%mu, 1.0e-15_dp, &
                            what // ': mu(0) = mu_ss(VC)')
      end if
      call suite%equal_int(law%n_state(), 0, what // ': no state')
    end do
  end subroutine check_rate_dependent

  !> Log form with the linear direct-term tail, both state laws (evaluate does not depend on
  !> the state law, so one set of points): derivatives around V_c, at rest, for several theta.
  subroutine check_rate_state(suite)
    type(test_suite_t), intent(inout) :: suite
    type(rate_state_t) :: law
    real(dp), parameter :: vc = 1.0e-9_dp, dc = 0.01_dp
    real(dp) :: rates(6), thetas(3)
    integer :: i, j
    type(friction_derivatives_t) :: below, above
    law = rate_state_t(mu0=0.6_dp, a=0.010_dp, b=0.015_dp, dc=dc, v0=1.0e-3_dp, theta0=10.0_dp, &
                       state_law=STATE_LAW_AGEING, cutoff_rate=vc)
    rates = [0.3_dp * vc, vc * (1.0_dp - 1.0e-3_dp), vc * (1.0_dp + 1.0e-3_dp), 1.0e-6_dp, &
             1.0e-3_dp, 1.0_dp]
    thetas = [1.0e-3_dp, 10.0_dp, 1.0e5_dp]
    do j = 1, size(thetas)
      do i = 1, size(rates)
        call check_derivatives(suite, law, 10.0_dp, rates(i), thetas(j), vc, 1.0_dp, 'RATE STATE')
      end do
      call check_derivatives(suite, law, 10.0_dp, 0.0_dp, thetas(j), vc, 1.0_dp, 'RATE STATE')
    end do
    ! Continuity at V_c of mu and dmu/dV (tolerances as for RATE DEPENDENT).
    below = law%evaluate(10.0_dp, vc * (1.0_dp - 1.0e-14_dp), 10.0_dp)
    above = law%evaluate(10.0_dp, vc, 10.0_dp)
    call suite%close_to(below%mu, above%mu, 1.0e-13_dp, 'RATE STATE: mu continuous at VC')
    call suite%close_to(below%dmu_drate, above%dmu_drate, 1.0e-12_dp, &
                        'RATE STATE: dmu/dV continuous at VC')
    call suite%close_to(law%mu(0.0_dp, 0.0_dp, 10.0_dp), above%mu - 0.010_dp, 1.0e-14_dp, &
                        'RATE STATE: mu(0) = mu(VC) - A')
    ! Steady state at V0: mu = MU0 exactly up to the rounding of two logarithms.
    call suite%close_to(law%mu(0.0_dp, 1.0e-3_dp, dc / 1.0e-3_dp), 0.6_dp, 1.0e-14_dp, &
                        'RATE STATE: mu_ss(V0) = MU0')
    call suite%equal_int(law%n_state(), 1, 'RATE STATE: one state')
    call suite%check(law%initial_state() == 10.0_dp, 'RATE STATE: initial state theta0')
    law%state_law = STATE_LAW_SLIP
    call check_derivatives(suite, law, 10.0_dp, 1.0e-4_dp, 3.0_dp, vc, 1.0_dp, 'RATE STATE slip')
  end subroutine check_rate_state

  !> arcsinh form: points on both sides of x = V z = 1 (where the evaluation switches from the
  !> direct asinh to the logarithmic form), far from it, and at V = 0; two parameter sets, one
  !> with z ~ e^60 (the paper's magnitudes), one with z ~ e^6 so that x ~ 1 at ordinary rates.
  subroutine check_rate_state_arcsinh(suite)
    type(test_suite_t), intent(inout) :: suite
    type(rate_state_arcsinh_t) :: law
    real(dp), parameter :: dc = 0.01_dp, v0 = 1.0e-3_dp
    real(dp), parameter :: factors(7) = [1.0e-3_dp, 0.5_dp, 0.99_dp, 1.01_dp, 2.0_dp, 1.0e3_dp, 1.0e20_dp]
    real(dp) :: mu0s(2), thetas(2), vstar, theta
    integer :: k, i, j
    character(len=40) :: what
    mu0s = [0.6_dp, 0.06_dp]
    thetas = [10.0_dp, 1.0e3_dp]
    do k = 1, 2
      law = rate_state_arcsinh_t(mu0=mu0s(k), a=0.010_dp, b=0.015_dp, dc=dc, v0=v0, &
                                 theta0=10.0_dp, state_law=STATE_LAW_AGEING)
      write (what, '(a,f4.2)') 'RATE STATE ARCSINH mu0=', mu0s(k)
      do j = 1, size(thetas)
        theta = thetas(j)
        ! V* = 1/z: the rate where x = 1.
        vstar = 2.0_dp * v0 * exp(-(law%mu0 + law%b * log(v0 * theta / dc)) / law%a)
        do i = 1, size(factors)
          call check_derivatives(suite, law, 10.0_dp, factors(i) * vstar, theta, vstar, 1.0_dp, &
                                 trim(what))
        end do
        call check_derivatives(suite, law, 10.0_dp, 0.0_dp, theta, vstar, 1.0_dp, trim(what))
        call check_derivatives(suite, law, 10.0_dp, 1.0e-3_dp, theta, vstar, 1.0_dp, trim(what))
        call suite%check(law%mu(0.0_dp, 0.0_dp, theta) == 0.0_dp, trim(what) // ': mu(0) = 0')
      end do
    end do
    ! Far above V*, the arcsinh form is the log form to O(x^-2): at steady state at V0,
    ! mu = MU0 (x = e^60/2, correction ~ 1e-53).
    law%mu0 = 0.6_dp
    call suite%close_to(law%mu(0.0_dp, v0, dc / v0), 0.6_dp, 1.0e-14_dp, &
                        'RATE STATE ARCSINH: mu_ss(V0) = MU0')
  end subroutine check_rate_state_arcsinh

  !> The fault-bend law mu = 0.60 + (0.010 - 0.025) ln(V/0.001) (Xing et al. 2003, sec. 4)
  !> against the 4-digit table of method notes 1.9 (tolerance: half a unit in the 4th digit),
  !> with V_c = 1e-12 mm/s below every tabulated rate; then the static levels the two
  !> regularisations give with V_c = 1e-6 mm/s (the numbers quoted in doc/friction.md).
  subroutine check_paper_law(suite)
    type(test_suite_t), intent(inout) :: suite
    type(rate_dependent_t) :: law
    real(dp), parameter :: rates(10) = [1.0e-9_dp, 1.0e-6_dp, 1.0e-5_dp, 1.0e-4_dp, 1.0e-3_dp, &
                                        1.0e-2_dp, 0.1_dp, 1.0_dp, 10.0_dp, 100.0_dp]
    real(dp), parameter :: table(10) = [0.8072_dp, 0.7036_dp, 0.6691_dp, 0.6345_dp, 0.6000_dp, &
                                        0.5655_dp, 0.5309_dp, 0.4964_dp, 0.4618_dp, 0.4273_dp]
    integer :: i
    character(len=40) :: what
    law = rate_dependent_t(mu0=0.60_dp, a=0.010_dp, b=0.025_dp, v0=0.001_dp, cutoff_rate=1.0e-12_dp, &
                           regularisation=REGULARISATION_FLOOR)
    do i = 1, size(rates)
      write (what, '(a,es8.1,a)') 'paper law at V =', rates(i), ' mm/s'
      call suite%close_to(law%mu(10.0_dp, rates(i), 0.0_dp), table(i), 0.5e-4_dp, trim(what), &
                          floor=1.0_dp)
    end do
    law%cutoff_rate = 1.0e-6_dp
    call suite%close_to(law%mu(10.0_dp, 0.0_dp, 0.0_dp), 0.7036_dp, 0.5e-4_dp, &
                        'paper law, FLOOR, VC = 1e-6: mu(0) = 0.7036', floor=1.0_dp)
    call suite%close_to(law%mu(10.0_dp, 1.0e-8_dp, 0.0_dp), 0.7036_dp, 0.5e-4_dp, &
                        'paper law, FLOOR, VC = 1e-6: mu(1e-8) = 0.7036', floor=1.0_dp)
    law%regularisation = REGULARISATION_LINEAR
    call suite%close_to(law%mu(10.0_dp, 0.0_dp, 0.0_dp), 0.7186_dp, 0.5e-4_dp, &
                        'paper law, LINEAR, VC = 1e-6: mu(0) = 0.7186', floor=1.0_dp)
    call suite%close_to(law%mu(10.0_dp, 0.5e-6_dp, 0.0_dp), 0.7111_dp, 0.5e-4_dp, &
                        'paper law, LINEAR, VC = 1e-6: mu(VC/2) = 0.7111', floor=1.0_dp)
  end subroutine check_paper_law

end program test_fcs_friction_laws
