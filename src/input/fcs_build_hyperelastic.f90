!> Model builder, hyperelastic keywords: *HYPERELASTIC and *HYPERFOAM (ccx 2.20 manual,
!> sections "*HYPERELASTIC" and "*HYPERFOAM"; the layouts of their data lines as ccx's readers
!> hyperelastics.f and hyperfoams.f take them). The energies are in fcs_hyperelastic.
!>
!> As in CalculiX: the form is a parameter without value (NEO HOOKE, OGDEN, ...; POLYNOMIAL by
!> default), N=1..3 the order of OGDEN, POLYNOMIAL and REDUCED POLYNOMIAL (and of *HYPERFOAM);
!> one line of constants and an optional temperature, or a pair of lines for OGDEN, N=3,
!> POLYNOMIAL, N=3 and *HYPERFOAM, N=3 (8 constants on the first); a compressibility constant
!> D_i given as 0 (or left out) becomes (0.1 / mu_0)^i, mu_0 the initial shear modulus (D_1 then
!> corresponds to an initial Poisson's ratio of 0.475), with a warning, as ccx does. Not
!> available (refused): VAN DER WAALS, and tables over more than one temperature.
!>
!> *DEFORMATION PLASTICITY (ccx 2.20 manual, "*DEFORMATION PLASTICITY"; ccx's reader
!> deformationplasticitys.f) takes the same total path (fcs_deformation_plasticity,
!> doc/theory.md 2.12): one line E, nu, sigma_0, n, alpha and an optional temperature; more
!> lines (a table over temperature) are refused.
module fcs_build_hyperelastic
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t
  use fcs_deck_fields, only: param_value, line_real
  use fcs_diagnostics, only: diagnostics_t, source_loc_t
  use fcs_builder_state, only: builder_t
  use fcs_model, only: model_t
  use fcs_hyperelastic, only: hyperelastic_law_t, hyperelastic_initial_moduli, HYPER_POLYNOMIAL, &
                              HYPER_ARRUDA_BOYCE, HYPER_OGDEN, HYPER_FOAM, &
                              HYPER_DEFORMATION_PLASTICITY
  use fcs_strings, only: str, parse_int
  implicit none
  private
  public :: handle_hyperelastic, handle_hyperfoam, handle_deformation_plasticity, HYPERELASTIC_FORMS

  !> The forms of *HYPERELASTIC, as parameters without value (the keyword table lists them).
  character(len=18), parameter :: HYPERELASTIC_FORMS(8) = [character(len=18) :: 'ARRUDA-BOYCE', &
    'MOONEY-RIVLIN', 'NEO HOOKE', 'OGDEN', 'POLYNOMIAL', 'REDUCED POLYNOMIAL', 'YEOH', &
    'VAN DER WAALS']

  !> The constants of one form: their names (in deck order), how many of them are compressibility
  !> constants D_i (the last ones), and whether they come as a pair of lines.
  type :: layout_t
    character(len=:), allocatable :: names
    integer :: n = 0
    integer :: n_d = 0
    logical :: paired = .false.
  end type layout_t

contains

  !> *HYPERELASTIC[, <form>][, N=]: the current material's hyperelastic law.
  subroutine handle_hyperelastic(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(hyperelastic_law_t) :: law
    type(layout_t) :: layout
    character(len=:), allocatable :: form
    real(dp), allocatable :: values(:)
    integer :: order, k, given
    logical :: ok
    if (.not. has_material(card, state, diag)) return
    form = 'POLYNOMIAL'
    given = 0
    do k = 1, size(HYPERELASTIC_FORMS)
      if (card%find_param(trim(HYPERELASTIC_FORMS(k))) == 0) cycle
      form = trim(HYPERELASTIC_FORMS(k))
      given = given + 1
    end do
    if (given > 1) then
      call diag%report(card%loc, '*HYPERELASTIC: give one form (one of ' // forms_text() // ')')
      return
    end if
    if (form == 'VAN DER WAALS') then
      call diag%report(card%loc, '*HYPERELASTIC, VAN DER WAALS is not available in fcs3d; the ' // &
        'forms available are ' // forms_text(7))
      return
    end if
    call read_order(card, 'HYPERELASTIC', order, ok, diag)
    if (.not. ok) return
    if (order > 1 .and. form /= 'OGDEN' .and. form /= 'POLYNOMIAL' .and. &
        form /= 'REDUCED POLYNOMIAL') then
      call diag%report(card%loc, '*HYPERELASTIC, ' // form // ': N=' // str(order) // ' is not ' // &
        'applicable (N is the order of OGDEN, POLYNOMIAL and REDUCED POLYNOMIAL)')
      return
    end if
    layout = hyperelastic_layout(form, order)
    call read_constants(card, 'HYPERELASTIC, ' // form, layout, values, ok, diag)
    if (.not. ok) return
    law = law_of(form, order, values)
    law%form = form
    if (order > 1) law%form = form // ', N=' // str(order)
    call set_law(card, law, model, state, diag)
  end subroutine handle_hyperelastic

  !> *HYPERFOAM[, N=]: mu_i, alpha_i, nu_i of the current material's hyperfoam law.
  subroutine handle_hyperfoam(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(hyperelastic_law_t) :: law
    type(layout_t) :: layout
    real(dp), allocatable :: values(:)
    integer :: order, i
    logical :: ok
    if (.not. has_material(card, state, diag)) return
    call read_order(card, 'HYPERFOAM', order, ok, diag)
    if (.not. ok) return
    layout%n = 3 * order
    layout%paired = order == 3
    layout%names = 'mu_1, alpha_1, nu_1'
    if (order == 2) layout%names = 'mu_1, alpha_1, mu_2, alpha_2, nu_1, nu_2'
    if (order == 3) layout%names = 'mu_1, alpha_1, mu_2, alpha_2, mu_3, alpha_3, nu_1, nu_2 / nu_3'
    call read_constants(card, 'HYPERFOAM', layout, values, ok, diag)
    if (.not. ok) return
    law%family = HYPER_FOAM
    law%order = order
    law%form = 'HYPERFOAM, N=' // str(order)
    do i = 1, order
      law%mu(i) = values(2 * i - 1)
      law%alpha(i) = values(2 * i)
      if (values(2 * order + i) >= 0.5_dp .or. values(2 * order + i) <= -1.0_dp) then
        call diag%report(card%lines(1)%loc, '*HYPERFOAM: nu_' // str(i) // ' must lie in (-1, 0.5)')
        return
      end if
      ! beta_i = nu_i / (1 - 2 nu_i) (ccx manual, *HYPERFOAM).
      law%beta(i) = values(2 * order + i) / (1.0_dp - 2.0_dp * values(2 * order + i))
    end do
    call set_law(card, law, model, state, diag)
  end subroutine handle_hyperfoam

  !> *DEFORMATION PLASTICITY: E, nu, sigma_0, n, alpha of the current material's Ramberg-Osgood
  !> law (E > 0, -1 < nu < 0.5, sigma_0 > 0, n >= 1, alpha >= 0).
  subroutine handle_deformation_plasticity(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(hyperelastic_law_t) :: law
    type(layout_t) :: layout
    real(dp), allocatable :: values(:)
    character(len=:), allocatable :: problem
    logical :: ok
    if (.not. has_material(card, state, diag)) return
    layout%names = 'E, nu, sigma_0, n, alpha'
    layout%n = 5
    call read_constants(card, 'DEFORMATION PLASTICITY', layout, values, ok, diag)
    if (.not. ok) return
    problem = ''
    if (.not. (values(1) > 0.0_dp)) problem = 'Young''s modulus E must be positive'
    if (.not. (values(2) > -1.0_dp .and. values(2) < 0.5_dp)) problem = 'Poisson''s ratio nu ' // &
      'must lie in (-1, 0.5)'
    if (.not. (values(3) > 0.0_dp)) problem = 'the yield stress sigma_0 must be positive'
    if (.not. (values(4) >= 1.0_dp)) problem = 'the exponent n must be at least 1'
    if (.not. (values(5) >= 0.0_dp)) problem = 'the yield offset alpha must not be negative'
    if (len(problem) > 0) then
      call diag%report(card%lines(1)%loc, '*DEFORMATION PLASTICITY: ' // problem // &
                       ' (E, nu, sigma_0, n, alpha[, temperature])')
      return
    end if
    law%family = HYPER_DEFORMATION_PLASTICITY
    law%form = 'DEFORMATION PLASTICITY'
    law%ramberg_osgood%youngs_modulus = values(1)
    law%ramberg_osgood%poisson_ratio = values(2)
    law%ramberg_osgood%yield_stress = values(3)
    law%ramberg_osgood%exponent = values(4)
    law%ramberg_osgood%yield_offset = values(5)
    call set_law(card, law, model, state, diag)
  end subroutine handle_deformation_plasticity

  !> The constants of *HYPERELASTIC's `form` of order N, in deck order (ccx hyperelastics.f).
  function hyperelastic_layout(form, order) result(layout)
    character(len=*), intent(in) :: form
    integer, intent(in) :: order
    type(layout_t) :: layout
    layout%n_d = 1
    select case (form)
    case ('ARRUDA-BOYCE')
      layout%names = 'mu, lambda_m, D'
    case ('MOONEY-RIVLIN')
      layout%names = 'C10, C01, D1'
    case ('NEO HOOKE')
      layout%names = 'C10, D1'
    case ('YEOH')
      layout%names = 'C10, C20, C30, D1, D2, D3'
      layout%n_d = 3
    case ('OGDEN')
      layout%n_d = order
      select case (order)
      case (1)
        layout%names = 'mu_1, alpha_1, D1'
      case (2)
        layout%names = 'mu_1, alpha_1, mu_2, alpha_2, D1, D2'
      case default
        layout%names = 'mu_1, alpha_1, mu_2, alpha_2, mu_3, alpha_3, D1, D2 / D3'
      end select
    case ('REDUCED POLYNOMIAL')
      layout%n_d = order
      select case (order)
      case (1)
        layout%names = 'C10, D1'
      case (2)
        layout%names = 'C10, C20, D1, D2'
      case default
        layout%names = 'C10, C20, C30, D1, D2, D3'
      end select
    case default
      layout%n_d = order
      select case (order)
      case (1)
        layout%names = 'C10, C01, D1'
      case (2)
        layout%names = 'C10, C01, C20, C11, C02, D1, D2'
      case default
        layout%names = 'C10, C01, C20, C11, C02, C30, C21, C12 / C03, D1, D2, D3'
      end select
    end select
    layout%n = count_names(layout%names)
    layout%paired = layout%n > 8
  end function hyperelastic_layout

  !> The law of `form` from its constants `v` in deck order.
  function law_of(form, order, v) result(law)
    character(len=*), intent(in) :: form
    integer, intent(in) :: order
    real(dp), intent(in) :: v(:)
    type(hyperelastic_law_t) :: law
    integer :: i
    law%family = HYPER_POLYNOMIAL
    law%order = order
    select case (form)
    case ('ARRUDA-BOYCE')
      law%family = HYPER_ARRUDA_BOYCE
      law%mu(1) = v(1)
      law%lambda_m = v(2)
      law%d(1) = v(3)
    case ('MOONEY-RIVLIN')
      law%c(1, 0) = v(1)
      law%c(0, 1) = v(2)
      law%d(1) = v(3)
    case ('NEO HOOKE')
      law%c(1, 0) = v(1)
      law%d(1) = v(2)
    case ('YEOH', 'REDUCED POLYNOMIAL')
      if (form == 'YEOH') law%order = 3
      do i = 1, law%order
        law%c(i, 0) = v(i)
        law%d(i) = v(law%order + i)
      end do
    case ('OGDEN')
      law%family = HYPER_OGDEN
      do i = 1, order
        law%mu(i) = v(2 * i - 1)
        law%alpha(i) = v(2 * i)
        law%d(i) = v(2 * order + i)
      end do
    case default
      ! POLYNOMIAL: C10, C01, then C20, C11, C02, then C30, C21, C12, C03 (i + j = 1, 2, 3).
      law%c(1, 0) = v(1)
      law%c(0, 1) = v(2)
      if (order >= 2) then
        law%c(2, 0) = v(3)
        law%c(1, 1) = v(4)
        law%c(0, 2) = v(5)
      end if
      if (order == 3) then
        law%c(3, 0) = v(6)
        law%c(2, 1) = v(7)
        law%c(1, 2) = v(8)
        law%c(0, 3) = v(9)
      end if
      do i = 1, order
        law%d(i) = v(size(v) - order + i)
      end do
    end select
  end function law_of

  !> Checks the law, gives zero compressibility constants CalculiX's defaults and makes it the
  !> current material's.
  subroutine set_law(card, law, model, state, diag)
    type(card_t), intent(in) :: card
    type(hyperelastic_law_t), intent(inout) :: law
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(hyperelastic_law_t) :: probe
    real(dp) :: mu0, k0
    integer :: i, n_terms
    character(len=:), allocatable :: keyword
    keyword = '*HYPERELASTIC, ' // law%form
    if (law%family == HYPER_FOAM .or. law%family == HYPER_DEFORMATION_PLASTICITY) &
      keyword = '*' // law%form
    n_terms = law%order
    if (law%family == HYPER_OGDEN .or. law%family == HYPER_FOAM) then
      do i = 1, n_terms
        if (law%alpha(i) == 0.0_dp) then
          call diag%report(card%lines(1)%loc, keyword // ': alpha_' // str(i) // ' must not be 0')
          return
        end if
      end do
    end if
    if (law%family == HYPER_ARRUDA_BOYCE .and. law%lambda_m <= 0.0_dp) then
      call diag%report(card%lines(1)%loc, keyword // ': lambda_m must be positive')
      return
    end if
    probe = law
    probe%d(1) = 1.0_dp
    call hyperelastic_initial_moduli(probe, mu0, k0)
    if (.not. (mu0 > 0.0_dp)) then
      call diag%report(card%lines(1)%loc, keyword // ': the initial shear modulus (' // &
                       initial_shear_text(law) // ') must be positive')
      return
    end if
    call default_compressibility(card, keyword, law, mu0, diag)
    call hyperelastic_initial_moduli(law, mu0, k0)
    if (.not. (k0 > 0.0_dp)) then
      call diag%report(card%lines(1)%loc, keyword // ': the initial bulk modulus must be ' // &
                       'positive (D1 > 0; for *HYPERFOAM, sum 2 mu_i (1/3 + beta_i) > 0)')
      return
    end if
    associate (m => model%materials(state%material))
      if (m%has_elastic) then
        call diag%report(card%loc, keyword // ': material ' // m%name // ' already has elastic ' // &
                         'constants (*ELASTIC, *HYPOELASTIC, *HYPERELASTIC, *HYPERFOAM or ' // &
                         '*DEFORMATION PLASTICITY)')
        return
      end if
      m%has_elastic = .true.
      m%elastic_loc = card%loc
      m%hyperelastic = law
      m%hyperelastic_loc = card%loc
      m%youngs_modulus = 9.0_dp * k0 * mu0 / (3.0_dp * k0 + mu0)
      m%poisson_ratio = (3.0_dp * k0 - 2.0_dp * mu0) / (2.0_dp * (3.0_dp * k0 + mu0))
    end associate
  end subroutine set_law

  !> A compressibility constant D_i given as 0 (|D_i| < 1e-10, as ccx tests) becomes
  !> (0.1 / mu_0)^i: K_0 = 2 / D_1 = 20 mu_0, an initial Poisson's ratio of 0.475 (ccx
  !> hyperelastics.f and the manual's remark on incompressible materials), with a warning.
  subroutine default_compressibility(card, keyword, law, mu0, diag)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: keyword
    type(hyperelastic_law_t), intent(inout) :: law
    real(dp), intent(in) :: mu0
    type(diagnostics_t), intent(inout) :: diag
    integer :: i, n_d
    if (law%family == HYPER_FOAM .or. law%family == HYPER_DEFORMATION_PLASTICITY) return
    n_d = law%order
    if (law%family == HYPER_ARRUDA_BOYCE) n_d = 1
    do i = 1, n_d
      if (abs(law%d(i)) >= 1.0e-10_dp) cycle
      law%d(i) = (0.1_dp / mu0)**i
      call diag%warn(card%lines(1)%loc, keyword // ': D' // str(i) // ' = 0 (incompressible) ' // &
        'is replaced by D' // str(i) // ' = (0.1 / mu_0)^' // str(i) // ' = ' // str(law%d(i)) // &
        ', as CalculiX does (an initial Poisson''s ratio of 0.475)')
    end do
  end subroutine default_compressibility

  function initial_shear_text(law) result(text)
    type(hyperelastic_law_t), intent(in) :: law
    character(len=:), allocatable :: text
    select case (law%family)
    case (HYPER_POLYNOMIAL)
      text = '2 (C10 + C01)'
    case (HYPER_ARRUDA_BOYCE)
      text = 'mu'
    case default
      text = 'the sum of the mu_i'
    end select
  end function initial_shear_text

  !> N= (1, 2 or 3; 1 by default).
  subroutine read_order(card, keyword, order, ok, diag)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: keyword
    integer, intent(out) :: order
    logical, intent(out) :: ok
    type(diagnostics_t), intent(inout) :: diag
    order = 1
    ok = .true.
    if (card%find_param('N') == 0) return
    call parse_int(param_value(card, 'N'), order, ok)
    if (.not. ok .or. order < 1 .or. order > 3) then
      call diag%report(card%loc, '*' // keyword // ': only N=1, N=2 or N=3 are allowed')
      ok = .false.
    end if
  end subroutine read_order

  !> The constants of one set (one line, or a pair of lines of which the first holds 8), each
  !> field a number (an empty field is 0, as ccx reads it), then an optional temperature. The
  !> non-compressibility constants must all be there; compressibility constants left out are
  !> 0 (and get their defaults). More lines than one set: a table over temperature, refused.
  subroutine read_constants(card, keyword, layout, values, ok, diag)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: keyword
    type(layout_t), intent(in) :: layout
    real(dp), allocatable, intent(out) :: values(:)
    logical, intent(out) :: ok
    type(diagnostics_t), intent(inout) :: diag
    integer :: per_set, first_count, n_fields, i, line
    type(source_loc_t) :: loc
    ok = .false.
    allocate (values(layout%n))
    values = 0.0_dp
    per_set = merge(2, 1, layout%paired)
    if (card%n_lines < per_set) then
      loc = card%loc
      if (card%n_lines > 0) loc = card%lines(card%n_lines)%loc
      call diag%report(loc, '*' // keyword // ': expected ' // str(per_set) // ' data line(s): ' // &
                       expected_text(layout))
      return
    end if
    if (card%n_lines > per_set) then
      call diag%report(card%lines(per_set + 1)%loc, '*' // keyword // ': constants that depend ' // &
        'on temperature (more than one set of constants) are not available; give one set: ' // &
        expected_text(layout))
      return
    end if
    first_count = layout%n
    if (layout%paired) first_count = 8
    do line = 1, per_set
      associate (data => card%lines(line))
        n_fields = given_count(card, line)
        if (line == 1 .and. layout%paired .and. n_fields /= 8) then
          call diag%report(data%loc, '*' // keyword // ': the first line of the pair holds 8 ' // &
            'constants; found ' // str(n_fields) // ' (' // expected_text(layout) // ')')
          return
        end if
        if (line == per_set) then
          if (n_fields > layout%n - first_count * (line - 1) + 1) then
            call diag%report(data%loc, '*' // keyword // ': too many values: expected ' // &
              expected_text(layout) // '; found ' // str(n_fields) // ' on this line')
            return
          end if
          if (n_fields < layout%n - layout%n_d - first_count * (line - 1)) then
            call diag%report(data%loc, '*' // keyword // ': missing constants: expected ' // &
              expected_text(layout) // '; found ' // str(n_fields) // ' on this line')
            return
          end if
        end if
        do i = 1, min(n_fields, layout%n - first_count * (line - 1))
          if (len(data%fields(i)%s) == 0) cycle
          if (.not. line_real(data, i, values(first_count * (line - 1) + i), 'constant ' // &
                              str(first_count * (line - 1) + i), keyword, diag)) return
        end do
      end associate
    end do
    ok = .true.
  end subroutine read_constants

  !> The number of fields of data line `line`, a trailing empty one (a final comma) left out.
  pure integer function given_count(card, line) result(n)
    type(card_t), intent(in) :: card
    integer, intent(in) :: line
    n = size(card%lines(line)%fields)
    if (n > 0) then
      if (len(card%lines(line)%fields(n)%s) == 0) n = n - 1
    end if
  end function given_count

  function expected_text(layout) result(text)
    type(layout_t), intent(in) :: layout
    character(len=:), allocatable :: text
    text = layout%names // '[, temperature]'
  end function expected_text

  !> The number of comma-separated names (a "/" between the lines of a pair separates too).
  pure integer function count_names(names) result(n)
    character(len=*), intent(in) :: names
    integer :: i
    n = 1
    do i = 1, len(names)
      if (names(i:i) == ',' .or. names(i:i) == '/') n = n + 1
    end do
  end function count_names

  !> The form names, the first `n` of them (all by default).
  function forms_text(n) result(text)
    integer, intent(in), optional :: n
    character(len=:), allocatable :: text
    integer :: k, last
    last = size(HYPERELASTIC_FORMS)
    if (present(n)) last = n
    text = trim(HYPERELASTIC_FORMS(1))
    do k = 2, last
      text = text // ', ' // trim(HYPERELASTIC_FORMS(k))
    end do
  end function forms_text

  logical function has_material(card, state, diag) result(ok)
    type(card_t), intent(in) :: card
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    ok = state%material > 0
    if (.not. ok) call diag%report(card%loc, '*' // card%keyword // ' must follow a *MATERIAL line')
  end function has_material

end module fcs_build_hyperelastic
