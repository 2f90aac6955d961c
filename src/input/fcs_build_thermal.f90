!> Model builder, thermal keywords and initial states: *EXPANSION, temperature-dependent
!> *ELASTIC tables, *INITIAL CONDITIONS (TYPE=TEMPERATURE, TYPE=STRESS with its GEOSTATIC
!> form, TYPE=PLASTIC STRAIN), *TEMPERATURE; after the last card, the nodal temperatures of
!> every step (`resolve_temperatures`) and the density check of the body loads (`check_body_loads`).
!>
!> Conventions of CalculiX 2.20 (ccx manual, sections 6.2.8 *ELASTIC, 6.2.9 *EXPANSION,
!> 6.2.17 *INITIAL CONDITIONS, 6.2.56 *TEMPERATURE; its tempload.f for the ramp):
!>   - a node without an initial temperature starts at 0;
!>   - *TEMPERATURE in a *STATIC step: the value is reached at the end of the step, ramped
!>     linearly from the node's temperature at the start of the step; with AMPLITUDE= the
!>     temperature is value x a(t). OP=MOD (default) changes the listed nodes and keeps the
!>     others; OP=NEW first returns every node to its initial temperature. A node that no
!>     *TEMPERATURE of the step names keeps its target (and amplitude) of the previous step.
module fcs_build_thermal
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t, data_line_t
  use fcs_deck_fields, only: param_upper, param_value, line_real, resolve_nodes
  use fcs_diagnostics, only: diagnostics_t
  use fcs_builder_state, only: builder_t
  use fcs_build_step, only: amplitude_param
  use fcs_model, only: model_t, initial_stress_t, initial_plastic_strain_t
  use fcs_deck_fields, only: resolve_elements, has_flag, line_int
  use fcs_material_factory, only: PLASTICITY_NONE
  use fcs_strings, only: parse_real, str
  implicit none
  private
  public :: handle_expansion, handle_elastic_table, handle_initial_conditions, handle_temperature
  public :: resolve_temperatures, given_fields, check_body_loads

