!> Dieterich-Ruina rate-and-state friction, arcsinh-regularised (law RATE STATE ARCSINH):
!>
!>     mu = a asinh[ V/(2 V0) exp((mu0 + b ln(V0 theta/D_c))/a) ]
!>
!> (Rice & Ben-Zion 1996, Proc. Natl. Acad. Sci. 93:3811; Lapusta et al. 2000, J. Geophys.
!> Res. 105:23765), in the form of QDYN RNS_LAW=2 and of the older PyLith RateStateAgeing
!> (method notes 3.2-3.3). Since asinh x = ln 2x + 1/(4x^2) + ..., it equals the logarithmic
!> law up to a/(4 x^2) with x = V z (below), i.e. wherever V >> 1/z. It is finite and smooth
!> through V = 0 and needs no cut-off rate, but mu(0) = 0: the law has no static friction, and
!> mu stays near 0 for V below 1/z (1.75e-29 mm/s for mu0 = 0.6, a = 0.01 at steady state at V0).
!> State theta [time] with the ageing or slip law (fcs_rate_state_base).
!>
!> Evaluation in logarithms, with ln x = ln V + ln z and ln z = (mu0 + b ln(V0 theta/D_c))/a
!> - ln(2 V0): for x > 1, asinh x = ln x + ln(1 + sqrt(1 + x^-2)), so nothing overflows however
!> small a is; dmu/dV = a z/sqrt(1 + x^2) (QDYN's a/sqrt(1/z^2 + V^2)), dmu/dtheta =
!> b x/(theta sqrt(1 + x^2)).
module fcs_rate_state_arcsinh
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_derivatives_t
  use fcs_rate_state_base, only: rate_state_base_t
  implicit none
  private
  public :: rate_state_arcsinh_t

  !> A bound on ln z below which exp(ln z) cannot overflow (ln huge = 709.78).
  real(dp), parameter :: LOG_CAP = log(huge(1.0_dp)) - 1.0_dp

  !> The arcsinh form; a > 0 required (parameters in rate_state_base_t).
  type, extends(rate_state_base_t) :: rate_state_arcsinh_t
  contains
    procedure :: evaluate => rate_state_arcsinh_evaluate
    procedure :: name => rate_state_arcsinh_name
  end type rate_state_arcsinh_t

contains

  !> mu, dmu/dV and dmu/dtheta at slip rate V >= 0 [length/time] and state theta > 0 [time]
  !> (QDYN RNS_LAW=2, method notes 3.3; module header). At V = 0, dmu/dV = a z (capped at huge for
  !> parameters with (mu0 + b ln(V0 theta/D_c))/a > ~709, where the slope is practically
  !> infinite); theta <= 0 is read as the smallest positive number.
  pure function rate_state_arcsinh_evaluate(this, pressure, rate, state) result(d)
    class(rate_state_arcsinh_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    real(dp) :: theta, log_z, log_x, x, inverse_x2, root
    theta = max(state, tiny(state))
    log_z = (this%mu0 + this%b * log(this%v0 * theta / this%dc)) / this%a - log(2.0_dp * this%v0)
    if (rate > 0.0_dp) then
      log_x = log(rate) + log_z
    else
      log_x = -huge(1.0_dp)
    end if
    if (log_x > 0.0_dp) then
      inverse_x2 = exp(-2.0_dp * log_x)
      root = sqrt(1.0_dp + inverse_x2)
      d%mu = this%a * (log_x + log(1.0_dp + root))
      d%dmu_drate = this%a / (rate * root)
      d%dmu_dstate = this%b / (theta * root)
    else
      if (rate > 0.0_dp) then
        x = exp(log_x)
      else
        x = 0.0_dp
      end if
      root = sqrt(1.0_dp + x**2)
      d%mu = this%a * asinh(x)
      d%dmu_drate = this%a * exp(min(log_z, LOG_CAP)) / root
      d%dmu_dstate = this%b * x / (theta * root)
    end if
  end function rate_state_arcsinh_evaluate

  pure function rate_state_arcsinh_name(this) result(name)
    class(rate_state_arcsinh_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'RATE STATE ARCSINH'
  end function rate_state_arcsinh_name

end module fcs_rate_state_arcsinh
