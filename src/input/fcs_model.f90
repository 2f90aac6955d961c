!> The model: everything the deck defines, as plain data, checked and with names resolved to
!> indices. The builder (`fcs_model_builder`) produces it; the stepper reads it and never
!> changes it. Units are the deck's own (consistent units, e.g. mm, s, MPa, N).
module fcs_model
  use fcs_kinds, only: dp
  use fcs_mesh, only: mesh_t
  use fcs_diagnostics, only: source_loc_t
  use fcs_strings, only: string_t
  use fcs_friction_factory, only: friction_def_t
  use fcs_material_factory, only: plastic_def_t
  use fcs_contact_pair, only: contact_pair_def_t
  use fcs_element_catalogue, only: element_catalogue_t
  implicit none
  private
  public :: model_t, material_def_t, section_t, amplitude_t, time_points_t, dof_condition_t
  public :: face_load_t, output_request_t, step_t, rmin_settings_t
  public :: friction_def_t, friction_change_t, interaction_def_t, contact_pair_def_t, checkpoint_settings_t
  public :: history_item_t, history_request_t, HISTORY_NSET_U, HISTORY_NSET_RF
  public :: HISTORY_CONTACT, HISTORY_ENERGY, HISTORY_RESIDUAL
  public :: BC_DISPLACEMENT, BC_VELOCITY, BC_FIXED, FORMULATION_FULL, FORMULATION_BBAR
  public :: OUTPUT_NODE_PRINT, OUTPUT_EL_PRINT, OUTPUT_NODE_FILE, OUTPUT_EL_FILE
  public :: OUTPUT_CONTACT_PRINT, OUTPUT_CONTACT_FILE
  public :: TOTALS_NO, TOTALS_YES, TOTALS_ONLY

  !> Kinds of prescribed degree-of-freedom conditions.
  !> BC_FIXED: the displacement the node has at the start of the step is kept (CalculiX's
  !> *BOUNDARY, FIXED).
  integer, parameter :: BC_DISPLACEMENT = 1, BC_VELOCITY = 2, BC_FIXED = 3
  !> Element formulations (see *SOLID SECTION, FORMULATION=).
  integer, parameter :: FORMULATION_FULL = 1, FORMULATION_BBAR = 2
  !> Output request kinds.
  integer, parameter :: OUTPUT_NODE_PRINT = 1, OUTPUT_EL_PRINT = 2, OUTPUT_NODE_FILE = 3, &
                        OUTPUT_EL_FILE = 4, OUTPUT_CONTACT_PRINT = 5, OUTPUT_CONTACT_FILE = 6
  !> What a *HISTORY line asks for: the mean displacement or the total force of a node set,
  !> the totals of a contact pair, the energies.
  integer, parameter :: HISTORY_NSET_U = 1, HISTORY_NSET_RF = 2, HISTORY_CONTACT = 3, &
                        HISTORY_ENERGY = 4, HISTORY_RESIDUAL = 5

  !> *NODE PRINT, TOTALS=.
  integer, parameter :: TOTALS_NO = 0, TOTALS_YES = 1, TOTALS_ONLY = 2

  !> A material as defined in the deck.
  type :: material_def_t
    character(len=:), allocatable :: name
    logical :: has_elastic = .false.
    real(dp) :: youngs_modulus = 0.0_dp
    real(dp) :: poisson_ratio = 0.0_dp
    logical :: has_density = .false.
    real(dp) :: density = 0.0_dp
    type(source_loc_t) :: loc
    !> Plasticity (*PLASTIC, *CYCLIC HARDENING, *DRUCKER PRAGER, *DRUCKER PRAGER HARDENING),
    !> with the cards that gave it (line 0: not given), for the checks of the whole material.
    type(plastic_def_t) :: plastic
    type(source_loc_t) :: plastic_loc, cyclic_loc, drucker_prager_loc, dp_hardening_loc
  end type material_def_t

  !> *SOLID SECTION: a material and a formulation for an element set. The material may be
  !> defined after the section (as CalculiX allows): its name is resolved after the last card.
  type :: section_t
    integer :: element_set = 0
    integer :: material = 0
    character(len=:), allocatable :: material_name
    integer :: formulation = FORMULATION_FULL
    type(source_loc_t) :: loc
  end type section_t

  !> A tabular amplitude a(t), linear between points, constant beyond the ends.
  type :: amplitude_t
    character(len=:), allocatable :: name
    real(dp), allocatable :: time(:)
    real(dp), allocatable :: value(:)
    logical :: total_time = .false.
  end type amplitude_t

  !> A list of output times.
  type :: time_points_t
    character(len=:), allocatable :: name
    real(dp), allocatable :: times(:)
    logical :: total_time = .false.
  end type time_points_t

  !> A prescribed value on one degree of freedom: displacement or velocity (*BOUNDARY) or a
  !> concentrated force (*CLOAD). `amplitude` = 0: no amplitude (ramped over the step).
  type :: dof_condition_t
    integer :: node = 0
    integer :: dof = 0
    real(dp) :: value = 0.0_dp
    integer :: kind = BC_DISPLACEMENT
    integer :: amplitude = 0
  end type dof_condition_t

  !> Pressure on one element face (*DSLOAD).
  type :: face_load_t
    integer :: element = 0
    integer :: face = 0
    real(dp) :: pressure = 0.0_dp
    integer :: amplitude = 0
  end type face_load_t

  !> An output request (*NODE PRINT, *EL PRINT, *NODE FILE, *EL FILE).
  type :: output_request_t
    integer :: kind = OUTPUT_NODE_PRINT
    integer :: set = 0
    type(string_t), allocatable :: variables(:)
    integer :: frequency = 0
    integer :: time_points = 0
    integer :: totals = TOTALS_NO
  end type output_request_t

  !> Limits of the R-minimum step control (defaults explained in doc/theory.md).
  type :: rmin_settings_t
    !> Largest equivalent strain increment in one increment [-].
    real(dp) :: max_strain_increment = 2.0e-3_dp
    !> Largest rotation increment in one increment [rad] (0.5 degree).
    real(dp) :: max_rotation_increment = 8.726646259971648e-3_dp
    !> Largest growth of the equivalent plastic strain at any integration point in one
    !> increment [-].
    real(dp) :: max_plastic_strain_increment = 1.0e-3_dp
    !> Events whose fractions are within this relative tolerance of the smallest are taken
    !> together in one increment [-].
    real(dp) :: event_tolerance = 1.0e-3_dp
    !> Largest changes from one increment to the next at a slipping node: of ln V (slip
    !> rate), of mu, and of ln(state) for laws with a state. They set the next trial time
    !> increment (the slip rate does not change when an increment is scaled).
    real(dp) :: max_log_rate_change = 1.0_dp
    real(dp) :: max_friction_change = 5.0e-3_dp
    real(dp) :: max_state_change = 0.2_dp
    !> MAX SLIP INCREMENT: largest slip of a slipping node in one increment, in units of the
    !> characteristic slip L of its rate-and-state law (xi of Lapusta et al. 2000: the next
    !> increment is at most xi L / V_max) [-]; 0: none (the default).
    real(dp) :: max_slip_increment = 0.0_dp
    !> Largest out-of-balance force left at the end of an increment, relative to the model's
    !> force scale (the mean nodal internal force flux) [-]; an increment that leaves more is
    !> corrected by equilibrium iterations.
    real(dp) :: equilibrium_tolerance = 1.0e-3_dp
    !> Equilibrium iterations allowed per increment before it is cut.
    integer :: max_iterations = 12
    !> At the minimum increment, an increment whose iterations do not converge stops the run
    !> (false) or is taken without them, its out-of-balance force carried into the next
    !> increment (true: NO EQUILIBRIUM=CARRY).
    logical :: carry_unbalanced = .false.
  end type rmin_settings_t

  !> *CHANGE FRICTION in a step: the Coulomb friction of interaction `interaction` from this
  !> step on (until a later change).
  type :: friction_change_t
    integer :: interaction = 0
    type(friction_def_t) :: friction
    !> Stick slope E_t [stress/length]; <= 0: the pair keeps its own.
    real(dp) :: stick_stiffness = 0.0_dp
    type(source_loc_t) :: loc
  end type friction_change_t

  !> One step (loading stage). The condition lists are complete: they hold every condition
  !> active in this step, after applying OP=NEW/MOD to those of the previous steps.
  type :: step_t
    character(len=:), allocatable :: name
    logical :: nlgeom = .false.
    integer :: max_increments = 1000000
    real(dp) :: initial_increment = 1.0_dp
    real(dp) :: period = 1.0_dp
    real(dp) :: min_increment = 1.0e-5_dp
    real(dp) :: max_increment = 1.0_dp
    !> *STATIC, DIRECT: every increment is tried with initial_increment and never grows beyond
    !> it (the R-minimum control may still shorten it).
    logical :: direct = .false.
    type(rmin_settings_t) :: rmin
    !> Whether *STATIC and *RMIN were given in the step (each at most once).
    logical :: has_procedure = .false.
    logical :: has_rmin = .false.
    type(dof_condition_t), allocatable :: boundary(:)
    type(dof_condition_t), allocatable :: loads(:)
    type(face_load_t), allocatable :: pressures(:)
    type(output_request_t), allocatable :: outputs(:)
    !> *CHANGE FRICTION of this step (the changes of earlier steps still hold).
    type(friction_change_t), allocatable :: friction_changes(:)
    type(source_loc_t) :: loc
  end type step_t

  !> *SURFACE INTERACTION with its *SURFACE BEHAVIOR and *FRICTION.
  type :: interaction_def_t
    character(len=:), allocatable :: name
    !> Normal penalty E_n and stick stiffness E_t [stress/length]; <= 0: default.
    real(dp) :: normal_stiffness = 0.0_dp
    real(dp) :: stick_stiffness = 0.0_dp
    logical :: has_friction = .false.
    !> PRESSURE-OVERCLOSURE=TIED: the pairs using it never separate nor slip.
    logical :: tied = .false.
    type(friction_def_t) :: friction
    !> *FRICTION, RADIATION DAMPING=: eta [stress time/length] as given (0: none), or from the
    !> elastic bodies on either side of each pair (damping_from_material: MATERIAL).
    real(dp) :: radiation_damping = 0.0_dp
    logical :: damping_from_material = .false.
    type(source_loc_t) :: loc
  end type interaction_def_t

  !> A node-to-point contact pair (*CONTACT PAIR) or a tied pair (*TIE): contact_pair_def_t of
  !> fcs_contact_pair (the contact layer owns the type; the model holds the pairs the deck
  !> defines).

  !> One quantity of a history request.
  type :: history_item_t
    integer :: kind = HISTORY_NSET_U
    !> Node set (NSET items) or contact pair (CONTACT items).
    integer :: target = 0
  end type history_item_t

  !> *HISTORY: quantities sampled through the whole run into <job>_<name>.csv and the results.
  type :: history_request_t
    character(len=:), allocatable :: name
    integer :: frequency = 1
    integer :: time_points = 0
    type(history_item_t), allocatable :: items(:)
  end type history_request_t

  !> When checkpoints are written (*RESTART, WRITE). Whatever the settings, one is written at
  !> the end of every step and when the run is stopped by SIGTERM or SIGINT.
  type :: checkpoint_settings_t
    !> Every this many increments (0: not by count).
    integer :: frequency = 0
    !> Every this many seconds of wall time (0: not by time).
    real(dp) :: interval = 600.0_dp
    !> Generations kept (<job>.rst.h5, <job>.rst.1.h5, ...).
    integer :: generations = 2
  end type checkpoint_settings_t

  !> The whole model.
  type :: model_t
    character(len=:), allocatable :: title
    character(len=:), allocatable :: deck_path
    type(mesh_t) :: mesh
    !> The element kinds the mesh's elements are of (mesh%element_kind(e) indexes them).
    type(element_catalogue_t) :: element_kinds
    type(material_def_t), allocatable :: materials(:)
    type(section_t), allocatable :: sections(:)
    !> Section index of every element (0 = none, an error after building).
    integer, allocatable :: element_section(:)
    !> Nodes in no element (gmsh geometry points, construction nodes): their displacements
    !> are held at zero, so that they add no singular rows.
    logical, allocatable :: free_node(:)
    type(amplitude_t), allocatable :: amplitudes(:)
    type(time_points_t), allocatable :: time_points(:)
    type(step_t), allocatable :: steps(:)
    character(len=:), allocatable :: solver_name
    !> True when the deck chose the solver (*SOLVER); otherwise a parallel run takes MUMPS.
    logical :: solver_chosen = .false.
    !> *SOLVER, REUSE TOLERANCE: relative residual of a solve with reused factors (0: off).
    real(dp) :: reuse_tolerance = 0.0_dp
    type(interaction_def_t), allocatable :: interactions(:)
    type(contact_pair_def_t), allocatable :: contact_pairs(:)
    !> Checksums of the model definition (its cards and the mesh) and of each step's cards,
    !> so that a restart can tell whether the deck still describes the checkpoint's model.
    character(len=:), allocatable :: model_hash
    type(string_t), allocatable :: step_hashes(:)
    type(checkpoint_settings_t) :: checkpoint
    type(history_request_t), allocatable :: histories(:)
    !> *EVENT CATALOG: slip-rate threshold of slip events [length/time]; <= 0: no catalog.
    real(dp) :: event_threshold = 0.0_dp
    !> Events whose largest slip stays below this are not catalogued [length].
    real(dp) :: event_min_slip = 0.0_dp
    !> The reader's warnings ("file:line: text"): input read, but not quite as written (a
    !> parameter CalculiX ignores, an undefined id skipped in a set); the driver logs them.
    type(string_t), allocatable :: warnings(:)
  end type model_t

end module fcs_model
