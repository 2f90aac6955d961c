!> Model builder, material keywords: *MATERIAL, *ELASTIC, *DENSITY, *SOLID SECTION, *SOLVER.
module fcs_build_material
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t
  use fcs_deck_fields, only: param_upper, line_real
  use fcs_diagnostics, only: diagnostics_t
  use fcs_builder_state, only: builder_t
  use fcs_model, only: model_t, material_def_t, section_t, FORMULATION_FULL, FORMULATION_BBAR
  use fcs_strings, only: str
  implicit none
  private
  public :: handle_material, handle_elastic, handle_density, handle_solid_section, handle_solver
  public :: handle_restart, resolve_section_materials

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

  !> *ELASTIC: E, nu of the current material.
  subroutine handle_elastic(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: e, nu
    if (.not. has_current_material(card, state, diag)) return
    if (card%n_lines /= 1 .or. size(card%lines(1)%fields) /= 2) then
      call diag%report(card%lines(1)%loc, '*ELASTIC: expected one line: Young''s modulus, ' // &
                       'Poisson''s ratio (temperature-dependent tables are not supported)')
      return
    end if
    if (.not. line_real(card%lines(1), 1, e, 'Young''s modulus', 'ELASTIC', diag)) return
    if (.not. line_real(card%lines(1), 2, nu, 'Poisson''s ratio', 'ELASTIC', diag)) return
    if (e <= 0.0_dp) then
      call diag%report(card%lines(1)%loc, '*ELASTIC: Young''s modulus must be positive')
      return
    end if
    if (nu <= -1.0_dp .or. nu >= 0.5_dp) then
      call diag%report(card%lines(1)%loc, '*ELASTIC: Poisson''s ratio must lie in (-1, 0.5)')
      return
    end if
    associate (m => model%materials(state%material))
      if (m%has_elastic) then
        call diag%report(card%loc, '*ELASTIC: material ' // m%name // ' already has elastic constants')
        return
      end if
      m%has_elastic = .true.
      m%youngs_modulus = e
      m%poisson_ratio = nu
    end associate
  end subroutine handle_elastic

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
    section%formulation = FORMULATION_FULL
    if (param_upper(card, 'FORMULATION') == 'BBAR') section%formulation = FORMULATION_BBAR
    if (section%element_set > 0) model%sections = [model%sections, section]
  end subroutine handle_solid_section

  !> After the last card: the material of every section, by name (a material may be defined
  !> after the *SOLID SECTION that names it, as CalculiX allows).
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

  !> *SOLVER, TYPE=, REUSE TOLERANCE=.
  subroutine handle_solver(card, model, diag)
    use fcs_deck_fields, only: param_value
    use fcs_strings, only: parse_real
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
      return
    end if
    model%reuse_tolerance = tolerance
  end subroutine handle_solver

end module fcs_build_material
