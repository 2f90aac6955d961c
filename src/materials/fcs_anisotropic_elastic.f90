!> Linear anisotropic (hypo)elasticity: sigma^J = C : D with a constant 6 x 6 stiffness C in
!> the material's local axes (ccx manual, *ELASTIC, TYPE=ORTHO | ENGINEERING CONSTANTS |
!> ANISO; doc/theory.md 2.9). The element loops turn the strain increment into the local axes
!> of an *ORIENTATION and the stress increment back (fcs_orientation); without one the local
!> axes are the global ones.
!>
!> Also the stiffness of each way CalculiX gives the constants, in Voigt order (11, 22, 33,
!> 12, 13, 23) with engineering shears, so that C(I, J) = D_ijkl of CalculiX's notation
!> (D1212 is the shear modulus G12):
!> * ORTHO: D1111, D1122, D2222, D1133, D2233, D3333, D1212, D1313, D2323;
!> * ENGINEERING CONSTANTS: E1, E2, E3, nu12, nu13, nu23, G12, G13, G23 (compliance
!>   S11 = 1/E1, S12 = -nu12/E1, S13 = -nu13/E1, S23 = -nu23/E2, S44 = 1/G12, ...; C = S^-1);
!> * ANISO: the upper triangle column by column, D1111, D1122, D2222, D1133, D2233, D3333,
!>   D1112, D2212, D3312, D1212, D1113, D2213, D3313, D1213, D1313, D1123, D2223, D3323,
!>   D1223, D1323, D2323.
module fcs_anisotropic_elastic
  use fcs_kinds, only: dp
  use fcs_material, only: material_t
  implicit none
  private
  public :: anisotropic_elastic_t, orthotropic_stiffness, engineering_stiffness
  public :: anisotropic_stiffness, is_positive_definite, voigt_isotropic

  type, extends(material_t) :: anisotropic_elastic_t
    !> C in the local axes [stress].
    real(dp) :: stiffness(6, 6) = 0.0_dp
  contains
    procedure :: tangent => anisotropic_tangent
    procedure :: update => anisotropic_update
    procedure :: event_fraction => anisotropic_event_fraction
    procedure :: n_state => anisotropic_n_state
    procedure :: name => anisotropic_name
    procedure :: elastic_matrix => anisotropic_elastic_matrix
    procedure :: is_anisotropic => anisotropic_is_anisotropic
  end type anisotropic_elastic_t

