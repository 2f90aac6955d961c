!> Model builder, material keywords: *MATERIAL, *ELASTIC, *DENSITY, *SOLID SECTION,
!> *ORIENTATION, *SOLVER.
module fcs_build_material
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t
  use fcs_deck_fields, only: param_upper, line_real
  use fcs_diagnostics, only: diagnostics_t, source_loc_t
  use fcs_builder_state, only: builder_t
  use fcs_model, only: model_t, material_def_t, section_t, orientation_def_t, FORMULATION_FULL, &
                       FORMULATION_BBAR
  use fcs_anisotropic_elastic, only: orthotropic_stiffness, engineering_stiffness, &
                                     anisotropic_stiffness, is_positive_definite, voigt_isotropic
  use fcs_orientation, only: orientation_is_valid, rotate_about_axis
  use fcs_strings, only: str
  implicit none
  private
  public :: handle_material, handle_elastic, handle_hypoelastic, handle_density, handle_solid_section, handle_solver
  public :: handle_restart, resolve_section_materials, handle_orientation, is_isotropic_elastic

contains

  !> *MATERIAL, NAME=: start a new material.
  subroutine handle_material(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(material_def_t) :: material
    integer :: k
    material%name = param_upper(card, 'NAME')
    material%loc = card%loc
    do k = 1, size(model%materials)
      if (model%materials(k)%name == material%name) then
        call diag%report(card%loc, '*MATERIAL: material ' // material%name // ' is defined twice')
        state%material = 0
        return
      end if
    end do
    model%materials = [model%materials, material]
    state%material = size(model%materials)
  end subroutine handle_material

  !> Whether *ELASTIC gives isotropic constants (TYPE=ISO, the default).
  pure logical function is_isotropic_elastic(card)
    type(card_t), intent(in) :: card
    character(len=:), allocatable :: kind
    kind = param_upper(card, 'TYPE')
    is_isotropic_elastic = kind == '' .or. kind == 'ISO' .or. kind == 'ISOTROPIC'
  end function is_isotropic_elastic

  !> *ELASTIC: E, nu of the current material (TYPE=ISO), or its anisotropic stiffness.
  subroutine handle_elastic(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    if (.not. has_current_material(card, state, diag)) return
    if (.not. is_isotropic_elastic(card)) then
      call handle_anisotropic_elastic(card, model, state, diag)
      return
    end if
    call set_isotropic_constants(card, 'ELASTIC', model, state, diag)
  end subroutine handle_elastic

  !> *HYPOELASTIC (Abaqus): E, nu of the current material, whose law under NLGEOM is the
  !> rate form (Xing, Mora & Makinouchi 2003, eq. 1) instead of *ELASTIC's St Venant-Kirchhoff.
  !> One line of two constants: Abaqus' strain-invariant and temperature columns are refused.
  subroutine handle_hypoelastic(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    if (.not. has_current_material(card, state, diag)) return
    if (card%n_lines > 1 .or. size(card%lines(1)%fields) > 2) then
      call diag%report(card%lines(1)%loc, '*HYPOELASTIC: expected one line: Young''s modulus, ' // &
                       'Poisson''s ratio (moduli depending on the strain invariants, on ' // &
                       'temperature or on field variables are not available)')
      return
    end if
    call set_isotropic_constants(card, 'HYPOELASTIC', model, state, diag)
    model%materials(state%material)%hypoelastic = .true.
  end subroutine handle_hypoelastic

  !> The isotropic constants E, nu of the one data line of `card` (*ELASTIC or *HYPOELASTIC,
  !> named by `keyword`) for the current material: E > 0, -1 < nu < 0.5, once per material.
  subroutine set_isotropic_constants(card, keyword, model, state, diag)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: keyword
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: e, nu
    if (card%n_lines /= 1 .or. size(card%lines(1)%fields) /= 2) then
      call diag%report(card%lines(1)%loc, '*' // keyword // ': expected one line: Young''s ' // &
                       'modulus, Poisson''s ratio (temperature-dependent tables are not supported)')
      return
    end if
    if (.not. line_real(card%lines(1), 1, e, 'Young''s modulus', keyword, diag)) return
    if (.not. line_real(card%lines(1), 2, nu, 'Poisson''s ratio', keyword, diag)) return
    if (e <= 0.0_dp) then
      call diag%report(card%lines(1)%loc, '*' // keyword // ': Young''s modulus must be positive')
      return
    end if
    if (nu <= -1.0_dp .or. nu >= 0.5_dp) then
      call diag%report(card%lines(1)%loc, '*' // keyword // ': Poisson''s ratio must lie in (-1, 0.5)')
      return
    end if
    associate (m => model%materials(state%material))
      if (m%has_elastic) then
        call diag%report(card%loc, '*' // keyword // ': material ' // m%name // &
                         ' already has elastic constants')
        return
      end if
      m%has_elastic = .true.
      m%youngs_modulus = e
      m%poisson_ratio = nu
      m%elastic_loc = card%loc
    end associate
  end subroutine set_isotropic_constants

  !> *ELASTIC, TYPE=ORTHO | ENGINEERING CONSTANTS | ANISO: 9 or 21 constants in CalculiX's
  !> order (fcs_anisotropic_elastic), over as many lines as the deck spreads them (CalculiX
  !> writes 8 per line), and an optional temperature after them. One set only: a table over
  !> temperature is refused. The stiffness must be positive definite.
  subroutine handle_anisotropic_elastic(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp), allocatable :: values(:)
    type(source_loc_t) :: last
    character(len=:), allocatable :: kind, names
    real(dp) :: c(6, 6)
    integer :: n
    logical :: ok
    kind = param_upper(card, 'TYPE')
    select case (kind)
    case ('ANISO', 'ANISOTROPIC')
      n = 21
      names = 'D1111, D1122, D2222, D1133, D2233, D3333, D1112, D2212, D3312, D1212, D1113, ' // &
              'D2213, D3313, D1213, D1313, D1123, D2223, D3323, D1223, D1323, D2323'
    case ('ENGINEERING CONSTANTS')
      n = 9
      names = 'E1, E2, E3, nu12, nu13, nu23, G12, G13, G23'
    case default
      n = 9
      names = 'D1111, D1122, D2222, D1133, D2233, D3333, D1212, D1313, D2323'
    end select
    call card_values(card, values, last, ok, diag)
    if (.not. ok) return
    if (size(values) < n) then
      call diag%report(last, '*ELASTIC, TYPE=' // kind // ': expected ' // str(n) // &
        ' constants (' // names // ')[, temperature]; found ' // str(size(values)))
      return
    end if
    if (size(values) > n + 1) then
      call diag%report(card%loc, '*ELASTIC, TYPE=' // kind // ': temperature-dependent ' // &
        'anisotropic constants are not available; give one set: ' // str(n) // ' constants[, ' // &
        'temperature] (found ' // str(size(values)) // ' values)')
      return
    end if
    select case (n)
    case (21)
      c = anisotropic_stiffness(values(1:21))
    case default
      if (kind == 'ENGINEERING CONSTANTS') then
        c = engineering_stiffness(values(1:9))
      else
        c = orthotropic_stiffness(values(1:9))
      end if
    end select
    if (.not. is_positive_definite(c)) then
      call diag%report(card%lines(1)%loc, '*ELASTIC, TYPE=' // kind // ': the stiffness ' // &
        'is not positive definite (the material would be unstable: some strain would release ' // &
        'energy); check the constants and their order (' // names // ')')
      return
    end if
    associate (m => model%materials(state%material))
      if (m%has_elastic) then
        call diag%report(card%loc, '*ELASTIC: material ' // m%name // ' already has elastic constants')
        return
      end if
      m%has_elastic = .true.
      m%anisotropic = .true.
      m%stiffness = c
      call voigt_isotropic(c, m%youngs_modulus, m%poisson_ratio)
      m%elastic_loc = card%loc
    end associate
  end subroutine handle_anisotropic_elastic

  !> Every given (non-empty) field of the card's data lines as a real, in order; `last` is
  !> the location of the last line.
  subroutine card_values(card, values, last, ok, diag)
    type(card_t), intent(in) :: card
    real(dp), allocatable, intent(out) :: values(:)
    type(source_loc_t), intent(out) :: last
    logical, intent(out) :: ok
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: value
    integer :: i, f
    allocate (values(0))
    ok = .true.
    last = card%loc
    do i = 1, card%n_lines
      last = card%lines(i)%loc
      do f = 1, size(card%lines(i)%fields)
        if (len(card%lines(i)%fields(f)%s) == 0) cycle
        ok = line_real(card%lines(i), f, value, 'constant', 'ELASTIC', diag)
        if (.not. ok) return
        values = [values, value]
      end do
    end do
  end subroutine card_values

  !> *ORIENTATION, NAME=, SYSTEM=: a, b (six numbers), then optionally a local axis (1..3)
  !> and an angle [degree] to turn the axes about it (rectangular systems only, as CalculiX).
  subroutine handle_orientation(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(orientation_def_t) :: item
    real(dp) :: ab(6), angle
    integer :: i, axis
    item%axes%name = param_upper(card, 'NAME')
    item%axes%cylindrical = param_upper(card, 'SYSTEM') == 'CYLINDRICAL' .or. &
                            param_upper(card, 'SYSTEM') == 'C'
    item%loc = card%loc
    do i = 1, size(model%orientations)
      if (model%orientations(i)%axes%name == item%axes%name) then
        call diag%report(card%loc, '*ORIENTATION: orientation ' // item%axes%name // &
                         ' is defined twice')
        return
      end if
    end do
    if (card%n_lines < 1 .or. card%n_lines > 2) then
      call diag%report(card%loc, '*ORIENTATION: expected a line with a1, a2, a3, b1, b2, b3 ' // &
                       'and optionally a line with a local axis (1, 2 or 3) and an angle')
      return
    end if
    do i = 1, 6
      if (.not. line_real(card%lines(1), i, ab(i), 'coordinate', 'ORIENTATION', diag)) return
    end do
    item%axes%a = ab(1:3)
    item%axes%b = ab(4:6)
    if (.not. orientation_is_valid(item%axes)) then
      if (item%axes%cylindrical) then
        call diag%report(card%lines(1)%loc, '*ORIENTATION: the two points of the axis coincide')
      else
        call diag%report(card%lines(1)%loc, '*ORIENTATION: a is zero or b is parallel to a')
      end if
      ! Kept (nothing runs on a deck with errors), so that its sections find it.
      model%orientations = [model%orientations, item]
      return
    end if
    if (card%n_lines == 2) then
      associate (line => card%lines(2))
        if (.not. line_real(line, 2, angle, 'angle', 'ORIENTATION', diag)) return
        if (.not. line_real(line, 1, ab(1), 'axis', 'ORIENTATION', diag)) return
        axis = nint(ab(1))
        if (axis < 1 .or. axis > 3 .or. ab(1) /= real(axis, dp)) then
          call diag%report(line%loc, '*ORIENTATION: the axis of the rotation must be 1, 2 or 3')
          return
        end if
        if (item%axes%cylindrical) then
          call diag%report(line%loc, '*ORIENTATION: an additional rotation is only allowed ' // &
                           'for rectangular systems (as in CalculiX)')
          model%orientations = [model%orientations, item]
          return
        end if
        item%axes = rotate_about_axis(item%axes, axis, angle)
      end associate
    end if
    model%orientations = [model%orientations, item]
  end subroutine handle_orientation

  !> *DENSITY: density of the current material.
  subroutine handle_density(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: rho, rho_line
    integer :: i, n
    if (.not. has_current_material(card, state, diag)) return
    ! One line, or a table over temperature (density, temperature) as CalculiX writes it:
    ! accepted when every line gives the same density (temperature-dependent densities are
    ! not available).
    rho = 0.0_dp
    do i = 1, card%n_lines
      n = size(card%lines(i)%fields)
      if (n > 0) then
        if (len(card%lines(i)%fields(n)%s) == 0) n = n - 1
      end if
      if (n < 1 .or. n > 2 .or. (card%n_lines > 1 .and. n /= 2)) then
        call diag%report(card%lines(i)%loc, '*DENSITY: expected the density[, temperature] ' // &
                         '(one line, or one line per temperature)')
        return
      end if
      if (.not. line_real(card%lines(i), 1, rho_line, 'density', 'DENSITY', diag)) return
      if (i > 1 .and. rho_line /= rho) then
        call diag%report(card%lines(i)%loc, '*DENSITY: a density that depends on temperature ' // &
                         'is not available (the lines give different densities)')
        return
      end if
      rho = rho_line
    end do
    if (rho <= 0.0_dp) then
      call diag%report(card%lines(1)%loc, '*DENSITY: the density must be positive')
      return
    end if
    model%materials(state%material)%has_density = .true.
    model%materials(state%material)%density = rho
  end subroutine handle_density

  logical function has_current_material(card, state, diag) result(ok)
    type(card_t), intent(in) :: card
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    ok = state%material > 0
    if (.not. ok) call diag%report(card%loc, '*' // card%keyword // ' must follow a *MATERIAL line')
  end function has_current_material

  !> *SOLID SECTION, ELSET=, MATERIAL=, FORMULATION=.
  subroutine handle_solid_section(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(section_t) :: section
    integer :: i, f
    do i = 1, card%n_lines
      do f = 1, size(card%lines(i)%fields)
        if (len(card%lines(i)%fields(f)%s) > 0) then
          call diag%warn(card%lines(i)%loc, '*SOLID SECTION: the data line (a thickness, for ' // &
                         'plane elements) is ignored for solid elements, as CalculiX ignores it')
          exit
        end if
      end do
    end do
    section%loc = card%loc
    section%element_set = model%mesh%find_element_set(param_upper(card, 'ELSET'))
    if (section%element_set == 0) then
      call diag%report(card%loc, '*SOLID SECTION: element set "' // param_upper(card, 'ELSET') // &
                       '" is not defined')
    end if
    section%material_name = param_upper(card, 'MATERIAL')
    section%orientation_name = param_upper(card, 'ORIENTATION')
    section%formulation = FORMULATION_FULL
    if (param_upper(card, 'FORMULATION') == 'BBAR') section%formulation = FORMULATION_BBAR
    if (section%element_set > 0) model%sections = [model%sections, section]
  end subroutine handle_solid_section

  !> After the last card: the material and the orientation of every section, by name (they may
  !> be defined after the *SOLID SECTION that names them, as CalculiX allows for materials).
  subroutine resolve_section_materials(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: s, k
    do s = 1, size(model%sections)
      associate (section => model%sections(s))
        section%material = 0
        do k = 1, size(model%materials)
          if (model%materials(k)%name == section%material_name) section%material = k
        end do
        if (section%material == 0) call diag%report(section%loc, '*SOLID SECTION: material "' // &
          section%material_name // '" is not defined (' // str(size(model%materials)) // &
          ' materials defined)')
        section%orientation = 0
        if (len(section%orientation_name) == 0) cycle
        do k = 1, size(model%orientations)
          if (model%orientations(k)%axes%name == section%orientation_name) section%orientation = k
        end do
        if (section%orientation == 0) call diag%report(section%loc, '*SOLID SECTION: ' // &
          'orientation "' // section%orientation_name // '" is not defined (' // &
          str(size(model%orientations)) // ' orientations defined)')
      end associate
    end do
  end subroutine resolve_section_materials

  !> *RESTART, WRITE, FREQUENCY=, INTERVAL=, GENERATIONS=.
  subroutine handle_restart(card, model, diag)
    use fcs_deck_fields, only: param_value
    use fcs_strings, only: parse_int, parse_real
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    logical :: ok
    associate (c => model%checkpoint)
      call parse_int(param_value(card, 'FREQUENCY'), c%frequency, ok)
      call parse_real(param_value(card, 'INTERVAL'), c%interval, ok)
      call parse_int(param_value(card, 'GENERATIONS'), c%generations, ok)
      if (c%frequency < 0) call diag%report(card%loc, '*RESTART: FREQUENCY must not be negative')
      if (c%interval < 0.0_dp) call diag%report(card%loc, '*RESTART: INTERVAL must not be negative')
      if (c%generations < 1 .or. c%generations > 100) &
        call diag%report(card%loc, '*RESTART: GENERATIONS must lie in 1..100')
    end associate
  end subroutine handle_restart

  !> *SOLVER, TYPE=, REUSE TOLERANCE=, LOW RANK TOLERANCE=.
  subroutine handle_solver(card, model, diag)
    use fcs_deck_fields, only: param_value
    use fcs_strings, only: parse_real
    use fcs_solver_factory, only: solver_has_low_rank, low_rank_solver_names_text
    use fcs_linear_solver, only: MAX_LOW_RANK_TOLERANCE
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: tolerance
    logical :: ok
    model%solver_name = param_upper(card, 'TYPE')
    model%solver_chosen = .true.
    call parse_real(param_value(card, 'REUSE TOLERANCE'), tolerance, ok)
    if (.not. ok .or. .not. (tolerance >= 0.0_dp .and. tolerance <= 1.0e-3_dp)) then
      call diag%report(card%loc, '*SOLVER: REUSE TOLERANCE must lie in [0, 1e-3] (0: factorise ' // &
                       'every tangent)')
    else
      model%reuse_tolerance = tolerance
    end if
    call parse_real(param_value(card, 'LOW RANK TOLERANCE'), tolerance, ok)
    if (.not. ok .or. .not. (tolerance >= 0.0_dp .and. tolerance <= MAX_LOW_RANK_TOLERANCE)) then
      call diag%report(card%loc, '*SOLVER: LOW RANK TOLERANCE must lie in [0, 1e-2] (0: ' // &
                       'full-rank factorisation)')
      return
    end if
    if (tolerance > 0.0_dp) then
      if (.not. solver_has_low_rank(model%solver_name)) then
        call diag%report(card%loc, '*SOLVER: LOW RANK TOLERANCE needs TYPE=' // &
                         low_rank_solver_names_text() // ' (block low-rank factorisation); ' // &
                         'TYPE=' // model%solver_name // ' has none')
        return
      end if
    end if
    model%low_rank_tolerance = tolerance
  end subroutine handle_solver

end module fcs_build_material
