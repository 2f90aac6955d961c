!> Unit test of fcs_von_mises (and the curves of fcs_hardening_table it uses): the radial
!> return against the closed forms of uniaxial stress with linear hardening and of pure shear
!> (monotonic, and reversed: the Bauschinger effect of kinematic hardening as CalculiX reads
!> the curve); the returned stress on the yield surface after increments that cross breakpoints
!> of the curves; the consistent tangent (V7) against central finite differences of the update
!> for isotropic, kinematic and combined hardening; the start-of-increment tangent (V4) as the
!> limit of the update for small loading increments; the yield event fraction (V8) landing on
!> the surface; objectivity (isotropy) of the update under a rotation of stress, state and
!> increment; purity (the same inputs give the same outputs).
program test_fcs_von_mises
  use fcs_kinds, only: dp
  use fcs_von_mises, only: von_mises_t
  use fcs_hardening_table, only: hardening_table_t, constant_table
  use fcs_voigt, only: deviator, stress_norm, mises_of, spin_rotation, rotate_stress_like, &
                       rotate_strain_like
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite

  real(dp), parameter :: YOUNG = 200000.0_dp, POISSON = 0.3_dp, YIELD = 200.0_dp
  !> Round-off of the closed-form checks: a handful of operations on numbers of size E eps,
  !> 1e-13 relative leaves a factor 100 over double precision.
  real(dp), parameter :: EXACT = 1.0e-12_dp
  !> Central differences with step h = 1e-7 (strain): truncation zero on one segment (the
  !> update is smooth there, its second derivative O(G / |xi|) gives h^2 terms of 1e-10
  !> relative), round-off eps E / (h E) ~ 1e-9; 1e-6 leaves margin and catches any wrong term.
  real(dp), parameter :: FD_STEP = 1.0e-7_dp, FD_TOLERANCE = 1.0e-6_dp

  suite%name = 'fcs_von_mises'
  call check_uniaxial(suite)
  call check_shear_bauschinger(suite)
  call check_breakpoints(suite)
  call check_consistent_tangent(suite)
  call check_start_tangent(suite)
  call check_event(suite)
  call check_objectivity(suite)
  call suite%report()

