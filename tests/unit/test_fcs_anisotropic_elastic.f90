!> Unit test of fcs_anisotropic_elastic and fcs_orientation: the stiffness of ENGINEERING
!> CONSTANTS is the inverse of the orthotropic compliance (S11 = 1/E1, S12 = -nu12/E1, ...);
!> ORTHO and ANISO place CalculiX's constants where its manual says (D1122 at (1,2), D1112 at
!> (1,4), D2323 at (6,6)); an isotropic stiffness given as ORTHO is the isotropic matrix and
!> its Voigt average gives back E and nu; the positive-definiteness test refuses a negative
!> modulus and a Poisson block that is not; the axes of a rectangular and a cylindrical
!> orientation and of a rotation line; the rotated stiffness gives the same stress as turning
!> the strain to local axes, applying C, and turning back; an isotropic stiffness is the same
!> in every axes; the update adds C eps.
program test_fcs_anisotropic_elastic
  use fcs_kinds, only: dp
  use fcs_anisotropic_elastic, only: anisotropic_elastic_t, orthotropic_stiffness, &
    engineering_stiffness, anisotropic_stiffness, is_positive_definite, voigt_isotropic
  use fcs_orientation, only: orientation_t, orientation_axes, rotate_about_axis, &
    rotate_stiffness, stress_to_global, stress_to_local, strain_to_local, orientation_is_valid
  use fcs_material, only: isotropic_elastic_matrix
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  !> A few operations on numbers of order one (a 3 x 3 inverse, a 6 x 6 product): 1e-12.
  real(dp), parameter :: EXACT = 1.0e-12_dp

  suite%name = 'fcs_anisotropic_elastic'
  call check_engineering(suite)
  call check_orders(suite)
  call check_definiteness(suite)
  call check_axes(suite)
  call check_rotation(suite)
  call check_update(suite)
  call suite%report()

