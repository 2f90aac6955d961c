!> Unit test of fcs_drucker_prager: the return mapping on the smooth cone (F = 0 after the
!> return, the plastic flow direction of (D3)-(D4): volume change tan(psi) per unit multiplier,
!> eps_bar = c dl), at the apex (sigma = d / tan(beta) I) with hardening; beta = psi = 0 against
!> fcs_von_mises (the same update); the consistent tangents (D7), (D8) against central finite
!> differences, associated (symmetric) and non-associated (unsymmetric); the start tangent (D5)
!> as the limit of the update for small loading increments; the yield event (D9) landing on the
!> cone, also through the apex; the triaxial compression yield stress of the closed form.
program test_fcs_drucker_prager
  use fcs_kinds, only: dp
  use fcs_drucker_prager, only: drucker_prager_t
  use fcs_von_mises, only: von_mises_t
  use fcs_hardening_table, only: hardening_table_t, constant_table
  use fcs_voigt, only: deviator, stress_norm, trace, VOIGT_IDENTITY
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite

  real(dp), parameter :: YOUNG = 30000.0_dp, POISSON = 0.25_dp, SIGMA_C = 40.0_dp
  real(dp), parameter :: DEGREE = acos(-1.0_dp) / 180.0_dp
  !> Round-off of the closed-form checks (see test_fcs_von_mises).
  real(dp), parameter :: EXACT = 1.0e-12_dp
  !> Central differences (see test_fcs_von_mises for the argument).
  real(dp), parameter :: FD_STEP = 1.0e-7_dp, FD_TOLERANCE = 1.0e-6_dp

  suite%name = 'fcs_drucker_prager'
  call check_smooth_return(suite)
  call check_apex(suite)
  call check_von_mises_limit(suite)
  call check_consistent_tangent(suite)
  call check_start_tangent(suite)
  call check_event(suite)
  call check_triaxial(suite)
  call suite%report()

