!> Deformation plasticity of CalculiX 2.20 (`*DEFORMATION PLASTICITY`): the Ramberg-Osgood
!> law (Ramberg & Osgood 1943, NACA TN 902) in its three-dimensional deformation-theory form,
!> a total (path-independent, nonlinear elastic) relation between strain and stress
!> (doc/theory.md section 2.12). The ccx 2.20 manual ("*DEFORMATION PLASTICITY", and the
!> material section "Deformation plasticity") writes it for the Cauchy stress sigma and an
!> Eulerian strain e, with p = -tr(sigma)/3, s = dev(sigma), q = sqrt(3/2 s:s):
!>   E e = (1 + nu) s - (1 - 2 nu) p I + 3/2 alpha (q / sigma_0)^(n - 1) s,             (D1)
!> which in uniaxial stress is E eps = sigma + alpha (|sigma| / sigma_0)^(n - 1) sigma.       (D2)
!> Its volumetric part is linear elastic, tr(e) = -3 (1 - 2 nu) p / E; its deviatoric part,
!> with the equivalent strain e_q = sqrt(2/3 dev(e):dev(e)), gives
!>   E e_q = (2 (1 + nu) / 3 + alpha (q / sigma_0)^(n - 1)) q                           (D3)
!> and s = 2 q / (3 e_q) dev(e). ccx (defplas.f) inverts (D3) for q by a Newton iteration
!> from an elastic or a power-law start; here the same Newton iteration, started from the
!> smaller of the two (both bound the root from above, and the left side of (D3) is convex
!> and increasing in q, so the iterates decrease monotonically to the root), to round-off.
!>
!> The strain the element loops pass is the Almansi strain e = (I - b^-1) / 2 of
!> F (fcs_hyperelastic, family HYPER_DEFORMATION_PLASTICITY): ccx 2.20 (e_c3d.f, results.f)
!> turns the Green-Lagrange E into F^-1 E F^-T, which is the Almansi strain F^-T E F^-1 when F
!> is symmetric (no rotation); the Almansi form keeps the law objective under rotation.
!>
!> Strains and stresses here are 3 x 3 tensors; the tangent a Voigt matrix (11, 22, 33, 12,
!> 13, 23) from engineering shear strains to stresses.
module fcs_deformation_plasticity
  use fcs_kinds, only: dp
  implicit none
  private
  public :: ramberg_osgood_t, ramberg_osgood_strain, deformation_plasticity_stress
  public :: deformation_plasticity_tangent, equivalent_stress_of

  !> The constants of one *DEFORMATION PLASTICITY line: E [stress], nu [-], sigma_0 [stress],
  !> n [-] (>= 1), alpha [-] (>= 0).
  type :: ramberg_osgood_t
    real(dp) :: youngs_modulus = 0.0_dp
    real(dp) :: poisson_ratio = 0.0_dp
    real(dp) :: yield_stress = 1.0_dp
    real(dp) :: exponent = 1.0_dp
    real(dp) :: yield_offset = 0.0_dp
  end type ramberg_osgood_t

  !> The Newton iteration on (D3) stops when a correction is below this fraction of q.
  real(dp), parameter :: NEWTON_TOLERANCE = 4.0_dp * epsilon(1.0_dp)
  integer, parameter :: NEWTON_LIMIT = 200
  !> Equivalent strains below this are taken as zero (the secant modulus is then 2 G).
  real(dp), parameter :: SMALL_STRAIN = 1.0e-300_dp
  integer, parameter :: VOIGT_I(6) = [1, 2, 3, 1, 1, 2], VOIGT_J(6) = [1, 2, 3, 2, 3, 3]

