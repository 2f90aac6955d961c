!> Unit test of fcs_simo_plasticity (doc/theory.md 2.8), combined hardening on a linear curve:
!> after a plastic update at a general F the point lies on its yield surface as the rate-form
!> checks read it (q of the printed stress less the stored back stress = R(alpha)); the update
!> is objective (the stress at R F is R sigma(F) R^T, the state the same); in the reference
!> configuration the tangent is the elastic matrix; on the surface, the tangent of continued
!> loading gives the stress rate of the update for a loading stretching rate (one-sided
!> differences); and without NLGEOM the rate form is fcs_von_mises's bit for bit.
program test_fcs_simo_plasticity
  use fcs_kinds, only: dp
  use fcs_simo_plasticity, only: simo_plasticity_t, simo_from_von_mises, N_STATE_SIMO
  use fcs_von_mises, only: von_mises_t, PEEQ, BACK_STRESS
  use fcs_hardening_table, only: hardening_table_t
  use fcs_st_venant_kirchhoff, only: voigt_tensor, tensor_voigt
  use fcs_material, only: isotropic_elastic_matrix
  use fcs_voigt, only: deviator, stress_norm
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  type(simo_plasticity_t) :: law
  type(von_mises_t) :: rate_law
  !> Products of a few numbers of order one (stresses of order 1e3): 1e-12 relative.
  real(dp), parameter :: EXACT = 1.0e-12_dp
  real(dp) :: eye(3, 3), f(3, 3)
  integer :: i

  suite%name = 'fcs_simo_plasticity'
  rate_law%youngs_modulus = 210000.0_dp
  rate_law%poisson_ratio = 0.3_dp
  rate_law%hardening = 'COMBINED'
  rate_law%radius = hardening_table_t(strain=[0.0_dp, 0.1_dp], stress=[800.0_dp, 1600.0_dp])
  rate_law%kinematic = hardening_table_t(strain=[0.0_dp, 0.1_dp], stress=[800.0_dp, 1600.0_dp])
  law = simo_from_von_mises(rate_law)
  eye = 0.0_dp
  do i = 1, 3
    eye(i, i) = 1.0_dp
  end do
  f = reshape([1.03_dp, 0.004_dp, -0.002_dp, 0.01_dp, 0.985_dp, 0.003_dp, -0.006_dp, 0.002_dp, &
               0.99_dp], [3, 3])
  call check_surface_and_objectivity(suite)
  call check_tangents(suite)
  call check_rate_form(suite)
  call suite%report()

