!> The model: everything the deck defines, as plain data, checked and with names resolved to
!> indices. The builder (`fcs_model_builder`) produces it; the stepper reads it and never
!> changes it. Units are the deck's own (consistent units, e.g. mm, s, MPa, N).
module fcs_model
  use fcs_kinds, only: dp
  use fcs_rmin_events, only: CONTACT_EVENTS_ALL
  use fcs_mesh, only: mesh_t
  use fcs_diagnostics, only: source_loc_t
  use fcs_strings, only: string_t
  use fcs_friction_factory, only: friction_def_t
  use fcs_material_factory, only: plastic_def_t
  use fcs_thermal_properties, only: thermal_properties_t
  use fcs_hyperelastic, only: hyperelastic_law_t
  use fcs_orientation, only: orientation_t
  use fcs_contact_pair, only: contact_pair_def_t
  use fcs_pressure_overclosure, only: pressure_overclosure_t
  use fcs_element_catalogue, only: element_catalogue_t
  use fcs_linear_constraints, only: linear_equation_t
  use fcs_nonlinear_constraints, only: nonlinear_constraint_t
  implicit none
  private
  public :: model_t, material_def_t, section_t, amplitude_t, time_points_t, dof_condition_t
  public :: face_load_t, output_request_t, step_t, rmin_settings_t, initial_stress_t
  public :: initial_plastic_strain_t
  public :: body_load_t, BODY_GRAV, BODY_CENTRIF, transform_def_t, orientation_def_t
  public :: friction_def_t, friction_change_t, behavior_change_t, interaction_def_t, contact_pair_def_t, checkpoint_settings_t
  public :: history_item_t, history_request_t, HISTORY_NSET_U, HISTORY_NSET_RF
  public :: HISTORY_CONTACT, HISTORY_ENERGY, HISTORY_RESIDUAL
  public :: BC_DISPLACEMENT, BC_VELOCITY, BC_FIXED, FORMULATION_FULL, FORMULATION_BBAR
  public :: OUTPUT_NODE_PRINT, OUTPUT_EL_PRINT, OUTPUT_NODE_FILE, OUTPUT_EL_FILE
  public :: OUTPUT_CONTACT_PRINT, OUTPUT_CONTACT_FILE
  public :: TOTALS_NO, TOTALS_YES, TOTALS_ONLY

  !> Body loads of *DLOAD: gravity and centrifugal (CalculiX's GRAV and CENTRIF).
  integer, parameter :: BODY_GRAV = 1, BODY_CENTRIF = 2

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
    !> *EXPANSION and a temperature-dependent *ELASTIC table (youngs_modulus and poisson_ratio
    !> above hold its first row), with the cards that gave them.
    type(thermal_properties_t) :: thermal
    type(source_loc_t) :: expansion_loc, elastic_loc
    !> *ELASTIC, TYPE=ORTHO, ENGINEERING CONSTANTS or ANISO: the stiffness in the material's
    !> local axes (fcs_anisotropic_elastic; youngs_modulus and poisson_ratio above then hold
    !> its Voigt-average isotropic scale).
    logical :: anisotropic = .false.
    real(dp) :: stiffness(6, 6) = 0.0_dp
    !> *HYPOELASTIC: the rate form under NLGEOM (else *ELASTIC: St Venant-Kirchhoff).
    logical :: hypoelastic = .false.
    !> *HYPERELASTIC or *HYPERFOAM (fcs_hyperelastic; family HYPER_NONE: neither), with the
    !> card that gave it. youngs_modulus and poisson_ratio above hold its initial moduli.
    type(hyperelastic_law_t) :: hyperelastic
    type(source_loc_t) :: hyperelastic_loc
  end type material_def_t

  !> *ORIENTATION: local material axes (fcs_orientation), with the card that gave them.
  type :: orientation_def_t
    type(orientation_t) :: axes
    type(source_loc_t) :: loc
  end type orientation_def_t

  !> *TRANSFORM: local axes for the nodes of a node set. TYPE=R: a is a point on the local x
  !> axis, b a point of the local x-y plane (through the origin); TYPE=C: a and b are two
  !> points of the axis of a cylindrical system (local x radial, y tangential, z axial).
  type :: transform_def_t
    integer :: node_set = 0
    logical :: cylindrical = .false.
    real(dp) :: a(3) = 0.0_dp
    real(dp) :: b(3) = 0.0_dp
    type(source_loc_t) :: loc
  end type transform_def_t

  !> *SOLID SECTION: a material and a formulation for an element set. The material may be
  !> defined after the section (as CalculiX allows): its name is resolved after the last card.
  type :: section_t
    integer :: element_set = 0
    integer :: material = 0
    character(len=:), allocatable :: material_name
    integer :: formulation = FORMULATION_FULL
    !> ORIENTATION=: the name, and the index into the model's orientations resolved after the
    !> last card (0: none, global axes).
    character(len=:), allocatable :: orientation_name
    integer :: orientation = 0
    type(source_loc_t) :: loc
  end type section_t

  !> A tabular amplitude a(t), linear between points, constant beyond the ends.
  type :: amplitude_t
    character(len=:), allocatable :: name
    real(dp), allocatable :: time(:)
    real(dp), allocatable :: value(:)
    logical :: total_time = .false.
    !> CalculiX's user amplitude QUADRATIC (`*AMPLITUDE, NAME=QUADRATIC, USER`: the
    !> uamplitude.f that ccx ships, a(t) = t^2); time and value are then empty.
    logical :: quadratic = .false.
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

  !> A body load on one element (*DLOAD, GRAV or CENTRIF, as CalculiX): GRAV, the
  !> acceleration `magnitude` [length/time^2] along the unit vector vector(1:3); CENTRIF,
  !> omega^2 = `magnitude` [1/time^2] about the axis through vector(1:3) along the unit
  !> vector vector(4:6). The force per unit volume is rho times the acceleration (the element's
  !> material needs *DENSITY). `amplitude` = 0: ramped over the step as the other loads.
  type :: body_load_t
    integer :: element = 0
    integer :: kind = BODY_GRAV
    real(dp) :: magnitude = 0.0_dp
    real(dp) :: vector(6) = 0.0_dp
    integer :: amplitude = 0
    type(source_loc_t) :: loc
  end type body_load_t

  !> *INITIAL CONDITIONS, TYPE=STRESS: the stress (Voigt: 11, 22, 33, 12, 13, 23) at
  !> integration point `point` of element `element`, as CalculiX; or, with GEOSTATIC (Abaqus),
  !> at every point of the element from its height z (the third coordinate, reference
  !> configuration): sigma_33 linear through (z1, s1) and (z2, s2), sigma_11 = k_x sigma_33,
  !> sigma_22 = k_y sigma_33, no shear (`geostatic` = [s1, z1, s2, z2, k_x, k_y]).
  type :: initial_stress_t
    integer :: element = 0
    integer :: point = 0
    real(dp) :: stress(6) = 0.0_dp
    logical :: is_geostatic = .false.
    real(dp) :: geostatic(6) = 0.0_dp
  end type initial_stress_t

  !> *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN: the plastic strain eps_0 (Voigt, engineering
  !> shear; CalculiX's data lines give tensor shears) at integration point `point` of element
  !> `element`, read at `loc`. CalculiX subtracts it from the mechanical strain of every
  !> material (an eigenstrain); fcs3d starts the point's stress at -C : eps_0 and a von Mises
  !> point's plastic strain at eps_0 (doc/theory.md, section 2.4).
  type :: initial_plastic_strain_t
    integer :: element = 0
    integer :: point = 0
    real(dp) :: strain(6) = 0.0_dp
    type(source_loc_t) :: loc
  end type initial_plastic_strain_t

  !> An output request (*NODE PRINT, *EL PRINT, *NODE FILE, *EL FILE).
  type :: output_request_t
    integer :: kind = OUTPUT_NODE_PRINT
    integer :: set = 0
    type(string_t), allocatable :: variables(:)
    integer :: frequency = 0
    integer :: time_points = 0
    integer :: totals = TOTALS_NO
    !> *NODE PRINT, GLOBAL=YES: nodes with local axes (*TRANSFORM) printed in global axes
    !> too (default NO, as CalculiX: in their local axes, rows marked L). *EL PRINT,
    !> GLOBAL=YES: S and E in global axes; NO (default, as CalculiX): in the *ORIENTATION axes
    !> of elements whose section has one.
    logical :: global = .false.
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
    !> CONTACT EVENTS: which contact changes end the increment (CONTACT_EVENTS_* of
    !> fcs_rmin_events): ALL (the paper's R-minimum events), NORMAL (onsets of slip and segment
    !> hand-overs left to the equilibrium iterations), CLOSING (opening and leaving the master
    !> surface left to them too).
    integer :: contact_events = CONTACT_EVENTS_ALL
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

  !> *CHANGE SURFACE BEHAVIOR, INTERACTION= with its *SURFACE BEHAVIOR: the interaction's new
  !> normal behaviour from this step on (LINEAR: penalty; EXPONENTIAL: c0, p0).
  type :: behavior_change_t
    integer :: interaction = 0
    !> New penalty E_n [stress/length] (LINEAR; <= 0: none given).
    real(dp) :: normal_stiffness = 0.0_dp
    type(pressure_overclosure_t) :: overclosure
    type(source_loc_t) :: loc
  end type behavior_change_t

  !> One step (loading stage). The condition lists are complete: they hold every condition
  !> active in this step, after applying OP=NEW/MOD to those of the previous steps.
  type :: step_t
    character(len=:), allocatable :: name
    logical :: nlgeom = .false.
    !> The step's card says NLGEOM=NO (hyperelastic materials need NLGEOM: fcs_model_checks).
    logical :: nlgeom_refused = .false.
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
    !> Body loads (*DLOAD GRAV, CENTRIF), complete as the other lists.
    type(body_load_t), allocatable :: body_loads(:)
    type(output_request_t), allocatable :: outputs(:)
    !> *CHANGE FRICTION of this step (the changes of earlier steps still hold).
    type(friction_change_t), allocatable :: friction_changes(:)
    !> *CHANGE SURFACE BEHAVIOR of this step (the changes of earlier steps still hold).
    type(behavior_change_t), allocatable :: behavior_changes(:)
    !> *TEMPERATURE of this step as read (node index, value, amplitude; `temperature_new`: an
    !> OP=NEW card cleared the earlier ones first), and, once the deck is read, the complete
    !> lists (every node, when the model has temperatures): the value each node reaches at
    !> the end of the step (ramped from its value at the step's start) or, with an amplitude
    !> (index; 0: none), the value times the amplitude.
    integer, allocatable :: temperature_node(:), temperature_card_amplitude(:)
    real(dp), allocatable :: temperature_value(:)
    logical :: temperature_new = .false.
    real(dp), allocatable :: temperature(:)
    integer, allocatable :: temperature_amplitude(:)
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
    !> PRESSURE-OVERCLOSURE=LINEAR (normal_stiffness) or EXPONENTIAL (c0, p0).
    type(pressure_overclosure_t) :: overclosure
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
    !> *SOLVER, LOW RANK TOLERANCE: dropping parameter of MUMPS's block low-rank
    !> factorisation (0: full rank, the exact factorisation).
    real(dp) :: low_rank_tolerance = 0.0_dp
    type(interaction_def_t), allocatable :: interactions(:)
    !> Linear constraints between displacement components (*EQUATION), in global axes; the
    !> first term of each is its dependent degree of freedom (eliminated, doc/theory.md 6.2).
    type(linear_equation_t), allocatable :: equations(:)
    !> Rotation nodes of *RIGID BODY: their three degrees of freedom are rotations [rad].
    integer, allocatable :: rotation_nodes(:)
    !> The nonlinear constraints (*MPC PLANE, STRAIGHT, MEANROT, *RIGID BODY), each owning an
    !> equation of `equations` (its linearisation); kept when a step has NLGEOM
    !> (fcs_nonlinear_constraints, doc/theory.md 6.2.3), emptied otherwise.
    type(nonlinear_constraint_t), allocatable :: nonlinear_constraints(:)
    !> Degrees of freedom of nodes in no element that no equation names (the unused
    !> directions of a MEANROT angle node): held at zero, as free_node's.
    logical, allocatable :: idle_dof(:)
    !> *TRANSFORM cards, and the local axes they give the nodes (resolved after the last
    !> card): node_frame(:, a, node) is local axis a in global components; `transformed`
    !> marks the nodes that have local axes (*BOUNDARY, *CLOAD, *EQUATION terms and the
    !> printed U and RF are in them there, as in CalculiX).
    type(transform_def_t), allocatable :: transforms(:)
    !> *ORIENTATION cards, named by the sections' ORIENTATION=.
    type(orientation_def_t), allocatable :: orientations(:)
    real(dp), allocatable :: node_frame(:, :, :)
    logical, allocatable :: transformed(:)
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
    !> Whether the model has nodal temperatures (*INITIAL CONDITIONS, TYPE=TEMPERATURE,
    !> *TEMPERATURE or a material that depends on temperature), and the temperature of every
    !> node at the start of the analysis (0 where none is given, as in CalculiX).
    logical :: has_temperature = .false.
    real(dp), allocatable :: initial_temperature(:)
    !> *INITIAL CONDITIONS, TYPE=STRESS, in deck order (a later line wins).
    type(initial_stress_t), allocatable :: initial_stresses(:)
    !> *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN, in deck order (a later line wins).
    type(initial_plastic_strain_t), allocatable :: initial_plastic_strains(:)
  end type model_t

end module fcs_model
