!> St Venant-Kirchhoff elasticity under NLGEOM, CalculiX's law for *ELASTIC in a geometrically
!> nonlinear step (ccx 2.20 manual, section 6.2.8; Holzapfel 2000, section 6.5; Simo & Hughes
!> 1998, section 7.1): the second Piola-Kirchhoff stress S = C : (E - E_th), with the
!> Green-Lagrange strain E = (F^T F - I)/2 of the deformation gradient F = dx/dX, C the elastic
!> stiffness in the reference axes and E_th the thermal strain; the Cauchy stress is
!> sigma = F S F^T / det F. doc/theory.md section 2.10 derives the Jaumann tangent.
!>
!> Stresses and strains are Voigt vectors (11, 22, 33, 12, 13, 23), engineering shear strains;
!> C is a 6 x 6 matrix from engineering strains to stresses.
module fcs_st_venant_kirchhoff
  use fcs_kinds, only: dp
  implicit none
  private
  public :: green_lagrange_strain, cauchy_from_pk2, pk2_from_cauchy, svk_jaumann_tangent
  public :: determinant_of, inverse_of, voigt_tensor, tensor_voigt

  !> Voigt index of the tensor components (i, j).
  integer, parameter :: VOIGT_INDEX(3, 3) = reshape([1, 4, 5, 4, 2, 6, 5, 6, 3], [3, 3])
  !> Tensor indices of the Voigt components.
  integer, parameter :: VOIGT_I(6) = [1, 2, 3, 1, 1, 2], VOIGT_J(6) = [1, 2, 3, 2, 3, 3]