contains

  !> The rotation by `angle` about the unit axis `axis` (Rodrigues).
  pure function rotation(axis, angle) result(r)
    real(dp), intent(in) :: axis(3), angle
    real(dp) :: r(3, 3)
    real(dp) :: k(3, 3)
    integer :: j
    k = reshape([0.0_dp, axis(3), -axis(2), -axis(3), 0.0_dp, axis(1), axis(2), -axis(1), &
                 0.0_dp], [3, 3])
    r = sin(angle) * k + (1.0_dp - cos(angle)) * matmul(k, k)
    do j = 1, 3
      r(j, j) = r(j, j) + 1.0_dp
    end do
  end function rotation

  subroutine check_surface_and_objectivity(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: state(N_STATE_SIMO), turned_state(N_STATE_SIMO), sigma(6), turned(6), r(3, 3), q
    state = 0.0_dp
    call law%finite_stress(f, 0.0_dp, 0.0_dp, state, sigma)
    q = sqrt(1.5_dp) * stress_norm(deviator(sigma) - state(BACK_STRESS:BACK_STRESS + 5))
    call suite%check(state(PEEQ) > 1.0e-3_dp, 'F yields (PEEQ > 1e-3)')
    call suite%check(abs(q - law%radius%value(state(PEEQ))) <= EXACT * q, &
                     'after the return q(sigma - back stress) = R(alpha)')
    call suite%check(law%on_surface(sigma, state), 'on the surface as the rate-form checks read it')
    r = rotation([0.48_dp, 0.6_dp, 0.64_dp], 0.7_dp)
    turned_state = 0.0_dp
    call law%finite_stress(matmul(r, f), 0.0_dp, 0.0_dp, turned_state, turned)
    call suite%close_array(turned, tensor_voigt(matmul(r, matmul(voigt_tensor(sigma), transpose(r)))), &
                           EXACT * maxval(abs(sigma)), 'sigma(R F) = R sigma(F) R^T')
    call suite%close_array(turned_state([PEEQ, (i, i = N_STATE_SIMO - 12, N_STATE_SIMO)]), &
                           state([PEEQ, (i, i = N_STATE_SIMO - 12, N_STATE_SIMO)]), EXACT, &
                           'the reference state (PEEQ, C_p^-1, B) does not see the rotation')
  end subroutine check_surface_and_objectivity

  !> Tangents by central differences of step 1e-6 (error O(1e-12) relative, round-off 1e-10):
  !> the elastic one at F = I within 1e-8 of C. The update's own rate from a point on the
  !> surface is one-sided (the return acts on loading only): step 1e-7, error O(1e-7), 1e-5.
  subroutine check_tangents(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: H = 1.0e-7_dp
    real(dp) :: state(N_STATE_SIMO), start(N_STATE_SIMO), c(6, 6), sigma(6), base(6), moved(6)
    real(dp) :: d(3, 3), d_voigt(6), rate(6)
    state = 0.0_dp
    c = law%finite_tangent(eye, 0.0_dp, 0.0_dp, state, .false.)
    call suite%close_array(reshape(c, [36]), reshape(isotropic_elastic_matrix(210000.0_dp, 0.3_dp), &
                           [36]), 1.0e-8_dp * 210000.0_dp, 'F = I, no stress: c = C')
    call law%finite_stress(f, 0.0_dp, 0.0_dp, state, sigma)
    start = state
    c = law%finite_tangent(f, 0.0_dp, 0.0_dp, start, .true.)
    d = reshape([1.0_dp, 0.1_dp, 0.0_dp, 0.1_dp, -0.4_dp, 0.05_dp, 0.0_dp, 0.05_dp, -0.5_dp], [3, 3])
    d_voigt = [d(1, 1), d(2, 2), d(3, 3), 2.0_dp * d(1, 2), 2.0_dp * d(1, 3), 2.0_dp * d(2, 3)]
    state = start
    call law%finite_stress(f, 0.0_dp, 0.0_dp, state, base)
    state = start
    call law%finite_stress(matmul(eye + H * d, f), 0.0_dp, 0.0_dp, state, moved)
    rate = (moved - base) / H
    call suite%check(state(PEEQ) > start(PEEQ), 'the loading rate flows plastically')
    call suite%close_array(matmul(c, d_voigt), rate, 1.0e-5_dp * maxval(abs(rate)), &
                           'continued loading: c : D = the update''s stress rate')
  end subroutine check_tangents

  subroutine check_rate_form(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: state(N_STATE_SIMO), rate_state(N_STATE_SIMO), sigma(6), rate_sigma(6)
    real(dp), parameter :: STRAIN(6) = [6.0e-3_dp, -2.0e-3_dp, -1.0e-3_dp, 1.0e-3_dp, 0.0_dp, 5.0e-4_dp]
    state = 0.0_dp
    rate_state = 0.0_dp
    sigma = 0.0_dp
    rate_sigma = 0.0_dp
    call law%update(sigma, STRAIN, state)
    call rate_law%update(rate_sigma, STRAIN, rate_state)
    call suite%check(all(sigma == rate_sigma) .and. all(state(1:13) == rate_state(1:13)) .and. &
                     state(PEEQ) > 0.0_dp, 'without NLGEOM: fcs_von_mises''s update, bit for bit')
  end subroutine check_rate_form

end program test_fcs_simo_plasticity