contains

  pure function anisotropic_elastic_matrix(this) result(c)
    class(anisotropic_elastic_t), intent(in) :: this
    real(dp) :: c(6, 6)
    c = this%stiffness
  end function anisotropic_elastic_matrix

  pure logical function anisotropic_is_anisotropic(this)
    class(anisotropic_elastic_t), intent(in) :: this
    anisotropic_is_anisotropic = .true.
  end function anisotropic_is_anisotropic

  pure function anisotropic_tangent(this, stress, state) result(c)
    class(anisotropic_elastic_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    real(dp) :: c(6, 6)
    c = this%stiffness
  end function anisotropic_tangent

  !> sigma <- sigma + C : delta_epsilon (local axes); the consistent tangent is C.
  pure subroutine anisotropic_update(this, stress, strain_increment, state, consistent_tangent)
    class(anisotropic_elastic_t), intent(in) :: this
    real(dp), intent(inout) :: stress(6)
    real(dp), intent(in) :: strain_increment(6)
    real(dp), intent(inout) :: state(:)
    real(dp), intent(out), optional :: consistent_tangent(6, 6)
    stress = stress + matmul(this%stiffness, strain_increment)
    if (present(consistent_tangent)) consistent_tangent = this%stiffness
  end subroutine anisotropic_update

  pure real(dp) function anisotropic_event_fraction(this, stress, stress_increment, state)
    class(anisotropic_elastic_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), stress_increment(6), state(:)
    anisotropic_event_fraction = huge(1.0_dp)
  end function anisotropic_event_fraction

  pure integer function anisotropic_n_state(this)
    class(anisotropic_elastic_t), intent(in) :: this
    anisotropic_n_state = 0
  end function anisotropic_n_state

  pure function anisotropic_name(this) result(name)
    class(anisotropic_elastic_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'anisotropic elastic'
  end function anisotropic_name

  !> C of *ELASTIC, TYPE=ORTHO: d = D1111, D1122, D2222, D1133, D2233, D3333, D1212, D1313,
  !> D2323 (ccx manual, *ELASTIC).
  pure function orthotropic_stiffness(d) result(c)
    real(dp), intent(in) :: d(9)
    real(dp) :: c(6, 6)
    c = 0.0_dp
    c(1, 1) = d(1)
    c(1, 2) = d(2)
    c(2, 2) = d(3)
    c(1, 3) = d(4)
    c(2, 3) = d(5)
    c(3, 3) = d(6)
    c(4, 4) = d(7)
    c(5, 5) = d(8)
    c(6, 6) = d(9)
    call symmetrise(c)
  end function orthotropic_stiffness

  !> C of *ELASTIC, TYPE=ENGINEERING CONSTANTS: k = E1, E2, E3, nu12, nu13, nu23, G12, G13,
  !> G23, the inverse of the orthotropic compliance (nu_ij = -eps_j / eps_i under uniaxial
  !> stress along i, so S_ij = -nu_ij / E_i; ccx manual, *ELASTIC). Not positive definite
  !> (is_positive_definite fails) when a modulus is not positive or the Poisson block is
  !> not: then the normal block is left zero.
  pure function engineering_stiffness(k) result(c)
    real(dp), intent(in) :: k(9)
    real(dp) :: c(6, 6)
    real(dp) :: s(3, 3), det
    c = 0.0_dp
    if (any(k(1:3) <= 0.0_dp) .or. any(k(7:9) <= 0.0_dp)) return
    s = reshape([1.0_dp / k(1), -k(4) / k(1), -k(5) / k(1), &
                 -k(4) / k(1), 1.0_dp / k(2), -k(6) / k(2), &
                 -k(5) / k(1), -k(6) / k(2), 1.0_dp / k(3)], [3, 3])
    ! Inverse of the symmetric 3 x 3 normal compliance by cofactors.
    det = s(1, 1) * (s(2, 2) * s(3, 3) - s(2, 3)**2) - s(1, 2) * (s(1, 2) * s(3, 3) - &
          s(2, 3) * s(1, 3)) + s(1, 3) * (s(1, 2) * s(2, 3) - s(2, 2) * s(1, 3))
    if (det <= 0.0_dp) return
    c(1, 1) = (s(2, 2) * s(3, 3) - s(2, 3)**2) / det
    c(2, 2) = (s(1, 1) * s(3, 3) - s(1, 3)**2) / det
    c(3, 3) = (s(1, 1) * s(2, 2) - s(1, 2)**2) / det
    c(1, 2) = (s(1, 3) * s(2, 3) - s(1, 2) * s(3, 3)) / det
    c(1, 3) = (s(1, 2) * s(2, 3) - s(1, 3) * s(2, 2)) / det
    c(2, 3) = (s(1, 2) * s(1, 3) - s(1, 1) * s(2, 3)) / det
    c(4, 4) = k(7)
    c(5, 5) = k(8)
    c(6, 6) = k(9)
    call symmetrise(c)
  end function engineering_stiffness

  !> C of *ELASTIC, TYPE=ANISO: the 21 constants of the upper triangle, column by column
  !> (ccx manual, *ELASTIC).
  pure function anisotropic_stiffness(d) result(c)
    real(dp), intent(in) :: d(21)
    real(dp) :: c(6, 6)
    integer :: i, j, k
    c = 0.0_dp
    k = 0
    do j = 1, 6
      do i = 1, j
        k = k + 1
        c(i, j) = d(k)
      end do
    end do
    call symmetrise(c)
  end function anisotropic_stiffness

  !> Whether the symmetric C is positive definite (the strain energy 1/2 eps C eps > 0 for
  !> every strain, the condition of material stability): Cholesky's pivots all exceed
  !> 1e-12 of the largest diagonal term.
  pure logical function is_positive_definite(c) result(ok)
    real(dp), intent(in) :: c(6, 6)
    real(dp) :: l(6, 6), pivot, scale
    integer :: i, j
    ok = .false.
    scale = maxval([(c(i, i), i = 1, 6)])
    if (.not. scale > 0.0_dp) return
    l = 0.0_dp
    do j = 1, 6
      pivot = c(j, j) - sum(l(j, 1:j - 1)**2)
      if (.not. pivot > 1.0e-12_dp * scale) return
      l(j, j) = sqrt(pivot)
      do i = j + 1, 6
        l(i, j) = (c(i, j) - sum(l(i, 1:j - 1) * l(j, 1:j - 1))) / l(j, j)
      end do
    end do
    ok = .true.
  end function is_positive_definite

  !> An isotropic E and nu of the same Voigt-average bulk and shear moduli as C (Hill 1952):
  !> K = (C11 + C22 + C33 + 2 (C12 + C13 + C23)) / 9, G = (C11 + C22 + C33 - C12 - C13 - C23
  !> + 3 (C44 + C55 + C66)) / 15, E = 9 K G / (3 K + G), nu = (3 K - 2 G) / (2 (3 K + G)).
  !> The scale of the material where one modulus is needed: contact penalties, C3D8R's
  !> hourglass stiffness.
  pure subroutine voigt_isotropic(c, e, nu)
    real(dp), intent(in) :: c(6, 6)
    real(dp), intent(out) :: e, nu
    real(dp) :: k, g
    k = (c(1, 1) + c(2, 2) + c(3, 3) + 2.0_dp * (c(1, 2) + c(1, 3) + c(2, 3))) / 9.0_dp
    g = (c(1, 1) + c(2, 2) + c(3, 3) - c(1, 2) - c(1, 3) - c(2, 3) + &
         3.0_dp * (c(4, 4) + c(5, 5) + c(6, 6))) / 15.0_dp
    e = 9.0_dp * k * g / (3.0_dp * k + g)
    nu = (3.0_dp * k - 2.0_dp * g) / (2.0_dp * (3.0_dp * k + g))
  end subroutine voigt_isotropic

  !> Copy the upper triangle into the lower one.
  pure subroutine symmetrise(c)
    real(dp), intent(inout) :: c(6, 6)
    integer :: i, j
    do j = 1, 6
      do i = j + 1, 6
        c(i, j) = c(j, i)
      end do
    end do
  end subroutine symmetrise

end module fcs_anisotropic_elastic