contains

  !> A material with angles beta, psi [degree], TYPE=COMPRESSION hardening through the points.
  function material(beta, psi, stress, strain) result(m)
    real(dp), intent(in) :: beta, psi, stress(:), strain(:)
    type(drucker_prager_t) :: m
    m%youngs_modulus = YOUNG
    m%poisson_ratio = POISSON
    m%tan_friction = tan(beta * DEGREE)
    m%tan_dilation = tan(psi * DEGREE)
    m%hardening%stress = stress
    m%hardening%strain = strain
    m%cohesion_factor = 1.0_dp - m%tan_friction / 3.0_dp
    m%rate_factor = 1.0_dp - m%tan_dilation / 3.0_dp
    m%hardening_type = 'compression'
  end function material

  pure real(dp) function yield_function(m, stress, eps_bar) result(f)
    type(drucker_prager_t), intent(in) :: m
    real(dp), intent(in) :: stress(6), eps_bar
    f = sqrt(1.5_dp) * stress_norm(deviator(stress)) + m%tan_friction * trace(stress) / 3.0_dp - &
        m%cohesion(eps_bar)
  end function yield_function

  !> A compressive, shearing trial beyond the cone: F = 0 after the return; tr(d eps_p) =
  !> tan(psi) dl and d eps_bar = c dl, i.e. tr(d eps_p) / d eps_bar = tan(psi) / c.
  subroutine check_smooth_return(suite)
    type(test_suite_t), intent(inout) :: suite
    type(drucker_prager_t) :: m
    real(dp) :: stress(6), state(7), plastic(6)
    m = material(30.0_dp, 10.0_dp, [SIGMA_C, 60.0_dp], [0.0_dp, 0.01_dp])
    stress = -20.0_dp * VOIGT_IDENTITY
    state = 0.0_dp
    call m%update(stress, [-0.004_dp, 0.001_dp, 0.0015_dp, 0.002_dp, -0.001_dp, 0.0_dp], state)
    call suite%check(state(1) > 0.0_dp, 'smooth return: plastic')
    call suite%close_to(yield_function(m, stress, state(1)), 0.0_dp, EXACT, &
                        'smooth return: on the cone', floor=SIGMA_C)
    plastic = m%plastic_strain(state)
    call suite%close_to(trace(plastic) / state(1), m%tan_dilation / m%rate_factor, EXACT, &
                        'smooth return: plastic volume change tan(psi) / c per unit eps_bar')
  end subroutine check_smooth_return

  !> Hydrostatic tension beyond the apex: sigma = d(eps_bar) / tan(beta) I on the hardened
  !> cohesion, plastic volume change v with eps_bar = eps_n + c v / tan(psi).
  subroutine check_apex(suite)
    type(test_suite_t), intent(inout) :: suite
    type(drucker_prager_t) :: m
    real(dp) :: stress(6), state(7), plastic(6)
    m = material(35.0_dp, 20.0_dp, [SIGMA_C, 80.0_dp], [0.0_dp, 0.01_dp])
    stress = 0.0_dp
    state = 0.0_dp
    call m%update(stress, [0.01_dp, 0.01_dp, 0.01_dp, 0.001_dp, 0.0_dp, 0.0_dp], state)
    call suite%check(state(1) > 0.0_dp, 'apex: plastic')
    call suite%close_array(stress, m%cohesion(state(1)) / m%tan_friction * VOIGT_IDENTITY, EXACT, &
                           'apex: sigma = d / tan(beta) I')
    plastic = m%plastic_strain(state)
    call suite%close_to(state(1), m%rate_factor * trace(plastic) / m%tan_dilation, EXACT, &
                        'apex: eps_bar = c v / tan(psi)')
  end subroutine check_apex

  !> beta = psi = 0 with COMPRESSION hardening is von Mises with isotropic hardening.
  subroutine check_von_mises_limit(suite)
    type(test_suite_t), intent(inout) :: suite
    type(drucker_prager_t) :: m
    type(von_mises_t) :: v
    real(dp) :: a(6), b(6), state_a(7), state_b(13), increment(6)
    m = material(0.0_dp, 0.0_dp, [SIGMA_C, 60.0_dp, 70.0_dp], [0.0_dp, 0.002_dp, 0.01_dp])
    v%youngs_modulus = YOUNG
    v%poisson_ratio = POISSON
    v%radius = m%hardening
    v%kinematic = constant_table(0.0_dp)
    v%hardening = 'isotropic'
    a = [10.0_dp, -5.0_dp, 3.0_dp, 4.0_dp, -2.0_dp, 1.0_dp]
    b = a
    state_a = 0.0_dp
    state_b = 0.0_dp
    increment = [0.003_dp, -0.001_dp, -0.0005_dp, 0.002_dp, 0.001_dp, -0.001_dp]
    call m%update(a, increment, state_a)
    call v%update(b, increment, state_b)
    call suite%close_array(a, b, EXACT, 'beta = psi = 0: the von Mises stress')
    call suite%close_to(state_a(1), state_b(1), EXACT, 'beta = psi = 0: the von Mises PEEQ')
  end subroutine check_von_mises_limit

  !> (D7) and (D8) against central differences; symmetric exactly when psi = beta.
  subroutine check_consistent_tangent(suite)
    type(test_suite_t), intent(inout) :: suite
    type(drucker_prager_t) :: m
    real(dp) :: stress0(6), state0(7), increment(6), tangent(6, 6), fd(6, 6), asymmetry
    integer :: case
    character(len=24) :: label
    do case = 1, 3
      select case (case)
      case (1)
        m = material(30.0_dp, 30.0_dp, [SIGMA_C, 60.0_dp, 65.0_dp], [0.0_dp, 0.05_dp, 0.5_dp])
        label = 'associated'
        increment = [-0.003_dp, 0.0012_dp, 0.0006_dp, 0.0018_dp, 0.0027_dp, -0.0009_dp]
      case (2)
        m = material(30.0_dp, 5.0_dp, [SIGMA_C, 60.0_dp, 65.0_dp], [0.0_dp, 0.05_dp, 0.5_dp])
        label = 'non-associated'
        increment = [-0.003_dp, 0.0012_dp, 0.0006_dp, 0.0018_dp, 0.0027_dp, -0.0009_dp]
      case default
        m = material(35.0_dp, 20.0_dp, [SIGMA_C, 80.0_dp], [0.0_dp, 0.5_dp])
        label = 'apex'
        increment = [0.01_dp, 0.011_dp, 0.012_dp, 0.0005_dp, 0.0_dp, 0.0002_dp]
      end select
      stress0 = -10.0_dp * VOIGT_IDENTITY
      state0 = 0.0_dp
      call tangents(m, stress0, state0, increment, tangent, fd)
      call suite%check(maxval(abs(tangent - m%elastic_matrix())) > 1.0e-3_dp * YOUNG, &
                       trim(label) // ': the increment is plastic')
      call suite%close_array(reshape(tangent, [36]), reshape(fd, [36]), FD_TOLERANCE, &
                             'consistent tangent vs finite differences, ' // trim(label))
      asymmetry = maxval(abs(tangent - transpose(tangent))) / maxval(abs(tangent))
      if (case == 2) then
        call suite%check(asymmetry > 1.0e-3_dp, 'non-associated tangent is unsymmetric')
      else
        call suite%check(asymmetry < 1.0e-14_dp, trim(label) // ' tangent is symmetric')
      end if
    end do
  end subroutine check_consistent_tangent

  subroutine tangents(m, stress0, state0, increment, tangent, fd)
    type(drucker_prager_t), intent(in) :: m
    real(dp), intent(in) :: stress0(6), state0(7), increment(6)
    real(dp), intent(out) :: tangent(6, 6), fd(6, 6)
    real(dp) :: stress(6), state(7), plus(6), minus(6)
    integer :: j
    stress = stress0
    state = state0
    call m%update(stress, increment, state, tangent)
    do j = 1, 6
      plus = stress0
      state = state0
      call m%update(plus, increment + FD_STEP * unit(j), state)
      minus = stress0
      state = state0
      call m%update(minus, increment - FD_STEP * unit(j), state)
      fd(:, j) = (plus - minus) / (2.0_dp * FD_STEP)
    end do
  end subroutine tangents

  !> (D5) is the limit of the update for small loading increments, and unsymmetric for
  !> psi /= beta.
  subroutine check_start_tangent(suite)
    type(test_suite_t), intent(inout) :: suite
    type(drucker_prager_t) :: m
    real(dp) :: stress0(6), state0(7), stress(6), state(7), direction(6), c(6, 6), error(2)
    integer :: i
    m = material(30.0_dp, 5.0_dp, [SIGMA_C, 60.0_dp, 65.0_dp], [0.0_dp, 0.05_dp, 0.5_dp])
    stress0 = -10.0_dp * VOIGT_IDENTITY
    state0 = 0.0_dp
    call m%update(stress0, [-0.004_dp, 0.001_dp, 0.0015_dp, 0.002_dp, -0.001_dp, 0.0_dp], state0)
    c = m%tangent(stress0, state0)
    call suite%check(maxval(abs(c - transpose(c))) > 1.0e-3_dp * maxval(abs(c)), &
                     'start tangent, non-associated: unsymmetric')
    direction = [-0.001_dp, 0.0004_dp, 0.0002_dp, 0.0006_dp, 0.0009_dp, -0.0003_dp]
    do i = 1, 2
      stress = stress0
      state = state0
      call m%update(stress, direction * 10.0_dp**(-2 * i), state)
      error(i) = norm2(stress - stress0 - matmul(c, direction * 10.0_dp**(-2 * i))) / &
                 norm2(matmul(c, direction * 10.0_dp**(-2 * i)))
    end do
    call suite%check(error(2) < 2.0e-2_dp * error(1) .and. error(2) < 1.0e-4_dp, &
                     'start tangent = limit of the update for small increments (first order)')
  end subroutine check_start_tangent

  !> (D9): the event lands on the cone; a hydrostatic tension path leaves through the apex.
  subroutine check_event(suite)
    type(test_suite_t), intent(inout) :: suite
    type(drucker_prager_t) :: m
    real(dp) :: stress(6), state(7), increment(6), r
    m = material(30.0_dp, 10.0_dp, [SIGMA_C, 60.0_dp], [0.0_dp, 0.01_dp])
    state = 0.0_dp
    stress = [-30.0_dp, -20.0_dp, -25.0_dp, 2.0_dp, 0.0_dp, 1.0_dp]
    increment = [-100.0_dp, 20.0_dp, 10.0_dp, 30.0_dp, -10.0_dp, 5.0_dp]
    r = m%event_fraction(stress, increment, state)
    call suite%check(r > 0.0_dp .and. r < 1.0_dp, 'yield event within the increment')
    call suite%close_to(yield_function(m, stress + r * increment, 0.0_dp), 0.0_dp, EXACT, &
                        'yield event lands on the cone', floor=SIGMA_C)
    ! From the cone, reversed: the path crosses the cone's interior and reaches it again.
    stress = stress + r * increment
    r = m%event_fraction(stress, -increment, state)
    call suite%check(r > 1.0e-3_dp .and. r < 10.0_dp, 'reversed from the cone: the far crossing')
    call suite%close_to(yield_function(m, stress - r * increment, 0.0_dp), 0.0_dp, EXACT, &
                        'reversed from the cone: lands on the cone again', floor=SIGMA_C)
    call suite%check(m%event_fraction(stress, increment, state) > 1.0e100_dp, &
                     'loading from the cone: no event (plastic already)')
    stress = -5.0_dp * VOIGT_IDENTITY
    increment = 200.0_dp * VOIGT_IDENTITY
    r = m%event_fraction(stress, increment, state)
    call suite%close_array(stress + r * increment, m%cohesion(0.0_dp) / m%tan_friction * &
                           VOIGT_IDENTITY, EXACT, 'hydrostatic tension: the event at the apex')
  end subroutine check_event

  !> Triaxial compression: confining pressure p_c, axial stress s_a (compression positive);
  !> F = 0 gives s_a = sigma_c + p_c (1 + 2 tan(beta)/3) / (1 - tan(beta)/3). The event of an
  !> axial stress path from the confined state lands there.
  subroutine check_triaxial(suite)
    type(test_suite_t), intent(inout) :: suite
    type(drucker_prager_t) :: m
    real(dp) :: stress(6), state(7), r, expected, confining
    integer :: k
    m = material(35.0_dp, 10.0_dp, [SIGMA_C], [0.0_dp])
    state = 0.0_dp
    do k = 0, 2
      confining = 10.0_dp * k
      stress = -confining * VOIGT_IDENTITY
      r = m%event_fraction(stress, [0.0_dp, 0.0_dp, -1000.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], state)
      expected = SIGMA_C + confining * (1.0_dp + 2.0_dp * m%tan_friction / 3.0_dp) / &
                 (1.0_dp - m%tan_friction / 3.0_dp)
      call suite%close_to(confining + 1000.0_dp * r, expected, EXACT, &
                          'triaxial compression yield stress (closed form)')
    end do
  end subroutine check_triaxial

  pure function unit(j) result(e)
    integer, intent(in) :: j
    real(dp) :: e(6)
    e = 0.0_dp
    e(j) = 1.0_dp
  end function unit

end program test_fcs_drucker_prager
