!> Isotropic hyperelastic laws of CalculiX 2.20 (`*HYPERELASTIC`, `*HYPERFOAM`): the Cauchy
!> stress as a function of the deformation gradient F through a strain energy U, and the
!> spatial tangent of the Jaumann rate the element loops take (doc/theory.md section 2.11).
!>
!> The energies are those of the ccx 2.20 manual, section 6.2.x "*HYPERELASTIC" (eqs. of the
!> reduced invariants Ibar_1 = III_C^(-1/3) I_C, Ibar_2 = III_C^(-2/3) II_C, J = III_C^(1/2) of
!> the right Cauchy-Green tensor C = F^T F, and the deviatoric stretches lambdabar_a =
!> J^(-1/3) lambda_a) and section "*HYPERFOAM" (the stretches lambda_a themselves):
!>   polynomial     U = sum_{i+j=1..N} C_ij (Ibar_1 - 3)^i (Ibar_2 - 3)^j + sum_{i=1..N} (J - 1)^(2i) / D_i
!>                  (NEO HOOKE: C10 only, N = 1; MOONEY-RIVLIN: C10, C01; REDUCED POLYNOMIAL:
!>                  C_i0 only; YEOH: reduced polynomial with N = 3)
!>   Arruda-Boyce   U = mu [1/2 (Ibar_1 - 3) + 1/(20 lm^2) (Ibar_1^2 - 9) + 11/(1050 lm^4) (Ibar_1^3 - 27)
!>                  + 19/(7000 lm^6) (Ibar_1^4 - 81) + 519/(673750 lm^8) (Ibar_1^5 - 243)]
!>                  + 1/D ((J^2 - 1)/2 - ln J)
!>   Ogden          U = sum_i 2 mu_i / alpha_i^2 (sum_a lambdabar_a^alpha_i - 3) + sum_i (J - 1)^(2i) / D_i
!>   hyperfoam      U = sum_i 2 mu_i / alpha_i^2 (sum_a lambda_a^alpha_i - 3 + (J^(-alpha_i beta_i) - 1) / beta_i),
!>                  beta_i = nu_i / (1 - 2 nu_i).
!> The Kirchhoff stress tau = 2 F dU/dC F^T is, for U(Ibar_1, Ibar_2, J) (Holzapfel 2000,
!> eq. 6.108 and section 6.4; bbar = J^(-2/3) F F^T),
!>   tau = dev[2 (U_1 + Ibar_1 U_2) bbar - 2 U_2 bbar^2] + J U_J I,                        (H1)
!> and for U of the principal stretches, in the eigenvectors n_a of b = F F^T (Holzapfel 2000,
!> eq. 6.87 and 6.198),
!>   Ogden:      tau_a = sum_i 2 mu_i / alpha_i (lambdabar_a^alpha_i - 1/3 sum_b lambdabar_b^alpha_i) + J U_J,
!>   hyperfoam:  tau_a = sum_i 2 mu_i / alpha_i (lambda_a^alpha_i - J^(-alpha_i beta_i)),          (H2)
!> and sigma = tau / J. The tangent is Miehe's (1996) numerical one (`hyperelastic_jaumann_tangent`).
!> The same total path serves `*DEFORMATION PLASTICITY` (family HYPER_DEFORMATION_PLASTICITY,
!> fcs_deformation_plasticity, doc/theory.md 2.12): a nonlinear elastic law without an energy
!> written here, sigma = f(e) of the Almansi strain e = (I - b^-1) / 2, tau = J sigma.
!>
!> Stresses are Voigt vectors (11, 22, 33, 12, 13, 23); tangents map engineering-shear rates of
!> deformation to stress rates.
module fcs_hyperelastic
  use fcs_kinds, only: dp
  use fcs_st_venant_kirchhoff, only: determinant_of, tensor_voigt, inverse_of
  use fcs_deformation_plasticity, only: ramberg_osgood_t, deformation_plasticity_stress
  implicit none
  private
  public :: hyperelastic_law_t, hyperelastic_stress, hyperelastic_jaumann_tangent
  public :: hyperelastic_initial_moduli, symmetric_eigen
  public :: HYPER_NONE, HYPER_POLYNOMIAL, HYPER_ARRUDA_BOYCE, HYPER_OGDEN, HYPER_FOAM
  public :: HYPER_DEFORMATION_PLASTICITY, almansi_strain, hyper_law_text, hyper_law_keyword

  !> Families of energies: by the reduced invariants (polynomial, with its special cases, and
  !> Arruda-Boyce) or by the principal stretches (Ogden; hyperfoam); and the Ramberg-Osgood
  !> deformation plasticity of the Almansi strain (*DEFORMATION PLASTICITY).
  integer, parameter :: HYPER_NONE = 0, HYPER_POLYNOMIAL = 1, HYPER_ARRUDA_BOYCE = 2, &
                        HYPER_OGDEN = 3, HYPER_FOAM = 4, HYPER_DEFORMATION_PLASTICITY = 5

  !> The perturbation of Miehe's numerical tangent (a central difference: truncation ~ h^2
  !> times the third derivative, round-off ~ 1e-16 / h, both ~1e-10 relative for stretches of
  !> order one).
  real(dp), parameter :: PERTURBATION = 1.0e-5_dp

  !> Voigt index pairs.
  integer, parameter :: VOIGT_I(6) = [1, 2, 3, 1, 1, 2], VOIGT_J(6) = [1, 2, 3, 2, 3, 3]

  !> One hyperelastic law: the family, its order N, and its constants (the compressibility
  !> constants D_i already given their defaults where the deck gave 0, as CalculiX does).
  type :: hyperelastic_law_t
    integer :: family = HYPER_NONE
    !> The deck's name of the form, for messages ("NEO HOOKE", "OGDEN, N=2", "HYPERFOAM, N=2").
    character(len=:), allocatable :: form
    integer :: order = 1
    !> Polynomial constants C_ij (i powers Ibar_1 - 3, j powers Ibar_2 - 3).
    real(dp) :: c(0:3, 0:3) = 0.0_dp
    !> Compressibility constants D_1..D_N (polynomial, Ogden; Arruda-Boyce: D_1 = D).
    real(dp) :: d(3) = 0.0_dp
    !> Ogden and hyperfoam mu_i, alpha_i; hyperfoam beta_i = nu_i / (1 - 2 nu_i).
    !> Arruda-Boyce: mu(1) = mu, lambda_m below.
    real(dp) :: mu(3) = 0.0_dp
    real(dp) :: alpha(3) = 0.0_dp
    real(dp) :: beta(3) = 0.0_dp
    real(dp) :: lambda_m = 1.0_dp
    !> *DEFORMATION PLASTICITY: E, nu, sigma_0, n, alpha.
    type(ramberg_osgood_t) :: ramberg_osgood
  end type hyperelastic_law_t

