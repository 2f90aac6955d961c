!> Creates material objects from their definitions: hypoelastic (`*ELASTIC` alone), von Mises
!> plasticity (`*PLASTIC`, `*CYCLIC HARDENING`) and Drucker-Prager plasticity (`*DRUCKER
!> PRAGER`, `*DRUCKER PRAGER HARDENING`). The definition is plain data, checked by the model
!> builder (which reports problems with the deck's file and line); the factory checks it
!> again and refuses what it cannot build, naming the valid choices.
!>
!> The material models are a registry (`material_registry_t`): one entry per model
!> (`material_entry_t`: name and a constructor from the plastic part of the definition; the
!> factory sets the elastic constants). `create_material` builds the model `plastic%model`
!> names (MATERIAL_MODEL_NAMES), or the one called `name`, from the registry given or the
!> built-in one (`builtin_material_registry`); an unknown name is an error listing the
!> registry's names. A model is added by its module and one entry in
!> `builtin_material_registry`, or at run time with `registry%register` (the unit test
!> registers a test-only material that way).
module fcs_material_factory
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error, fatal_error
  use fcs_material, only: material_t
  use fcs_hypoelastic, only: hypoelastic_t
  use fcs_anisotropic_elastic, only: anisotropic_elastic_t
  use fcs_von_mises, only: von_mises_t
  use fcs_drucker_prager, only: drucker_prager_t
  use fcs_hardening_table, only: hardening_table_t, constant_table
  use fcs_strings, only: to_lower, to_upper, string_t, join_strings, name_index
  implicit none
  private
  public :: create_material, plastic_def_t, HARDENING_NAMES, DP_HARDENING_TYPES
  public :: PLASTICITY_NONE, PLASTICITY_MISES, PLASTICITY_DRUCKER_PRAGER, max_friction_angle
  public :: material_registry_t, material_entry_t, material_constructor, builtin_material_registry
  public :: MATERIAL_MODEL_NAMES

  !> *PLASTIC, HARDENING= and *DRUCKER PRAGER HARDENING, TYPE= choices.
  character(len=*), parameter :: HARDENING_NAMES = 'ISOTROPIC, KINEMATIC, COMBINED'
  character(len=*), parameter :: DP_HARDENING_TYPES = 'COMPRESSION, TENSION, SHEAR'
  !> Which plasticity a material has.
  integer, parameter :: PLASTICITY_NONE = 0, PLASTICITY_MISES = 1, PLASTICITY_DRUCKER_PRAGER = 2
  !> The registry name of each PLASTICITY_ model (blank-padded: trim them).
  character(len=14), parameter :: MATERIAL_MODEL_NAMES(0:2) = [character(len=14) :: &
    'HYPOELASTIC', 'VON MISES', 'DRUCKER PRAGER']

  !> The plastic part of a material definition. Curves are (plastic strain, stress) points,
  !> strains strictly increasing from 0, stresses positive; angles in degrees.
  type :: plastic_def_t
    integer :: model = PLASTICITY_NONE
    !> von Mises: HARDENING= of *PLASTIC, its curve, and the *CYCLIC HARDENING curve.
    character(len=:), allocatable :: hardening
    type(hardening_table_t) :: curve
    type(hardening_table_t) :: cyclic_curve
    !> Drucker-Prager: friction angle beta, flow stress ratio K, dilation angle psi, and the
    !> TYPE= of *DRUCKER PRAGER HARDENING (its curve is `curve`).
    real(dp) :: friction_angle = 0.0_dp
    real(dp) :: flow_stress_ratio = 1.0_dp
    real(dp) :: dilation_angle = 0.0_dp
    character(len=:), allocatable :: hardening_type
  end type plastic_def_t

  abstract interface
    !> Allocate `material` as one model from the plastic part of its definition (the elastic
    !> constants are set by create_material); a definition it cannot build is an input error.
    subroutine material_constructor(plastic, material, err)
      import :: plastic_def_t, material_t, error_t
      type(plastic_def_t), intent(in) :: plastic
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: err
    end subroutine material_constructor
  end interface

  !> One material model of the registry: its name (upper case) and constructor.
  type :: material_entry_t
    character(len=:), allocatable :: name
    procedure(material_constructor), pointer, nopass :: construct => null()
  end type material_entry_t

  !> The material models a run knows, in the order the messages list them.
  type :: material_registry_t
    type(material_entry_t), allocatable :: models(:)
  contains
    procedure :: init => registry_init
    procedure :: free => registry_free
    procedure :: register => registry_register
    procedure :: find => registry_find
    procedure :: names => registry_names
    procedure :: size => registry_size
  end type material_registry_t

contains

  !> Largest friction (or dilation) angle [degree] of a Drucker-Prager material whose curve
  !> is given as `hardening_type`: in COMPRESSION, d = (1 - tan(beta)/3) sigma_c and
  !> c = 1 - tan(psi)/3 must stay positive (tan < 3); otherwise below 90 degrees.
  pure real(dp) function max_friction_angle(hardening_type) result(angle)
    character(len=*), intent(in) :: hardening_type
    if (hardening_type == 'COMPRESSION') then
      angle = atan(3.0_dp) * 180.0_dp / acos(-1.0_dp)
    else
      angle = 90.0_dp
    end if
  end function max_friction_angle

  !> A material with Young's modulus `e`, Poisson's ratio `nu` and the plastic part `plastic`:
  !> the model `name` if given, else the one `plastic%model` names, of `registry` (by default
  !> the built-in models); with `stiffness` (6 x 6, local axes), an anisotropic elastic one
  !> (fcs_anisotropic_elastic; e and nu then give its isotropic scale, voigt_isotropic), which
  !> takes no plasticity.
  subroutine create_material(e, nu, plastic, material, err, stiffness, name, registry)
    real(dp), intent(in) :: e, nu
    type(plastic_def_t), intent(in) :: plastic
    class(material_t), allocatable, intent(out) :: material
    type(error_t), allocatable, intent(out) :: err
    real(dp), intent(in), optional :: stiffness(6, 6)
    character(len=*), intent(in), optional :: name
    type(material_registry_t), intent(in), optional :: registry
    type(material_registry_t) :: models
    character(len=:), allocatable :: model
    integer :: k
    if (present(stiffness)) then
      if (plastic%model /= PLASTICITY_NONE) then
        call input_error(err, 'plasticity with anisotropic elasticity is not available')
        return
      end if
      allocate (material, source=anisotropic_elastic_t(stiffness=stiffness))
      material%youngs_modulus = e
      material%poisson_ratio = nu
      return
    end if
    if (present(registry)) then
      models = registry
    else
      models = builtin_material_registry()
    end if
    model = ''
    if (present(name)) then
      model = name
    else if (plastic%model >= lbound(MATERIAL_MODEL_NAMES, 1) .and. &
             plastic%model <= ubound(MATERIAL_MODEL_NAMES, 1)) then
      model = trim(MATERIAL_MODEL_NAMES(plastic%model))
    end if
    k = models%find(model)
    if (k == 0) then
      call input_error(err, 'unknown material model "' // model // '"; expected one of ' // &
                       join_strings(models%names(), ', '))
      return
    end if
    call models%models(k)%construct(plastic, material, err)
    if (allocated(err)) return
    material%youngs_modulus = e
    material%poisson_ratio = nu
  end subroutine create_material

  !> The built-in models, one entry each: adding a model is its module and one entry here.
  function builtin_material_registry() result(registry)
    type(material_registry_t) :: registry
    registry%models = [entry(MATERIAL_MODEL_NAMES(PLASTICITY_NONE), create_hypoelastic), &
                       entry(MATERIAL_MODEL_NAMES(PLASTICITY_MISES), create_von_mises), &
                       entry(MATERIAL_MODEL_NAMES(PLASTICITY_DRUCKER_PRAGER), create_drucker_prager)]
  contains
    function entry(name, construct) result(e)
      character(len=*), intent(in) :: name
      procedure(material_constructor) :: construct
      type(material_entry_t) :: e
      e%name = trim(name)
      e%construct => construct
    end function entry
  end function builtin_material_registry

  !> The built-in models.
  subroutine registry_init(this)
    class(material_registry_t), intent(inout) :: this
    type(material_registry_t) :: builtin
    call this%free()
    builtin = builtin_material_registry()
    call move_alloc(builtin%models, this%models)
  end subroutine registry_init

  !> Forget every model.
  subroutine registry_free(this)
    class(material_registry_t), intent(inout) :: this
    if (allocated(this%models)) deallocate (this%models)
  end subroutine registry_free

  !> Add model `entry`. An internal error if it has no name or constructor, or if its name is
  !> already registered.
  subroutine registry_register(this, entry, err)
    class(material_registry_t), intent(inout) :: this
    type(material_entry_t), intent(in) :: entry
    type(error_t), allocatable, intent(out) :: err
    if (.not. allocated(this%models)) allocate (this%models(0))
    if (.not. allocated(entry%name) .or. .not. associated(entry%construct)) then
      call fatal_error(err, 'material registry: a model needs a name and a constructor')
      return
    end if
    if (this%find(entry%name) /= 0) then
      call fatal_error(err, 'material registry: model ' // entry%name // ' is already registered')
      return
    end if
    this%models = [this%models, entry]
  end subroutine registry_register

  !> Index of model `name` (case and surrounding blanks ignored), 0 if none.
  pure integer function registry_find(this, name) result(index)
    class(material_registry_t), intent(in) :: this
    character(len=*), intent(in) :: name
    index = name_index(this%names(), name)
  end function registry_find

  !> The model names in registry order.
  pure function registry_names(this) result(names)
    class(material_registry_t), intent(in) :: this
    type(string_t), allocatable :: names(:)
    integer :: i
    allocate (names(this%size()))
    do i = 1, size(names)
      names(i)%s = this%models(i)%name
    end do
  end function registry_names

  !> Number of models.
  pure integer function registry_size(this) result(n)
    class(material_registry_t), intent(in) :: this
    n = 0
    if (allocated(this%models)) n = size(this%models)
  end function registry_size

  !> Hypoelastic: nothing beyond the elastic constants.
  subroutine create_hypoelastic(plastic, material, err)
    type(plastic_def_t), intent(in) :: plastic
    class(material_t), allocatable, intent(out) :: material
    type(error_t), allocatable, intent(out) :: err
    allocate (hypoelastic_t :: material)
  end subroutine create_hypoelastic

  !> R and B of fcs_von_mises from HARDENING= (the CalculiX reading of the curves).
  subroutine create_von_mises(plastic, material, err)
    type(plastic_def_t), intent(in) :: plastic
    class(material_t), allocatable, intent(out) :: material
    type(error_t), allocatable, intent(out) :: err
    type(von_mises_t) :: law
    if (.not. valid_curve(plastic%curve)) then
      call input_error(err, '*PLASTIC: the hardening curve is not valid')
      return
    end if
    law%hardening = plastic%hardening
    select case (plastic%hardening)
    case ('ISOTROPIC')
      law%radius = plastic%curve
      law%kinematic = constant_table(0.0_dp)
    case ('KINEMATIC')
      law%radius = constant_table(plastic%curve%stress(1))
      law%kinematic = plastic%curve
    case ('COMBINED')
      if (.not. valid_curve(plastic%cyclic_curve)) then
        call input_error(err, '*PLASTIC, HARDENING=COMBINED needs a *CYCLIC HARDENING curve')
        return
      end if
      law%radius = plastic%cyclic_curve
      law%kinematic = plastic%curve
    case default
      call input_error(err, '*PLASTIC: unknown HARDENING=' // plastic%hardening // &
                       '; expected one of ' // HARDENING_NAMES)
      return
    end select
    allocate (material, source=law)
  end subroutine create_von_mises

  !> Cohesion and rate factors of fcs_drucker_prager from TYPE= (K = 1).
  subroutine create_drucker_prager(plastic, material, err)
    type(plastic_def_t), intent(in) :: plastic
    class(material_t), allocatable, intent(out) :: material
    type(error_t), allocatable, intent(out) :: err
    type(drucker_prager_t) :: law
    real(dp), parameter :: degree = acos(-1.0_dp) / 180.0_dp
    if (.not. valid_curve(plastic%curve)) then
      call input_error(err, '*DRUCKER PRAGER HARDENING: the hardening curve is not valid')
      return
    end if
    if (plastic%flow_stress_ratio /= 1.0_dp) then
      call input_error(err, '*DRUCKER PRAGER: only the flow stress ratio K = 1 is available')
      return
    end if
    if (plastic%friction_angle < 0.0_dp .or. &
        plastic%friction_angle >= max_friction_angle(plastic%hardening_type) .or. &
        plastic%dilation_angle < 0.0_dp .or. &
        plastic%dilation_angle >= max_friction_angle(plastic%hardening_type)) then
      call input_error(err, '*DRUCKER PRAGER: friction or dilation angle out of range')
      return
    end if
    law%tan_friction = tan(plastic%friction_angle * degree)
    law%tan_dilation = tan(plastic%dilation_angle * degree)
    law%hardening = plastic%curve
    law%hardening_type = to_lower(plastic%hardening_type)
    select case (plastic%hardening_type)
    case ('COMPRESSION')
      law%cohesion_factor = 1.0_dp - law%tan_friction / 3.0_dp
      law%rate_factor = 1.0_dp - law%tan_dilation / 3.0_dp
    case ('TENSION')
      law%cohesion_factor = 1.0_dp + law%tan_friction / 3.0_dp
      law%rate_factor = 1.0_dp + law%tan_dilation / 3.0_dp
    case ('SHEAR')
      law%cohesion_factor = sqrt(3.0_dp)
      law%rate_factor = 1.0_dp
    case default
      call input_error(err, '*DRUCKER PRAGER HARDENING: unknown TYPE=' // plastic%hardening_type // &
                       '; expected one of ' // DP_HARDENING_TYPES)
      return
    end select
    allocate (material, source=law)
  end subroutine create_drucker_prager

  !> At least one point, strains strictly increasing from 0, stresses positive.
  pure logical function valid_curve(curve)
    type(hardening_table_t), intent(in) :: curve
    integer :: i
    valid_curve = .false.
    if (curve%n_points() < 1) return
    if (size(curve%stress) /= size(curve%strain)) return
    if (curve%strain(1) /= 0.0_dp .or. any(curve%stress <= 0.0_dp)) return
    do i = 2, size(curve%strain)
      if (curve%strain(i) <= curve%strain(i - 1)) return
    end do
    valid_curve = .true.
  end function valid_curve

end module fcs_material_factory
