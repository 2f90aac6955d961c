!> Unit test of fcs_st_venant_kirchhoff: the Green-Lagrange strain vanishes under a rigid
!> rotation and is (lambda^2 - 1)/2 under a stretch lambda; Cauchy and second Piola-Kirchhoff
!> stresses turn into each other; the Cauchy stress of a rotated stretched body is the rotated
!> one (objectivity); and the Jaumann tangent c of svk_jaumann_tangent gives the Jaumann rate
!> of the Cauchy stress, sigma^J = sigma' - W sigma + sigma W = c : D, against central finite
!> differences of sigma(F) along F' = L F, for an anisotropic stiffness (an orthotropic one in
!> turned axes), a general F and a velocity gradient L with stretching and spin.
program test_fcs_st_venant_kirchhoff
  use fcs_kinds, only: dp
  use fcs_st_venant_kirchhoff, only: green_lagrange_strain, cauchy_from_pk2, pk2_from_cauchy, &
    svk_jaumann_tangent, voigt_tensor, tensor_voigt
  use fcs_anisotropic_elastic, only: engineering_stiffness
  use fcs_orientation, only: rotate_stiffness
  use fcs_material, only: isotropic_elastic_matrix
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  !> A few products and a 3 x 3 inverse of numbers of order one: 1e-12.
  real(dp), parameter :: EXACT = 1.0e-12_dp

  suite%name = 'fcs_st_venant_kirchhoff'
  call check_strain(suite)
  call check_stresses(suite)
  call check_tangent(suite)
  call suite%report()

