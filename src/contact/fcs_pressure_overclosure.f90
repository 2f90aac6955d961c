!> Pressure-overclosure laws of the normal contact (*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=):
!> the contact pressure p as a function of the clearance g (the gap: positive open, negative in
!> penetration) and its derivative dp/dg.
!>
!>   - LINEAR (the penalty of Xing, Mora & Makinouchi 2003, eq. 2): p = E_n max(-g, 0). Its
!>     arithmetic stays in fcs_contact_element (p = E_n (-g) is written there as it always was).
!>   - EXPONENTIAL (CalculiX, ccx 2.20 manual, *SURFACE BEHAVIOR; surfacebehaviors.f,
!>     springforc_n2f.f, springstiff_f2f.f): p = p0 exp(-beta g) with beta = ln(100) / c0, so
!>     that p = p0 at contact (g = 0) and p = p0 / 100 at the clearance c0. It acts at positive
!>     clearance: CalculiX makes a contact element for a slave node whose clearance is at most
!>     c0 (gencontelem_n2f.f), and so does fcs3d (`acts`). dp/dg = -beta p.
!>     For deep penetration the exponent is capped: beyond beta (-g) = EXPONENT_CAP the pressure
!>     continues linearly with the slope it has there (p and dp/dg continuous, no overflow).
!>     CalculiX caps the force A p at e^23 instead (its beta then changes with g), a guard
!>     against overflow that neither decks of the suite nor ordinary ones reach.
module fcs_pressure_overclosure
  use fcs_kinds, only: dp
  implicit none
  private
  public :: pressure_overclosure_t, OVERCLOSURE_LINEAR, OVERCLOSURE_EXPONENTIAL, EXPONENT_CAP

  !> Kinds of law.
  integer, parameter :: OVERCLOSURE_LINEAR = 0, OVERCLOSURE_EXPONENTIAL = 1
  !> Largest exponent beta (-g) of the exponential law; the pressure continues linearly past it
  !> (p <= p0 e^23 = 1e10 p0 on the exponential part).
  real(dp), parameter :: EXPONENT_CAP = 23.0_dp

  !> One pressure-overclosure law. c0 [length] and p0 [stress] for EXPONENTIAL.
  type :: pressure_overclosure_t
    integer :: kind = OVERCLOSURE_LINEAR
    real(dp) :: c0 = 0.0_dp
    real(dp) :: p0 = 0.0_dp
  contains
    procedure :: is_exponential => law_is_exponential
    procedure :: decay => law_decay
    procedure :: pressure => law_pressure
    procedure :: slope => law_slope
    procedure :: acts => law_acts
    procedure :: reach => law_reach
  end type pressure_overclosure_t

contains

  !> True for the exponential law.
  elemental logical function law_is_exponential(this)
    class(pressure_overclosure_t), intent(in) :: this
    law_is_exponential = this%kind == OVERCLOSURE_EXPONENTIAL
  end function law_is_exponential

  !> beta = ln(100) / c0 [1/length] (surfacebehaviors.f: the pressure falls to 1 % of p0 at c0).
  elemental real(dp) function law_decay(this) result(beta)
    class(pressure_overclosure_t), intent(in) :: this
    beta = log(100.0_dp) / this%c0
  end function law_decay

  !> Pressure p(g) of the exponential law [stress] at clearance g.
  elemental real(dp) function law_pressure(this, gap) result(p)
    class(pressure_overclosure_t), intent(in) :: this
    real(dp), intent(in) :: gap
    real(dp) :: x
    x = -this%decay() * gap
    if (x <= EXPONENT_CAP) then
      p = this%p0 * exp(x)
    else
      p = this%p0 * exp(EXPONENT_CAP) * (1.0_dp + (x - EXPONENT_CAP))
    end if
  end function law_pressure

  !> dp/dg of the exponential law [stress/length] at clearance g (-beta p, -beta p_cap past
  !> the cap).
  elemental real(dp) function law_slope(this, gap) result(slope)
    class(pressure_overclosure_t), intent(in) :: this
    real(dp), intent(in) :: gap
    real(dp) :: beta
    beta = this%decay()
    slope = -beta * this%p0 * exp(min(-beta * gap, EXPONENT_CAP))
  end function law_slope

  !> Whether a contact point at clearance g carries the law's pressure: g <= c0 (CalculiX's
  !> rule for the exponential law, gencontelem_n2f.f).
  elemental logical function law_acts(this, gap)
    class(pressure_overclosure_t), intent(in) :: this
    real(dp), intent(in) :: gap
    law_acts = gap <= this%c0
  end function law_acts

  !> The clearance up to which the law acts: c0 (0 for the linear law).
  elemental real(dp) function law_reach(this) result(reach)
    class(pressure_overclosure_t), intent(in) :: this
    reach = 0.0_dp
    if (this%kind == OVERCLOSURE_EXPONENTIAL) reach = this%c0
  end function law_reach

end module fcs_pressure_overclosure
