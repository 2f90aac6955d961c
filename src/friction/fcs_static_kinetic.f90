!> Static-kinetic friction with exponential decay in the slip rate (law STATIC KINETIC):
!>
!>     mu(V) = mu_k + (mu_s - mu_k) exp(-d V)
!>
!> with the static coefficient mu_s = MU0, the kinetic coefficient mu_k = MUK <= mu_s and the
!> decay coefficient d = DECAY [time/length]. This is the exponential-decay law of Oden & Martins
!> (1985, CMAME 52:527-634) in the form the Abaqus Analysis User's Guide gives it
!> ("Frictional behavior", static-kinetic exponential decay). No state variable.
module fcs_static_kinetic
  use fcs_kinds, only: dp
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  implicit none
  private
  public :: static_kinetic_t

  !> Exponential static-to-kinetic decay; mu0 = static and mu_kinetic = kinetic coefficient [-],
  !> decay [time/length] (the inverse of the slip rate over which mu loses 63% of mu0 - muk).
  type, extends(friction_law_t) :: static_kinetic_t
    real(dp) :: mu0 = 0.0_dp
    real(dp) :: mu_kinetic = 0.0_dp
    real(dp) :: decay = 0.0_dp
  contains
    procedure :: evaluate => static_kinetic_evaluate
    procedure :: name => static_kinetic_name
    procedure :: rate_dependent => always_rate_dependent
  end type static_kinetic_t

contains

  !> mu = muk + (mu0 - muk) exp(-decay V) and dmu/dV = -decay (mu0 - muk) exp(-decay V)
  !> (Oden & Martins 1985; Abaqus "Frictional behavior"); slip rate V >= 0 [length/time].
  pure function static_kinetic_evaluate(this, pressure, rate, state) result(d)
    class(static_kinetic_t), intent(in) :: this
    real(dp), intent(in) :: pressure, rate, state
    type(friction_derivatives_t) :: d
    real(dp) :: weight
    weight = exp(-this%decay * rate)
    d%mu = this%mu_kinetic + (this%mu0 - this%mu_kinetic) * weight
    d%dmu_drate = -this%decay * (this%mu0 - this%mu_kinetic) * weight
  end function static_kinetic_evaluate

  pure function static_kinetic_name(this) result(name)
    class(static_kinetic_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'STATIC KINETIC'
  end function static_kinetic_name

  !> mu depends on the slip rate.
  pure logical function always_rate_dependent(this)
    class(static_kinetic_t), intent(in) :: this
    always_rate_dependent = .true.
  end function always_rate_dependent

end module fcs_static_kinetic
