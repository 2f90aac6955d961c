!> Checks of the finished model that no single card can make: every element has a section
!> with an elastic material, no element is inverted, the deck has steps, every body is held
!> (fcs_model_supports).
module fcs_model_checks
  use fcs_tie_equations, only: ties_as_equations
  use fcs_kinds, only: dp
  use fcs_diagnostics, only: diagnostics_t, source_loc_t
  use fcs_deck_lexer, only: deck_t
  use fcs_error, only: error_t, input_error
  use fcs_element_loops, only: element_jacobian_ratio, element_volume_of, element_face_area_of
  use fcs_model, only: model_t
  use fcs_mesh, only: SURFACE_FACES
  use fcs_model_supports, only: check_supports
  use fcs_build_plasticity, only: check_plasticity, check_initial_plastic_strains
  use fcs_material_factory, only: PLASTICITY_NONE
  use fcs_hyperelastic, only: HYPER_NONE, hyper_law_text, hyper_law_keyword
  use fcs_element_kind, only: FORMULATION_HOURGLASS
  use fcs_linear_constraints, only: constraint_map_t
  use fcs_strings, only: str, parse_int
  implicit none
  private
  public :: check_model, check_mesh_file_orientation

  !> How many offending entities are named in one message.
  integer, parameter :: MAX_NAMED = 5
  !> Inverted elements of a mesh file named one by one in the error.
  integer, parameter :: MAX_INVERTED_NAMED = 5
  !> Default normal penalty E_n = DEFAULT_PENALTY_FACTOR * E / h.
  real(dp), parameter :: DEFAULT_PENALTY_FACTOR = 10.0_dp

