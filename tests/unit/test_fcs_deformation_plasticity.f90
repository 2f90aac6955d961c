!> Unit test of fcs_deformation_plasticity (*DEFORMATION PLASTICITY, doc/theory.md 2.12), with
!> CalculiX's test deck beampl's constants E = 190000, nu = 0.34, sigma_0 = 900, n = 12,
!> alpha = 0.45:
!> - uniaxial stress: the Ramberg-Osgood strain eps(sigma) (Ramberg & Osgood 1943) with the
!>   lateral strains of (D1), -nu sigma/E - alpha/2 (|sigma|/sigma_0)^(n-1) sigma/E, gives back
!>   the stress diag(0, 0, sigma) to round-off, below and above sigma_0, in tension and
!>   compression (the inverse);
!> - the equivalent stress q(e_q) of the Newton iteration satisfies (D3) to round-off;
!> - the tangent d sigma / d e against central differences of the stress, at a general strain
!>   in the plastic range and at a small one, and its elastic limit at e = 0;
!> - the law on the total path (fcs_hyperelastic, family HYPER_DEFORMATION_PLASTICITY): the
!>   stress is objective, sigma(Q F) = Q sigma(F) Q^T, and Miehe's numerical Jaumann tangent
!>   gives sigma^J = c : D against central differences of sigma(F) along F' = L F.
program test_fcs_deformation_plasticity
  use fcs_kinds, only: dp
  use fcs_deformation_plasticity, only: ramberg_osgood_t, ramberg_osgood_strain, &
    deformation_plasticity_stress, deformation_plasticity_tangent, equivalent_stress_of
  use fcs_hyperelastic, only: hyperelastic_law_t, hyperelastic_stress, &
    hyperelastic_jaumann_tangent, HYPER_DEFORMATION_PLASTICITY
  use fcs_st_venant_kirchhoff, only: voigt_tensor, tensor_voigt
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  !> Round-off: the Newton iteration stops at a correction of 4 eps q; the stress is a sum of
  !> terms of order E e ~ 2e3 that cancel to 0 laterally, so 1e-12 of sigma with a floor.
  real(dp), parameter :: EXACT = 1.0e-12_dp

  suite%name = 'fcs_deformation_plasticity'
  call check_uniaxial(suite)
  call check_equivalent_stress(suite)
  call check_tangent(suite)
  call check_total_path(suite)
  call suite%report()

