!> Constant Coulomb friction, mu = mu0 (Xing, Mora & Makinouchi 2003, eq. 3 with constant mu).
module fcs_coulomb
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  implicit none
  private
  public :: coulomb_t

  !> Constant friction coefficient mu0 [-]; no state.
  type, extends(friction_law_t) :: coulomb_t
    real(dp) :: mu0 = 0.0_dp
  contains
    procedure :: evaluate => coulomb_evaluate
    procedure :: name => coulomb_name
  end type coulomb_t

contains

  pure function coulomb_evaluate(this, pressure, rate, state) result(d)
    class(coulomb_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    d%mu = this%mu0
  end function coulomb_evaluate

  pure function coulomb_name(this) result(name)
    class(coulomb_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'COULOMB'
  end function coulomb_name

end module fcs_coulomb
