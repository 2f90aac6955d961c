!> What the command line asks for: the deck, where results go, solver override, modes.
module fcs_run_options
  use fcs_kinds, only: dp
  implicit none
  private
  public :: run_options_t

  type :: run_options_t
    !> The input deck.
    character(len=:), allocatable :: deck_path
    !> Path stem of every output file (`<dir>/<job>`): .log, .dat, .echo, .h5, .xdmf, ...
    character(len=:), allocatable :: job
    !> Linear solver named on the command line ('' = the deck's or the default).
    character(len=:), allocatable :: solver
    !> Checkpoint to restart from ('' = start from the beginning).
    character(len=:), allocatable :: restart_file
    !> *SOLVER, REUSE TOLERANCE given on the command line (negative: the deck's).
    real(dp) :: reuse_tolerance = -1.0_dp
    !> *RMIN, CONTACT EVENTS for every step, from the command line ('' = each step's own).
    character(len=:), allocatable :: contact_events
    !> *SOLVER, LOW RANK TOLERANCE given on the command line (negative: the deck's).
    real(dp) :: low_rank_tolerance = -1.0_dp
    logical :: quiet = .false.
    logical :: check_only = .false.
  end type run_options_t

end module fcs_run_options