contains

  !> The symmetric tensor of a stress-like Voigt vector.
  pure function voigt_tensor(v) result(t)
    real(dp), intent(in) :: v(6)
    real(dp) :: t(3, 3)
    integer :: i, j
    do j = 1, 3
      do i = 1, 3
        t(i, j) = v(VOIGT_INDEX(i, j))
      end do
    end do
  end function voigt_tensor

  !> The stress-like Voigt vector of a symmetric tensor.
  pure function tensor_voigt(t) result(v)
    real(dp), intent(in) :: t(3, 3)
    real(dp) :: v(6)
    integer :: a
    do a = 1, 6
      v(a) = t(VOIGT_I(a), VOIGT_J(a))
    end do
  end function tensor_voigt

  pure real(dp) function determinant_of(f) result(det)
    real(dp), intent(in) :: f(3, 3)
    det = f(1, 1) * (f(2, 2) * f(3, 3) - f(2, 3) * f(3, 2)) - &
          f(1, 2) * (f(2, 1) * f(3, 3) - f(2, 3) * f(3, 1)) + &
          f(1, 3) * (f(2, 1) * f(3, 2) - f(2, 2) * f(3, 1))
  end function determinant_of

  !> Inverse of a 3 x 3 matrix with a nonzero determinant (the adjugate over the determinant).
  pure function inverse_of(f) result(g)
    real(dp), intent(in) :: f(3, 3)
    real(dp) :: g(3, 3)
    g(1, 1) = f(2, 2) * f(3, 3) - f(2, 3) * f(3, 2)
    g(1, 2) = f(1, 3) * f(3, 2) - f(1, 2) * f(3, 3)
    g(1, 3) = f(1, 2) * f(2, 3) - f(1, 3) * f(2, 2)
    g(2, 1) = f(2, 3) * f(3, 1) - f(2, 1) * f(3, 3)
    g(2, 2) = f(1, 1) * f(3, 3) - f(1, 3) * f(3, 1)
    g(2, 3) = f(1, 3) * f(2, 1) - f(1, 1) * f(2, 3)
    g(3, 1) = f(2, 1) * f(3, 2) - f(2, 2) * f(3, 1)
    g(3, 2) = f(1, 2) * f(3, 1) - f(1, 1) * f(3, 2)
    g(3, 3) = f(1, 1) * f(2, 2) - f(1, 2) * f(2, 1)
    g = g / determinant_of(f)
  end function inverse_of

  !> Green-Lagrange strain E = (F^T F - I)/2 (Holzapfel 2000, eq. 2.67), Voigt with
  !> engineering shears: CalculiX's Lagrangian strain (its E output under NLGEOM).
  pure function green_lagrange_strain(f) result(e)
    real(dp), intent(in) :: f(3, 3)
    real(dp) :: e(6)
    real(dp) :: c(3, 3)
    c = matmul(transpose(f), f)
    e = [0.5_dp * (c(1, 1) - 1.0_dp), 0.5_dp * (c(2, 2) - 1.0_dp), 0.5_dp * (c(3, 3) - 1.0_dp), &
         c(1, 2), c(1, 3), c(2, 3)]
  end function green_lagrange_strain

  !> Cauchy stress sigma = F S F^T / det F from the second Piola-Kirchhoff stress S
  !> (Holzapfel 2000, eq. 3.65).
  pure function cauchy_from_pk2(f, s) result(sigma)
    real(dp), intent(in) :: f(3, 3), s(6)
    real(dp) :: sigma(6)
    sigma = tensor_voigt(matmul(f, matmul(voigt_tensor(s), transpose(f)))) / determinant_of(f)
  end function cauchy_from_pk2

  !> Second Piola-Kirchhoff stress S = det F F^-1 sigma F^-T from the Cauchy stress.
  pure function pk2_from_cauchy(f, sigma) result(s)
    real(dp), intent(in) :: f(3, 3), sigma(6)
    real(dp) :: s(6)
    real(dp) :: g(3, 3)
    g = inverse_of(f)
    s = determinant_of(f) * tensor_voigt(matmul(g, matmul(voigt_tensor(sigma), transpose(g))))
  end function pk2_from_cauchy

  !> The tangent of St Venant-Kirchhoff in the rate form of the element loops, sigma^J = c : D
  !> (Jaumann rate of the Cauchy stress, D the rate of deformation; doc/theory.md 2.10):
  !>   c_ijkl = (1/J) F_iI F_jJ F_kK F_lL C_IJKL
  !>          + 1/2 (delta_ik s_jl + delta_il s_jk + s_ik delta_jl + s_il delta_jk) - s_ij delta_kl,
  !> from the Lie derivative of the Kirchhoff stress tau = F S F^T, L_v tau = F (C : dE/dt) F^T,
  !> tau^J = L_v tau + D tau + tau D and sigma^J = tau^J / J - sigma tr D (Simo & Hughes 1998,
  !> section 7.1.5; Holzapfel 2000, section 6.7). `c_ref` is C in the reference axes, `sigma`
  !> the Cauchy stress at F. The last term makes c unsymmetric (the element loops add sigma tr D
  !> back: doc/theory.md 1.2), which the solvers accept.
  pure function svk_jaumann_tangent(f, sigma, c_ref) result(c)
    real(dp), intent(in) :: f(3, 3), sigma(6), c_ref(6, 6)
    real(dp) :: c(6, 6)
    real(dp) :: p(6, 6), s(3, 3)
    integer :: a, b, i, j, k, l, ii, jj
    ! P(a, A): sum over the index pairs (I, J) of Voigt component A of F_iI F_jJ, (i, j) of a.
    do b = 1, 6
      ii = VOIGT_I(b)
      jj = VOIGT_J(b)
      do a = 1, 6
        i = VOIGT_I(a)
        j = VOIGT_J(a)
        p(a, b) = f(i, ii) * f(j, jj)
        if (ii /= jj) p(a, b) = p(a, b) + f(i, jj) * f(j, ii)
      end do
    end do
    c = matmul(p, matmul(c_ref, transpose(p))) / determinant_of(f)
    s = voigt_tensor(sigma)
    do b = 1, 6
      k = VOIGT_I(b)
      l = VOIGT_J(b)
      do a = 1, 6
        i = VOIGT_I(a)
        j = VOIGT_J(a)
        c(a, b) = c(a, b) + 0.5_dp * (delta(i, k) * s(j, l) + delta(i, l) * s(j, k) + &
                                      s(i, k) * delta(j, l) + s(i, l) * delta(j, k)) - &
                  s(i, j) * delta(k, l)
      end do
    end do
  end function svk_jaumann_tangent

  pure real(dp) function delta(i, j)
    integer, intent(in) :: i, j
    delta = merge(1.0_dp, 0.0_dp, i == j)
  end function delta

end module fcs_st_venant_kirchhoff
