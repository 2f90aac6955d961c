!> Friction laws by name: the parameters a deck gives (*FRICTION) and the factory that turns
!> them into a friction_law_t.
module fcs_friction_factory
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_friction_law, only: friction_law_t
  use fcs_coulomb, only: coulomb_t
  use fcs_diagnostics, only: source_loc_t
  implicit none
  private
  public :: friction_def_t, create_friction_law, FRICTION_LAW_NAMES

  !> Valid law names.
  character(len=*), parameter :: FRICTION_LAW_NAMES = 'COULOMB'

  !> A friction law as the deck defines it: its name and parameters (deck units). Parameters
  !> a law does not use keep their defaults.
  type :: friction_def_t
    character(len=:), allocatable :: law
    real(dp) :: mu0 = 0.0_dp
    real(dp) :: a = 0.0_dp
    real(dp) :: b = 0.0_dp
    real(dp) :: dc = 0.0_dp
    real(dp) :: v0 = 0.0_dp
    real(dp) :: mu_kinetic = 0.0_dp
    real(dp) :: decay = 0.0_dp
    real(dp) :: initial_state = -1.0_dp
    character(len=:), allocatable :: state_law
    character(len=:), allocatable :: regularisation
    real(dp) :: cutoff_rate = 0.0_dp
    type(source_loc_t) :: loc
  end type friction_def_t

contains

  !> The law `def` describes; an unknown name is an error listing the valid ones.
  subroutine create_friction_law(def, law, err)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    type(error_t), allocatable, intent(out) :: err
    select case (def%law)
    case ('COULOMB')
      allocate (law, source=coulomb_t(mu0=def%mu0))
    case default
      call input_error(err, 'unknown friction law "' // def%law // '"; expected one of ' // &
                       FRICTION_LAW_NAMES)
    end select
  end subroutine create_friction_law

end module fcs_friction_factory
