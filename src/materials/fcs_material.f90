!> The abstract material: the constitutive part of the rate formulation, sigma^J = C : D
!> (Xing, Mora & Makinouchi 2003, eq. 1), for one integration point.
!>
!> Stresses and strains are in Voigt order (11, 22, 33, 12, 13, 23) with engineering shear
!> strains (gamma_12 = 2 eps_12), the order CalculiX prints them in. The element rotates the
!> stress objectively (Hughes & Winget 1980) before calling `update`, which adds the
!> constitutive part for the strain increment. Each material may keep internal variables per
!> integration point (`n_state` of them) and may report R-minimum events (yield).
module fcs_material
  use fcs_kinds, only: dp
  implicit none
  private
  public :: material_t, isotropic_elastic_matrix

  type, abstract :: material_t
    real(dp) :: youngs_modulus = 0.0_dp
    real(dp) :: poisson_ratio = 0.0_dp
  contains
    procedure(tangent_interface), deferred :: tangent
    procedure(update_interface), deferred :: update
    procedure(event_interface), deferred :: event_fraction
    procedure(n_state_interface), deferred :: n_state
    procedure(name_interface), deferred :: name
    procedure :: elastic_matrix => material_elastic_matrix
  end type material_t

  abstract interface
    !> Tangent modulus C (6x6) for the current state of one integration point.
    pure function tangent_interface(this, stress, state) result(c)
      import :: material_t, dp
      class(material_t), intent(in) :: this
      real(dp), intent(in) :: stress(6), state(:)
      real(dp) :: c(6, 6)
    end function tangent_interface

    !> Add the constitutive stress change for `strain_increment` to `stress` (already rotated
    !> to the end of the increment) and update internal variables.
    pure subroutine update_interface(this, stress, strain_increment, state)
      import :: material_t, dp
      class(material_t), intent(in) :: this
      real(dp), intent(inout) :: stress(6)
      real(dp), intent(in) :: strain_increment(6)
      real(dp), intent(inout) :: state(:)
    end subroutine update_interface

    !> Fraction r of a trial stress increment at which the state changes (e.g. first yield),
    !> or a value > 1 if it does not within the increment.
    pure real(dp) function event_interface(this, stress, stress_increment, state)
      import :: material_t, dp
      class(material_t), intent(in) :: this
      real(dp), intent(in) :: stress(6), stress_increment(6), state(:)
    end function event_interface

    !> Number of internal variables per integration point.
    pure integer function n_state_interface(this)
      import :: material_t
      class(material_t), intent(in) :: this
    end function n_state_interface

    pure function name_interface(this) result(name)
      import :: material_t
      class(material_t), intent(in) :: this
      character(len=:), allocatable :: name
    end function name_interface
  end interface

contains

  !> Isotropic elasticity matrix of this material.
  pure function material_elastic_matrix(this) result(c)
    class(material_t), intent(in) :: this
    real(dp) :: c(6, 6)
    c = isotropic_elastic_matrix(this%youngs_modulus, this%poisson_ratio)
  end function material_elastic_matrix

  !> Isotropic elasticity matrix in Voigt order (11,22,33,12,13,23), engineering shear.
  pure function isotropic_elastic_matrix(e, nu) result(c)
    real(dp), intent(in) :: e, nu
    real(dp) :: c(6, 6)
    real(dp) :: lambda, mu
    integer :: i
    lambda = e * nu / ((1.0_dp + nu) * (1.0_dp - 2.0_dp * nu))
    mu = 0.5_dp * e / (1.0_dp + nu)
    c = 0.0_dp
    c(1:3, 1:3) = lambda
    do i = 1, 3
      c(i, i) = lambda + 2.0_dp * mu
      c(i + 3, i + 3) = mu
    end do
  end function isotropic_elastic_matrix

end module fcs_material
