!> The thermal part of a material: isotropic thermal expansion (*EXPANSION) and
!> temperature-dependent isotropic elastic constants (*ELASTIC with a temperature column), as
!> CalculiX 2.20 defines them (ccx manual, sections 6.2.8 *ELASTIC and 6.2.9 *EXPANSION):
!>   - tables are linear between their temperatures and constant beyond the first and last;
!>   - alpha is the secant coefficient from the reference temperature ZERO = T_Z: the thermal
!>     strain at temperature T is eps_th(T) = alpha(T) (T - T_Z) I, and the strain a point
!>     takes from its initial temperature T_0 to T is eps_th(T) - eps_th(T_0) (CalculiX's
!>     `calcthermal`/`thermmodel`: alph(t1l) (t1l - alzero) - alph(t0l) (t0l - alzero)).
!> Temperatures are in the deck's unit; alpha in 1/temperature.
module fcs_thermal_properties
  use fcs_kinds, only: dp
  implicit none
  private
  public :: thermal_properties_t, table_value

  type :: thermal_properties_t
    !> *EXPANSION: reference temperature T_Z (ZERO=) and the table alpha(T).
    real(dp) :: zero = 0.0_dp
    real(dp), allocatable :: alpha(:), alpha_temperature(:)
    !> *ELASTIC with more than one temperature: E(T), nu(T).
    real(dp), allocatable :: youngs_modulus(:), poisson_ratio(:), elastic_temperature(:)
  contains
    procedure :: has_expansion => thermal_has_expansion
    procedure :: elastic_varies => thermal_elastic_varies
    procedure :: is_active => thermal_is_active
    procedure :: strain => thermal_strain
    procedure :: elastic_at => thermal_elastic_at
  end type thermal_properties_t

contains

  !> Whether the material expands with temperature.
  pure logical function thermal_has_expansion(this) result(has)
    class(thermal_properties_t), intent(in) :: this
    has = .false.
    if (allocated(this%alpha)) has = size(this%alpha) > 0
  end function thermal_has_expansion

  !> Whether the elastic constants depend on temperature (a table of two rows or more).
  pure logical function thermal_elastic_varies(this) result(varies)
    class(thermal_properties_t), intent(in) :: this
    varies = .false.
    if (allocated(this%youngs_modulus)) varies = size(this%youngs_modulus) > 1
  end function thermal_elastic_varies

  !> Whether temperature changes anything for this material.
  pure logical function thermal_is_active(this) result(active)
    class(thermal_properties_t), intent(in) :: this
    active = this%has_expansion() .or. this%elastic_varies()
  end function thermal_is_active

  !> The (volumetric, per normal component) thermal strain alpha(T) (T - T_Z) at temperature
  !> t: 0 without *EXPANSION.
  pure real(dp) function thermal_strain(this, t) result(strain)
    class(thermal_properties_t), intent(in) :: this
    real(dp), intent(in) :: t
    strain = 0.0_dp
    if (.not. this%has_expansion()) return
    strain = table_value(this%alpha_temperature, this%alpha, t) * (t - this%zero)
  end function thermal_strain

  !> E and nu at temperature t (only meaningful when `elastic_varies`).
  pure subroutine thermal_elastic_at(this, t, e, nu)
    class(thermal_properties_t), intent(in) :: this
    real(dp), intent(in) :: t
    real(dp), intent(out) :: e, nu
    e = table_value(this%elastic_temperature, this%youngs_modulus, t)
    nu = table_value(this%elastic_temperature, this%poisson_ratio, t)
  end subroutine thermal_elastic_at

  !> y(x) of the table (xs strictly increasing, ys): linear between the points, constant
  !> beyond the first and the last (CalculiX's reading of every material table).
  pure real(dp) function table_value(xs, ys, x) result(y)
    real(dp), intent(in) :: xs(:), ys(:), x
    integer :: i, n
    real(dp) :: w
    n = size(xs)
    if (n == 1 .or. x <= xs(1)) then
      y = ys(1)
      return
    end if
    if (x >= xs(n)) then
      y = ys(n)
      return
    end if
    do i = 2, n
      if (x <= xs(i)) exit
    end do
    w = (x - xs(i - 1)) / (xs(i) - xs(i - 1))
    y = (1.0_dp - w) * ys(i - 1) + w * ys(i)
  end function table_value

end module fcs_thermal_properties