contains

  !> Number of fields of a data line up to its last non-empty one (CalculiX lines may end
  !> with a comma).
  pure integer function given_fields(line) result(n)
    type(data_line_t), intent(in) :: line
    do n = size(line%fields), 1, -1
      if (len(line%fields(n)%s) > 0) return
    end do
    n = 0
  end function given_fields

  !> A table of rows (values..., temperature) of `n_values` values each: one row may omit
  !> the temperature; several rows need it, strictly increasing. False (reported) if not.
  logical function read_table(card, n_values, what, values, temperatures, diag) result(ok)
    type(card_t), intent(in) :: card
    integer, intent(in) :: n_values
    character(len=*), intent(in) :: what
    real(dp), allocatable, intent(out) :: values(:, :), temperatures(:)
    type(diagnostics_t), intent(inout) :: diag
    integer :: i, j, n
    ok = .false.
    allocate (values(n_values, card%n_lines), temperatures(card%n_lines))
    temperatures = 0.0_dp
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        n = given_fields(line)
        if (n /= n_values + 1 .and. .not. (n == n_values .and. card%n_lines == 1)) then
          if (card%n_lines > 1) then
            call diag%report(line%loc, '*' // card%keyword // ': expected ' // what // &
                             ', temperature (every line of a table of several lines)')
          else
            call diag%report(line%loc, '*' // card%keyword // ': expected ' // what // &
                             '[, temperature]')
          end if
          return
        end if
        do j = 1, n_values
          if (.not. line_real(line, j, values(j, i), 'value', card%keyword, diag)) return
        end do
        if (n == n_values + 1) then
          if (.not. line_real(line, n, temperatures(i), 'temperature', card%keyword, diag)) return
        end if
        if (i > 1) then
          if (temperatures(i) <= temperatures(i - 1)) then
            call diag%report(line%loc, '*' // card%keyword // ': the temperatures of the table ' // &
                             'must increase strictly from line to line')
            return
          end if
        end if
      end associate
    end do
    ok = .true.
  end function read_table

  !> *EXPANSION, ZERO=: the isotropic secant expansion coefficient alpha, constant or as a
  !> table over temperature.
  subroutine handle_expansion(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp), allocatable :: values(:, :), temperatures(:)
    real(dp) :: zero
    logical :: ok
    if (state%material == 0) then
      call diag%report(card%loc, '*EXPANSION must follow a *MATERIAL line')
      return
    end if
    call parse_real(param_value(card, 'ZERO'), zero, ok)
    if (.not. ok) then
      call diag%report(card%loc, '*EXPANSION: ZERO= must be a number (the reference temperature)')
      return
    end if
    if (.not. read_table(card, 1, 'alpha', values, temperatures, diag)) return
    associate (m => model%materials(state%material))
      if (m%thermal%has_expansion()) then
        call diag%report(card%loc, '*EXPANSION: material ' // m%name // ' already has one')
        return
      end if
      m%thermal%zero = zero
      m%thermal%alpha = values(1, :)
      m%thermal%alpha_temperature = temperatures
      m%expansion_loc = card%loc
    end associate
  end subroutine handle_expansion

  !> *ELASTIC with a temperature column: E, nu, T per line (linear between the lines,
  !> constant beyond them). The first line also gives the material's E and nu.
  subroutine handle_elastic_table(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp), allocatable :: values(:, :), temperatures(:)
    integer :: i
    if (state%material == 0) then
      call diag%report(card%loc, '*ELASTIC must follow a *MATERIAL line')
      return
    end if
    if (.not. read_table(card, 2, 'Young''s modulus, Poisson''s ratio', values, temperatures, diag)) return
    do i = 1, card%n_lines
      if (values(1, i) <= 0.0_dp) then
        call diag%report(card%lines(i)%loc, '*ELASTIC: Young''s modulus must be positive')
        return
      end if
      if (values(2, i) <= -1.0_dp .or. values(2, i) >= 0.5_dp) then
        call diag%report(card%lines(i)%loc, '*ELASTIC: Poisson''s ratio must lie in (-1, 0.5)')
        return
      end if
    end do
    associate (m => model%materials(state%material))
      if (m%has_elastic) then
        call diag%report(card%loc, '*ELASTIC: material ' // m%name // ' already has elastic constants')
        return
      end if
      m%has_elastic = .true.
      m%youngs_modulus = values(1, 1)
      m%poisson_ratio = values(2, 1)
      m%thermal%youngs_modulus = values(1, :)
      m%thermal%poisson_ratio = values(2, :)
      m%thermal%elastic_temperature = temperatures
      m%elastic_loc = card%loc
    end associate
  end subroutine handle_elastic_table

  !> *INITIAL CONDITIONS: TYPE=TEMPERATURE (initial_temperatures), TYPE=STRESS
  !> (initial_stresses) or TYPE=PLASTIC STRAIN (initial_plastic_strains).
  subroutine handle_initial_conditions(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    if (param_upper(card, 'TYPE') == 'STRESS') then
      call initial_stresses(card, model, diag)
    else if (param_upper(card, 'TYPE') == 'PLASTIC STRAIN') then
      if (has_flag(card, 'GEOSTATIC')) then
        call diag%report(card%loc, '*INITIAL CONDITIONS: GEOSTATIC goes with TYPE=STRESS')
        return
      end if
      call initial_plastic_strains(card, model, diag)
    else
      if (has_flag(card, 'GEOSTATIC')) then
        call diag%report(card%loc, '*INITIAL CONDITIONS: GEOSTATIC goes with TYPE=STRESS')
        return
      end if
      call initial_temperatures(card, model, state, diag)
    end if
  end subroutine handle_initial_conditions

  !> *INITIAL CONDITIONS, TYPE=STRESS: element (or element set), integration point, the six
  !> stress components (as CalculiX); with GEOSTATIC (Abaqus): element or element set, s1, z1,
  !> s2, z2, k_x[, k_y] (k_y = k_x when empty) - the vertical stress linear in z through
  !> (z1, s1) and (z2, s2), the horizontal ones k times it (fcs_model, initial_stress_t).
  subroutine initial_stresses(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(initial_stress_t) :: item
    integer, allocatable :: elements(:)
    real(dp) :: values(6)
    integer :: i, j, n, n_points
    logical :: geostatic, ok
    geostatic = has_flag(card, 'GEOSTATIC')
    if (.not. allocated(model%initial_stresses)) allocate (model%initial_stresses(0))
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        n = given_fields(line)
        if (geostatic .and. (n < 6 .or. n > 7)) then
          call diag%report(line%loc, '*INITIAL CONDITIONS: expected element or element set, ' // &
                           's1, z1, s2, z2, k_x[, k_y] (GEOSTATIC)')
          cycle
        else if (.not. geostatic .and. n /= 8) then
          call diag%report(line%loc, '*INITIAL CONDITIONS: expected element, integration point, ' // &
                           'sxx, syy, szz, sxy, sxz, syz (TYPE=STRESS)')
          cycle
        end if
        item = initial_stress_t()
        item%is_geostatic = geostatic
        ok = .true.
        if (geostatic) then
          do j = 1, n - 1
            if (ok) ok = line_real(line, j + 1, values(j), 'value', card%keyword, diag)
          end do
          if (.not. ok) cycle
          if (n == 6) values(6) = values(5)
          if (values(2) == values(4)) then
            call diag%report(line%loc, '*INITIAL CONDITIONS: GEOSTATIC needs two different ' // &
                             'heights z1 and z2')
            cycle
          end if
          item%geostatic = values
        else
          if (.not. line_int(line, 2, item%point, 'integration point', card%keyword, diag)) cycle
          do j = 1, 6
            if (ok) ok = line_real(line, j + 2, item%stress(j), 'stress component', card%keyword, diag)
          end do
          if (.not. ok) cycle
        end if
        call resolve_elements(model%mesh, line%fields(1)%s, line, card%keyword, diag, elements)
        do j = 1, size(elements)
          item%element = elements(j)
          if (.not. geostatic) then
            n_points = model%element_kinds%kinds(model%mesh%element_kind(elements(j)))%n_points
            if (item%point < 1 .or. item%point > n_points) then
              call diag%report(line%loc, '*INITIAL CONDITIONS: element ' // line%fields(1)%s // &
                ' has integration points 1 to ' // str(n_points) // ', not ' // str(item%point))
              exit
            end if
          end if
          model%initial_stresses = [model%initial_stresses, item]
        end do
      end associate
    end do
  end subroutine initial_stresses

  !> *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN: element (or element set), integration point,
  !> exx, eyy, ezz, exy, exz, eyz, as CalculiX (ccx 2.20 `initialconditionss.f`; the shears are
  !> tensor components, as CalculiX subtracts them from its tensor strain), stored with
  !> engineering shears (fcs_model, initial_plastic_strain_t). Whether the element's material
  !> takes it is checked once the deck is read (fcs_build_plasticity,
  !> check_initial_plastic_strains).
  subroutine initial_plastic_strains(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(initial_plastic_strain_t) :: item
    integer, allocatable :: elements(:)
    integer :: i, j, n_points
    logical :: ok
    if (.not. allocated(model%initial_plastic_strains)) allocate (model%initial_plastic_strains(0))
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (given_fields(line) /= 8) then
          call diag%report(line%loc, '*INITIAL CONDITIONS: expected element, integration point, ' // &
                           'exx, eyy, ezz, exy, exz, eyz (TYPE=PLASTIC STRAIN; tensor shears, as CalculiX)')
          cycle
        end if
        item = initial_plastic_strain_t()
        item%loc = line%loc
        if (.not. line_int(line, 2, item%point, 'integration point', card%keyword, diag)) cycle
        ok = .true.
        do j = 1, 6
          if (ok) ok = line_real(line, j + 2, item%strain(j), 'plastic strain component', &
                                 card%keyword, diag)
        end do
        if (.not. ok) cycle
        item%strain(4:6) = 2.0_dp * item%strain(4:6)
        call resolve_elements(model%mesh, line%fields(1)%s, line, card%keyword, diag, elements)
        do j = 1, size(elements)
          item%element = elements(j)
          n_points = model%element_kinds%kinds(model%mesh%element_kind(elements(j)))%n_points
          if (item%point < 1 .or. item%point > n_points) then
            call diag%report(line%loc, '*INITIAL CONDITIONS: element ' // line%fields(1)%s // &
              ' has integration points 1 to ' // str(n_points) // ', not ' // str(item%point))
            exit
          end if
          model%initial_plastic_strains = [model%initial_plastic_strains, item]
        end do
      end associate
    end do
  end subroutine initial_plastic_strains

  !> *INITIAL CONDITIONS, TYPE=TEMPERATURE: node or node set, temperature.
  subroutine initial_temperatures(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: nodes(:)
    real(dp), allocatable :: values(:)
    if (.not. allocated(state%initial_temperature_node)) then
      allocate (state%initial_temperature_node(0), state%initial_temperature_value(0))
    end if
    call nodal_values(card, model, '*INITIAL CONDITIONS', diag, nodes, values)
    state%initial_temperature_node = [state%initial_temperature_node, nodes]
    state%initial_temperature_value = [state%initial_temperature_value, values]
  end subroutine initial_temperatures

  !> The data lines "node or node set, value" of a card, one entry per node (a set gives each
  !> of its nodes the line's value), in line order. Lines with another number of fields or a
  !> value that is not a number are reported and skipped. The lists grow by doubling: thermal
  !> decks give a line per node.
  subroutine nodal_values(card, model, keyword, diag, nodes, values)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    character(len=*), intent(in) :: keyword
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable, intent(out) :: nodes(:)
    real(dp), allocatable, intent(out) :: values(:)
    integer, allocatable :: found(:), grown_nodes(:)
    real(dp), allocatable :: grown_values(:)
    real(dp) :: value
    integer :: i, n, m
    allocate (nodes(max(card%n_lines, 1)), values(max(card%n_lines, 1)))
    n = 0
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (given_fields(line) /= 2) then
          call diag%report(line%loc, keyword // ': expected node or node set, temperature')
          cycle
        end if
        if (.not. line_real(line, 2, value, 'temperature', card%keyword, diag)) cycle
        call resolve_nodes(model%mesh, line%fields(1)%s, line, card%keyword, diag, found)
        m = size(found)
        if (n + m > size(nodes)) then
          allocate (grown_nodes(max(2 * size(nodes), n + m)), grown_values(max(2 * size(nodes), n + m)))
          grown_nodes(1:n) = nodes(1:n)
          grown_values(1:n) = values(1:n)
          call move_alloc(grown_nodes, nodes)
          call move_alloc(grown_values, values)
        end if
        nodes(n + 1:n + m) = found
        values(n + 1:n + m) = value
        n = n + m
      end associate
    end do
    nodes = nodes(1:n)
    values = values(1:n)
  end subroutine nodal_values

  !> *TEMPERATURE, OP=, AMPLITUDE=: node or node set, temperature at the end of the step.
  subroutine handle_temperature(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: nodes(:)
    real(dp), allocatable :: values(:)
    integer :: amplitude
    if (.not. amplitude_param(card, model, diag, amplitude)) return
    associate (step => state%step)
      if (.not. allocated(step%temperature_node)) then
        allocate (step%temperature_node(0), step%temperature_value(0), step%temperature_card_amplitude(0))
      end if
      if (param_upper(card, 'OP') == 'NEW') then
        step%temperature_new = .true.
        deallocate (step%temperature_node, step%temperature_value, step%temperature_card_amplitude)
        allocate (step%temperature_node(0), step%temperature_value(0), step%temperature_card_amplitude(0))
      end if
      call nodal_values(card, model, '*TEMPERATURE', diag, nodes, values)
      step%temperature_node = [step%temperature_node, nodes]
      step%temperature_value = [step%temperature_value, values]
      step%temperature_card_amplitude = [step%temperature_card_amplitude, &
                                         spread(amplitude, 1, size(nodes))]
    end associate
  end subroutine handle_temperature

  !> After the last card: whether the model has temperatures, the initial temperature of every
  !> node and the complete target and amplitude lists of every step (module comment); a
  !> temperature-dependent *ELASTIC table with plasticity is refused.
  subroutine resolve_temperatures(model, state, diag)
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp), allocatable :: target(:)
    integer, allocatable :: amplitude(:)
    integer :: k, i, n_nodes
    logical :: has
    has = allocated(state%initial_temperature_node)
    do k = 1, size(model%materials)
      associate (m => model%materials(k))
        if (m%thermal%is_active()) has = .true.
        if (m%thermal%elastic_varies() .and. m%plastic%model /= PLASTICITY_NONE) &
          call diag%report(m%elastic_loc, '*ELASTIC: material ' // m%name // ': temperature-' // &
            'dependent elastic constants are available for elastic materials only, not with ' // &
            'plasticity (*PLASTIC, *DRUCKER PRAGER)')
      end associate
    end do
    do k = 1, size(model%steps)
      if (allocated(model%steps(k)%temperature_node)) has = .true.
    end do
    model%has_temperature = has
    if (.not. has) return
    n_nodes = model%mesh%n_nodes
    allocate (model%initial_temperature(n_nodes))
    model%initial_temperature = 0.0_dp
    if (allocated(state%initial_temperature_node)) then
      do i = 1, size(state%initial_temperature_node)
        model%initial_temperature(state%initial_temperature_node(i)) = state%initial_temperature_value(i)
      end do
    end if
    target = model%initial_temperature
    allocate (amplitude(n_nodes))
    amplitude = 0
    do k = 1, size(model%steps)
      associate (step => model%steps(k))
        if (step%temperature_new) then
          target = model%initial_temperature
          amplitude = 0
        end if
        if (allocated(step%temperature_node)) then
          do i = 1, size(step%temperature_node)
            target(step%temperature_node(i)) = step%temperature_value(i)
            amplitude(step%temperature_node(i)) = step%temperature_card_amplitude(i)
          end do
        end if
        step%temperature = target
        step%temperature_amplitude = amplitude
      end associate
    end do
  end subroutine resolve_temperatures

  !> After the sections are resolved: every element with a body load (*DLOAD GRAV, CENTRIF)
  !> has a material with *DENSITY (reported once per *DLOAD line).
  subroutine check_body_loads(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: k, i, section, material, last_line
    character(len=:), allocatable :: last_file
    do k = 1, size(model%steps)
      if (.not. allocated(model%steps(k)%body_loads)) cycle
      last_line = 0
      last_file = ''
      do i = 1, size(model%steps(k)%body_loads)
        associate (b => model%steps(k)%body_loads(i))
          section = model%element_section(b%element)
          if (section == 0) cycle
          material = model%sections(section)%material
          if (material == 0) cycle
          if (model%materials(material)%has_density) cycle
          if (b%loc%line == last_line .and. b%loc%file == last_file) cycle
          last_line = b%loc%line
          last_file = b%loc%file
          call diag%report(b%loc, '*DLOAD: a body load needs the density of the material (' // &
            'material ' // model%materials(material)%name // ' has no *DENSITY)')
        end associate
      end do
    end do
  end subroutine check_body_loads

end module fcs_build_thermal
