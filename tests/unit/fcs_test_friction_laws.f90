!> Friction laws used only by the tests: a smooth rate-dependent law
!> mu = mu0 + c ln(1 + V/v_ref), strengthening (c > 0) or weakening (c < 0).
module fcs_test_friction_laws
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  implicit none
  private
  public :: log_rate_law_t

  type, extends(friction_law_t) :: log_rate_law_t
    real(dp) :: mu0 = 0.4_dp
    real(dp) :: c = 0.02_dp
    real(dp) :: v_ref = 1.0e-2_dp
  contains
    procedure :: evaluate => log_rate_evaluate
    procedure :: name => log_rate_name
  end type log_rate_law_t

contains

  pure function log_rate_evaluate(this, pressure, rate, state) result(d)
    class(log_rate_law_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    d%mu = this%mu0 + this%c * log(1.0_dp + rate / this%v_ref)
    d%dmu_drate = this%c / (this%v_ref + rate)
  end function log_rate_evaluate

  pure function log_rate_name(this) result(name)
    class(log_rate_law_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'LOG RATE (test)'
  end function log_rate_name

end module fcs_test_friction_laws