contains

  subroutine check_engineering(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: k(9) = [100.0e3_dp, 20.0e3_dp, 10.0e3_dp, 0.3_dp, 0.25_dp, 0.4_dp, &
                                   8.0e3_dp, 6.0e3_dp, 4.0e3_dp]
    real(dp) :: c(6, 6), s(6, 6), identity(6, 6), e, nu
    integer :: i
    c = engineering_stiffness(k)
    s = 0.0_dp
    s(1, 1:3) = [1.0_dp / k(1), -k(4) / k(1), -k(5) / k(1)]
    s(2, 1:3) = [-k(4) / k(1), 1.0_dp / k(2), -k(6) / k(2)]
    s(3, 1:3) = [-k(5) / k(1), -k(6) / k(2), 1.0_dp / k(3)]
    s(4, 4) = 1.0_dp / k(7)
    s(5, 5) = 1.0_dp / k(8)
    s(6, 6) = 1.0_dp / k(9)
    identity = 0.0_dp
    do i = 1, 6
      identity(i, i) = 1.0_dp
    end do
    call suite%close_array(reshape(matmul(c, s), [36]), reshape(identity, [36]), EXACT, &
                           'ENGINEERING CONSTANTS: C S = I')
    call suite%check(is_positive_definite(c), 'ENGINEERING CONSTANTS: positive definite')
    c = engineering_stiffness([200.0e3_dp, 200.0e3_dp, 200.0e3_dp, 0.3_dp, 0.3_dp, 0.3_dp, &
                               200.0e3_dp / 2.6_dp, 200.0e3_dp / 2.6_dp, 200.0e3_dp / 2.6_dp])
    call suite%close_array(reshape(c, [36]), reshape(isotropic_elastic_matrix(200.0e3_dp, 0.3_dp), &
                           [36]), EXACT, 'isotropic engineering constants: the isotropic C')
    call voigt_isotropic(c, e, nu)
    call suite%close_to(e, 200.0e3_dp, EXACT, 'Voigt average of an isotropic C: E')
    call suite%close_to(nu, 0.3_dp, EXACT, 'Voigt average of an isotropic C: nu')
  end subroutine check_engineering

  subroutine check_orders(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: c(6, 6), d(21)
    integer :: i
    c = orthotropic_stiffness([1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp, 5.0_dp, 6.0_dp, 7.0_dp, 8.0_dp, 9.0_dp])
    call suite%close_array([c(1, 1), c(1, 2), c(2, 2), c(1, 3), c(2, 3), c(3, 3), c(4, 4), &
                           c(5, 5), c(6, 6)], [(real(i, dp), i = 1, 9)], EXACT, &
                           'ORTHO: D1111 D1122 D2222 D1133 D2233 D3333 D1212 D1313 D2323')
    call suite%close_array([c(2, 1), c(3, 1), c(3, 2), c(1, 4), c(5, 6)], &
                           [2.0_dp, 4.0_dp, 5.0_dp, 0.0_dp, 0.0_dp], EXACT, 'ORTHO: symmetric, no coupling')
    d = [(real(i, dp), i = 1, 21)]
    c = anisotropic_stiffness(d)
    ! D1112 (7) at (1,4), D3312 (9) at (3,4), D1212 (10) at (4,4), D1213 (14) at (4,5),
    ! D1123 (16) at (1,6), D1323 (20) at (5,6), D2323 (21) at (6,6).
    call suite%close_array([c(1, 4), c(3, 4), c(4, 4), c(4, 5), c(1, 6), c(5, 6), c(6, 6), c(6, 5)], &
                           [7.0_dp, 9.0_dp, 10.0_dp, 14.0_dp, 16.0_dp, 20.0_dp, 21.0_dp, 20.0_dp], &
                           EXACT, 'ANISO: the upper triangle column by column, symmetric')
  end subroutine check_orders

  subroutine check_definiteness(suite)
    type(test_suite_t), intent(inout) :: suite
    call suite%check(.not. is_positive_definite(engineering_stiffness([100.0_dp, 100.0_dp, &
      -100.0_dp, 0.3_dp, 0.3_dp, 0.3_dp, 40.0_dp, 40.0_dp, 40.0_dp])), 'a negative E3 is refused')
    call suite%check(.not. is_positive_definite(engineering_stiffness([100.0_dp, 100.0_dp, &
      100.0_dp, 0.7_dp, 0.7_dp, 0.7_dp, 40.0_dp, 40.0_dp, 40.0_dp])), &
      'Poisson ratios 0.7 (1 - 2 nu < 0 in every direction) are refused')
    call suite%check(.not. is_positive_definite(orthotropic_stiffness([1.0_dp, 2.0_dp, 1.0_dp, &
      0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp])), 'ORTHO with D1122^2 > D1111 D2222 is refused')
    call suite%check(is_positive_definite(isotropic_elastic_matrix(1.0_dp, 0.49_dp)), &
                     'isotropic nu = 0.49 is accepted')
  end subroutine check_definiteness

  subroutine check_axes(suite)
    type(test_suite_t), intent(inout) :: suite
    type(orientation_t) :: o
    real(dp) :: a(3, 3)
    real(dp), parameter :: h = sqrt(0.5_dp)
    o%a = [2.0_dp, 0.0_dp, 0.0_dp]
    o%b = [1.0_dp, 3.0_dp, 0.0_dp]
    a = orientation_axes(o, [5.0_dp, 5.0_dp, 5.0_dp])
    call suite%close_array(reshape(a, [9]), [1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
                           0.0_dp, 0.0_dp, 1.0_dp], EXACT, 'rectangular: e1 along a, e2 from b')
    a = orientation_axes(rotate_about_axis(o, 3, 90.0_dp), [0.0_dp, 0.0_dp, 0.0_dp])
    call suite%close_array(reshape(a, [9]), [0.0_dp, 1.0_dp, 0.0_dp, -1.0_dp, 0.0_dp, 0.0_dp, &
                           0.0_dp, 0.0_dp, 1.0_dp], EXACT, 'rotation line: 90 degrees about 3')
    o%cylindrical = .true.
    o%a = [0.0_dp, 0.0_dp, 1.0_dp]
    o%b = [0.0_dp, 0.0_dp, 3.0_dp]
    a = orientation_axes(o, [2.0_dp, 2.0_dp, 7.0_dp])
    call suite%close_array(reshape(a, [9]), [h, h, 0.0_dp, -h, h, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], &
                           EXACT, 'cylindrical: radial, tangential, axial')
    call suite%check(orientation_is_valid(o), 'cylindrical: two distinct points are valid')
    o%b = o%a
    call suite%check(.not. orientation_is_valid(o), 'cylindrical: coinciding points are refused')
    o%cylindrical = .false.
    o%a = [1.0_dp, 1.0_dp, 0.0_dp]
    o%b = [2.0_dp, 2.0_dp, 0.0_dp]
    call suite%check(.not. orientation_is_valid(o), 'rectangular: b parallel to a is refused')
  end subroutine check_axes

  subroutine check_rotation(suite)
    type(test_suite_t), intent(inout) :: suite
    type(orientation_t) :: o
    real(dp) :: a(3, 3), c_local(6, 6), strain(6), local(6)
    o%a = [1.0_dp, 0.6_dp, -0.3_dp]
    o%b = [-0.2_dp, 1.0_dp, 0.5_dp]
    a = orientation_axes(o, [0.0_dp, 0.0_dp, 0.0_dp])
    c_local = engineering_stiffness([100.0e3_dp, 20.0e3_dp, 10.0e3_dp, 0.3_dp, 0.25_dp, 0.4_dp, &
                                     8.0e3_dp, 6.0e3_dp, 4.0e3_dp])
    strain = [1.0e-3_dp, -2.0e-4_dp, 3.0e-4_dp, 5.0e-4_dp, -1.0e-4_dp, 2.0e-4_dp]
    call suite%close_array(matmul(rotate_stiffness(c_local, a), strain), &
                           stress_to_global(matmul(c_local, strain_to_local(strain, a)), a), EXACT, &
                           'T C T^T eps = to_global(C to_local(eps))')
    local = stress_to_local(stress_to_global(strain, a), a)
    call suite%close_array(local, strain, EXACT, 'to_local(to_global(s)) = s')
    call suite%close_array(reshape(rotate_stiffness(isotropic_elastic_matrix(3.0_dp, 0.2_dp), a), [36]), &
                           reshape(isotropic_elastic_matrix(3.0_dp, 0.2_dp), [36]), EXACT, &
                           'an isotropic C is the same in every axes')
    call suite%check(maxval(abs(rotate_stiffness(c_local, a) - &
                                transpose(rotate_stiffness(c_local, a)))) < EXACT * 1.0e5_dp, &
                     'the rotated stiffness is symmetric')
  end subroutine check_rotation

  subroutine check_update(suite)
    type(test_suite_t), intent(inout) :: suite
    type(anisotropic_elastic_t) :: m
    real(dp) :: stress(6), state(0), strain(6), tangent(6, 6)
    integer :: i
    m%stiffness = anisotropic_stiffness([(real(i, dp), i = 1, 21)])
    strain = [1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp, 5.0_dp, 6.0_dp]
    stress = 1.0_dp
    call m%update(stress, strain, state, tangent)
    call suite%close_array(stress, 1.0_dp + matmul(m%stiffness, strain), EXACT, 'update adds C eps')
    call suite%close_array(reshape(tangent, [36]), reshape(m%stiffness, [36]), EXACT, &
                           'consistent tangent is C')
    call suite%check(m%is_anisotropic() .and. m%n_state() == 0, 'anisotropic, no internal variables')
  end subroutine check_update

end program test_fcs_anisotropic_elastic
