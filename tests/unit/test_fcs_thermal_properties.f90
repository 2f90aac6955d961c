!> Unit test of fcs_thermal_properties and the thermal procedures of fcs_material: tables
!> linear between their points and constant beyond the ends (CalculiX); the secant thermal
!> strain alpha(T) (T - T_Z) and its increments, which telescope (the sum over any partition of
!> [T0, T] is eps_th(T) - eps_th(T0)); the stress rescaling C(T1) C(T0)^-1 sigma, which keeps
!> the elastic strain (C(T1)^-1 of the result is C(T0)^-1 sigma) and leaves a material with
!> constant constants unchanged; the compliance as the inverse of the elastic matrix.
program test_fcs_thermal_properties
  use fcs_kinds, only: dp
  use fcs_thermal_properties, only: thermal_properties_t, table_value
  use fcs_material, only: isotropic_elastic_matrix, isotropic_compliance_matrix
  use fcs_hypoelastic, only: hypoelastic_t
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  !> A handful of operations on numbers of order one: 1e-13 relative.
  real(dp), parameter :: EXACT = 1.0e-13_dp

  suite%name = 'fcs_thermal_properties'
  call check_table(suite)
  call check_strain(suite)
  call check_rescale(suite)
  call suite%report()

contains

  subroutine check_table(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: xs(3) = [0.0_dp, 100.0_dp, 300.0_dp], ys(3) = [1.0_dp, 3.0_dp, 2.0_dp]
    call suite%close_to(table_value(xs, ys, -50.0_dp), 1.0_dp, EXACT, 'constant below the first point')
    call suite%close_to(table_value(xs, ys, 50.0_dp), 2.0_dp, EXACT, 'linear in the first interval')
    call suite%close_to(table_value(xs, ys, 200.0_dp), 2.5_dp, EXACT, 'linear in the second interval')
    call suite%close_to(table_value(xs, ys, 100.0_dp), 3.0_dp, EXACT, 'at a point')
    call suite%close_to(table_value(xs, ys, 1000.0_dp), 2.0_dp, EXACT, 'constant beyond the last point')
    call suite%close_to(table_value(xs(1:1), ys(1:1), 1000.0_dp), 1.0_dp, EXACT, 'one point: constant')
  end subroutine check_table

  subroutine check_strain(suite)
    type(test_suite_t), intent(inout) :: suite
    type(hypoelastic_t) :: m
    real(dp) :: total(6), t
    integer :: i
    m%youngs_modulus = 200000.0_dp
    m%poisson_ratio = 0.3_dp
    call suite%check(.not. m%thermal%is_active(), 'a material without *EXPANSION is not thermal')
    total = m%thermal_strain_increment(0.0_dp, 100.0_dp)
    call suite%close_to(total(1), 0.0_dp, EXACT, 'no expansion: no thermal strain', floor=1.0_dp)
    m%thermal%zero = 20.0_dp
    m%thermal%alpha = [1.0e-5_dp, 2.0e-5_dp]
    m%thermal%alpha_temperature = [0.0_dp, 200.0_dp]
    call suite%close_to(m%thermal%strain(120.0_dp), 1.6e-5_dp * 100.0_dp, EXACT, &
                        'secant strain alpha(T) (T - Z)')
    total = 0.0_dp
    t = 20.0_dp
    do i = 1, 7
      total = total + m%thermal_strain_increment(t, t + 25.0_dp)
      t = t + 25.0_dp
    end do
    call suite%close_to(total(1), m%thermal%strain(195.0_dp) - m%thermal%strain(20.0_dp), EXACT, &
                        'increments telescope to eps_th(T) - eps_th(T0)')
    call suite%close_to(total(4), 0.0_dp, EXACT, 'no thermal shear', floor=1.0_dp)
    call suite%close_to(total(3), total(1), EXACT, 'isotropic')
  end subroutine check_strain

  subroutine check_rescale(suite)
    type(test_suite_t), intent(inout) :: suite
    type(hypoelastic_t) :: m
    real(dp) :: sigma(6), rescaled(6), product(6, 6), identity(6, 6)
    integer :: i
    m%youngs_modulus = 200000.0_dp
    m%poisson_ratio = 0.3_dp
    sigma = [-100.0_dp, 30.0_dp, 5.0_dp, 12.0_dp, -7.0_dp, 3.0_dp]
    rescaled = m%rescale_stress(sigma, 0.0_dp, 100.0_dp)
    call suite%close_array(rescaled, sigma, EXACT, 'constant constants: stress unchanged')
    product = matmul(isotropic_elastic_matrix(2.0_dp, 0.3_dp), isotropic_compliance_matrix(2.0_dp, 0.3_dp))
    identity = 0.0_dp
    do i = 1, 6
      identity(i, i) = 1.0_dp
    end do
    call suite%close_array(reshape(product, [36]), reshape(identity, [36]), EXACT, &
                           'compliance is the inverse of the elastic matrix')
    m%thermal%youngs_modulus = [200000.0_dp, 100000.0_dp]
    m%thermal%poisson_ratio = [0.3_dp, 0.2_dp]
    m%thermal%elastic_temperature = [0.0_dp, 200.0_dp]
    rescaled = m%rescale_stress(sigma, 0.0_dp, 100.0_dp)
    call suite%close_array(matmul(isotropic_compliance_matrix(150000.0_dp, 0.25_dp), rescaled), &
                           matmul(isotropic_compliance_matrix(200000.0_dp, 0.3_dp), sigma), EXACT, &
                           'rescaling keeps the elastic strain')
    product = m%elastic_matrix_at(100.0_dp)
    identity = isotropic_elastic_matrix(150000.0_dp, 0.25_dp)
    call suite%close_array(reshape(product, [36]), reshape(identity, [36]), EXACT, &
                           'elastic matrix at T from the table')
  end subroutine check_rescale

end program test_fcs_thermal_properties
