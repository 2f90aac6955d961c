!> The element loops: everything the stepper does element by element, for elements of any
!> kind, asking each element's kind (fcs_element_kernels) and never assuming a number of nodes
!> or integration points:
!>   - `assemble`: internal forces and the tangent K (material part, initial stress with
!>     NLGEOM, B-bar), added into a sparse matrix passed in (doc/theory.md 1.2-1.3);
!>   - `update`: strains and stresses of the (scaled) increment, point by point through
!>     `update_point` (Hughes & Winget 1980; doc/theory.md 1.4);
!>   - `collect_events`: the R-minimum limits of a trial increment - strain and rotation
!>     increments, yield and plastic-strain events (doc/theory.md 6.4);
!>   - `count_unloading`: points on their yield surface that a trial increment unloads;
!>   - `check_geometry`, `most_distorted`: Jacobian checks of a configuration;
!>   - `thermal_forces`: the load of a change of the nodal temperatures (doc/theory.md 2.5);
!>   - `nodal_average`, `point_volumes`, `plastic_fields`, `cliques`, `face_nodes`,
!>     `face_pressure`: what outputs, monitors, the sparse pattern and the loads need.
!> Nodal temperatures, where the model has them, are passed in (start and end of the
!> increment) and interpolated to the integration points with the element's shape functions.
!> The loops own the material objects (one per material of the model) and know, for every
!> element, its kind, nodes, material and formulation, and which elements this process works
!> on (`mine`). Kinds come from the model's element catalogue (fcs_element_catalogue), with
!> their formulations (doc/theory.md 1.5): C3D8R's hourglass force and stiffness are added in
!> `assemble` (from the total displacements, as CalculiX), C3D8I's incompatible modes are
!> condensed in the tangent and found element by element in `update` (`update_modes`: the
!> modes' generalised forces vanish at the end of every increment), and predicted from the
!> condensed tangent for the trial increments of `collect_events` and `count_unloading`.
!> C3D8R's generalised hourglass forces (12 per element) are element state: `update` adds
!> their increment (rotated with the element's spin under NLGEOM), `assemble` turns them into
!> nodal forces. They are kept after the material's internal variables at the element's first
!> point (`material_state(n + 1:n + 12, 1, e)`, n the material's own count), so that they are
!> restored, gathered and checkpointed with them; `n_material_state` counts them,
!> `has_states` does not (it tells whether a material has a yield surface).
module fcs_element_loops
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  use fcs_mesh, only: mesh_t, mesh_kind_t, MESH_MAX_FACES, MESH_MAX_FACE_NODES
  use fcs_element_kind, only: element_kind_t, MAX_NODES, MAX_POINTS, FORMULATION_HOURGLASS
  use fcs_element_catalogue, only: element_catalogue_t
  use fcs_element_kernels, only: element_geometry_t, element_geometry, element_internal_force, &
    element_tangent, element_strain_increments, element_point_volumes, element_extrapolate, &
    element_min_jacobian_ratio, element_volume, element_face_nodes, element_face_pressure, &
    element_face_area, element_hourglass_force, element_hourglass_stiffness, &
    element_hourglass_increment, &
    element_mode_residual, element_mode_correction, MAX_MODES, element_displacement_gradients
  use fcs_element_state, only: element_state_t
  use fcs_hex8_element, only: hex8_rotate_stress, mises_stress
  use fcs_material, only: material_t, material_slot_t
  use fcs_voigt, only: spin_rotation, rotate_stress_like, rotate_strain_like
  use fcs_simo_plasticity, only: simo_plasticity_t
  use fcs_hyperelastic, only: hyperelastic_stress, hyperelastic_jaumann_tangent, almansi_strain, &
                              HYPER_DEFORMATION_PLASTICITY
  use fcs_hyperelastic_material, only: hyperelastic_t
  use fcs_st_venant_kirchhoff, only: green_lagrange_strain, cauchy_from_pk2, pk2_from_cauchy, &
                                     svk_jaumann_tangent, determinant_of, tensor_voigt
  use fcs_orientation, only: orientation_t, orientation_axes, stress_to_global, strain_to_local, &
                             stress_to_local, rotate_stiffness
  use fcs_sparse, only: sparse_matrix_t
  use fcs_rmin_events, only: rmin_collector_t, EVENT_STRAIN_LIMIT, EVENT_ROTATION_LIMIT, &
                             EVENT_YIELD, EVENT_PLASTIC_STRAIN_LIMIT
  use fcs_strings, only: str
  implicit none
  private
  public :: element_loops_t, event_limits_t, update_point, mesh_kinds, mises_stress
  public :: element_jacobian_ratio, element_volume_of, element_face_area_of
  public :: BODY_FORCE_GRAVITY, BODY_FORCE_CENTRIFUGAL

  !> Body forces of `body_force`: uniform acceleration, centrifugal acceleration about an axis.
  integer, parameter :: BODY_FORCE_GRAVITY = 1, BODY_FORCE_CENTRIFUGAL = 2

  !> C3D8I: the modes of an increment are iterated until their generalised forces are below
  !> MODE_TOLERANCE times the sum of the magnitudes of their terms (round-off of an elastic
  !> increment is about 1e-15; a return mapping converges quadratically with its consistent
  !> tangent), at most MAX_MODE_ITERATIONS Newton corrections.
  real(dp), parameter :: MODE_TOLERANCE = 1.0e-10_dp
  integer, parameter :: MAX_MODE_ITERATIONS = 25
  !> C3D8R: generalised hourglass forces Q(3, 4) kept per element.
  integer, parameter :: HOURGLASS_STATE = 12
  !> Tensor Voigt components to engineering shears (strains are stored with 2 e_12, ...).
  real(dp), parameter :: ENGINEERING_SHEARS(6) = [1.0_dp, 1.0_dp, 1.0_dp, 2.0_dp, 2.0_dp, 2.0_dp]

  !> The R-minimum limits of an increment at the integration points (doc/theory.md 6.4):
  !> largest equivalent strain increment [-], rotation increment [rad] and growth of the
  !> equivalent plastic strain [-].
  type :: event_limits_t
    real(dp) :: strain = 0.0_dp
    real(dp) :: rotation = 0.0_dp
    real(dp) :: plastic_strain = 0.0_dp
  end type event_limits_t

  type :: element_loops_t
    !> The model's element kinds; per element its kind (index into them), nodes (rows
    !> 1..n_nodes of its kind), user id, material (index into `materials`) and formulation.
    type(element_catalogue_t) :: catalogue
    integer :: n_elements = 0
    !> The largest number of integration points of an element of the model.
    integer :: max_points = 0
    integer, allocatable :: kind(:)
    integer, allocatable :: nodes(:, :)
    integer, allocatable :: element_id(:)
    integer, allocatable :: material(:)
    logical, allocatable :: bbar(:)
    type(material_slot_t), allocatable :: materials(:)
    !> Reference coordinates (the configuration of the integrals without NLGEOM).
    real(dp), allocatable :: x_reference(:, :)
    !> The elements this process assembles and updates (all of them in a serial run).
    integer, allocatable :: mine(:)
    !> Whether some element has hourglass control (C3D8R), whose forces are element state.
    logical :: hourglass = .false.
    !> *ORIENTATION axes of the elements whose section has one: axes(:, :, q, axes_index(e))
    !> at point q (columns: the local unit vectors in global components, from the point's
    !> reference position); axes_index(e) = 0: none (empty without orientations). An
    !> anisotropic material works in these axes (`update_point`); others need them for output
    !> only (`to_material_axes`).
    integer, allocatable :: axes_index(:)
    real(dp), allocatable :: axes(:, :, :, :)
  contains
    procedure :: init => loops_init
    procedure :: set_orientations => loops_set_orientations
    procedure :: to_material_axes => loops_to_material_axes
    procedure :: has_orientation => loops_has_orientation
    procedure :: set_share => loops_set_share
    procedure :: n_points => loops_n_points
    procedure :: point_counts => loops_point_counts
    procedure :: n_material_state => loops_n_material_state
    procedure :: has_states => loops_has_states
    procedure :: has_thermal => loops_has_thermal
    procedure :: point_positions => loops_point_positions
    procedure :: body_force => loops_body_force
    procedure :: thermal_forces => loops_thermal_forces
    procedure :: assemble => loops_assemble
    procedure :: update => loops_update
    procedure :: check_geometry => loops_check_geometry
    procedure :: collect_events => loops_collect_events
    procedure :: count_unloading => loops_count_unloading
    procedure :: most_distorted => loops_most_distorted
    procedure :: nodal_average => loops_nodal_average
    procedure :: point_volumes => loops_point_volumes
    procedure :: thermal_strains => loops_thermal_strains
    procedure :: energy_stresses => loops_energy_stresses
    procedure :: plastic_fields => loops_plastic_fields
    procedure :: cliques => loops_cliques
    procedure :: face_nodes => loops_face_nodes
    procedure :: face_pressure => loops_face_pressure
  end type element_loops_t

contains

  !> What the mesh is to know of the catalogue's kinds (fcs_mesh): names, node counts, gmsh
  !> types and node orders and the local nodes of their faces, in catalogue order (mesh kind k is catalogue
  !> kind k).
  function mesh_kinds(catalogue) result(kinds)
    type(element_catalogue_t), intent(in) :: catalogue
    type(mesh_kind_t), allocatable :: kinds(:)
    integer, allocatable :: local(:)
    integer :: k, f
    allocate (kinds(catalogue%size()))
    do k = 1, catalogue%size()
      associate (kind => catalogue%kinds(k))
        kinds(k)%name = kind%name
        kinds(k)%n_nodes = kind%n_nodes
        kinds(k)%gmsh_type = kind%gmsh_type
        if (allocated(kind%gmsh_order)) kinds(k)%gmsh_order = kind%gmsh_order
        kinds(k)%n_faces = min(kind%n_faces, MESH_MAX_FACES)
        do f = 1, kinds(k)%n_faces
          local = element_face_nodes(kind, f)
          kinds(k)%face_size(f) = min(size(local), MESH_MAX_FACE_NODES)
          kinds(k)%face_local(1:kinds(k)%face_size(f), f) = local(1:kinds(k)%face_size(f))
        end do
      end associate
    end do
  end function mesh_kinds

  !> Smallest det J of element e of `mesh` over its mean (<= 0: inverted or degenerate).
  real(dp) function element_jacobian_ratio(catalogue, mesh, e) result(ratio)
    type(element_catalogue_t), intent(in) :: catalogue
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: e
    ratio = element_min_jacobian_ratio(catalogue%kinds(mesh%element_kind(e)), &
                                       mesh%x(:, mesh%element_nodes(e)))
  end function element_jacobian_ratio

  !> Volume of element e of `mesh` (reference configuration).
  real(dp) function element_volume_of(catalogue, mesh, e) result(volume)
    type(element_catalogue_t), intent(in) :: catalogue
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: e
    volume = element_volume(catalogue%kinds(mesh%element_kind(e)), mesh%x(:, mesh%element_nodes(e)))
  end function element_volume_of

  !> Area of face f of element e of `mesh` (reference configuration).
  real(dp) function element_face_area_of(catalogue, mesh, e, f) result(area)
    type(element_catalogue_t), intent(in) :: catalogue
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: e, f
    area = element_face_area(catalogue%kinds(mesh%element_kind(e)), f, mesh%x(:, mesh%face_nodes(e, f)))
  end function element_face_area_of

  !> Set up the loops over the elements of `mesh`, of the kinds of `catalogue`; element e has
  !> material material(e) of `materials` (moved in) and the B-bar formulation when bbar(e).
  !> Every element is this process's until `set_share`.
  subroutine loops_init(this, catalogue, mesh, material, bbar, materials, err)
    class(element_loops_t), intent(inout) :: this
    type(element_catalogue_t), intent(in) :: catalogue
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: material(:)
    logical, intent(in) :: bbar(:)
    type(material_slot_t), allocatable, intent(inout) :: materials(:)
    type(error_t), allocatable, intent(out) :: err
    logical :: used(catalogue%size())
    integer :: e, k
    this%catalogue = catalogue
    this%n_elements = mesh%n_elements
    this%kind = mesh%element_kind(1:mesh%n_elements)
    this%nodes = mesh%connectivity(:, 1:mesh%n_elements)
    this%element_id = mesh%element_id(1:mesh%n_elements)
    this%material = material
    this%bbar = bbar
    this%x_reference = mesh%x(:, 1:mesh%n_nodes)
    call move_alloc(materials, this%materials)
    this%mine = [(e, e = 1, mesh%n_elements)]
    if (allocated(this%axes_index)) deallocate (this%axes_index)
    if (allocated(this%axes)) deallocate (this%axes)
    allocate (this%axes_index(0), this%axes(3, 3, 0, 0))
    used = .false.
    used(this%kind) = .true.
    this%max_points = 0
    this%hourglass = .false.
    do k = 1, catalogue%size()
      if (.not. used(k)) cycle
      this%max_points = max(this%max_points, catalogue%kinds(k)%n_points)
      if (catalogue%kinds(k)%formulation == FORMULATION_HOURGLASS) this%hourglass = .true.
    end do
  end subroutine loops_init

  !> The *ORIENTATION of every element (`element_orientation(e)`: index into `orientations`,
  !> 0 none): the axes at each of its integration points (orientation_axes at the point's
  !> reference position; CalculiX evaluates them there too).
  subroutine loops_set_orientations(this, orientations, element_orientation)
    class(element_loops_t), intent(inout) :: this
    type(orientation_t), intent(in) :: orientations(:)
    integer, intent(in) :: element_orientation(:)
    real(dp), allocatable :: x(:, :)
    integer :: e, q, k
    if (allocated(this%axes_index)) deallocate (this%axes_index)
    if (allocated(this%axes)) deallocate (this%axes)
    allocate (this%axes_index(this%n_elements))
    this%axes_index = 0
    k = 0
    do e = 1, this%n_elements
      if (element_orientation(e) == 0) cycle
      k = k + 1
      this%axes_index(e) = k
    end do
    allocate (this%axes(3, 3, this%max_points, k))
    this%axes = 0.0_dp
    do e = 1, this%n_elements
      if (this%axes_index(e) == 0) cycle
      x = this%point_positions(e)
      do q = 1, size(x, 2)
        this%axes(:, :, q, this%axes_index(e)) = orientation_axes(orientations(element_orientation(e)), &
                                                                  x(:, q))
      end do
    end do
  end subroutine loops_set_orientations

  !> Whether element e has an *ORIENTATION.
  pure logical function loops_has_orientation(this, e) result(has)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    has = .false.
    if (size(this%axes_index) > 0) has = this%axes_index(e) > 0
  end function loops_has_orientation

  !> Whether the points of element e work in local axes: an anisotropic material in an
  !> element with an *ORIENTATION.
  pure logical function works_in_local_axes(this, e) result(local)
    type(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    local = .false.
    if (.not. this%has_orientation(e)) return
    local = this%materials(this%material(e))%m%is_anisotropic()
  end function works_in_local_axes

  !> A copy of stress-like (`strain_like` false) or engineering-strain values(6, q, e) with
  !> the points of oriented elements in their local axes (*EL PRINT, GLOBAL=NO).
  function loops_to_material_axes(this, values, strain_like) result(local)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: values(:, :, :)
    logical, intent(in) :: strain_like
    real(dp), allocatable :: local(:, :, :)
    integer :: e, q
    local = values
    do e = 1, this%n_elements
      if (.not. this%has_orientation(e)) cycle
      do q = 1, this%n_points(e)
        associate (axes => this%axes(:, :, q, this%axes_index(e)))
          if (strain_like) then
            local(:, q, e) = strain_to_local(values(:, q, e), axes)
          else
            local(:, q, e) = stress_to_local(values(:, q, e), axes)
          end if
        end associate
      end do
    end do
  end function loops_to_material_axes

  !> The elements this process works on.
  subroutine loops_set_share(this, mine)
    class(element_loops_t), intent(inout) :: this
    integer, intent(in) :: mine(:)
    this%mine = mine
  end subroutine loops_set_share

  !> Number of integration points of element e.
  pure integer function loops_n_points(this, e) result(n)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    n = this%catalogue%kinds(this%kind(e))%n_points
  end function loops_n_points

  !> Number of integration points of every element.
  pure function loops_point_counts(this) result(counts)
    class(element_loops_t), intent(in) :: this
    integer :: counts(this%n_elements)
    integer :: e
    do e = 1, this%n_elements
      counts(e) = this%n_points(e)
    end do
  end function loops_point_counts

  !> The number of internal variables kept per integration point: the largest number a
  !> material keeps, and with C3D8R elements 12 more for their hourglass forces.
  pure integer function loops_n_material_state(this) result(n)
    class(element_loops_t), intent(in) :: this
    n = largest_material_state(this)
    if (this%hourglass) n = n + HOURGLASS_STATE
  end function loops_n_material_state

  !> The largest number of internal variables a material keeps per point.
  pure integer function largest_material_state(this) result(n)
    type(element_loops_t), intent(in) :: this
    integer :: k
    n = 0
    do k = 1, size(this%materials)
      n = max(n, this%materials(k)%m%n_state())
    end do
  end function largest_material_state

  !> Whether some material has internal variables (a yield surface).
  pure logical function loops_has_states(this) result(has)
    class(element_loops_t), intent(in) :: this
    has = largest_material_state(this) > 0
  end function loops_has_states

  !> C3D8R element e: where its hourglass forces Q(3, 4) lie in material_state(:, 1, e) (after
  !> its material's internal variables).
  pure integer function hourglass_first(this, e) result(first)
    type(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    first = this%materials(this%material(e))%m%n_state() + 1
  end function hourglass_first

  !> Whether some material depends on temperature (expansion or temperature-dependent
  !> elastic constants).
  pure logical function loops_has_thermal(this) result(has)
    class(element_loops_t), intent(in) :: this
    integer :: k
    has = .false.
    do k = 1, size(this%materials)
      if (this%materials(k)%m%thermal%is_active()) has = .true.
    end do
  end function loops_has_thermal

  !> Reference positions x(3, q) of the integration points of element e (q = 1..n_points):
  !> x_q = sum_a N_a(xi_q) X_a.
  pure function loops_point_positions(this, e) result(x)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), allocatable :: x(:, :)
    integer :: n
    associate (kind => this%catalogue%kinds(this%kind(e)))
      n = kind%n_nodes
      x = matmul(this%x_reference(:, this%nodes(1:n, e)), kind%point_values(1:n, 1:kind%n_points))
    end associate
  end function loops_point_positions

  !> Consistent nodal forces f(3 n_nodes of the element) of a body force on element e:
  !> f_a = int N_a rho b dV_0 over the reference volume (the mass of the element is kept),
  !> rho b = `scale` times
  !>   - BODY_FORCE_GRAVITY: the unit vector vector(1:3) (scale = rho g);
  !>   - BODY_FORCE_CENTRIFUGAL: the distance vector r from the axis through vector(1:3)
  !>     along the unit vector vector(4:6) to the point (scale = rho omega^2), at the
  !>     point's position on the current configuration x with NLGEOM, else the reference
  !>     one (CalculiX's CENTRIF; no load stiffness is added).
  !> The integration rule is the element's own (exact for the constant part of b).
  subroutine loops_body_force(this, e, x, nlgeom, kind_of_force, vector, scale, f)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e, kind_of_force
    real(dp), intent(in) :: x(:, :), vector(6), scale
    logical, intent(in) :: nlgeom
    real(dp), intent(out) :: f(:)
    type(element_geometry_t) :: geo
    real(dp) :: xe(3, MAX_NODES), x0(3, MAX_NODES), dv(MAX_POINTS), b(3), position(3), r(3)
    integer :: q, a, n, np
    logical :: ok
    associate (kind => this%catalogue%kinds(this%kind(e)))
      n = kind%n_nodes
      np = kind%n_points
      call element_x(this, e, this%x_reference, .false., x0)
      call element_geometry(kind, x0(:, 1:n), geo, ok)
      dv(1:np) = element_point_volumes(kind, geo)
      call element_x(this, e, x, nlgeom, xe)
      f(1:3 * n) = 0.0_dp
      do q = 1, np
        if (kind_of_force == BODY_FORCE_GRAVITY) then
          b = scale * vector(1:3)
        else
          position = matmul(xe(:, 1:n), kind%point_values(1:n, q))
          r = position - vector(1:3)
          r = r - dot_product(r, vector(4:6)) * vector(4:6)
          b = scale * r
        end if
        do a = 1, n
          f(3 * a - 2:3 * a) = f(3 * a - 2:3 * a) + kind%point_values(a, q) * dv(q) * b
        end do
      end do
    end associate
  end subroutine loops_body_force

  !> Temperatures at the integration points of element e from the nodal temperatures
  !> `nodal` (n_nodes of the model): T_q = sum_a N_a(xi_q) T_a, or the kind's projected table
  !> (C3D20: fcs_element_kind, build_temperature_table).
  pure subroutine point_temperatures(this, e, nodal, t)
    type(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: nodal(:)
    real(dp), intent(out) :: t(:)
    integer :: q, n
    associate (kind => this%catalogue%kinds(this%kind(e)))
      n = kind%n_nodes
      do q = 1, kind%n_points
        t(q) = dot_product(kind%temperature_values(1:n, q), nodal(this%nodes(1:n, e)))
      end do
    end associate
  end subroutine point_temperatures

  !> Nodal coordinates of element e: current ones x(3, n_nodes) with NLGEOM, else the
  !> reference ones.
  pure subroutine element_x(this, e, x, nlgeom, xe)
    type(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: x(:, :)
    logical, intent(in) :: nlgeom
    real(dp), intent(out) :: xe(:, :)
    integer :: n
    n = this%catalogue%kinds(this%kind(e))%n_nodes
    if (nlgeom) then
      xe(:, 1:n) = x(:, this%nodes(1:n, e))
    else
      xe(:, 1:n) = this%x_reference(:, this%nodes(1:n, e))
    end if
  end subroutine element_x

  !> Nodal displacement increments du_e(3, n_nodes) of element e from du(3 n_nodes).
  pure subroutine element_increment(this, e, du, du_e)
    type(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: du(:)
    real(dp), intent(out) :: du_e(:, :)
    integer :: a, node
    do a = 1, this%catalogue%kinds(this%kind(e))%n_nodes
      node = this%nodes(a, e)
      du_e(:, a) = du(3 * node - 2:3 * node)
    end do
  end subroutine element_increment

  !> Error for an element whose Jacobian is no longer positive.
  subroutine inverted_element_error(this, e, err)
    type(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    type(error_t), allocatable, intent(out) :: err
    call fatal_error(err, 'element ' // str(this%element_id(e)) // ' is inverted ' // &
      '(Jacobian determinant <= 0): the deformation is too large for the mesh, or a load or ' // &
      'contact penalty crushes it; refine the mesh there or reduce the R-minimum limits')
  end subroutine inverted_element_error

  !> Internal forces f_int (3 n_nodes) of this process's elements on the configuration of
  !> `nlgeom` (current coordinates x, or the reference), and, when `matrix` is present, their
  !> tangent K added into it (values only: the caller zeroes it). Points marked in
  !> `elastic(q, e)` (elastic unloading) take the elastic tangent. With `flux` (n_nodes), the
  !> sum over the elements of a node of the magnitudes of their nodal forces: the force the
  !> node passes on, the scale its out-of-balance force is measured against (f_int itself
  !> vanishes at a free node in equilibrium).
  subroutine loops_assemble(this, x, fields, nlgeom, f_int, err, matrix, elastic, flux, temperature)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :)
    type(element_state_t), intent(in) :: fields
    logical, intent(in) :: nlgeom
    real(dp), intent(out) :: f_int(:)
    type(error_t), allocatable, intent(out) :: err
    type(sparse_matrix_t), intent(inout), optional :: matrix
    logical, intent(in), optional :: elastic(:, :)
    real(dp), intent(out), optional :: flux(:)
    !> Nodal temperatures: the elastic tangent of temperature-dependent constants at them.
    real(dp), intent(in), optional :: temperature(:)
    type(element_geometry_t) :: geo
    real(dp) :: xe(3, MAX_NODES), f(3 * MAX_NODES), k(3 * MAX_NODES, 3 * MAX_NODES)
    real(dp) :: c(6, 6, MAX_POINTS), tq(MAX_POINTS)
    integer :: e, q, a, node, i, n, first
    logical :: ok, missing
    f_int = 0.0_dp
    if (present(flux)) flux = 0.0_dp
    do i = 1, size(this%mine)
      e = this%mine(i)
      associate (kind => this%catalogue%kinds(this%kind(e)))
        n = kind%n_nodes
        call element_x(this, e, x, nlgeom, xe)
        call element_geometry(kind, xe(:, 1:n), geo, ok)
        if (.not. ok) then
          call inverted_element_error(this, e, err)
          return
        end if
        call element_internal_force(kind, geo, fields%stress(:, :, e), this%bbar(e), f(1:3 * n))
        if (kind%formulation == FORMULATION_HOURGLASS) then
          first = hourglass_first(this, e)
          call element_hourglass_force(kind, geo, reshape(fields%material_state(first:first + &
                                       HOURGLASS_STATE - 1, 1, e), [3, 4]), f(1:3 * n))
        end if
        do a = 1, n
          node = this%nodes(a, e)
          f_int(3 * node - 2:3 * node) = f_int(3 * node - 2:3 * node) + f(3 * a - 2:3 * a)
        end do
        if (present(flux)) then
          do a = 1, n
            node = this%nodes(a, e)
            flux(node) = flux(node) + norm2(f(3 * a - 2:3 * a))
          end do
        end if
        if (.not. present(matrix)) cycle
        associate (material => this%materials(this%material(e))%m)
          if (takes_svk(this, e, nlgeom) .or. takes_simo(this, e, nlgeom) .or. &
              takes_hyperelastic(this, e, nlgeom)) then
            if (takes_hyperelastic(this, e, nlgeom)) then
              call hyperelastic_tangents(this, e, xe(:, 1:n), c, err)
            else if (takes_svk(this, e, nlgeom)) then
              call svk_tangents(this, e, xe(:, 1:n), fields%stress(:, :, e), c, err, temperature)
            else
              call simo_tangents(this, e, xe(:, 1:n), fields, c, err, elastic, temperature)
            end if
            if (allocated(err)) return
            call element_tangent(kind, geo, fields%stress(:, :, e), c(:, :, 1:kind%n_points), &
                                 this%bbar(e), nlgeom, k(1:3 * n, 1:3 * n))
            if (kind%formulation == FORMULATION_HOURGLASS) call element_hourglass_stiffness(kind, &
              geo, youngs_modulus(material), k(1:3 * n, 1:3 * n))
            call matrix%add_matrix(this%nodes(1:n, e), k(1:3 * n, 1:3 * n), missing)
            cycle
          end if
          do q = 1, kind%n_points
            c(:, :, q) = material%tangent(fields%stress(:, q, e), fields%material_state(:, q, e))
          end do
          if (present(elastic)) then
            do q = 1, kind%n_points
              if (elastic(q, e)) c(:, :, q) = material%elastic_matrix()
            end do
          end if
          if (present(temperature)) then
            if (material%thermal%elastic_varies()) then
              call point_temperatures(this, e, temperature, tq)
              do q = 1, kind%n_points
                c(:, :, q) = material%elastic_matrix_at(tq(q))
              end do
            end if
          end if
          if (works_in_local_axes(this, e)) then
            do q = 1, kind%n_points
              c(:, :, q) = rotate_stiffness(c(:, :, q), this%axes(:, :, q, this%axes_index(e)))
            end do
          end if
        end associate
        call element_tangent(kind, geo, fields%stress(:, :, e), c(:, :, 1:kind%n_points), &
                             this%bbar(e), nlgeom, k(1:3 * n, 1:3 * n))
        if (kind%formulation == FORMULATION_HOURGLASS) call element_hourglass_stiffness(kind, &
          geo, youngs_modulus(this%materials(this%material(e))%m), k(1:3 * n, 1:3 * n))
        call matrix%add_matrix(this%nodes(1:n, e), k(1:3 * n, 1:3 * n), missing)
      end associate
    end do
  end subroutine loops_assemble

  !> Stress and strain update of this process's elements for the (scaled) increment du:
  !> gradients on the mid-increment configuration (with NLGEOM; the reference one without),
  !> objective rotation (Hughes & Winget 1980), then the material law (`update_point`).
  subroutine loops_update(this, x, du, fields, nlgeom, err, temperature_start, temperature_end, &
                         temperature_zero)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :), du(:)
    type(element_state_t), intent(inout) :: fields
    logical, intent(in) :: nlgeom
    type(error_t), allocatable, intent(out) :: err
    !> Nodal temperatures at the start and the end of the increment (models with
    !> temperatures): the thermal strain increment of each point (update_point_thermal).
    real(dp), intent(in), optional :: temperature_start(:), temperature_end(:)
    !> The initial (stress-free) nodal temperatures: the total thermal strain of St Venant-
    !> Kirchhoff points (update_svk; without it, those at the increment's start).
    real(dp), intent(in), optional :: temperature_zero(:)
    type(element_geometry_t) :: geo
    real(dp) :: strain(6, MAX_POINTS), spin(3, 3, MAX_POINTS), equivalent(MAX_POINTS)
    real(dp) :: angle(MAX_POINTS), du_e(3, MAX_NODES), xe(3, MAX_NODES)
    real(dp) :: t_start(MAX_POINTS), t_end(MAX_POINTS), t_zero(MAX_POINTS)
    integer :: e, q, i, n
    logical :: ok, thermal
    do i = 1, size(this%mine)
      e = this%mine(i)
      associate (kind => this%catalogue%kinds(this%kind(e)))
        n = kind%n_nodes
        call element_increment(this, e, du, du_e)
        call element_x(this, e, x, nlgeom, xe)
        if (kind%n_modes > 0) then
          call update_modes(this, e, xe(:, 1:n), du_e(:, 1:n), fields, nlgeom, err)
          if (allocated(err)) return
          cycle
        end if
        if (nlgeom) xe(:, 1:n) = xe(:, 1:n) + 0.5_dp * du_e(:, 1:n)
        call element_geometry(kind, xe(:, 1:n), geo, ok)
        if (.not. ok) then
          call inverted_element_error(this, e, err)
          return
        end if
        call element_strain_increments(kind, geo, du_e(:, 1:n), this%bbar(e), strain, spin, &
                                       equivalent, angle)
        associate (material => this%materials(this%material(e))%m)
          thermal = present(temperature_start) .and. present(temperature_end)
          if (thermal) thermal = material%thermal%is_active()
          if (takes_hyperelastic(this, e, nlgeom)) then
            call element_x(this, e, x, nlgeom, xe)
            call update_hyperelastic(this, e, xe(:, 1:n) + du_e(:, 1:n), fields, err)
            if (allocated(err)) return
          else if (takes_simo(this, e, nlgeom)) then
            call element_x(this, e, x, nlgeom, xe)
            xe(:, 1:n) = xe(:, 1:n) + du_e(:, 1:n)
            if (thermal) then
              call point_temperatures(this, e, temperature_end, t_end)
              t_zero = t_end
              if (present(temperature_zero)) call point_temperatures(this, e, temperature_zero, t_zero)
              call update_simo(this, e, xe(:, 1:n), fields, err, &
                               reshape([t_zero(1:kind%n_points), t_end(1:kind%n_points)], &
                                       [kind%n_points, 2]))
            else
              call update_simo(this, e, xe(:, 1:n), fields, err)
            end if
            if (allocated(err)) return
          else if (takes_svk(this, e, nlgeom)) then
            call element_x(this, e, x, nlgeom, xe)
            if (thermal) then
              call point_temperatures(this, e, temperature_start, t_start)
              call point_temperatures(this, e, temperature_end, t_end)
              t_zero = t_start
              if (present(temperature_zero)) call point_temperatures(this, e, temperature_zero, t_zero)
              call update_svk(this, e, xe(:, 1:n), du_e(:, 1:n), fields, err, &
                              reshape([t_zero(1:kind%n_points), t_start(1:kind%n_points), &
                                       t_end(1:kind%n_points)], [kind%n_points, 3]))
            else
              call update_svk(this, e, xe(:, 1:n), du_e(:, 1:n), fields, err)
            end if
            if (allocated(err)) return
          else if (works_in_local_axes(this, e)) then
            if (thermal) then
              call point_temperatures(this, e, temperature_start, t_start)
              call point_temperatures(this, e, temperature_end, t_end)
            else
              t_start = 0.0_dp
              t_end = 0.0_dp
            end if
            do q = 1, kind%n_points
              call update_point_thermal(material, nlgeom, strain(:, q), spin(:, :, q), &
                fields%stress(:, q, e), fields%strain(:, q, e), fields%material_state(:, q, e), &
                t_start(q), t_end(q), this%axes(:, :, q, this%axes_index(e)))
            end do
          else if (thermal) then
            call point_temperatures(this, e, temperature_start, t_start)
            call point_temperatures(this, e, temperature_end, t_end)
            do q = 1, kind%n_points
              call update_point_thermal(material, nlgeom, strain(:, q), spin(:, :, q), &
                fields%stress(:, q, e), fields%strain(:, q, e), fields%material_state(:, q, e), &
                t_start(q), t_end(q))
            end do
          else
            do q = 1, kind%n_points
              call update_point(material, nlgeom, strain(:, q), spin(:, :, q), fields%stress(:, q, e), &
                                fields%strain(:, q, e), fields%material_state(:, q, e))
            end do
          end if
        end associate
        if (kind%formulation == FORMULATION_HOURGLASS) &
          call update_hourglass(this, e, geo, du_e(:, 1:n), spin(:, :, 1), nlgeom, fields)
      end associate
    end do
  end subroutine loops_update

  !> Whether element e takes St Venant-Kirchhoff (doc/theory.md 2.10): under NLGEOM, a material
  !> marked `st_venant_kirchhoff` (*ELASTIC without plasticity) in an element without
  !> incompatible modes. C3D8I keeps the rate form: its modes are found anew in every increment
  !> (update_modes), so the total deformation gradient with the modes is not known.
  pure logical function takes_svk(this, e, nlgeom) result(svk)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    logical, intent(in) :: nlgeom
    svk = nlgeom
    if (.not. svk) return
    svk = this%materials(this%material(e))%m%st_venant_kirchhoff .and. &
          this%catalogue%kinds(this%kind(e))%n_modes == 0
  end function takes_svk

  !> Whether element e takes a hyperelastic law (fcs_hyperelastic, doc/theory.md 2.11): under
  !> NLGEOM, a hyperelastic_t material in an element without incompatible modes (the model
  !> checks refuse C3D8I with these materials: its modes are found anew in every increment,
  !> so the total deformation gradient with the modes is not known; takes_svk).
  pure logical function takes_hyperelastic(this, e, nlgeom) result(hyper)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    logical, intent(in) :: nlgeom
    hyper = nlgeom
    if (.not. hyper) return
    hyper = this%catalogue%kinds(this%kind(e))%n_modes == 0
    if (.not. hyper) return
    select type (material => this%materials(this%material(e))%m)
    type is (hyperelastic_t)
    class default
      hyper = .false.
    end select
  end function takes_hyperelastic

  !> Hyperelastic update of element e whose nodes have reached xe (3, n): each point's Cauchy
  !> stress is the law's at its deformation gradient F (hyperelastic_stress: a total form, a
  !> function of F alone, so that iterations and restarts recompute it exactly); its strain
  !> the Green-Lagrange strain of F (CalculiX's E under NLGEOM), or for *DEFORMATION
  !> PLASTICITY the Almansi strain the law takes (ccx 2.20 prints that Eulerian strain as E for
  !> this material: e_c3d.f / results.f convert the strain in place before the law).
  subroutine update_hyperelastic(this, e, xe, fields, err)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: xe(:, :)
    type(element_state_t), intent(inout) :: fields
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: f(3, 3, MAX_POINTS)
    integer :: q
    call deformation_gradients(this, e, xe, f, err)
    if (allocated(err)) return
    select type (material => this%materials(this%material(e))%m)
    type is (hyperelastic_t)
      do q = 1, this%catalogue%kinds(this%kind(e))%n_points
        fields%stress(:, q, e) = hyperelastic_stress(material%law, f(:, :, q))
        if (material%law%family == HYPER_DEFORMATION_PLASTICITY) then
          fields%strain(:, q, e) = tensor_voigt(almansi_strain(f(:, :, q))) * ENGINEERING_SHEARS
        else
          fields%strain(:, q, e) = green_lagrange_strain(f(:, :, q))
        end if
      end do
    end select
  end subroutine update_hyperelastic

  !> The tangents c(:, :, q) of element e's hyperelastic law at its nodes xe
  !> (hyperelastic_jaumann_tangent: Miehe's numerical tangent of the Jaumann rate).
  subroutine hyperelastic_tangents(this, e, xe, c, err)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: xe(:, :)
    real(dp), intent(out) :: c(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: f(3, 3, MAX_POINTS)
    integer :: q
    call deformation_gradients(this, e, xe, f, err)
    if (allocated(err)) return
    select type (material => this%materials(this%material(e))%m)
    type is (hyperelastic_t)
      do q = 1, this%catalogue%kinds(this%kind(e))%n_points
        c(:, :, q) = hyperelastic_jaumann_tangent(material%law, f(:, :, q))
      end do
    end select
  end subroutine hyperelastic_tangents

  !> Whether element e takes the multiplicative finite-strain plasticity of CalculiX
  !> (fcs_simo_plasticity, doc/theory.md 2.8): under NLGEOM, a simo_plasticity_t material
  !> (*ELASTIC with *PLASTIC) in an element without incompatible modes (C3D8I keeps the rate
  !> form, as for St Venant-Kirchhoff: takes_svk).
  pure logical function takes_simo(this, e, nlgeom) result(simo)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    logical, intent(in) :: nlgeom
    simo = nlgeom
    if (.not. simo) return
    simo = this%catalogue%kinds(this%kind(e))%n_modes == 0
    if (.not. simo) return
    select type (material => this%materials(this%material(e))%m)
    type is (simo_plasticity_t)
    class default
      simo = .false.
    end select
  end function takes_simo

  !> Multiplicative plasticity update of element e whose nodes have reached xe (3, n): the
  !> stress and state of each point from its deformation gradient F at xe and its state at
  !> the start of the increment (simo_finite_stress, a total form: no strain increments or
  !> rotations); the strain becomes the Green-Lagrange strain of F (CalculiX's E).
  !> `temperatures(q, :)`: the point's initial and end temperatures (ccx's thermal stretch
  !> a = alpha (T - T_0) taken off F, the elastic constants at T).
  subroutine update_simo(this, e, xe, fields, err, temperatures)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: xe(:, :)
    type(element_state_t), intent(inout) :: fields
    type(error_t), allocatable, intent(out) :: err
    real(dp), intent(in), optional :: temperatures(:, :)
    real(dp) :: f(3, 3, MAX_POINTS), a, t
    integer :: q
    call deformation_gradients(this, e, xe, f, err)
    if (allocated(err)) return
    select type (material => this%materials(this%material(e))%m)
    type is (simo_plasticity_t)
      do q = 1, this%catalogue%kinds(this%kind(e))%n_points
        a = 0.0_dp
        t = 0.0_dp
        if (present(temperatures)) then
          a = first(material%thermal_strain_increment(temperatures(q, 1), temperatures(q, 2)))
          t = temperatures(q, 2)
        end if
        call material%finite_stress(f(:, :, q), a, t, fields%material_state(:, q, e), &
                                    fields%stress(:, q, e))
        fields%strain(:, q, e) = green_lagrange_strain(f(:, :, q))
      end do
    end select
  end subroutine update_simo

  !> The tangents c(:, :, q) of element e's multiplicative plasticity (simo_finite_tangent)
  !> at its nodes xe: of continued loading at points on their yield surface that `elastic`
  !> does not mark as unloading, elastic elsewhere; elastic constants at the nodal
  !> `temperature` interpolated to the points when given.
  subroutine simo_tangents(this, e, xe, fields, c, err, elastic, temperature)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: xe(:, :)
    type(element_state_t), intent(in) :: fields
    real(dp), intent(out) :: c(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: elastic(:, :)
    real(dp), intent(in), optional :: temperature(:)
    real(dp) :: f(3, 3, MAX_POINTS), tq(MAX_POINTS)
    integer :: q
    logical :: plastic
    call deformation_gradients(this, e, xe, f, err)
    if (allocated(err)) return
    tq = 0.0_dp
    if (present(temperature)) call point_temperatures(this, e, temperature, tq)
    select type (material => this%materials(this%material(e))%m)
    type is (simo_plasticity_t)
      do q = 1, this%catalogue%kinds(this%kind(e))%n_points
        associate (state => fields%material_state(:, q, e))
          plastic = material%on_surface(fields%stress(:, q, e), state)
          if (present(elastic)) plastic = plastic .and. .not. elastic(q, e)
          c(:, :, q) = material%finite_tangent(f(:, :, q), material%thermal_stretch(f(:, :, q), &
                                               state), tq(q), state, plastic)
        end associate
      end do
    end select
  end subroutine simo_tangents

  !> Deformation gradients f(:, :, q) = dx/dX at the points of element e whose nodes are at xe
  !> (3, n), from the reference coordinates; with FORMULATION=BBAR the F-bar of de Souza Neto
  !> et al. (1996): each F scaled by (Jbar / det F)^(1/3), Jbar the element's volume ratio
  !> (the volume-weighted mean of det F), as B-bar takes the mean volumetric strain.
  subroutine deformation_gradients(this, e, xe, f, err)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: xe(:, :)
    real(dp), intent(out) :: f(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    type(element_geometry_t) :: geo
    real(dp) :: x0(3, MAX_NODES), dv(MAX_POINTS), det(MAX_POINTS), mean
    integer :: q, n, np, i
    logical :: ok
    associate (kind => this%catalogue%kinds(this%kind(e)))
      n = kind%n_nodes
      np = kind%n_points
      x0(:, 1:n) = this%x_reference(:, this%nodes(1:n, e))
      call element_geometry(kind, x0(:, 1:n), geo, ok)
      if (.not. ok) then
        call inverted_element_error(this, e, err)
        return
      end if
      f(:, :, 1:np) = element_displacement_gradients(kind, geo, xe(:, 1:n) - x0(:, 1:n))
      do q = 1, np
        do i = 1, 3
          f(i, i, q) = f(i, i, q) + 1.0_dp
        end do
        det(q) = determinant_of(f(:, :, q))
      end do
      if (any(det(1:np) <= 0.0_dp)) then
        call inverted_element_error(this, e, err)
        return
      end if
      if (.not. this%bbar(e)) return
      dv(1:np) = element_point_volumes(kind, geo)
      mean = sum(det(1:np) * dv(1:np)) / sum(dv(1:np))
      do q = 1, np
        f(:, :, q) = f(:, :, q) * (mean / det(q))**(1.0_dp / 3.0_dp)
      end do
    end associate
  end subroutine deformation_gradients

  !> The elastic stiffness of element e's material at its point q in the global reference axes
  !> (the *ORIENTATION axes at the point's reference position turned to global ones for an
  !> anisotropic material), at temperature t (without it, the material's own constants).
  function reference_stiffness(this, e, q, t) result(c)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e, q
    real(dp), intent(in), optional :: t
    real(dp) :: c(6, 6)
    if (present(t)) then
      c = this%materials(this%material(e))%m%elastic_matrix_at(t)
    else
      c = this%materials(this%material(e))%m%elastic_matrix()
    end if
    if (works_in_local_axes(this, e)) c = rotate_stiffness(c, this%axes(:, :, q, this%axes_index(e)))
  end function reference_stiffness

  !> St Venant-Kirchhoff update of element e (doc/theory.md 2.10) for nodal increments du_e
  !> from the nodes' start positions xe: with F0 and F1 the deformation gradients at the start
  !> and the end of the increment, S0 = det F0 F0^-1 sigma F0^-T,
  !>   S1 = C(T1) C(T0)^-1 S0 + C(T1) : (E_m(F1, a1) - E_m(F0, a0)),   sigma = F1 S1 F1^T / det F1,
  !> which is S = C : E_m (+ the initial stress) exactly, as a function of the start state and
  !> the increment. E_m(F, a) = E(F - a I) is CalculiX's mechanical strain (calcmechstrain.f:
  !> the thermal stretch taken off the deformation gradient), a the total thermal strain of
  !> the point from its initial temperature (material%thermal_strain_increment, secant);
  !> without temperatures E_m = E. `temperatures(q, :)`: the point's initial, start and end
  !> temperatures. The point's strain becomes the Green-Lagrange strain E(F1) (total, the
  !> thermal part included: CalculiX's E).
  subroutine update_svk(this, e, xe, du_e, fields, err, temperatures)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: xe(:, :), du_e(:, :)
    type(element_state_t), intent(inout) :: fields
    type(error_t), allocatable, intent(out) :: err
    real(dp), intent(in), optional :: temperatures(:, :)
    real(dp) :: f0(3, 3, MAX_POINTS), f1(3, 3, MAX_POINTS), s(6), strain_end(6), dstrain(6)
    real(dp) :: a0, a1
    integer :: q, n
    associate (kind => this%catalogue%kinds(this%kind(e)), &
               material => this%materials(this%material(e))%m)
      n = kind%n_nodes
      call deformation_gradients(this, e, xe(:, 1:n), f0, err)
      if (allocated(err)) return
      call deformation_gradients(this, e, xe(:, 1:n) + du_e(:, 1:n), f1, err)
      if (allocated(err)) return
      do q = 1, kind%n_points
        s = pk2_from_cauchy(f0(:, :, q), fields%stress(:, q, e))
        strain_end = green_lagrange_strain(f1(:, :, q))
        if (present(temperatures)) then
          associate (t => temperatures(q, :))
            a0 = first(material%thermal_strain_increment(t(1), t(2)))
            a1 = first(material%thermal_strain_increment(t(1), t(3)))
            dstrain = mechanical_strain(f1(:, :, q), a1) - mechanical_strain(f0(:, :, q), a0)
            s = material%rescale_stress(s, t(2), t(3)) + &
                matmul(reference_stiffness(this, e, q, t(3)), dstrain)
          end associate
        else
          dstrain = strain_end - green_lagrange_strain(f0(:, :, q))
          s = s + matmul(reference_stiffness(this, e, q), dstrain)
        end if
        fields%stress(:, q, e) = cauchy_from_pk2(f1(:, :, q), s)
        fields%strain(:, q, e) = strain_end
      end do
    end associate
  end subroutine update_svk

  !> CalculiX's mechanical strain under NLGEOM (calcmechstrain.f): the Green-Lagrange strain of
  !> F - a I, a the isotropic thermal strain.
  pure function mechanical_strain(f, a) result(strain)
    real(dp), intent(in) :: f(3, 3), a
    real(dp) :: strain(6)
    integer :: i
    real(dp) :: fm(3, 3)
    fm = f
    do i = 1, 3
      fm(i, i) = fm(i, i) - a
    end do
    strain = green_lagrange_strain(fm)
  end function mechanical_strain

  pure real(dp) function first(v)
    real(dp), intent(in) :: v(:)
    first = v(1)
  end function first

  !> The St Venant-Kirchhoff tangents c(:, :, q) of element e (svk_jaumann_tangent) for its
  !> nodes at xe and its points' Cauchy stresses, with the stiffness at the points' temperatures
  !> when the nodal `temperature` is given.
  subroutine svk_tangents(this, e, xe, stress, c, err, temperature)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: xe(:, :), stress(:, :)
    real(dp), intent(out) :: c(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp), intent(in), optional :: temperature(:)
    real(dp) :: f(3, 3, MAX_POINTS), tq(MAX_POINTS)
    integer :: q
    call deformation_gradients(this, e, xe, f, err)
    if (allocated(err)) return
    if (present(temperature)) call point_temperatures(this, e, temperature, tq)
    do q = 1, this%catalogue%kinds(this%kind(e))%n_points
      if (present(temperature)) then
        c(:, :, q) = svk_jaumann_tangent(f(:, :, q), stress(:, q), reference_stiffness(this, e, q, tq(q)))
      else
        c(:, :, q) = svk_jaumann_tangent(f(:, :, q), stress(:, q), reference_stiffness(this, e, q))
      end if
    end do
  end subroutine svk_tangents

  !> C3D8R element e: its generalised hourglass forces Q go from the start to the end of the
  !> increment: Q_{n+1} = R Q_n + E a du Gamma, with Gamma and a on the mid-increment
  !> configuration `geo` and, with NLGEOM, R the Hughes-Winget rotation of the element's spin
  !> increment (Q's first index is spatial; Flanagan & Belytschko 1981 rotate their hourglass
  !> forces with the element). Without NLGEOM the sum of the increments is CalculiX's
  !> E a u Gamma (hgforce.f) exactly; with NLGEOM CalculiX recomputes E a u_total Gamma on
  !> the current configuration, which is not objective (doc/theory.md 1.5).
  subroutine update_hourglass(this, e, geo, du_e, spin, nlgeom, fields)
    type(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: du_e(:, :), spin(3, 3)
    logical, intent(in) :: nlgeom
    type(element_state_t), intent(inout) :: fields
    real(dp) :: q(3, 4)
    integer :: first
    first = hourglass_first(this, e)
    q = reshape(fields%material_state(first:first + HOURGLASS_STATE - 1, 1, e), [3, 4])
    if (nlgeom) q = matmul(spin_rotation(spin), q)
    associate (kind => this%catalogue%kinds(this%kind(e)))
      q = q + element_hourglass_increment(kind, geo, du_e, youngs_modulus(this%materials(this%material(e))%m))
    end associate
    fields%material_state(first:first + HOURGLASS_STATE - 1, 1, e) = reshape(q, [HOURGLASS_STATE])
  end subroutine update_hourglass

  !> C3D8I element e: the update of its points (`update_point`) for nodal increments du_e from
  !> start coordinates xe (the reference ones without NLGEOM), with mode increments that make
  !> the modes' generalised forces vanish on the end configuration (doc/theory.md 1.5):
  !> predicted from the condensed tangent at the start state, then corrected by Newton
  !> iterations with the points' consistent tangents (the material part on the end
  !> configuration; one correction at most for an elastic increment without NLGEOM). The
  !> result depends only on the start state and du_e (an increment recomputed from its start
  !> gives the same stresses), so the modes are no state of their own.
  subroutine update_modes(this, e, xe, du_e, fields, nlgeom, err)
    type(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    real(dp), intent(in) :: xe(:, :), du_e(:, :)
    type(element_state_t), intent(inout) :: fields
    logical, intent(in) :: nlgeom
    type(error_t), allocatable, intent(out) :: err
    type(element_geometry_t) :: geo_mid, geo_end
    real(dp) :: strain(6, MAX_POINTS), spin(3, 3, MAX_POINTS), equivalent(MAX_POINTS)
    real(dp) :: angle(MAX_POINTS), c(6, 6, MAX_POINTS), stress(6, MAX_POINTS)
    real(dp) :: total_strain(6, MAX_POINTS), state(size(fields%material_state, 1), MAX_POINTS)
    real(dp) :: modes(3, MAX_MODES), correction(3, MAX_MODES), residual(3 * MAX_MODES)
    real(dp) :: scale
    integer :: q, np, iteration
    logical :: ok_mid, ok_end, ok
    associate (kind => this%catalogue%kinds(this%kind(e)), &
               material => this%materials(this%material(e))%m)
      np = kind%n_points
      if (nlgeom) then
        call element_geometry(kind, xe + 0.5_dp * du_e, geo_mid, ok_mid)
        call element_geometry(kind, xe + du_e, geo_end, ok_end)
      else
        call element_geometry(kind, xe, geo_mid, ok_mid)
        geo_end = geo_mid
        ok_end = ok_mid
      end if
      if (.not. (ok_mid .and. ok_end)) then
        call inverted_element_error(this, e, err)
        return
      end if
      do q = 1, np
        c(:, :, q) = material%tangent(fields%stress(:, q, e), fields%material_state(:, q, e))
      end do
      residual = 0.0_dp
      call element_mode_correction(kind, geo_end, fields%stress(:, :, e), c(:, :, 1:np), &
                                   this%bbar(e), .false., du_e, residual, modes, ok)
      do iteration = 0, MAX_MODE_ITERATIONS
        call element_strain_increments(kind, geo_mid, du_e, this%bbar(e), strain, spin, &
                                       equivalent, angle, modes)
        stress(:, 1:np) = fields%stress(:, 1:np, e)
        total_strain(:, 1:np) = fields%strain(:, 1:np, e)
        state(:, 1:np) = fields%material_state(:, 1:np, e)
        do q = 1, np
          call update_point(material, nlgeom, strain(:, q), spin(:, :, q), stress(:, q), &
                            total_strain(:, q), state(:, q), c(:, :, q))
        end do
        call element_mode_residual(kind, geo_end, stress(:, 1:np), this%bbar(e), residual)
        scale = 0.0_dp
        do q = 1, np
          scale = scale + maxval(abs(stress(:, q))) * geo_end%dv(q) * &
                  maxval(abs(geo_end%grad(:, kind%n_nodes + 1:geo_end%n_columns, q)))
        end do
        if (maxval(abs(residual(1:3 * kind%n_modes))) <= MODE_TOLERANCE * scale) exit
        if (iteration == MAX_MODE_ITERATIONS) exit
        call element_mode_correction(kind, geo_end, stress(:, 1:np), c(:, :, 1:np), this%bbar(e), &
                                     .false., 0.0_dp * du_e, residual, correction, ok)
        if (.not. ok) exit
        modes(:, 1:kind%n_modes) = modes(:, 1:kind%n_modes) + correction(:, 1:kind%n_modes)
      end do
      fields%stress(:, 1:np, e) = stress(:, 1:np)
      fields%strain(:, 1:np, e) = total_strain(:, 1:np)
      fields%material_state(:, 1:np, e) = state(:, 1:np)
    end associate
  end subroutine update_modes

  !> C3D8I element e: the mode increments that go with nodal increments du_e in the condensed
  !> tangent on `geo` (the trial increments of the R-minimum events); zero for other kinds.
  subroutine trial_modes(this, e, geo, fields, du_e, nlgeom, modes)
    type(element_loops_t), intent(in) :: this
    integer, intent(in) :: e
    type(element_geometry_t), intent(in) :: geo
    type(element_state_t), intent(in) :: fields
    real(dp), intent(in) :: du_e(:, :)
    logical, intent(in) :: nlgeom
    real(dp), intent(out) :: modes(:, :)
    real(dp) :: c(6, 6, MAX_POINTS), residual(3 * MAX_MODES)
    integer :: q
    logical :: ok
    modes = 0.0_dp
    associate (kind => this%catalogue%kinds(this%kind(e)), &
               material => this%materials(this%material(e))%m)
      if (kind%n_modes == 0) return
      do q = 1, kind%n_points
        c(:, :, q) = material%tangent(fields%stress(:, q, e), fields%material_state(:, q, e))
      end do
      residual = 0.0_dp
      call element_mode_correction(kind, geo, fields%stress(:, :, e), c(:, :, 1:kind%n_points), &
                                   this%bbar(e), nlgeom, du_e, residual, modes, ok)
    end associate
  end subroutine trial_modes

  !> Young's modulus of a material's elastic part, E = 9 K G / (3 K + G) (the modulus of
  !> CalculiX's hourglass stiffness, elas(1), for its isotropic materials).
  pure real(dp) function youngs_modulus(material) result(youngs)
    class(material_t), intent(in) :: material
    real(dp) :: k, g
    k = material%bulk_modulus()
    g = material%shear_modulus()
    youngs = 9.0_dp * k * g / (3.0_dp * k + g)
  end function youngs_modulus

  !> The objective update of one integration point (doc/theory.md, 1.4): strain increment
  !> and spin increment on the mid-increment configuration; `stress`, `strain` (accumulated,
  !> output only) and the material's `state` go from the start to the end of the increment and
  !> depend on nothing else, so an increment recomputed from its saved start gives the same
  !> result.
  !> * A material without internal variables: the midpoint Hughes-Winget update (1f), half of
  !>   the constitutive increment before the rotation and half after, second order in the
  !>   increment and exact under rigid rotation.
  !> * A material with internal variables (a yield surface): the stress and the tensor-valued
  !>   variables are rotated first, Q sigma Q^T, and the material's update (return mapping)
  !>   then works in the rotated frame (1g; Simo & Hughes 1998, section 8.3), so that the
  !>   stress it returns lies on the yield surface; the midpoint split would move the returned
  !>   stress off the surface by the rotation of half an increment (second order).
  !> Without NLGEOM there is no rotation: sigma + the material's increment.
  !> With `tangent`, also the material's consistent tangent d(sigma)/d(strain_increment) of
  !> this update (in the rotated frame), for equilibrium iterations.
  !> With `axes` (an anisotropic elastic material in an element with an *ORIENTATION, small
  !> strains: the model checks refuse it with NLGEOM or plasticity), the material takes the
  !> strain increment in those axes and its stress increment is turned back to global ones
  !> (doc/theory.md 2.9): sigma + T C_local T^T delta_epsilon.
  pure subroutine update_point(material, nlgeom, strain_increment, spin, stress, strain, state, &
                               tangent, axes)
    class(material_t), intent(in) :: material
    logical, intent(in) :: nlgeom
    real(dp), intent(in) :: strain_increment(6), spin(3, 3)
    real(dp), intent(inout) :: stress(6), strain(6), state(:)
    real(dp), intent(out), optional :: tangent(6, 6)
    real(dp), intent(in), optional :: axes(3, 3)
    real(dp) :: updated(6), increment(6), q(3, 3)
    if (present(axes)) then
      increment = 0.0_dp
      call material%update(increment, strain_to_local(strain_increment, axes), state, tangent)
      stress = stress + stress_to_global(increment, axes)
      strain = strain + strain_increment
      if (present(tangent)) tangent = rotate_stiffness(tangent, axes)
    else if (nlgeom .and. material%n_state() > 0) then
      q = spin_rotation(spin)
      stress = rotate_stress_like(stress, q)
      call material%rotate_state(state, q)
      call material%update(stress, strain_increment, state, tangent)
      strain = rotate_strain_like(strain, q) + strain_increment
    else if (nlgeom) then
      updated = stress
      call material%update(updated, strain_increment, state, tangent)
      increment = updated - stress
      stress = hex8_rotate_stress(stress + 0.5_dp * increment, spin) + 0.5_dp * increment
      strain = rotate_strain(strain + 0.5_dp * strain_increment, spin) + 0.5_dp * strain_increment
    else
      call material%update(stress, strain_increment, state, tangent)
      strain = strain + strain_increment
    end if
  end subroutine update_point

  !> The update of one integration point whose temperature goes from t_start to t_end over
  !> the increment (doc/theory.md 2.5): the rate form sigma^J = C(T) : (D - D_th) +
  !> dC/dT T' : C^-1 : sigma, D_th = d(alpha(T) (T - T_Z))/dt I. The thermal strain increment
  !> (material%thermal_strain_increment, CalculiX's secant form) is taken off the strain
  !> increment before the material's update (`update_point`, which rotates as without
  !> temperature); temperature-dependent elastic constants first rescale the stress to the
  !> end temperature with the elastic strain held (material%rescale_stress: isotropic, so it
  !> commutes with the rotation) and update with the constants at t_end. The accumulated
  !> strain is the total one (mechanical + thermal), CalculiX's E.
  !> With `axes`, the update in local axes of update_point (the isotropic thermal strain is
  !> the same in any axes).
  subroutine update_point_thermal(material, nlgeom, strain_increment, spin, stress, strain, &
                                  state, t_start, t_end, axes)
    class(material_t), intent(in) :: material
    logical, intent(in) :: nlgeom
    real(dp), intent(in) :: strain_increment(6), spin(3, 3), t_start, t_end
    real(dp), intent(inout) :: stress(6), strain(6), state(:)
    real(dp), intent(in), optional :: axes(3, 3)
    real(dp) :: thermal(6)
    class(material_t), allocatable :: at_end
    thermal = material%thermal_strain_increment(t_start, t_end)
    if (material%thermal%elastic_varies()) then
      stress = material%rescale_stress(stress, t_start, t_end)
      call material%at_temperature(t_end, at_end)
      call update_point(at_end, nlgeom, strain_increment - thermal, spin, stress, strain, state, &
                        axes=axes)
    else
      call update_point(material, nlgeom, strain_increment - thermal, spin, stress, strain, state, &
                        axes=axes)
    end if
    strain = strain + thermal
  end subroutine update_point_thermal

  !> The load of the temperature change from `temperature_start` to `temperature_end` (nodal)
  !> at fixed displacements, f_th = - sum_e int B^T dsigma_th dv (3 n_nodes, this process's
  !> elements), dsigma_th the stress change of every point under the thermal strain alone
  !> (update_point_thermal with a zero strain increment: - C dalpha_th for an elastic
  !> point), on the configuration of `nlgeom`. Added to the load increment of a trial
  !> solution, it makes the R-minimum increment scale the thermal load with the others.
  subroutine loops_thermal_forces(this, x, fields, nlgeom, temperature_start, temperature_end, &
                                  f_th, err)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :), temperature_start(:), temperature_end(:)
    type(element_state_t), intent(in) :: fields
    logical, intent(in) :: nlgeom
    real(dp), intent(out) :: f_th(:)
    type(error_t), allocatable, intent(out) :: err
    type(element_geometry_t) :: geo
    real(dp) :: xe(3, MAX_NODES), f(3 * MAX_NODES), dsigma(6, MAX_POINTS), stress(6), strain(6)
    real(dp) :: t_start(MAX_POINTS), t_end(MAX_POINTS)
    real(dp), allocatable :: state(:)
    real(dp), parameter :: NO_SPIN(3, 3) = 0.0_dp, NO_STRAIN(6) = 0.0_dp
    integer :: e, q, a, node, i, n
    logical :: ok
    f_th = 0.0_dp
    do i = 1, size(this%mine)
      e = this%mine(i)
      associate (kind => this%catalogue%kinds(this%kind(e)), &
                 material => this%materials(this%material(e))%m)
        if (.not. material%thermal%is_active()) cycle
        n = kind%n_nodes
        call point_temperatures(this, e, temperature_start, t_start)
        call point_temperatures(this, e, temperature_end, t_end)
        do q = 1, kind%n_points
          stress = fields%stress(:, q, e)
          strain = 0.0_dp
          state = fields%material_state(:, q, e)
          if (works_in_local_axes(this, e)) then
            call update_point_thermal(material, .false., NO_STRAIN, NO_SPIN, stress, strain, &
              state, t_start(q), t_end(q), this%axes(:, :, q, this%axes_index(e)))
          else
            call update_point_thermal(material, .false., NO_STRAIN, NO_SPIN, stress, strain, &
                                      state, t_start(q), t_end(q))
          end if
          dsigma(:, q) = stress - fields%stress(:, q, e)
        end do
        if (all(dsigma(:, 1:kind%n_points) == 0.0_dp)) cycle
        call element_x(this, e, x, nlgeom, xe)
        call element_geometry(kind, xe(:, 1:n), geo, ok)
        if (.not. ok) then
          call inverted_element_error(this, e, err)
          return
        end if
        call element_internal_force(kind, geo, dsigma(:, 1:kind%n_points), this%bbar(e), f(1:3 * n))
        do a = 1, n
          node = this%nodes(a, e)
          f_th(3 * node - 2:3 * node) = f_th(3 * node - 2:3 * node) - f(3 * a - 2:3 * a)
        end do
      end associate
    end do
  end subroutine loops_thermal_forces

  !> Rotate an engineering-shear strain like a stress (tensor shear in between).
  pure function rotate_strain(strain, spin) result(rotated)
    real(dp), intent(in) :: strain(6), spin(3, 3)
    real(dp) :: rotated(6)
    real(dp) :: tensor(6)
    tensor = strain
    tensor(4:6) = 0.5_dp * tensor(4:6)
    rotated = hex8_rotate_stress(tensor, spin)
    rotated(4:6) = 2.0_dp * rotated(4:6)
  end function rotate_strain

  !> Every element of this process must keep a positive Jacobian on the mid-increment and the
  !> end configurations of the increment du about to be applied to current coordinates x.
  subroutine loops_check_geometry(this, x, du, err)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :), du(:)
    type(error_t), allocatable, intent(out) :: err
    type(element_geometry_t) :: geo
    real(dp) :: du_e(3, MAX_NODES), xe(3, MAX_NODES)
    integer :: e, i, n
    logical :: ok_mid, ok_end
    do i = 1, size(this%mine)
      e = this%mine(i)
      associate (kind => this%catalogue%kinds(this%kind(e)))
        n = kind%n_nodes
        call element_increment(this, e, du, du_e)
        call element_x(this, e, x, .true., xe)
        call element_geometry(kind, xe(:, 1:n) + 0.5_dp * du_e(:, 1:n), geo, ok_mid)
        call element_geometry(kind, xe(:, 1:n) + du_e(:, 1:n), geo, ok_end)
        if (.not. (ok_mid .and. ok_end)) then
          call inverted_element_error(this, e, err)
          return
        end if
      end associate
    end do
  end subroutine loops_check_geometry

  !> Offer the element events and limits of the trial increment du_residual + r du_load to
  !> the collector: with NLGEOM the strain and rotation limits of du_load; with materials that
  !> have internal variables the yield and plastic-strain-limit fractions of every point
  !> (material%point_events). Gradients on the configuration of `nlgeom`.
  subroutine loops_collect_events(this, x, du_load, du_residual, fields, nlgeom, limits, &
                                  collector, err, temperature_start, temperature_end)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :), du_load(:), du_residual(:)
    type(element_state_t), intent(in) :: fields
    logical, intent(in) :: nlgeom
    type(event_limits_t), intent(in) :: limits
    type(rmin_collector_t), intent(inout) :: collector
    type(error_t), allocatable, intent(out) :: err
    !> Nodal temperatures at the start and the end of the trial increment: the thermal
    !> strain of the trial is part of its load (scaled by r), taken off the strain of du_load.
    real(dp), intent(in), optional :: temperature_start(:), temperature_end(:)
    type(element_geometry_t) :: geo
    real(dp) :: strain(6, MAX_POINTS), spin(3, 3, MAX_POINTS), equivalent(MAX_POINTS)
    real(dp) :: angle(MAX_POINTS), du_e(3, MAX_NODES), strain_fixed(6, MAX_POINTS)
    real(dp) :: xe(3, MAX_NODES), r_yield, r_plastic, modes(3, MAX_MODES)
    real(dp) :: t_start(MAX_POINTS), t_end(MAX_POINTS)
    integer :: e, q, i, n, np
    logical :: ok, states
    states = this%has_states()
    if (.not. (nlgeom .or. states)) return
    do i = 1, size(this%mine)
      e = this%mine(i)
      associate (kind => this%catalogue%kinds(this%kind(e)))
        n = kind%n_nodes
        np = kind%n_points
        call element_x(this, e, x, nlgeom, xe)
        call element_geometry(kind, xe(:, 1:n), geo, ok)
        if (.not. ok) then
          call inverted_element_error(this, e, err)
          return
        end if
        call element_increment(this, e, du_load, du_e)
        call trial_modes(this, e, geo, fields, du_e(:, 1:n), nlgeom, modes)
        call element_strain_increments(kind, geo, du_e(:, 1:n), this%bbar(e), strain, spin, &
                                       equivalent, angle, modes)
        if (nlgeom) then
          if (maxval(equivalent(1:np)) > 0.0_dp) call collector%offer(limits%strain / &
            maxval(equivalent(1:np)), EVENT_STRAIN_LIMIT, e, maxloc(equivalent(1:np), 1))
          if (maxval(angle(1:np)) > 0.0_dp) call collector%offer(limits%rotation / &
            maxval(angle(1:np)), EVENT_ROTATION_LIMIT, e, maxloc(angle(1:np), 1))
        end if
        if (.not. states) cycle
        call element_increment(this, e, du_residual, du_e)
        call trial_modes(this, e, geo, fields, du_e(:, 1:n), nlgeom, modes)
        call element_strain_increments(kind, geo, du_e(:, 1:n), this%bbar(e), strain_fixed, &
                                       spin, equivalent, angle, modes)
        associate (material => this%materials(this%material(e))%m)
          if (present(temperature_start) .and. present(temperature_end)) then
            if (material%thermal%has_expansion()) then
              call point_temperatures(this, e, temperature_start, t_start)
              call point_temperatures(this, e, temperature_end, t_end)
              do q = 1, np
                strain(:, q) = strain(:, q) - material%thermal_strain_increment(t_start(q), t_end(q))
              end do
            end if
          end if
          do q = 1, np
            call material%point_events(fields%stress(:, q, e), fields%material_state(:, q, e), &
                                       strain_fixed(:, q), strain(:, q), limits%plastic_strain, &
                                       r_yield, r_plastic)
            call collector%offer(r_yield, EVENT_YIELD, e, q)
            call collector%offer(r_plastic, EVENT_PLASTIC_STRAIN_LIMIT, e, q)
          end do
        end associate
      end associate
    end do
  end subroutine loops_collect_events

  !> Elastic unloading as a state switch (doc/theory.md 6.3; Yamada, Yoshimura & Sakurai
  !> 1968): every point of this process's elements on its yield surface that the trial
  !> increment du moves inwards (material%unloads, strain increment on the start
  !> configuration) is marked in `unloading(q, e)`, to take the elastic tangent for the rest
  !> of the increment; returns the number of newly marked points.
  function loops_count_unloading(this, x, du, fields, nlgeom, unloading) result(n_new)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :), du(:)
    type(element_state_t), intent(in) :: fields
    logical, intent(in) :: nlgeom
    logical, intent(inout) :: unloading(:, :)
    real(dp) :: n_new
    type(element_geometry_t) :: geo
    real(dp) :: strain(6, MAX_POINTS), spin(3, 3, MAX_POINTS), equivalent(MAX_POINTS)
    real(dp) :: angle(MAX_POINTS), du_e(3, MAX_NODES), xe(3, MAX_NODES), modes(3, MAX_MODES)
    integer :: e, q, i, n
    logical :: ok
    n_new = 0.0_dp
    do i = 1, size(this%mine)
      e = this%mine(i)
      associate (kind => this%catalogue%kinds(this%kind(e)))
        n = kind%n_nodes
        call element_x(this, e, x, nlgeom, xe)
        call element_geometry(kind, xe(:, 1:n), geo, ok)
        if (.not. ok) cycle
        call element_increment(this, e, du, du_e)
        call trial_modes(this, e, geo, fields, du_e(:, 1:n), nlgeom, modes)
        call element_strain_increments(kind, geo, du_e(:, 1:n), this%bbar(e), strain, spin, &
                                       equivalent, angle, modes)
        associate (material => this%materials(this%material(e))%m)
          do q = 1, kind%n_points
            if (unloading(q, e)) cycle
            if (.not. material%unloads(fields%stress(:, q, e), fields%material_state(:, q, e), &
                                       strain(:, q))) cycle
            unloading(q, e) = .true.
            n_new = n_new + 1.0_dp
          end do
        end associate
      end associate
    end do
  end function loops_count_unloading

  !> The most distorted of this process's elements on current coordinates x: `element` (0:
  !> none) and the ratio of its smallest to its largest det J w over its points (0 if
  !> inverted).
  subroutine loops_most_distorted(this, x, element, ratio)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :)
    integer, intent(out) :: element
    real(dp), intent(out) :: ratio
    type(element_geometry_t) :: geo
    real(dp) :: xe(3, MAX_NODES), this_ratio, dv(MAX_POINTS)
    integer :: i, e, n, np
    logical :: ok
    ratio = huge(1.0_dp)
    element = 0
    do i = 1, size(this%mine)
      e = this%mine(i)
      associate (kind => this%catalogue%kinds(this%kind(e)))
        n = kind%n_nodes
        np = kind%n_points
        call element_x(this, e, x, .true., xe)
        call element_geometry(kind, xe(:, 1:n), geo, ok)
        this_ratio = 0.0_dp
        if (ok) then
          dv(1:np) = element_point_volumes(kind, geo)
          this_ratio = minval(dv(1:np)) / maxval(dv(1:np))
        end if
        if (this_ratio < ratio) then
          ratio = this_ratio
          element = e
        end if
      end associate
    end do
  end subroutine loops_most_distorted

  !> Nodal values (n_components, n_nodes): the integration-point values values(:, q, e) of
  !> every element extrapolated to its nodes (element_extrapolate), averaged over the
  !> elements sharing a node.
  function loops_nodal_average(this, values, n_nodes) result(nodal)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: values(:, :, :)
    integer, intent(in) :: n_nodes
    real(dp), allocatable :: nodal(:, :)
    real(dp), allocatable :: weight(:)
    real(dp) :: at_nodes(size(values, 1), MAX_NODES)
    integer :: e, a, node
    allocate (nodal(size(values, 1), n_nodes), weight(n_nodes))
    nodal = 0.0_dp
    weight = 0.0_dp
    do e = 1, this%n_elements
      associate (kind => this%catalogue%kinds(this%kind(e)))
        call element_extrapolate(kind, values(:, :, e), at_nodes)
        do a = 1, kind%n_nodes
          node = this%nodes(a, e)
          nodal(:, node) = nodal(:, node) + at_nodes(:, a)
          weight(node) = weight(node) + 1.0_dp
        end do
      end associate
    end do
    do node = 1, n_nodes
      if (weight(node) > 0.0_dp) nodal(:, node) = nodal(:, node) / weight(node)
    end do
  end function loops_nodal_average

  !> The reference volume each integration point of every element represents,
  !> volume(q, e) = det J w_q (0 beyond an element's points).
  function loops_point_volumes(this) result(volume)
    class(element_loops_t), intent(in) :: this
    real(dp), allocatable :: volume(:, :)
    type(element_geometry_t) :: geo
    real(dp) :: xe(3, MAX_NODES)
    integer :: e
    logical :: ok
    allocate (volume(this%max_points, this%n_elements))
    volume = 0.0_dp
    do e = 1, this%n_elements
      associate (kind => this%catalogue%kinds(this%kind(e)))
        call element_x(this, e, this%x_reference, .false., xe)
        call element_geometry(kind, xe(:, 1:kind%n_nodes), geo, ok)
        volume(1:kind%n_points, e) = element_point_volumes(kind, geo)
      end associate
    end do
  end function loops_point_volumes

  !> The stress work-conjugate to each point's strain field, for the energy density 1/2 S:E of
  !> *EL PRINT, ENER: the second Piola-Kirchhoff stress S = det F F^-1 sigma F^-T of the points
  !> that take St Venant-Kirchhoff under `nlgeom` (their strain is Green-Lagrange, the energy
  !> per reference volume, CalculiX's ENER), the Cauchy stress elsewhere; x the current
  !> coordinates. Beyond an element's points, 0.
  function loops_energy_stresses(this, x, stress, nlgeom, err) result(conjugate)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :), stress(:, :, :)
    logical, intent(in) :: nlgeom
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: conjugate(:, :, :)
    real(dp) :: f(3, 3, MAX_POINTS), xe(3, MAX_NODES)
    integer :: e, q, n
    conjugate = stress
    do e = 1, this%n_elements
      if (.not. takes_svk(this, e, nlgeom)) cycle
      n = this%catalogue%kinds(this%kind(e))%n_nodes
      call element_x(this, e, x, nlgeom, xe)
      call deformation_gradients(this, e, xe(:, 1:n), f, err)
      if (allocated(err)) return
      do q = 1, this%catalogue%kinds(this%kind(e))%n_points
        conjugate(:, q, e) = pk2_from_cauchy(f(:, :, q), stress(:, q, e))
      end do
    end do
  end function loops_energy_stresses

  !> The thermal strain of every integration point (Voigt, engineering shear) between the
  !> nodal temperatures `temperature_zero` (stress free, *INITIAL CONDITIONS) and
  !> `temperature`: CalculiX's secant form alpha(T) (T - T_Z) - alpha(T_0) (T_0 - T_Z) on the
  !> normal components (material%thermal_strain_increment), 0 without *EXPANSION and beyond
  !> an element's points. The mechanical strain is the total strain less this.
  function loops_thermal_strains(this, temperature_zero, temperature) result(strain)
    class(element_loops_t), intent(in) :: this
    real(dp), intent(in) :: temperature_zero(:), temperature(:)
    real(dp), allocatable :: strain(:, :, :)
    real(dp) :: t_zero(MAX_POINTS), t_now(MAX_POINTS)
    integer :: e, q
    allocate (strain(6, this%max_points, this%n_elements))
    strain = 0.0_dp
    do e = 1, this%n_elements
      associate (material => this%materials(this%material(e))%m)
        if (.not. material%thermal%has_expansion()) cycle
        call point_temperatures(this, e, temperature_zero, t_zero)
        call point_temperatures(this, e, temperature, t_now)
        do q = 1, this%n_points(e)
          strain(:, q, e) = material%thermal_strain_increment(t_zero(q), t_now(q))
        end do
      end associate
    end do
  end function loops_thermal_strains

  !> The plastic state of every integration point, as each element's material reports it:
  !> equivalent plastic strain peeq(q, e), plastic strain(6, q, e) (Voigt, engineering shear)
  !> and back stress(6, q, e); zeros for materials without plasticity and beyond an
  !> element's points.
  subroutine loops_plastic_fields(this, fields, peeq, plastic_strain, back_stress)
    class(element_loops_t), intent(in) :: this
    type(element_state_t), intent(in) :: fields
    real(dp), allocatable, intent(out) :: peeq(:, :), plastic_strain(:, :, :), back_stress(:, :, :)
    integer :: e, q
    allocate (peeq(this%max_points, this%n_elements), &
              plastic_strain(6, this%max_points, this%n_elements), &
              back_stress(6, this%max_points, this%n_elements))
    peeq = 0.0_dp
    plastic_strain = 0.0_dp
    back_stress = 0.0_dp
    do e = 1, this%n_elements
      associate (material => this%materials(this%material(e))%m)
        do q = 1, this%n_points(e)
          peeq(q, e) = material%equivalent_plastic_strain(fields%material_state(:, q, e))
          plastic_strain(:, q, e) = material%plastic_strain(fields%material_state(:, q, e))
          back_stress(:, q, e) = material%back_stress(fields%material_state(:, q, e))
        end do
      end associate
    end do
  end subroutine loops_plastic_fields

  !> Node lists of the given elements as cliques for the sparse pattern.
  subroutine loops_cliques(this, elements, clique_ptr, clique_nodes)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: elements(:)
    integer, allocatable, intent(out) :: clique_ptr(:), clique_nodes(:)
    integer :: i, e, n
    allocate (clique_ptr(size(elements) + 1))
    clique_ptr(1) = 1
    do i = 1, size(elements)
      clique_ptr(i + 1) = clique_ptr(i) + this%catalogue%kinds(this%kind(elements(i)))%n_nodes
    end do
    allocate (clique_nodes(clique_ptr(size(elements) + 1) - 1))
    do i = 1, size(elements)
      e = elements(i)
      n = clique_ptr(i + 1) - clique_ptr(i)
      clique_nodes(clique_ptr(i):clique_ptr(i + 1) - 1) = this%nodes(1:n, e)
    end do
  end subroutine loops_cliques

  !> Global nodes of face f of element e, corners first, outward.
  pure function loops_face_nodes(this, e, f) result(nodes)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e, f
    integer, allocatable :: nodes(:)
    nodes = this%nodes(element_face_nodes(this%catalogue%kinds(this%kind(e)), f), e)
  end function loops_face_nodes

  !> Nodal forces force(3 m) of pressure p on face f of element e (its m nodes as
  !> `face_nodes` lists them) on coordinates x (current with NLGEOM, else the reference) and,
  !> optionally, the derivative dfdx of a follower pressure.
  subroutine loops_face_pressure(this, e, f, x, nlgeom, p, force, dfdx)
    class(element_loops_t), intent(in) :: this
    integer, intent(in) :: e, f
    real(dp), intent(in) :: x(:, :), p
    logical, intent(in) :: nlgeom
    real(dp), intent(out) :: force(:)
    real(dp), intent(out), optional :: dfdx(:, :)
    integer, allocatable :: nodes(:)
    nodes = this%face_nodes(e, f)
    associate (kind => this%catalogue%kinds(this%kind(e)))
      if (nlgeom) then
        call element_face_pressure(kind, f, x(:, nodes), p, force, dfdx)
      else
        call element_face_pressure(kind, f, this%x_reference(:, nodes), p, force, dfdx)
      end if
    end associate
  end subroutine loops_face_pressure

end module fcs_element_loops