contains

  !> The rotation by `angle` about the unit axis `axis` (Rodrigues).
  pure function rotation(axis, angle) result(r)
    real(dp), intent(in) :: axis(3), angle
    real(dp) :: r(3, 3)
    real(dp) :: k(3, 3)
    integer :: i
    k = reshape([0.0_dp, axis(3), -axis(2), -axis(3), 0.0_dp, axis(1), axis(2), -axis(1), &
                 0.0_dp], [3, 3])
    r = sin(angle) * k + (1.0_dp - cos(angle)) * matmul(k, k)
    do i = 1, 3
      r(i, i) = r(i, i) + 1.0_dp
    end do
  end function rotation

  subroutine check_strain(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: f(3, 3), r(3, 3)
    r = rotation([0.0_dp, 0.6_dp, 0.8_dp], 1.1_dp)
    call suite%check(maxval(abs(green_lagrange_strain(r))) <= EXACT, 'rigid rotation: E = 0')
    f = 0.0_dp
    f(1, 1) = 1.3_dp
    f(2, 2) = 0.9_dp
    f(3, 3) = 1.0_dp
    f = matmul(r, f)
    call suite%close_array(green_lagrange_strain(f), [0.5_dp * (1.3_dp**2 - 1.0_dp), &
                           0.5_dp * (0.9_dp**2 - 1.0_dp), 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], EXACT, &
                           'rotated stretch: E = (lambda^2 - 1)/2, whatever the rotation')
  end subroutine check_strain

  subroutine check_stresses(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: f(3, 3), r(3, 3), s(6), sigma(6), c(6, 6), u(3, 3)
    f = reshape([1.1_dp, 0.05_dp, -0.02_dp, 0.2_dp, 0.95_dp, 0.03_dp, -0.1_dp, 0.04_dp, 1.05_dp], [3, 3])
    s = [100.0_dp, -50.0_dp, 20.0_dp, 30.0_dp, -10.0_dp, 5.0_dp]
    call suite%close_array(pk2_from_cauchy(f, cauchy_from_pk2(f, s)), s, EXACT, &
                           'S -> sigma -> S is the identity')
    ! Objectivity: the stress of R U is R sigma(U) R^T.
    c = isotropic_elastic_matrix(1000.0_dp, 0.3_dp)
    u = reshape([1.2_dp, 0.1_dp, 0.0_dp, 0.1_dp, 0.9_dp, 0.05_dp, 0.0_dp, 0.05_dp, 1.0_dp], [3, 3])
    r = rotation([0.48_dp, 0.6_dp, 0.64_dp], 0.7_dp)
    sigma = cauchy_from_pk2(u, matmul(c, green_lagrange_strain(u)))
    call suite%close_array(cauchy_from_pk2(matmul(r, u), matmul(c, green_lagrange_strain(matmul(r, u)))), &
                           tensor_voigt(matmul(r, matmul(voigt_tensor(sigma), transpose(r)))), &
                           EXACT, 'sigma(R U) = R sigma(U) R^T')
  end subroutine check_stresses

  !> sigma(F) of St Venant-Kirchhoff with stiffness c.
  pure function svk_stress(f, c) result(sigma)
    real(dp), intent(in) :: f(3, 3), c(6, 6)
    real(dp) :: sigma(6)
    sigma = cauchy_from_pk2(f, matmul(c, green_lagrange_strain(f)))
  end function svk_stress

  !> Central differences of sigma((I + h L) F) at h = 0 with step H: the error is O(H^2) times
  !> the third derivative (relative 1e-10 for H = 1e-5 at strains of order 0.1-1) plus the
  !> round-off 1e-16 / H = 1e-11; tolerance 1e-7 of the largest rate.
  subroutine check_tangent(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: H = 1.0e-5_dp
    real(dp) :: c_ref(6, 6), f(3, 3), l(3, 3), d(3, 3), w(3, 3), sigma(6), rate(6), jaumann(6)
    real(dp) :: c(6, 6), eye(3, 3), d_voigt(6)
    integer :: i
    eye = 0.0_dp
    do i = 1, 3
      eye(i, i) = 1.0_dp
    end do
    c_ref = rotate_stiffness(engineering_stiffness([100.0e3_dp, 20.0e3_dp, 10.0e3_dp, 0.3_dp, &
      0.25_dp, 0.4_dp, 8.0e3_dp, 6.0e3_dp, 4.0e3_dp]), rotation([0.0_dp, 0.6_dp, 0.8_dp], 0.5_dp))
    f = reshape([1.15_dp, 0.08_dp, -0.05_dp, 0.25_dp, 0.9_dp, 0.06_dp, -0.12_dp, 0.07_dp, 1.1_dp], [3, 3])
    l = reshape([0.3_dp, -0.7_dp, 0.2_dp, 0.5_dp, -0.4_dp, 0.9_dp, -0.6_dp, 0.1_dp, 0.25_dp], [3, 3])
    d = 0.5_dp * (l + transpose(l))
    w = 0.5_dp * (l - transpose(l))
    sigma = svk_stress(f, c_ref)
    rate = (svk_stress(matmul(eye + H * l, f), c_ref) - svk_stress(matmul(eye - H * l, f), c_ref)) / &
           (2.0_dp * H)
    jaumann = rate - tensor_voigt(matmul(w, voigt_tensor(sigma)) - matmul(voigt_tensor(sigma), w))
    d_voigt = [d(1, 1), d(2, 2), d(3, 3), 2.0_dp * d(1, 2), 2.0_dp * d(1, 3), 2.0_dp * d(2, 3)]
    c = svk_jaumann_tangent(f, sigma, c_ref)
    call suite%close_array(matmul(c, d_voigt), jaumann, 1.0e-7_dp, &
                           'Jaumann tangent: c : D = sigma^J (finite differences)')
    ! A spin alone (D = 0) leaves the Jaumann rate zero: the rate is W sigma - sigma W.
    rate = (svk_stress(matmul(eye + H * w, f), c_ref) - svk_stress(matmul(eye - H * w, f), c_ref)) / &
           (2.0_dp * H)
    call suite%close_array(rate, tensor_voigt(matmul(w, voigt_tensor(sigma)) - &
                           matmul(voigt_tensor(sigma), w)), 1.0e-7_dp, &
                           'a spin turns the stress: sigma'' = W sigma - sigma W')
    ! The reference configuration: c is C.
    call suite%close_array(reshape(svk_jaumann_tangent(eye, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
                           0.0_dp, 0.0_dp], c_ref), [36]), reshape(c_ref, [36]), EXACT, &
                           'F = I, no stress: c = C')
  end subroutine check_tangent

end program test_fcs_st_venant_kirchhoff