contains

  !> Check the built model; `deck` gives the locations of the elements named in messages and
  !> of the deck's end.
  subroutine check_model(model, diag, deck)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(deck_t), intent(in) :: deck
    call model%mesh%compact()
    if (model%mesh%n_elements == 0) then
      call diag%report(deck_end(deck), 'the model has no elements (*ELEMENT or *MESH)')
      return
    end if
    call assign_sections(model, diag, deck)
    call check_materials(model, diag)
    call check_hyperelastic(model, diag)
    call check_thermal_kinds(model, diag)
    call check_anisotropy(model, diag)
    call check_jacobians(model, diag, deck)
    call resolve_contact(model, diag)
    ! Ties with triangular or quadratic faces become CalculiX's tie equations (T1).
    if (.not. diag%has_errors()) call ties_as_equations(model, diag)
    if (size(model%steps) == 0) then
      call diag%report(deck_end(deck), 'the deck ends here and defines no step (*STEP ... ' // &
                       '*END STEP): nothing to compute')
    end if
    call check_constraints(model, diag)
    if (.not. diag%has_errors()) call check_supports(model, diag)
  end subroutine check_model

  !> Anisotropic elasticity (fcs_anisotropic_elastic) is elastic only (St Venant-Kirchhoff
  !> under NLGEOM, its axes fixed in the reference configuration) and works through the
  !> standard point update: refused with plasticity (isotropic yield surfaces on an anisotropic stiffness are
  !> not CalculiX's anisotropic plasticity), and for element kinds with their own update
  !> (C3D8I's incompatible modes, C3D8R's hourglass control).
  subroutine check_anisotropy(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: k, i, e, kind
    do k = 1, size(model%materials)
      associate (m => model%materials(k))
        if (.not. m%anisotropic) cycle
        if (m%plastic%model /= PLASTICITY_NONE) call diag%report(m%elastic_loc, '*ELASTIC: ' // &
          'material ' // m%name // ': plasticity (*PLASTIC, *DRUCKER PRAGER) with anisotropic ' // &
          'elasticity is not available; use TYPE=ISO')
      end associate
    end do
    do k = 1, size(model%sections)
      associate (section => model%sections(k))
        if (section%material <= 0 .or. section%element_set <= 0) cycle
        if (.not. model%materials(section%material)%anisotropic) cycle
        associate (members => model%mesh%element_sets(section%element_set)%members)
          do i = 1, size(members)
            e = members(i)
            kind = model%mesh%element_kind(e)
            if (model%element_kinds%kinds(kind)%n_modes == 0 .and. &
                model%element_kinds%kinds(kind)%formulation /= FORMULATION_HOURGLASS) cycle
            call diag%report(section%loc, '*SOLID SECTION: material ' // &
              model%materials(section%material)%name // ' is anisotropic, which ' // &
              model%mesh%kinds(kind)%name // ' elements (element ' // &
              str(model%mesh%element_id(e)) // ') do not take; use C3D8, C3D20 or C3D20R')
            exit
          end do
        end associate
      end associate
    end do
  end subroutine check_anisotropy

  !> Hyperelastic materials (*HYPERELASTIC, *HYPERFOAM; doc/theory.md 2.11) and *DEFORMATION
  !> PLASTICITY (2.12) take their stress from the total deformation gradient under NLGEOM. As CalculiX (its readers turn
  !> "nonlinear geometric effects" on), a model with one has NLGEOM in every step; a step
  !> whose card says NLGEOM=NO is refused. Refused too: plasticity or thermal expansion with
  !> them (not CalculiX's finite-strain laws), and C3D8I elements (their incompatible modes
  !> are found anew in every increment, so the total F is not known).
  subroutine check_hyperelastic(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: k, i, e, first
    first = 0
    do k = 1, size(model%materials)
      associate (m => model%materials(k))
        if (m%hyperelastic%family == HYPER_NONE) cycle
        if (first == 0) first = k
        if (m%plastic%model /= PLASTICITY_NONE) call diag%report(m%hyperelastic_loc, '*' // &
          hyper_law_keyword(m%hyperelastic%family) // ': material ' // m%name // ': ' // &
          'plasticity (*PLASTIC, *DRUCKER PRAGER) with a hyperelastic law (or *DEFORMATION ' // &
          'PLASTICITY) is not available')
        if (m%thermal%is_active()) call diag%report(m%hyperelastic_loc, '*' // &
          hyper_law_keyword(m%hyperelastic%family) // ': material ' // m%name // ': ' // &
          'thermal expansion (*EXPANSION) with a hyperelastic law (or *DEFORMATION ' // &
          'PLASTICITY) is not available')
      end associate
    end do
    if (first == 0) return
    do k = 1, size(model%steps)
      if (model%steps(k)%nlgeom) cycle
      if (model%steps(k)%nlgeom_refused) then
        call diag%report(model%steps(k)%loc, '*STEP: NLGEOM=NO, but material ' // &
          model%materials(first)%name // ' is ' // &
          hyper_law_text(model%materials(first)%hyperelastic%family) // ', which needs NLGEOM ' // &
          '(CalculiX turns ' // &
          'nonlinear geometric effects on for *HYPERELASTIC, *HYPERFOAM and *DEFORMATION PLASTICITY)')
      else
        model%steps(k)%nlgeom = .true.
        call diag%warn(model%steps(k)%loc, '*STEP: NLGEOM is turned on: material ' // &
          model%materials(first)%name // ' is ' // &
          hyper_law_text(model%materials(first)%hyperelastic%family) // &
          ' (as CalculiX: "nonlinear geometric ' // &
          'effects are turned on")')
      end if
    end do
    do k = 1, size(model%sections)
      associate (section => model%sections(k))
        if (section%material <= 0 .or. section%element_set <= 0) cycle
        if (model%materials(section%material)%hyperelastic%family == HYPER_NONE) cycle
        associate (members => model%mesh%element_sets(section%element_set)%members)
          do i = 1, size(members)
            e = members(i)
            if (model%element_kinds%kinds(model%mesh%element_kind(e))%n_modes == 0) cycle
            call diag%report(section%loc, '*SOLID SECTION: material ' // &
              model%materials(section%material)%name // ' is ' // &
              hyper_law_text(model%materials(section%material)%hyperelastic%family) // ', which ' // &
              model%mesh%kinds(model%mesh%element_kind(e))%name // ' elements (element ' // &
              str(model%mesh%element_id(e)) // ') do not take; use C3D8, C3D8R, C3D20 or C3D20R')
            exit
          end do
        end associate
      end associate
    end do
    call check_hyperelastic_initial_states(model, diag)
  end subroutine check_hyperelastic

  !> Initial stresses and plastic strains (*INITIAL CONDITIONS) are not in the hyperelastic
  !> stress, a function of F alone: refused on elements of hyperelastic materials.
  subroutine check_hyperelastic_initial_states(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: k, s
    if (allocated(model%initial_stresses)) then
      do k = 1, size(model%initial_stresses)
        s = model%element_section(model%initial_stresses(k)%element)
        if (s <= 0) cycle
        associate (m => model%materials(model%sections(s)%material))
          if (m%hyperelastic%family == HYPER_NONE) cycle
          call diag%report(m%hyperelastic_loc, '*' // hyper_law_keyword(m%hyperelastic%family) // &
            ': material ' // m%name // ' is ' // hyper_law_text(m%hyperelastic%family) // &
            ': initial stresses on its elements ' // &
            '(*INITIAL CONDITIONS, TYPE=STRESS, element ' // &
            str(model%mesh%element_id(model%initial_stresses(k)%element)) // ') are not available')
          exit
        end associate
      end do
    end if
    if (.not. allocated(model%initial_plastic_strains)) return
    do k = 1, size(model%initial_plastic_strains)
      s = model%element_section(model%initial_plastic_strains(k)%element)
      if (s <= 0) cycle
      associate (m => model%materials(model%sections(s)%material))
        if (m%hyperelastic%family == HYPER_NONE) cycle
        call diag%report(model%initial_plastic_strains(k)%loc, '*INITIAL CONDITIONS, TYPE=' // &
          'PLASTIC STRAIN: material ' // m%name // ' is ' // hyper_law_text(m%hyperelastic%family) // &
          ': initial plastic strains ' // &
          'are not available for it')
        exit
      end associate
    end do
  end subroutine check_hyperelastic_initial_states

  !> Thermal strain is not in the incompatible-mode update (C3D8I) yet: a section that gives
  !> elements with incompatible modes a material with expansion or temperature-dependent
  !> constants is refused.
  subroutine check_thermal_kinds(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: k, i, e
    do k = 1, size(model%sections)
      associate (section => model%sections(k))
        if (section%material <= 0 .or. section%element_set <= 0) cycle
        if (.not. model%materials(section%material)%thermal%is_active()) cycle
        associate (members => model%mesh%element_sets(section%element_set)%members)
          do i = 1, size(members)
            e = members(i)
            ! The mesh's kinds are the catalogue's, in its order (mesh_kinds).
            if (model%element_kinds%kinds(model%mesh%element_kind(e))%n_modes == 0) cycle
            call diag%report(section%loc, '*SOLID SECTION: material ' // &
              model%materials(section%material)%name // ' has thermal expansion or ' // &
              'temperature-dependent constants, which ' // &
              model%mesh%kinds(model%mesh%element_kind(e))%name // ' elements (element ' // &
              str(model%mesh%element_id(e)) // ') do not take yet; use C3D8 or C3D20R')
            exit
          end do
        end associate
      end associate
    end do
  end subroutine check_thermal_kinds

  !> The linear constraints resolve (fcs_linear_constraints: one dependent term per degree
  !> of freedom, no cycles), and no step prescribes a dependent degree of freedom by
  !> *BOUNDARY: CalculiX stops on that too ("*ERROR in cascade: the DOF corresponding to node
  !> N in direction d is detected on the dependent side of a MPC and a SPC").
  subroutine check_constraints(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(constraint_map_t) :: map
    type(error_t), allocatable :: err
    integer :: k, i, d, r
    if (size(model%equations) == 0) return
    call settle_nonlinear_constraints(model, diag)
    call check_rotation_nodes(model, diag)
    do k = 1, size(model%equations)
      if (model%equations(k)%origin == '*EQUATION') cycle
      if (.not. any(model%transformed(model%equations(k)%terms(:)%node))) cycle
      call diag%report(model%equations(k)%loc, model%equations(k)%origin // ': a node of it ' // &
        'has local axes (*TRANSFORM); fcs3d builds this constraint in global axes and does ' // &
        'not combine it with *TRANSFORM')
      return
    end do
    call map%init(model%equations, model%mesh%n_nodes, model%mesh%node_id, err)
    if (allocated(err)) then
      call diag%report_plain(err%message)
      return
    end if
    do k = 1, size(model%steps)
      do i = 1, size(model%steps(k)%boundary)
        associate (c => model%steps(k)%boundary(i))
          d = 3 * (c%node - 1) + c%dof
          if (.not. map%dependent(d)) cycle
          r = map%row_of(d)
          call diag%report(model%equations(r)%loc, model%equations(r)%origin // ': node ' // &
            str(model%mesh%node_id(c%node)) // ', direction ' // str(c%dof) // ' is the ' // &
            'dependent term of this equation and is prescribed by *BOUNDARY in step "' // &
            model%steps(k)%name // '" (CalculiX stops too: a degree of freedom cannot be on ' // &
            'the dependent side of an equation and prescribed); make another term dependent')
          return
        end associate
      end do
    end do
  end subroutine check_constraints

  !> With NLGEOM in a step the nonlinear constraints (*MPC PLANE, STRAIGHT, MEANROT, *RIGID
  !> BODY) follow the geometry (fcs_nonlinear_constraints): their equations keep their zero
  !> terms; without, they stay the linearisations built from the initial configuration. A
  !> linear equation may not name the dependent term of a nonlinear one (its elimination is
  !> exact for linear terms only).
  subroutine settle_nonlinear_constraints(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    logical, allocatable :: dependent(:)
    integer :: k, j
    if (.not. any(model%steps(:)%nlgeom)) then
      model%nonlinear_constraints = model%nonlinear_constraints(1:0)
      return
    end if
    allocate (dependent(3 * model%mesh%n_nodes))
    dependent = .false.
    do k = 1, size(model%nonlinear_constraints)
      associate (equation => model%equations(model%nonlinear_constraints(k)%equation))
        equation%nonlinear = .true.
        dependent(3 * (equation%terms(1)%node - 1) + equation%terms(1)%dof) = .true.
      end associate
    end do
    do k = 1, size(model%equations)
      if (model%equations(k)%nonlinear) cycle
      associate (terms => model%equations(k)%terms)
        do j = 2, size(terms)
          if (.not. dependent(3 * (terms(j)%node - 1) + terms(j)%dof)) cycle
          call diag%report(model%equations(k)%loc, model%equations(k)%origin // ': node ' // &
            str(model%mesh%node_id(terms(j)%node)) // ', direction ' // str(terms(j)%dof) // &
            ' is the dependent term of a nonlinear constraint (*MPC or *RIGID BODY under ' // &
            'NLGEOM); fcs3d does not chain a linear equation onto it: make another term dependent')
          return
        end do
      end associate
    end do
  end subroutine settle_nonlinear_constraints

  !> The rotation node of a *RIGID BODY holds rotations: it may not be a node of an element.
  subroutine check_rotation_nodes(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: e, k, r
    do e = 1, model%mesh%n_elements
      do k = 1, size(model%rotation_nodes)
        if (.not. any(model%mesh%element_nodes(e) == model%rotation_nodes(k))) cycle
        do r = 1, size(model%equations)
          if (.not. model%equations(r)%transmits) cycle
          if (.not. any(model%equations(r)%terms(:)%node == model%rotation_nodes(k))) cycle
          call diag%report(model%equations(r)%loc, '*RIGID BODY: ROT NODE ' // &
            str(model%mesh%node_id(model%rotation_nodes(k))) // ' is a node of element ' // &
            str(model%mesh%element_id(e)) // '; its degrees of freedom are the rotations of ' // &
            'the body: use a node in no element')
          return
        end do
      end do
    end do
  end subroutine check_rotation_nodes

  !> element_section(e) from the *SOLID SECTIONs; an element in two sections or in none is an error.
  subroutine assign_sections(model, diag, deck)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(deck_t), intent(in) :: deck
    integer :: s, j, e, n_missing
    character(len=:), allocatable :: names
    allocate (model%element_section(model%mesh%n_elements))
    model%element_section = 0
    do s = 1, size(model%sections)
      associate (members => model%mesh%element_sets(model%sections(s)%element_set)%members)
        do j = 1, size(members)
          e = members(j)
          if (model%element_section(e) /= 0) then
            call diag%report(model%sections(s)%loc, '*SOLID SECTION: element ' // &
                             str(model%mesh%element_id(e)) // ' already has a section (line ' // &
                             str(model%sections(model%element_section(e))%loc%line) // ')')
            exit
          end if
          model%element_section(e) = s
        end do
      end associate
    end do
    n_missing = count(model%element_section == 0)
    if (n_missing == 0) return
    names = ''
    j = 0
    do e = 1, model%mesh%n_elements
      if (model%element_section(e) /= 0) cycle
      j = j + 1
      if (j > MAX_NAMED) exit
      names = names // merge(', ', '  ', j > 1) // str(model%mesh%element_id(e))
    end do
    e = findloc(model%element_section, 0, 1)
    call report_at_element(diag, deck, model, e, str(n_missing) // ' element(s) have no ' // &
                           '*SOLID SECTION (elements' // names(2:) // trim(merge(', ...', '     ', &
                           n_missing > MAX_NAMED)) // ')')
  end subroutine assign_sections

  !> Report `message` at the line that defined element e (its *ELEMENT data line), or, for an
  !> element of a mesh file, with the deck's name.
  subroutine report_at_element(diag, deck, model, e, message)
    type(diagnostics_t), intent(inout) :: diag
    type(deck_t), intent(in) :: deck
    type(model_t), intent(in) :: model
    integer, intent(in) :: e
    character(len=*), intent(in) :: message
    type(source_loc_t) :: loc
    if (element_location(deck, model%mesh%element_id(e), loc)) then
      call diag%report(loc, message)
    else
      call diag%report_plain(model%deck_path // ': ' // message)
    end if
  end subroutine report_at_element

  !> The *ELEMENT data line that defines element `id`; false if there is none (the element
  !> comes from a mesh file).
  logical function element_location(deck, id, loc) result(found)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: id
    type(source_loc_t), intent(out) :: loc
    integer :: i, j, value
    logical :: ok
    found = .false.
    do i = 1, deck%n_cards
      if (deck%cards(i)%keyword /= 'ELEMENT') cycle
      do j = 1, deck%cards(i)%n_lines
        associate (line => deck%cards(i)%lines(j))
          if (size(line%fields) < 1) cycle
          call parse_int(line%fields(1)%s, value, ok)
          if (.not. ok .or. value /= id) cycle
          loc = line%loc
          found = .true.
          return
        end associate
      end do
    end do
  end function element_location

  !> The location of the deck's last card (where a missing part would have to follow).
  function deck_end(deck) result(loc)
    type(deck_t), intent(in) :: deck
    type(source_loc_t) :: loc
    if (deck%n_cards == 0) return
    associate (card => deck%cards(deck%n_cards))
      loc = card%loc
      if (card%n_lines > 0) loc = card%lines(card%n_lines)%loc
    end associate
  end function deck_end

  subroutine check_materials(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: s, k
    do s = 1, size(model%sections)
      associate (m => model%materials(model%sections(s)%material))
        if (.not. m%has_elastic) call diag%report(m%loc, '*MATERIAL: material ' // m%name // &
                                                   ' is used by a section but has no *ELASTIC')
      end associate
    end do
    do k = 1, size(model%materials)
      call check_plasticity(model%materials(k), diag)
    end do
    call check_initial_plastic_strains(model, diag)
  end subroutine check_materials

  !> Penalty defaults of every contact pair: E_n = DEFAULT_PENALTY_FACTOR E / h, with E the
  !> Young's modulus and h the mean thickness (volume / face area) of the master elements
  !> (method notes 1.7: alpha E / h with alpha 10..100); E_t = E_n unless given. The tie
  !> position tolerance defaults to 5% of the mean master face size.
  subroutine resolve_contact(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: k, j, e, s
    real(dp) :: thickness, modulus, face_size, volume, area
    do k = 1, size(model%contact_pairs)
      associate (pair => model%contact_pairs(k), master => model%mesh%surfaces( &
                 model%contact_pairs(k)%master_surface))
        if (size(master%element) == 0) then
          call diag%report(pair%loc, 'contact pair ' // pair%name // ': the master surface has no faces')
          cycle
        end if
        thickness = 0.0_dp
        modulus = 0.0_dp
        face_size = 0.0_dp
        do j = 1, size(master%element)
          e = master%element(j)
          call element_volume_and_face_area(model, e, master%face(j), volume, area)
          ! A degenerate master element (reported by check_jacobians) adds nothing.
          if (area > 0.0_dp .and. volume > 0.0_dp) then
            thickness = thickness + volume / area
            face_size = face_size + sqrt(area)
          end if
          s = model%element_section(e)
          if (s > 0) modulus = modulus + model%materials(model%sections(s)%material)%youngs_modulus
        end do
        if (thickness <= 0.0_dp) then
          call diag%report(pair%loc, 'contact pair ' // pair%name // ': every element under ' // &
            'its master surface is degenerate (zero face area or volume), so no penalty ' // &
            'can be derived from it')
          cycle
        end if
        pair%master_thickness = thickness / size(master%element)
        pair%master_modulus = modulus / size(master%element)
        pair%normal_stiffness = DEFAULT_PENALTY_FACTOR * pair%master_modulus / pair%master_thickness
        pair%stick_stiffness = pair%normal_stiffness
        if (pair%interaction > 0) then
          associate (interaction => model%interactions(pair%interaction))
            if (interaction%normal_stiffness > 0.0_dp) pair%normal_stiffness = interaction%normal_stiffness
            pair%overclosure = interaction%overclosure
            pair%stick_stiffness = pair%normal_stiffness
            if (interaction%stick_stiffness > 0.0_dp) pair%stick_stiffness = interaction%stick_stiffness
          end associate
        end if
        if (pair%tied .and. pair%position_tolerance <= 0.0_dp) &
          pair%position_tolerance = 0.05_dp * face_size / size(master%element)
        if (pair%interaction > 0 .and. .not. pair%tied) then
          pair%radiation_damping = model%interactions(pair%interaction)%radiation_damping
          if (model%interactions(pair%interaction)%damping_from_material) &
            call resolve_damping(model, k, diag)
        end if
      end associate
    end do
  end subroutine resolve_contact

  !> RADIATION DAMPING=MATERIAL of contact pair k: the damping of two elastic half-spaces
  !> sliding past each other (Rice 1993; quasi-dynamic approximation), eta = 1 / (1/Z_s + 1/Z_m)
  !> with the shear impedances Z = rho c_s = sqrt(G rho), G = E / (2 (1 + nu)), of the slave
  !> and master sides (the mean over the elements of each surface; a node-based slave surface
  !> takes the master side's). For one material, eta = G / (2 c_s). Every material involved
  !> needs *DENSITY.
  subroutine resolve_damping(model, k, diag)
    type(model_t), intent(inout) :: model
    integer, intent(in) :: k
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: impedance_master, impedance_slave
    logical :: ok
    associate (pair => model%contact_pairs(k))
      call side_impedance(model%mesh%surfaces(pair%master_surface)%element, impedance_master, ok)
      if (.not. ok) return
      impedance_slave = impedance_master
      if (model%mesh%surfaces(pair%slave_surface)%kind == SURFACE_FACES) then
        call side_impedance(model%mesh%surfaces(pair%slave_surface)%element, impedance_slave, ok)
        if (.not. ok) return
      end if
      pair%radiation_damping = impedance_slave * impedance_master / (impedance_slave + impedance_master)
    end associate
  contains
    !> Mean shear impedance sqrt(G rho) of the elements; ok false (reported) when a material
    !> has no *DENSITY.
    subroutine side_impedance(elements, impedance, ok)
      integer, intent(in) :: elements(:)
      real(dp), intent(out) :: impedance
      logical, intent(out) :: ok
      integer :: j, s
      real(dp) :: shear_modulus
      impedance = 0.0_dp
      ok = .false.
      do j = 1, size(elements)
        s = model%element_section(elements(j))
        if (s == 0) return
        associate (m => model%materials(model%sections(s)%material))
          if (.not. m%has_density .or. .not. (m%density > 0.0_dp)) then
            call diag%report(model%interactions(model%contact_pairs(k)%interaction)%friction%loc, &
              '*FRICTION: RADIATION DAMPING=MATERIAL needs the density of material ' // m%name // &
              ' (*DENSITY), on a side of contact pair ' // model%contact_pairs(k)%name)
            return
          end if
          shear_modulus = m%youngs_modulus / (2.0_dp * (1.0_dp + m%poisson_ratio))
          impedance = impedance + sqrt(shear_modulus * m%density)
        end associate
      end do
      impedance = impedance / max(size(elements), 1)
      ok = impedance > 0.0_dp
    end subroutine side_impedance
  end subroutine resolve_damping

  !> Volume of element e and area of its face f (reference configuration).
  subroutine element_volume_and_face_area(model, e, f, volume, area)
    type(model_t), intent(in) :: model
    integer, intent(in) :: e, f
    real(dp), intent(out) :: volume, area
    volume = element_volume_of(model%element_kinds, model%mesh, e)
    area = element_face_area_of(model%element_kinds, model%mesh, e, f)
  end subroutine element_volume_and_face_area

  !> Inverted or degenerate elements (det J <= 0 at a Gauss point or node).
  !> Inverted or degenerate elements (det J <= 0 at a Gauss point or node), each reported at its
  !> *ELEMENT line (the first MAX_NAMED; mesh files check their own, fcs_gmsh_reader).
  subroutine check_jacobians(model, diag, deck)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(deck_t), intent(in) :: deck
    integer :: e, n_bad
    real(dp) :: ratio
    n_bad = 0
    do e = 1, model%mesh%n_elements
      ratio = element_jacobian_ratio(model%element_kinds, model%mesh, e)
      if (ratio > 0.0_dp) cycle
      n_bad = n_bad + 1
      if (n_bad > MAX_NAMED) cycle
      call report_at_element(diag, deck, model, e, 'element ' // str(model%mesh%element_id(e)) // &
        ' is inverted or degenerate (Jacobian determinant <= 0). ' // &
        numbering_hint(model%mesh%kinds(model%mesh%element_kind(e))%n_faces))
    end do
    if (n_bad > MAX_NAMED) call diag%report_plain(model%deck_path // ': ' // &
      str(n_bad - MAX_NAMED) // ' more inverted or degenerate element(s)')
  end subroutine check_jacobians

  !> How CalculiX numbers the corners of a solid with `n_faces` faces (4 tetrahedron, 5 wedge,
  !> 6 hexahedron; mid-side nodes follow the corners, edge by edge).
  pure function numbering_hint(n_faces) result(text)
    integer, intent(in) :: n_faces
    character(len=:), allocatable :: text
    select case (n_faces)
    case (4)
      text = 'Tetrahedron numbering: 1-2-3 seen from node 4 is counterclockwise'
    case (5)
      text = 'Wedge numbering: nodes 1-3 go around one triangle and 4-6 around the other in ' // &
             'the same sense, so that 1-2-3 seen from node 4 is counterclockwise'
    case default
      text = 'C3D8 numbering: nodes 1-4 go around one face and 5-8 around the opposite face ' // &
             'in the same sense, so that 1-2-3-4 seen from node 5 is counterclockwise'
    end select
    if (n_faces < 4 .or. n_faces > 6) text = text // ' (hexahedra)'
  end function numbering_hint

  !> Every element read from the mesh file `path` (elements first.. of the mesh, element k of
  !> them on line lines(k) of the file, 0 in a binary file) must have a positive Jacobian: an
  !> inverted or degenerate one is an error at its line of the file (the first
  !> MAX_INVERTED_NAMED are named).
  subroutine check_mesh_file_orientation(path, model, first, lines, err)
    character(len=*), intent(in) :: path
    type(model_t), intent(in) :: model
    integer, intent(in) :: first, lines(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: k, e, n_bad
    character(len=:), allocatable :: text
    n_bad = 0
    text = ''
    do k = 1, size(lines)
      e = first + k - 1
      if (element_jacobian_ratio(model%element_kinds, model%mesh, e) > 0.0_dp) cycle
      n_bad = n_bad + 1
      if (n_bad > MAX_INVERTED_NAMED) cycle
      if (n_bad > 1) text = text // new_line('a')
      text = text // path
      if (lines(k) > 0) text = text // ':' // str(lines(k))
      text = text // ': element ' // str(model%mesh%element_id(e)) // ' is inverted or ' // &
        'degenerate (Jacobian determinant <= 0)'
    end do
    if (n_bad == 0) return
    if (n_bad > MAX_INVERTED_NAMED) text = text // new_line('a') // path // ': ' // &
      str(n_bad - MAX_INVERTED_NAMED) // ' more inverted or degenerate element(s)'
    call input_error(err, text // new_line('a') // 'gmsh numbers the corners of tetrahedra, ' // &
      'prisms and hexahedra as CalculiX does (a tetrahedron''s nodes 1-2-3 counter-clockwise ' // &
      'seen from node 4; a hexahedron''s nodes 1-4 counter-clockwise seen from the opposite ' // &
      'face 5-8); a volume meshed with the reverse orientation gives inverted elements ' // &
      '(reverse the surface loop of the volume in the .geo file)')
  end subroutine check_mesh_file_orientation

end module fcs_model_checks