contains

  !> The Cauchy stress sigma = tau(F) / det F of the law at F, (H1)-(H2).
  pure function hyperelastic_stress(law, f) result(sigma)
    type(hyperelastic_law_t), intent(in) :: law
    real(dp), intent(in) :: f(3, 3)
    real(dp) :: sigma(6)
    sigma = tensor_voigt(kirchhoff_stress(law, f)) / determinant_of(f)
  end function hyperelastic_stress

  !> The tangent c of sigma^J = c : D (Jaumann rate of the Cauchy stress, D the rate of
  !> deformation, engineering shears) at F, by Miehe's (1996, eq. 45-47) perturbation: the
  !> rate of deformation D^(kl) = sym(e_k x e_l) alone (no spin) moves F by dF = h D^(kl) F,
  !> and then tau' = tau^J (the Jaumann rate of the Kirchhoff stress: W = 0), so
  !>   c^tau(:, kl) = [tau((I + h D^(kl)) F) - tau((I - h D^(kl)) F)] / (2 h)
  !> (central differences), and with J' = J tr D, sigma^J = tau^J / J - sigma tr D:
  !>   c(:, kl) = c^tau(:, kl) / J - sigma delta_kl                                      (H3)
  !> (as svk_jaumann_tangent, doc/theory.md 2.10, S4).
  pure function hyperelastic_jaumann_tangent(law, f) result(c)
    type(hyperelastic_law_t), intent(in) :: law
    real(dp), intent(in) :: f(3, 3)
    real(dp) :: c(6, 6)
    real(dp) :: d(3, 3), eye(3, 3), sigma(6), j
    integer :: b, k, l
    eye = identity()
    j = determinant_of(f)
    sigma = tensor_voigt(kirchhoff_stress(law, f)) / j
    do b = 1, 6
      k = VOIGT_I(b)
      l = VOIGT_J(b)
      d = 0.0_dp
      d(k, l) = 0.5_dp
      d(l, k) = d(l, k) + 0.5_dp
      c(:, b) = tensor_voigt(kirchhoff_stress(law, matmul(eye + PERTURBATION * d, f)) - &
                             kirchhoff_stress(law, matmul(eye - PERTURBATION * d, f))) / &
                (2.0_dp * PERTURBATION * j)
      if (b <= 3) c(:, b) = c(:, b) - sigma
    end do
  end function hyperelastic_jaumann_tangent

  !> The initial shear modulus mu_0 and bulk modulus K_0 of the law (its small-strain limit):
  !> polynomial mu_0 = 2 (C10 + C01), Ogden sum mu_i, Arruda-Boyce mu, K_0 = 2 / D_1;
  !> hyperfoam mu_0 = sum mu_i, K_0 = sum 2 mu_i (1/3 + beta_i); deformation plasticity
  !> mu_0 = E / (2 (1 + nu)), K_0 = E / (3 (1 - 2 nu)).
  pure subroutine hyperelastic_initial_moduli(law, mu0, k0)
    type(hyperelastic_law_t), intent(in) :: law
    real(dp), intent(out) :: mu0, k0
    if (law%family == HYPER_DEFORMATION_PLASTICITY) then
      mu0 = law%ramberg_osgood%youngs_modulus / (2.0_dp * (1.0_dp + law%ramberg_osgood%poisson_ratio))
      k0 = law%ramberg_osgood%youngs_modulus / (3.0_dp * (1.0_dp - 2.0_dp * &
           law%ramberg_osgood%poisson_ratio))
      return
    end if
    select case (law%family)
    case (HYPER_POLYNOMIAL)
      mu0 = 2.0_dp * (law%c(1, 0) + law%c(0, 1))
    case (HYPER_ARRUDA_BOYCE)
      mu0 = law%mu(1)
    case default
      mu0 = sum(law%mu(1:law%order))
    end select
    if (law%family == HYPER_FOAM) then
      k0 = sum(2.0_dp * law%mu(1:law%order) * (1.0_dp / 3.0_dp + law%beta(1:law%order)))
    else
      k0 = 2.0_dp / law%d(1)
    end if
  end subroutine hyperelastic_initial_moduli

  !> The Kirchhoff stress tau (3 x 3) of the law at F.
  pure function kirchhoff_stress(law, f) result(tau)
    type(hyperelastic_law_t), intent(in) :: law
    real(dp), intent(in) :: f(3, 3)
    real(dp) :: tau(3, 3)
    select case (law%family)
    case (HYPER_POLYNOMIAL, HYPER_ARRUDA_BOYCE)
      tau = invariant_stress(law, f)
    case (HYPER_DEFORMATION_PLASTICITY)
      tau = determinant_of(f) * deformation_plasticity_stress(law%ramberg_osgood, almansi_strain(f))
    case default
      tau = principal_stress(law, f)
    end select
  end function kirchhoff_stress

  !> (H1): tau = dev[2 (U_1 + Ibar_1 U_2) bbar - 2 U_2 bbar^2] + J U_J I for the polynomial
  !> energies and Arruda-Boyce.
  pure function invariant_stress(law, f) result(tau)
    type(hyperelastic_law_t), intent(in) :: law
    real(dp), intent(in) :: f(3, 3)
    real(dp) :: tau(3, 3)
    real(dp) :: bbar(3, 3), bbar2(3, 3), j, i1, i2, u1, u2, ju_j, lm2
    integer :: i, k
    j = determinant_of(f)
    bbar = j**(-2.0_dp / 3.0_dp) * matmul(f, transpose(f))
    bbar2 = matmul(bbar, bbar)
    i1 = trace(bbar)
    i2 = 0.5_dp * (i1**2 - trace(bbar2))
    u1 = 0.0_dp
    u2 = 0.0_dp
    if (law%family == HYPER_ARRUDA_BOYCE) then
      ! dU/dIbar_1 of the manual's five-term series; 1/D ((J^2 - 1)/2 - ln J): J U_J = (J^2 - 1)/D.
      lm2 = law%lambda_m**2
      u1 = law%mu(1) * (0.5_dp + i1 / (10.0_dp * lm2) + 33.0_dp * i1**2 / (1050.0_dp * lm2**2) + &
           76.0_dp * i1**3 / (7000.0_dp * lm2**3) + 2595.0_dp * i1**4 / (673750.0_dp * lm2**4))
      ju_j = (j**2 - 1.0_dp) / law%d(1)
    else
      do i = 0, law%order
        do k = 0, law%order - i
          if (i >= 1) u1 = u1 + i * law%c(i, k) * (i1 - 3.0_dp)**(i - 1) * (i2 - 3.0_dp)**k
          if (k >= 1) u2 = u2 + k * law%c(i, k) * (i1 - 3.0_dp)**i * (i2 - 3.0_dp)**(k - 1)
        end do
      end do
      ju_j = j * volumetric_derivative(law, j)
    end if
    tau = deviator(2.0_dp * (u1 + i1 * u2) * bbar - 2.0_dp * u2 * bbar2) + ju_j * identity()
  end function invariant_stress

  !> dU_vol/dJ = sum_{i=1..N} 2 i (J - 1)^(2i - 1) / D_i.
  pure real(dp) function volumetric_derivative(law, j) result(du)
    type(hyperelastic_law_t), intent(in) :: law
    real(dp), intent(in) :: j
    integer :: i
    du = 0.0_dp
    do i = 1, law%order
      du = du + 2.0_dp * i * (j - 1.0_dp)**(2 * i - 1) / law%d(i)
    end do
  end function volumetric_derivative

  !> (H2): Ogden and hyperfoam, tau = sum_a tau_a n_a x n_a in the eigenvectors of b = F F^T.
  pure function principal_stress(law, f) result(tau)
    type(hyperelastic_law_t), intent(in) :: law
    real(dp), intent(in) :: f(3, 3)
    real(dp) :: tau(3, 3)
    real(dp) :: stretch2(3), vectors(3, 3), principal(3), powers(3), j, ju_j
    integer :: a, i
    j = determinant_of(f)
    call symmetric_eigen(matmul(f, transpose(f)), stretch2, vectors)
    principal = 0.0_dp
    if (law%family == HYPER_OGDEN) then
      ! Deviatoric stretches lambdabar_a = J^(-1/3) lambda_a: lambdabar_a^alpha = (J^(-2/3) lambda_a^2)^(alpha/2).
      stretch2 = j**(-2.0_dp / 3.0_dp) * stretch2
      do i = 1, law%order
        powers = stretch2**(0.5_dp * law%alpha(i))
        principal = principal + 2.0_dp * law%mu(i) / law%alpha(i) * (powers - sum(powers) / 3.0_dp)
      end do
      ju_j = j * volumetric_derivative(law, j)
      principal = principal + ju_j
    else
      do i = 1, law%order
        powers = stretch2**(0.5_dp * law%alpha(i))
        principal = principal + 2.0_dp * law%mu(i) / law%alpha(i) * &
                    (powers - j**(-law%alpha(i) * law%beta(i)))
      end do
    end if
    tau = 0.0_dp
    do a = 1, 3
      tau = tau + principal(a) * spread(vectors(:, a), 2, 3) * spread(vectors(:, a), 1, 3)
    end do
  end function principal_stress

  !> The Almansi strain e = (I - b^-1) / 2 = F^-T E F^-1 (b = F F^T, E the Green-Lagrange
  !> strain) of F.
  pure function almansi_strain(f) result(e)
    real(dp), intent(in) :: f(3, 3)
    real(dp) :: e(3, 3)
    real(dp) :: g(3, 3)
    g = inverse_of(f)
    e = 0.5_dp * (identity() - matmul(transpose(g), g))
  end function almansi_strain

  !> Eigenvalues `values` and orthonormal eigenvectors (columns of `vectors`) of a symmetric
  !> 3 x 3 matrix by cyclic Jacobi rotations (Golub & Van Loan 2013, section 8.5): accurate to
  !> round-off, also for repeated eigenvalues (any orthonormal basis of the eigenspace).
  pure subroutine symmetric_eigen(m, values, vectors)
    real(dp), intent(in) :: m(3, 3)
    real(dp), intent(out) :: values(3), vectors(3, 3)
    real(dp) :: a(3, 3), theta, t, cs, sn, g(3, 3), scale
    integer :: sweep, p, q
    a = m
    vectors = identity()
    scale = max(maxval(abs(m)), tiny(1.0_dp))
    do sweep = 1, 50
      if (abs(a(1, 2)) + abs(a(1, 3)) + abs(a(2, 3)) <= 1.0e-18_dp * scale) exit
      do p = 1, 2
        do q = p + 1, 3
          if (a(p, q) == 0.0_dp) cycle
          theta = (a(q, q) - a(p, p)) / (2.0_dp * a(p, q))
          t = sign(1.0_dp, theta) / (abs(theta) + sqrt(theta**2 + 1.0_dp))
          cs = 1.0_dp / sqrt(t**2 + 1.0_dp)
          sn = t * cs
          g = identity()
          g(p, p) = cs
          g(q, q) = cs
          g(p, q) = sn
          g(q, p) = -sn
          a = matmul(transpose(g), matmul(a, g))
          a(p, q) = 0.0_dp
          a(q, p) = 0.0_dp
          vectors = matmul(vectors, g)
        end do
      end do
    end do
    values = [a(1, 1), a(2, 2), a(3, 3)]
  end subroutine symmetric_eigen

  pure function deviator(t) result(d)
    real(dp), intent(in) :: t(3, 3)
    real(dp) :: d(3, 3)
    d = t - trace(t) / 3.0_dp * identity()
  end function deviator

  pure real(dp) function trace(t)
    real(dp), intent(in) :: t(3, 3)
    trace = t(1, 1) + t(2, 2) + t(3, 3)
  end function trace

  pure function identity() result(eye)
    real(dp) :: eye(3, 3)
    integer :: i
    eye = 0.0_dp
    do i = 1, 3
      eye(i, i) = 1.0_dp
    end do
  end function identity

  !> What a law of `family` is, for messages: "hyperelastic", or for *DEFORMATION PLASTICITY
  !> "Ramberg-Osgood (*DEFORMATION PLASTICITY)".
  pure function hyper_law_text(family) result(text)
    integer, intent(in) :: family
    character(len=:), allocatable :: text
    text = 'hyperelastic'
    if (family == HYPER_DEFORMATION_PLASTICITY) text = 'Ramberg-Osgood (*DEFORMATION PLASTICITY)'
  end function hyper_law_text

  !> The keyword that defines a law of `family` (without the star), for messages.
  pure function hyper_law_keyword(family) result(keyword)
    integer, intent(in) :: family
    character(len=:), allocatable :: keyword
    select case (family)
    case (HYPER_FOAM)
      keyword = 'HYPERFOAM'
    case (HYPER_DEFORMATION_PLASTICITY)
      keyword = 'DEFORMATION PLASTICITY'
    case default
      keyword = 'HYPERELASTIC'
    end select
  end function hyper_law_keyword

end module fcs_hyperelastic