contains

  !> The uniaxial strain of the uniaxial stress sigma [stress], (D2).
  pure real(dp) function ramberg_osgood_strain(law, sigma) result(strain)
    type(ramberg_osgood_t), intent(in) :: law
    real(dp), intent(in) :: sigma
    strain = (sigma + law%yield_offset * (abs(sigma) / law%yield_stress)**(law%exponent - 1.0_dp) &
              * sigma) / law%youngs_modulus
  end function ramberg_osgood_strain

  !> The Mises equivalent stress q >= 0 of the equivalent strain e_q >= 0: the root of (D3) by
  !> Newton's method from the smaller of the elastic (alpha = 0) and power-law (no elastic
  !> term) solutions, both of which lie above the root.
  pure real(dp) function equivalent_stress_of(law, equivalent_strain) result(q)
    type(ramberg_osgood_t), intent(in) :: law
    real(dp), intent(in) :: equivalent_strain
    real(dp) :: c_elastic, c_plastic, target, dq
    integer :: iteration
    c_elastic = 2.0_dp * (1.0_dp + law%poisson_ratio) / 3.0_dp
    target = law%youngs_modulus * equivalent_strain
    q = target / c_elastic
    if (equivalent_strain <= 0.0_dp .or. law%yield_offset <= 0.0_dp) return
    q = min(q, (law%yield_stress**(law%exponent - 1.0_dp) * target / law%yield_offset)** &
                (1.0_dp / law%exponent))
    do iteration = 1, NEWTON_LIMIT
      c_plastic = law%yield_offset * (q / law%yield_stress)**(law%exponent - 1.0_dp)
      dq = (target - (c_elastic + c_plastic) * q) / (c_elastic + law%exponent * c_plastic)
      q = q + dq
      if (abs(dq) <= NEWTON_TOLERANCE * q) exit
    end do
  end function equivalent_stress_of

  !> The stress (3 x 3) of the strain e (3 x 3, symmetric): sigma = K tr(e) I + 2 q / (3 e_q)
  !> dev(e), K = E / (3 (1 - 2 nu)), q of (D3).
  pure function deformation_plasticity_stress(law, e) result(sigma)
    type(ramberg_osgood_t), intent(in) :: law
    real(dp), intent(in) :: e(3, 3)
    real(dp) :: sigma(3, 3)
    real(dp) :: deviator(3, 3), volumetric, equivalent, secant
    integer :: i
    call split(e, deviator, volumetric, equivalent)
    secant = secant_modulus(law, equivalent)
    sigma = secant * deviator
    do i = 1, 3
      sigma(i, i) = sigma(i, i) + bulk_modulus(law) * volumetric
    end do
  end function deformation_plasticity_stress

  !> The tangent d sigma / d e (Voigt, engineering shears) of deformation_plasticity_stress:
  !>   C = K I x I + g (I_sym - I x I / 3) + (2 / (3 e_q)) g'(e_q) dev(e) x dev(e),
  !> g = 2 q / (3 e_q) the secant modulus, g' = 2/3 (q' / e_q - q / e_q^2), and
  !> q' = E / (2 (1 + nu) / 3 + n alpha (q / sigma_0)^(n - 1)) from (D3).
  pure function deformation_plasticity_tangent(law, e) result(c)
    type(ramberg_osgood_t), intent(in) :: law
    real(dp), intent(in) :: e(3, 3)
    real(dp) :: c(6, 6)
    real(dp) :: deviator(3, 3), volumetric, equivalent, secant, q, slope, factor, d(6)
    integer :: a, b
    call split(e, deviator, volumetric, equivalent)
    secant = secant_modulus(law, equivalent)
    c = 0.0_dp
    do a = 1, 3
      do b = 1, 3
        c(a, b) = bulk_modulus(law) - secant / 3.0_dp
      end do
      c(a, a) = c(a, a) + secant
      c(a + 3, a + 3) = 0.5_dp * secant
    end do
    if (equivalent <= SMALL_STRAIN) return
    q = equivalent_stress_of(law, equivalent)
    slope = law%youngs_modulus / (2.0_dp * (1.0_dp + law%poisson_ratio) / 3.0_dp + law%exponent * &
            law%yield_offset * (q / law%yield_stress)**(law%exponent - 1.0_dp))
    factor = 2.0_dp / (3.0_dp * equivalent) * 2.0_dp / 3.0_dp * (slope / equivalent - q / equivalent**2)
    do a = 1, 6
      d(a) = deviator(VOIGT_I(a), VOIGT_J(a))
    end do
    do b = 1, 6
      c(:, b) = c(:, b) + factor * d * d(b)
    end do
  end function deformation_plasticity_tangent

  !> dev(e), tr(e) and e_q = sqrt(2/3 dev(e):dev(e)).
  pure subroutine split(e, deviator, volumetric, equivalent)
    real(dp), intent(in) :: e(3, 3)
    real(dp), intent(out) :: deviator(3, 3), volumetric, equivalent
    integer :: i
    volumetric = e(1, 1) + e(2, 2) + e(3, 3)
    deviator = 0.5_dp * (e + transpose(e))
    do i = 1, 3
      deviator(i, i) = deviator(i, i) - volumetric / 3.0_dp
    end do
    equivalent = sqrt(2.0_dp / 3.0_dp * sum(deviator**2))
  end subroutine split

  !> g = 2 q / (3 e_q), its limit E / (1 + nu) = 2 G at e_q = 0.
  pure real(dp) function secant_modulus(law, equivalent) result(g)
    type(ramberg_osgood_t), intent(in) :: law
    real(dp), intent(in) :: equivalent
    if (equivalent <= SMALL_STRAIN) then
      g = law%youngs_modulus / (1.0_dp + law%poisson_ratio)
    else
      g = 2.0_dp * equivalent_stress_of(law, equivalent) / (3.0_dp * equivalent)
    end if
  end function secant_modulus

  pure real(dp) function bulk_modulus(law)
    type(ramberg_osgood_t), intent(in) :: law
    bulk_modulus = law%youngs_modulus / (3.0_dp * (1.0_dp - 2.0_dp * law%poisson_ratio))
  end function bulk_modulus

end module fcs_deformation_plasticity