contains

  !> A material with the curve (stress, strain) points and the given hardening.
  function material(hardening, stress, strain, cyclic_stress, cyclic_strain) result(m)
    character(len=*), intent(in) :: hardening
    real(dp), intent(in) :: stress(:), strain(:)
    real(dp), intent(in), optional :: cyclic_stress(:), cyclic_strain(:)
    type(von_mises_t) :: m
    type(hardening_table_t) :: curve
    m%youngs_modulus = YOUNG
    m%poisson_ratio = POISSON
    m%hardening = hardening
    curve%stress = stress
    curve%strain = strain
    select case (hardening)
    case ('isotropic')
      m%radius = curve
      m%kinematic = constant_table(0.0_dp)
    case ('kinematic')
      m%radius = constant_table(stress(1))
      m%kinematic = curve
    case default
      m%kinematic = curve
      m%radius%stress = cyclic_stress
      m%radius%strain = cyclic_strain
    end select
  end function material

  !> Uniaxial stress s along z, linear hardening H (slope of stress against plastic strain):
  !> s = s_y + E H / (E + H) (eps - s_y / E), eps_p = (s - s_y) / H, lateral strain
  !> -nu s / E - eps_p / 2. The exact strains, applied in one increment and in ten, give s to
  !> round-off, with zero lateral stress.
  subroutine check_uniaxial(suite)
    type(test_suite_t), intent(inout) :: suite
    type(von_mises_t) :: m
    real(dp), parameter :: h = 2000.0_dp, total = 0.01_dp
    real(dp) :: stress(6), state(13), expected, plastic, strain(6), previous(6), eps
    integer :: k, n
    character(len=16) :: label
    m = material('isotropic', [YIELD, YIELD + h * 0.1_dp], [0.0_dp, 0.1_dp])
    do n = 1, 10, 9
      stress = 0.0_dp
      state = 0.0_dp
      previous = 0.0_dp
      do k = 1, n
        eps = total * k / n
        strain = exact_strain(eps, h)
        call m%update(stress, strain - previous, state)
        previous = strain
      end do
      write (label, '(i0,a)') n, ' increments'
      expected = YIELD + YOUNG * h / (YOUNG + h) * (total - YIELD / YOUNG)
      plastic = (expected - YIELD) / h
      call suite%close_to(stress(3), expected, EXACT, 'uniaxial s_zz, ' // trim(label))
      call suite%close_to(maxval(abs(stress([1, 2, 4, 5, 6]))), 0.0_dp, EXACT, &
                          'uniaxial lateral and shear stresses, ' // trim(label), floor=YIELD)
      call suite%close_to(m%equivalent_plastic_strain(state), plastic, EXACT, &
                          'uniaxial PEEQ, ' // trim(label))
      strain = m%plastic_strain(state)
      call suite%close_to(strain(3), plastic, EXACT, 'uniaxial plastic strain zz, ' // trim(label))
      call suite%close_to(strain(1), -0.5_dp * plastic, EXACT, &
                          'uniaxial plastic strain xx (isochoric flow), ' // trim(label))
    end do
  end subroutine check_uniaxial

  !> The strain tensor of uniaxial stress along z at axial strain eps, hardening slope h.
  pure function exact_strain(eps, h) result(e)
    real(dp), intent(in) :: eps, h
    real(dp) :: e(6), s, ep
    s = min(YOUNG * eps, YIELD + YOUNG * h / (YOUNG + h) * (eps - YIELD / YOUNG))
    ep = max(0.0_dp, (s - YIELD) / h)
    e = 0.0_dp
    e(3) = eps
    e(1:2) = -POISSON * s / YOUNG - 0.5_dp * ep
  end function exact_strain

  !> Pure shear gamma (engineering) along 12: sqrt(3) tau = R on the surface, eps_bar =
  !> gamma_p / sqrt(3). Loaded to gamma_max, then reversed: with kinematic hardening the
  !> surface, of constant radius s_y, reaches back to sqrt(3) tau = sqrt(3) tau_max - 2 s_y
  !> (Bauschinger effect); with isotropic hardening to -tau_max.
  subroutine check_shear_bauschinger(suite)
    type(test_suite_t), intent(inout) :: suite
    type(von_mises_t) :: m
    real(dp), parameter :: h = 20000.0_dp, gamma = 0.01_dp, scale = 1000.0_dp
    real(dp) :: stress(6), state(13), g, tau_max, reverse, shear(6), r
    integer :: kind
    character(len=9), parameter :: kinds(2) = [character(len=9) :: 'isotropic', 'kinematic']
    g = 0.5_dp * YOUNG / (1.0_dp + POISSON)
    do kind = 1, 2
      m = material(trim(kinds(kind)), [YIELD, YIELD + h], [0.0_dp, 1.0_dp])
      stress = 0.0_dp
      state = 0.0_dp
      shear = 0.0_dp
      shear(4) = gamma
      call m%update(stress, shear, state)
      ! Monotonic: gamma = tau / G + sqrt(3) eps_bar with sqrt(3) tau = s_y + h eps_bar.
      tau_max = (gamma + sqrt(3.0_dp) * YIELD / h) / (1.0_dp / g + 3.0_dp / h)
      call suite%close_to(stress(4), tau_max, EXACT, 'shear, ' // trim(kinds(kind)) // ': tau')
      call suite%close_to(state(1), (sqrt(3.0_dp) * tau_max - YIELD) / h, EXACT, &
                          'shear, ' // trim(kinds(kind)) // ': PEEQ')
      if (kind == 1) then
        reverse = -tau_max
      else
        reverse = tau_max - 2.0_dp * YIELD / sqrt(3.0_dp)
      end if
      ! Reversed: the yield event of a stress increment -scale along 12.
      r = m%event_fraction(stress, [0.0_dp, 0.0_dp, 0.0_dp, -scale, 0.0_dp, 0.0_dp], state)
      call suite%close_to(stress(4) - r * scale, reverse, EXACT, &
                          'shear, ' // trim(kinds(kind)) // ': reverse yield stress (Bauschinger)')
      ! Unloading elastically to just before it leaves the plastic state unchanged.
      shear(4) = -0.999_dp * r * scale / g
      call m%update(stress, shear, state)
      call suite%close_to(state(1), (sqrt(3.0_dp) * tau_max - YIELD) / h, EXACT, &
                          'shear, ' // trim(kinds(kind)) // ': elastic unloading keeps PEEQ')
      call suite%close_to(stress(4), tau_max - 0.999_dp * r * scale, EXACT, &
                          'shear, ' // trim(kinds(kind)) // ': elastic unloading slope G')
    end do
  end subroutine check_shear_bauschinger

  !> A three-segment curve crossed in one increment: the return lands on the surface of the
  !> curve at the new PEEQ, in every hardening variant.
  subroutine check_breakpoints(suite)
    type(test_suite_t), intent(inout) :: suite
    type(von_mises_t) :: m
    real(dp) :: stress(6), state(13), increment(6), radius, q
    integer :: kind
    character(len=9), parameter :: kinds(3) = [character(len=9) :: 'isotropic', 'kinematic', 'combined']
    do kind = 1, 3
      m = material(trim(kinds(kind)), [YIELD, 260.0_dp, 280.0_dp, 285.0_dp], &
                   [0.0_dp, 0.002_dp, 0.005_dp, 0.02_dp], [YIELD, 230.0_dp], [0.0_dp, 0.01_dp])
      stress = 0.0_dp
      state = 0.0_dp
      increment = 3.0_dp * [0.004_dp, -0.001_dp, -0.002_dp, 0.003_dp, -0.002_dp, 0.001_dp]
      call m%update(stress, increment, state)
      call suite%check(state(1) > 0.005_dp, 'breakpoints, ' // trim(kinds(kind)) // &
                       ': the increment crosses two breakpoints')
      radius = m%radius%value(state(1))
      q = sqrt(1.5_dp) * stress_norm(deviator(stress) - state(8:13))
      call suite%close_to(q, radius, EXACT, 'breakpoints, ' // trim(kinds(kind)) // &
                          ': on the surface of radius R(PEEQ)')
      call suite%close_to(sqrt(1.5_dp) * stress_norm(state(8:13)), &
                          m%kinematic%value(state(1)) - m%kinematic%value(0.0_dp), EXACT, &
                          'breakpoints, ' // trim(kinds(kind)) // ': |back stress| = B(PEEQ) - B(0)', &
                          floor=YIELD)
    end do
  end subroutine check_breakpoints

  !> (V7) against central differences of the update, from a plastic state, for an increment
  !> that stays on one segment of the curves.
  subroutine check_consistent_tangent(suite)
    type(test_suite_t), intent(inout) :: suite
    type(von_mises_t) :: m
    real(dp) :: stress0(6), state0(13), increment(6), stress(6), state(13), tangent(6, 6)
    real(dp) :: plus(6), minus(6), fd(6, 6), scratch(13)
    integer :: kind, j
    character(len=9), parameter :: kinds(3) = [character(len=9) :: 'isotropic', 'kinematic', 'combined']
    do kind = 1, 3
      m = material(trim(kinds(kind)), [YIELD, 300.0_dp, 320.0_dp], [0.0_dp, 0.05_dp, 0.5_dp], &
                   [YIELD, 250.0_dp], [0.0_dp, 0.2_dp])
      stress0 = 0.0_dp
      state0 = 0.0_dp
      call m%update(stress0, [0.002_dp, -0.001_dp, 0.0005_dp, 0.001_dp, 0.0_dp, -0.0005_dp], state0)
      increment = [0.001_dp, 0.0004_dp, -0.0007_dp, 0.0006_dp, 0.0009_dp, -0.0003_dp]
      stress = stress0
      state = state0
      call m%update(stress, increment, state, tangent)
      call suite%check(state(1) > state0(1), 'tangent, ' // trim(kinds(kind)) // ': plastic increment')
      do j = 1, 6
        plus = stress0
        scratch = state0
        call m%update(plus, increment + FD_STEP * unit(j), scratch)
        minus = stress0
        scratch = state0
        call m%update(minus, increment - FD_STEP * unit(j), scratch)
        fd(:, j) = (plus - minus) / (2.0_dp * FD_STEP)
      end do
      call suite%close_array(reshape(tangent, [36]), reshape(fd, [36]), FD_TOLERANCE, &
                             'consistent tangent vs finite differences, ' // trim(kinds(kind)))
      call suite%close_array(reshape(tangent, [36]), reshape(transpose(tangent), [36]), 1.0e-14_dp, &
                             'consistent tangent symmetric (associated flow), ' // trim(kinds(kind)))
    end do
  end subroutine check_consistent_tangent

  !> (V4): for a point on the surface and a small loading increment de, the update gives
  !> sigma + C_ep de + O(|de|^2): the relative difference shrinks linearly with |de|.
  subroutine check_start_tangent(suite)
    type(test_suite_t), intent(inout) :: suite
    type(von_mises_t) :: m
    real(dp) :: stress0(6), state0(13), stress(6), state(13), direction(6), c(6, 6), error(2)
    integer :: i
    m = material('combined', [YIELD, 300.0_dp, 320.0_dp], [0.0_dp, 0.05_dp, 0.5_dp], &
                 [YIELD, 250.0_dp], [0.0_dp, 0.2_dp])
    stress0 = 0.0_dp
    state0 = 0.0_dp
    call m%update(stress0, [0.002_dp, -0.001_dp, 0.0005_dp, 0.001_dp, 0.0_dp, -0.0005_dp], state0)
    c = m%tangent(stress0, state0)
    call suite%check(maxval(abs(c - m%elastic_matrix())) > 0.1_dp * YIELD, &
                     'start tangent on the surface is elastoplastic')
    direction = [0.001_dp, 0.0004_dp, -0.0007_dp, 0.0006_dp, 0.0009_dp, -0.0003_dp]
    do i = 1, 2
      stress = stress0
      state = state0
      call m%update(stress, direction * 10.0_dp**(-2 * i), state)
      error(i) = norm2(stress - stress0 - matmul(c, direction * 10.0_dp**(-2 * i))) / &
                 norm2(matmul(c, direction * 10.0_dp**(-2 * i)))
    end do
    call suite%check(error(2) < 2.0e-2_dp * error(1) .and. error(2) < 1.0e-4_dp, &
                     'start tangent = limit of the update for small increments (first order)')
    stress = stress0 * 0.5_dp
    call suite%close_array(reshape(m%tangent(stress, state0), [36]), reshape(m%elastic_matrix(), [36]), &
                           0.0_dp, 'start tangent inside the surface is elastic')
  end subroutine check_start_tangent

  !> (V8): sigma + r dsigma lies on the surface, for a point inside it and a back stress.
  subroutine check_event(suite)
    type(test_suite_t), intent(inout) :: suite
    type(von_mises_t) :: m
    real(dp) :: stress(6), state(13), increment(6), r
    m = material('kinematic', [YIELD, 300.0_dp], [0.0_dp, 0.05_dp])
    state = 0.0_dp
    state(1) = 0.01_dp
    state(8:13) = [10.0_dp, -4.0_dp, -6.0_dp, 3.0_dp, 1.0_dp, -2.0_dp]
    stress = [50.0_dp, 20.0_dp, -30.0_dp, 10.0_dp, 5.0_dp, 0.0_dp]
    increment = [100.0_dp, -200.0_dp, 50.0_dp, 80.0_dp, -20.0_dp, 60.0_dp]
    r = m%event_fraction(stress, increment, state)
    call suite%check(r > 0.0_dp .and. r < 1.0_dp, 'yield event within the increment')
    call suite%close_to(sqrt(1.5_dp) * stress_norm(deviator(stress + r * increment) - state(8:13)), &
                        YIELD, EXACT, 'yield event lands on the surface')
    call suite%check(m%event_fraction(stress, 1.0e-3_dp * increment, state) > 1.0_dp, &
                     'no yield event within a small increment')
  end subroutine check_event

  !> Isotropy: rotating the start stress, the state's tensors and the increment rotates the
  !> result (the update commutes with Q).
  subroutine check_objectivity(suite)
    type(test_suite_t), intent(inout) :: suite
    type(von_mises_t) :: m
    real(dp) :: stress0(6), state0(13), a(6), b(6), state_a(13), state_b(13), q(3, 3), w(3, 3)
    real(dp) :: increment(6), again(6), state_again(13)
    m = material('combined', [YIELD, 300.0_dp, 320.0_dp], [0.0_dp, 0.05_dp, 0.5_dp], &
                 [YIELD, 250.0_dp], [0.0_dp, 0.2_dp])
    stress0 = 0.0_dp
    state0 = 0.0_dp
    call m%update(stress0, [0.002_dp, -0.001_dp, 0.0005_dp, 0.001_dp, 0.0_dp, -0.0005_dp], state0)
    increment = [0.001_dp, 0.0004_dp, -0.0007_dp, 0.0006_dp, 0.0009_dp, -0.0003_dp]
    w = reshape([0.0_dp, 0.3_dp, -0.2_dp, -0.3_dp, 0.0_dp, 0.5_dp, 0.2_dp, -0.5_dp, 0.0_dp], [3, 3])
    q = spin_rotation(w)
    a = stress0
    state_a = state0
    call m%update(a, increment, state_a)
    b = rotate_stress_like(stress0, q)
    state_b = state0
    call m%rotate_state(state_b, q)
    call m%update(b, rotate_strain_like(increment, q), state_b)
    call suite%close_array(b, rotate_stress_like(a, q), EXACT, 'objectivity: stress')
    call m%rotate_state(state_a, q)
    call suite%close_array(state_b, state_a, EXACT, 'objectivity: plastic strain and back stress')
    call suite%close_to(mises_of(b), mises_of(a), EXACT, 'objectivity: Mises stress')
    again = stress0
    state_again = state0
    call m%update(again, increment, state_again)
    a = stress0
    state_a = state0
    call m%update(a, increment, state_a)
    call suite%check(all(again == a) .and. all(state_again == state_a), &
                     'the update is a pure function of its inputs (bit for bit)')
  end subroutine check_objectivity

  pure function unit(j) result(e)
    integer, intent(in) :: j
    real(dp) :: e(6)
    e = 0.0_dp
    e(j) = 1.0_dp
  end function unit

end program test_fcs_von_mises
