!> Symmetric second-order tensors in Voigt order (11, 22, 33, 12, 13, 23), as the materials
!> use them: stress-like vectors hold tensor components, strain-like vectors engineering
!> shears (gamma_12 = 2 eps_12), so that the work sigma : eps is the plain dot product of the
!> two vectors. A 6 x 6 matrix maps an engineering strain to a stress (C, the tangents).
!>
!> Also the objective rotation of tensor-valued internal variables over an increment with
!> spin increment w: Q = (I - w/2)^-1 (I + w/2) (Hughes & Winget 1980, IJNME 15, 1862), the
!> rotation the elements apply to the stress.
module fcs_voigt
  use fcs_kinds, only: dp
  implicit none
  private
  public :: VOIGT_IDENTITY, deviator, stress_norm, stress_dot, trace, mises_of
  public :: deviatoric_projector, outer, spin_rotation, rotate_stress_like, rotate_strain_like
  public :: strain_to_stress_like

  !> The identity tensor as a Voigt vector.
  real(dp), parameter :: VOIGT_IDENTITY(6) = [1.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]

contains

  !> Trace of a Voigt tensor.
  pure real(dp) function trace(v)
    real(dp), intent(in) :: v(6)
    trace = v(1) + v(2) + v(3)
  end function trace

  !> Deviatoric part of a stress-like tensor.
  pure function deviator(v) result(s)
    real(dp), intent(in) :: v(6)
    real(dp) :: s(6)
    s = v - trace(v) / 3.0_dp * VOIGT_IDENTITY
  end function deviator

  !> a : b of two stress-like tensors (shear components count twice).
  pure real(dp) function stress_dot(a, b)
    real(dp), intent(in) :: a(6), b(6)
    stress_dot = a(1) * b(1) + a(2) * b(2) + a(3) * b(3) + &
                 2.0_dp * (a(4) * b(4) + a(5) * b(5) + a(6) * b(6))
  end function stress_dot

  !> Frobenius norm sqrt(a : a) of a stress-like tensor.
  pure real(dp) function stress_norm(a)
    real(dp), intent(in) :: a(6)
    stress_norm = sqrt(stress_dot(a, a))
  end function stress_norm

  !> von Mises equivalent sqrt(3/2 s : s) of a stress-like tensor.
  pure real(dp) function mises_of(v)
    real(dp), intent(in) :: v(6)
    mises_of = sqrt(1.5_dp) * stress_norm(deviator(v))
  end function mises_of

  !> Engineering-shear strain to tensor components (a strain-like vector as stress-like).
  pure function strain_to_stress_like(e) result(t)
    real(dp), intent(in) :: e(6)
    real(dp) :: t(6)
    t = e
    t(4:6) = 0.5_dp * e(4:6)
  end function strain_to_stress_like

  !> The deviatoric projector P as a 6 x 6 matrix from engineering strain to stress-like
  !> components: P de = dev(de) (tensor components), so that 2 G P is the deviatoric part of
  !> the isotropic elasticity matrix.
  pure function deviatoric_projector() result(p)
    real(dp) :: p(6, 6)
    integer :: i
    p = 0.0_dp
    p(1:3, 1:3) = -1.0_dp / 3.0_dp
    do i = 1, 3
      p(i, i) = 2.0_dp / 3.0_dp
      p(i + 3, i + 3) = 0.5_dp
    end do
  end function deviatoric_projector

  !> Outer product a b^T of two Voigt vectors: with a, b stress-like, (a x b) de = a (b : de)
  !> for an engineering strain de.
  pure function outer(a, b) result(m)
    real(dp), intent(in) :: a(6), b(6)
    real(dp) :: m(6, 6)
    integer :: j
    do j = 1, 6
      m(:, j) = a * b(j)
    end do
  end function outer

  !> The rotation of the Hughes-Winget update for spin increment w (skew 3 x 3):
  !> Q = (I - w/2)^-1 (I + w/2), an exact rotation (the Cayley transform of w/2).
  pure function spin_rotation(w) result(q)
    real(dp), intent(in) :: w(3, 3)
    real(dp) :: q(3, 3)
    real(dp) :: a(3, 3), b(3, 3), inverse(3, 3), det
    integer :: i
    a = -0.5_dp * w
    b = 0.5_dp * w
    do i = 1, 3
      a(i, i) = a(i, i) + 1.0_dp
      b(i, i) = b(i, i) + 1.0_dp
    end do
    inverse(1, 1) = a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)
    inverse(1, 2) = a(1, 3) * a(3, 2) - a(1, 2) * a(3, 3)
    inverse(1, 3) = a(1, 2) * a(2, 3) - a(1, 3) * a(2, 2)
    inverse(2, 1) = a(2, 3) * a(3, 1) - a(2, 1) * a(3, 3)
    inverse(2, 2) = a(1, 1) * a(3, 3) - a(1, 3) * a(3, 1)
    inverse(2, 3) = a(1, 3) * a(2, 1) - a(1, 1) * a(2, 3)
    inverse(3, 1) = a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1)
    inverse(3, 2) = a(1, 2) * a(3, 1) - a(1, 1) * a(3, 2)
    inverse(3, 3) = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)
    det = a(1, 1) * inverse(1, 1) + a(1, 2) * inverse(2, 1) + a(1, 3) * inverse(3, 1)
    q = matmul(inverse / det, b)
  end function spin_rotation

  !> Q t Q^T of a stress-like tensor t.
  pure function rotate_stress_like(t, q) result(rotated)
    real(dp), intent(in) :: t(6), q(3, 3)
    real(dp) :: rotated(6)
    real(dp) :: m(3, 3)
    m = reshape([t(1), t(4), t(5), t(4), t(2), t(6), t(5), t(6), t(3)], [3, 3])
    m = matmul(matmul(q, m), transpose(q))
    rotated = [m(1, 1), m(2, 2), m(3, 3), 0.5_dp * (m(1, 2) + m(2, 1)), &
               0.5_dp * (m(1, 3) + m(3, 1)), 0.5_dp * (m(2, 3) + m(3, 2))]
  end function rotate_stress_like

  !> Q e Q^T of a strain-like tensor e (engineering shears in and out).
  pure function rotate_strain_like(e, q) result(rotated)
    real(dp), intent(in) :: e(6), q(3, 3)
    real(dp) :: rotated(6)
    rotated = rotate_stress_like(strain_to_stress_like(e), q)
    rotated(4:6) = 2.0_dp * rotated(4:6)
  end function rotate_strain_like

end module fcs_voigt