contains

  function beampl_law() result(law)
    type(ramberg_osgood_t) :: law
    law%youngs_modulus = 190000.0_dp
    law%poisson_ratio = 0.34_dp
    law%yield_stress = 900.0_dp
    law%exponent = 12.0_dp
    law%yield_offset = 0.45_dp
  end function beampl_law

  !> Uniaxial stress sigma: strain diag(e_lat, e_lat, eps(sigma)) -> stress diag(0, 0, sigma).
  subroutine check_uniaxial(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: STRESSES(6) = [100.0_dp, 600.0_dp, 900.0_dp, 1100.0_dp, -850.0_dp, &
                                          -1300.0_dp]
    type(ramberg_osgood_t) :: law
    real(dp) :: e(3, 3), sigma(3, 3), s, lateral, plastic
    character(len=40) :: label
    integer :: k
    law = beampl_law()
    do k = 1, size(STRESSES)
      s = STRESSES(k)
      write (label, '(a,f8.1)') 'uniaxial sigma =', s
      plastic = law%yield_offset * (abs(s) / law%yield_stress)**(law%exponent - 1.0_dp) * s / &
                law%youngs_modulus
      lateral = -law%poisson_ratio * s / law%youngs_modulus - 0.5_dp * plastic
      ! (D2) by its own terms: eps = sigma/E + alpha (|sigma|/sigma_0)^(n-1) sigma/E.
      call suite%close_to(ramberg_osgood_strain(law, s), s / law%youngs_modulus + plastic, EXACT, &
                          trim(label) // ': Ramberg-Osgood strain')
      e = 0.0_dp
      e(1, 1) = lateral
      e(2, 2) = lateral
      e(3, 3) = ramberg_osgood_strain(law, s)
      sigma = deformation_plasticity_stress(law, e)
      call suite%close_to(sigma(3, 3), s, EXACT, trim(label) // ': stress of its strain')
      call suite%close_to(sigma(1, 1), 0.0_dp, EXACT, trim(label) // ': no lateral stress', &
                          floor=abs(s))
      call suite%close_to(sigma(2, 2), 0.0_dp, EXACT, trim(label) // ': no lateral stress (2)', &
                          floor=abs(s))
    end do
  end subroutine check_uniaxial

  !> E e_q = (2 (1 + nu)/3 + alpha (q/sigma_0)^(n-1)) q at the q returned, from e_q of q.
  subroutine check_equivalent_stress(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: STRESSES(5) = [1.0_dp, 450.0_dp, 900.0_dp, 1200.0_dp, 2000.0_dp]
    type(ramberg_osgood_t) :: law, linear
    real(dp) :: q, strain
    integer :: k
    law = beampl_law()
    do k = 1, size(STRESSES)
      q = STRESSES(k)
      strain = (2.0_dp * (1.0_dp + law%poisson_ratio) / 3.0_dp + law%yield_offset * &
                (q / law%yield_stress)**(law%exponent - 1.0_dp)) * q / law%youngs_modulus
      call suite%close_to(equivalent_stress_of(law, strain), q, EXACT, &
                          'equivalent stress of its equivalent strain (D3)')
    end do
    call suite%close_to(equivalent_stress_of(law, 0.0_dp), 0.0_dp, EXACT, 'q(0) = 0', floor=1.0_dp)
    ! alpha = 0: linear elasticity, q = 3 G e_q.
    linear = law
    linear%yield_offset = 0.0_dp
    call suite%close_to(equivalent_stress_of(linear, 1.0e-3_dp), 1.5_dp * law%youngs_modulus / &
                        (1.0_dp + law%poisson_ratio) * 1.0e-3_dp, EXACT, 'alpha = 0: q = 3 G e_q')
  end subroutine check_equivalent_stress

  !> C against central differences (engineering shears perturbed by h, tensor components by h/2).
  !> Step 1e-8 on strains of 1e-2: truncation ~h^2 sigma''' ~ 1e-16 * E / e^2 ~ 1e-7, round-off
  !> ~1e-16 * 2e3 / 1e-8 ~ 2e-5, against entries of order E = 2e5: 1e-7 relative.
  subroutine check_tangent(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: H = 1.0e-8_dp
    real(dp), parameter :: E_PLASTIC(6) = [0.012_dp, -0.004_dp, -0.005_dp, 0.003_dp, -0.002_dp, &
                                           0.0015_dp]
    type(ramberg_osgood_t) :: law
    real(dp) :: c(6, 6), column(6), strain(6), e_elastic(6, 6), g, k
    integer :: b, scale_index
    law = beampl_law()
    do scale_index = 1, 2
      strain = E_PLASTIC
      if (scale_index == 2) strain = 1.0e-2_dp * E_PLASTIC
      c = deformation_plasticity_tangent(law, engineering_tensor(strain))
      do b = 1, 6
        column = (tensor_voigt(deformation_plasticity_stress(law, engineering_tensor(strain + &
                  H * unit(b)))) - tensor_voigt(deformation_plasticity_stress(law, &
                  engineering_tensor(strain - H * unit(b))))) / (2.0_dp * H)
        call suite%close_array(c(:, b) / law%youngs_modulus, column / law%youngs_modulus, 1.0e-7_dp, &
                               merge('plastic strain', 'small strain  ', scale_index == 1) // &
                               ': tangent column against central differences')
      end do
    end do
    ! e = 0: isotropic elasticity, lambda + 2 G on the diagonal, lambda off it, G on shears.
    g = law%youngs_modulus / (2.0_dp * (1.0_dp + law%poisson_ratio))
    k = law%youngs_modulus / (3.0_dp * (1.0_dp - 2.0_dp * law%poisson_ratio))
    e_elastic = 0.0_dp
    e_elastic(1:3, 1:3) = k - 2.0_dp * g / 3.0_dp
    do b = 1, 3
      e_elastic(b, b) = k + 4.0_dp * g / 3.0_dp
      e_elastic(b + 3, b + 3) = g
    end do
    c = deformation_plasticity_tangent(law, engineering_tensor([(0.0_dp, b = 1, 6)]))
    call suite%close_array(reshape(c, [36]), reshape(e_elastic, [36]), EXACT, &
                           'e = 0: the isotropic elastic matrix')
  end subroutine check_tangent

  !> The law as fcs3d's elements take it: sigma of the Almansi strain of F.
  subroutine check_total_path(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: H = 1.0e-6_dp
    !> A deformation gradient with stretches of a few percent, shear and rotation.
    real(dp), parameter :: F(3, 3) = reshape([1.012_dp, 0.004_dp, -0.003_dp, 0.006_dp, 0.995_dp, &
      0.002_dp, -0.002_dp, 0.003_dp, 0.994_dp], [3, 3])
    real(dp), parameter :: L(3, 3) = reshape([0.3_dp, -0.7_dp, 0.2_dp, 0.5_dp, -0.4_dp, 0.9_dp, &
      -0.6_dp, 0.1_dp, 0.25_dp], [3, 3])
    type(hyperelastic_law_t) :: law
    real(dp) :: q(3, 3), eye(3, 3), d(3, 3), w(3, 3), sigma(6), rate(6), jaumann(6), d_voigt(6)
    real(dp) :: angle
    integer :: i
    law%family = HYPER_DEFORMATION_PLASTICITY
    law%ramberg_osgood = beampl_law()
    eye = 0.0_dp
    do i = 1, 3
      eye(i, i) = 1.0_dp
    end do
    angle = 0.7_dp
    q = eye
    q(1, 1) = cos(angle)
    q(2, 2) = cos(angle)
    q(1, 2) = -sin(angle)
    q(2, 1) = sin(angle)
    sigma = hyperelastic_stress(law, F)
    call suite%check(sqrt(1.5_dp * sum(dev(voigt_tensor(sigma))**2)) > law%ramberg_osgood%yield_stress, &
                     'the general F is in the plastic range (Mises stress above sigma_0)')
    call suite%close_array(hyperelastic_stress(law, matmul(q, F)), &
                           tensor_voigt(matmul(q, matmul(voigt_tensor(sigma), transpose(q)))), &
                           EXACT, 'objective: sigma(Q F) = Q sigma(F) Q^T')
    ! Miehe's tangent: a central difference of step 1e-5 inside one of step 1e-6 here, both
    ! ~1e-10 truncation against the stress scale of 1e3 per unit rate: 1e-6 relative.
    d = 0.5_dp * (L + transpose(L))
    w = 0.5_dp * (L - transpose(L))
    d_voigt = [d(1, 1), d(2, 2), d(3, 3), 2.0_dp * d(1, 2), 2.0_dp * d(1, 3), 2.0_dp * d(2, 3)]
    rate = (hyperelastic_stress(law, matmul(eye + H * L, F)) - &
            hyperelastic_stress(law, matmul(eye - H * L, F))) / (2.0_dp * H)
    jaumann = rate - tensor_voigt(matmul(w, voigt_tensor(sigma)) - matmul(voigt_tensor(sigma), w))
    call suite%close_array(matmul(hyperelastic_jaumann_tangent(law, F), d_voigt), jaumann, 1.0e-6_dp, &
                           'Jaumann tangent c : D = sigma^J (finite differences)')
  end subroutine check_total_path

  pure function unit(b) result(v)
    integer, intent(in) :: b
    real(dp) :: v(6)
    v = 0.0_dp
    v(b) = 1.0_dp
  end function unit

  !> The symmetric tensor of a Voigt strain with engineering shears.
  pure function engineering_tensor(v) result(t)
    real(dp), intent(in) :: v(6)
    real(dp) :: t(3, 3)
    t = voigt_tensor([v(1:3), 0.5_dp * v(4:6)])
  end function engineering_tensor

  pure function dev(t) result(d)
    real(dp), intent(in) :: t(3, 3)
    real(dp) :: d(3, 3)
    integer :: i
    d = t
    do i = 1, 3
      d(i, i) = d(i, i) - (t(1, 1) + t(2, 2) + t(3, 3)) / 3.0_dp
    end do
  end function dev

end program test_fcs_deformation_plasticity
