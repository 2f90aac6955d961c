!> Model builder, plasticity keywords of the current material: *PLASTIC, *CYCLIC HARDENING
!> (CalculiX), *DRUCKER PRAGER, *DRUCKER PRAGER HARDENING (Abaqus). Each card is checked on
!> its own here (numbers, ranges, curves); what needs the whole material (a Drucker-Prager
!> material has its hardening, COMBINED has its cyclic curve, the angles suit the hardening
!> TYPE) is checked by `check_plasticity` once the deck is read.
module fcs_build_plasticity
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t, data_line_t
  use fcs_deck_fields, only: param_upper, line_real
  use fcs_diagnostics, only: diagnostics_t, source_loc_t
  use fcs_builder_state, only: builder_t
  use fcs_model, only: model_t, material_def_t, initial_plastic_strain_t
  use fcs_material_factory, only: PLASTICITY_NONE, PLASTICITY_MISES, PLASTICITY_DRUCKER_PRAGER, &
                                  max_friction_angle
  use fcs_hardening_table, only: hardening_table_t
  use fcs_strings, only: str
  implicit none
  private
  public :: handle_plastic, handle_cyclic_hardening, handle_drucker_prager
  public :: handle_drucker_prager_hardening, check_plasticity, check_initial_plastic_strains

  !> A von Mises initial plastic strain counts as deviatoric when its trace is below this
  !> fraction of its largest component (the round-off of the decimal values of a deck).
  real(dp), parameter :: TRACE_TOLERANCE = 1.0e-9_dp

contains

  !> *PLASTIC, HARDENING=: the von Mises hardening curve of the current material.
  subroutine handle_plastic(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(hardening_table_t) :: curve
    if (.not. current_material(card, state, diag)) return
    associate (m => model%materials(state%material))
      if (.not. plasticity_free(card, m, diag)) return
      if (.not. read_curve(card, 'von Mises stress', 'temperature-dependent hardening (a third ' // &
                           'field, the temperature) is not available yet: the thermal issue adds it', &
                           curve, diag)) return
      m%plastic%model = PLASTICITY_MISES
      m%plastic%hardening = param_upper(card, 'HARDENING')
      m%plastic%curve = curve
      m%plastic_loc = card%loc
    end associate
  end subroutine handle_plastic

  !> *CYCLIC HARDENING: the radius curve of HARDENING=COMBINED.
  subroutine handle_cyclic_hardening(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(hardening_table_t) :: curve
    if (.not. current_material(card, state, diag)) return
    associate (m => model%materials(state%material))
      if (m%cyclic_loc%line > 0) then
        call diag%report(card%loc, '*CYCLIC HARDENING: material ' // m%name // ' already has ' // &
                         'a cyclic hardening curve (line ' // str(m%cyclic_loc%line) // ')')
        return
      end if
      if (.not. read_curve(card, 'von Mises stress', 'temperature-dependent hardening (a third ' // &
                           'field, the temperature) is not available yet: the thermal issue adds it', &
                           curve, diag)) return
      m%plastic%cyclic_curve = curve
      m%cyclic_loc = card%loc
    end associate
  end subroutine handle_cyclic_hardening

  !> *DRUCKER PRAGER: beta, K, psi of the current material.
  subroutine handle_drucker_prager(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: beta, ratio, psi
    if (.not. current_material(card, state, diag)) return
    associate (m => model%materials(state%material), line => card%lines(1))
      if (.not. plasticity_free(card, m, diag)) return
      if (card%n_lines /= 1 .or. size(line%fields) > 4 .or. size(line%fields) < 3) then
        call diag%report(line%loc, '*DRUCKER PRAGER: expected one line: friction angle beta ' // &
                         '[degree], flow stress ratio K, dilation angle psi [degree]')
        return
      end if
      if (size(line%fields) == 4) then
        if (len(line%fields(4)%s) > 0) then
          call diag%report(line%loc, '*DRUCKER PRAGER: temperature-dependent parameters (a ' // &
                           'fourth field) are not available yet: the thermal issue adds them')
          return
        end if
      end if
      if (.not. line_real(line, 1, beta, 'friction angle beta', 'DRUCKER PRAGER', diag)) return
      ratio = 1.0_dp
      if (len(line%fields(2)%s) > 0) then
        if (.not. line_real(line, 2, ratio, 'flow stress ratio K', 'DRUCKER PRAGER', diag)) return
      end if
      if (.not. line_real(line, 3, psi, 'dilation angle psi', 'DRUCKER PRAGER', diag)) return
      if (ratio /= 1.0_dp) then
        call diag%report(line%loc, '*DRUCKER PRAGER: flow stress ratio K = ' // str(ratio) // &
                         ' is not available: only K = 1 (a circular section of the cone in the ' // &
                         'deviatoric plane; leave the field empty or write 1)')
        return
      end if
      if (beta < 0.0_dp .or. beta >= 90.0_dp) then
        call diag%report(line%loc, '*DRUCKER PRAGER: the friction angle beta must lie in ' // &
                         '[0, 90) degrees, not ' // str(beta))
        return
      end if
      if (psi < 0.0_dp .or. psi >= 90.0_dp) then
        call diag%report(line%loc, '*DRUCKER PRAGER: the dilation angle psi must lie in ' // &
                         '[0, 90) degrees, not ' // str(psi))
        return
      end if
      m%plastic%model = PLASTICITY_DRUCKER_PRAGER
      m%plastic%friction_angle = beta
      m%plastic%flow_stress_ratio = ratio
      m%plastic%dilation_angle = psi
      m%drucker_prager_loc = line%loc
    end associate
  end subroutine handle_drucker_prager

  !> *DRUCKER PRAGER HARDENING, TYPE=: the hardening curve of the current material.
  subroutine handle_drucker_prager_hardening(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(hardening_table_t) :: curve
    if (.not. current_material(card, state, diag)) return
    associate (m => model%materials(state%material))
      if (m%dp_hardening_loc%line > 0) then
        call diag%report(card%loc, '*DRUCKER PRAGER HARDENING: material ' // m%name // &
                         ' already has a hardening curve (line ' // str(m%dp_hardening_loc%line) // ')')
        return
      end if
      if (.not. read_curve(card, 'yield stress', 'rate- and temperature-dependent hardening ' // &
                           '(a third field) are not available', curve, diag)) return
      m%plastic%curve = curve
      m%plastic%hardening_type = param_upper(card, 'TYPE')
      m%dp_hardening_loc = card%loc
    end associate
  end subroutine handle_drucker_prager_hardening

  !> The checks that need the whole material: a Drucker-Prager material has its hardening
  !> curve and angles that suit its TYPE; the hardening curve belongs to a *DRUCKER PRAGER;
  !> HARDENING=COMBINED has its *CYCLIC HARDENING and a cyclic curve belongs to it.
  subroutine check_plasticity(material, diag)
    type(material_def_t), intent(in) :: material
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: limit
    associate (m => material)
      if (m%dp_hardening_loc%line > 0 .and. m%drucker_prager_loc%line == 0) &
        call diag%report(m%dp_hardening_loc, '*DRUCKER PRAGER HARDENING: material ' // m%name // &
                         ' has no *DRUCKER PRAGER')
      if (m%drucker_prager_loc%line > 0) then
        if (m%dp_hardening_loc%line == 0) then
          call diag%report(m%drucker_prager_loc, '*DRUCKER PRAGER: material ' // m%name // &
                           ' needs a *DRUCKER PRAGER HARDENING curve (its cohesion)')
        else
          limit = max_friction_angle(m%plastic%hardening_type)
          if (m%plastic%friction_angle >= limit .or. m%plastic%dilation_angle >= limit) &
            call diag%report(m%drucker_prager_loc, '*DRUCKER PRAGER: with TYPE=' // &
              m%plastic%hardening_type // ' hardening the friction and dilation angles must ' // &
              'be below ' // str(limit, 5) // ' degrees (tan < 3: the cohesion d = (1 - ' // &
              'tan(beta)/3) sigma_c and the plastic strain of the compression test must stay ' // &
              'positive)')
        end if
      end if
      if (m%cyclic_loc%line > 0 .and. .not. (m%plastic%model == PLASTICITY_MISES .and. &
          m%plastic%hardening == 'COMBINED')) &
        call diag%report(m%cyclic_loc, '*CYCLIC HARDENING: material ' // m%name // ' has no ' // &
                         '*PLASTIC, HARDENING=COMBINED (the cyclic curve is the isotropic part ' // &
                         'of combined hardening)')
      if (m%plastic%model == PLASTICITY_MISES .and. m%cyclic_loc%line == 0) then
        if (m%plastic%hardening == 'COMBINED') call diag%report(m%plastic_loc, &
          '*PLASTIC: HARDENING=COMBINED needs a *CYCLIC HARDENING curve in material ' // m%name // &
          ' (its isotropic part)')
      end if
    end associate
  end subroutine check_plasticity

  !> *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN, once the sections are assigned: the element's
  !> material is elastic (the strain is an eigenstrain, as in CalculiX) or von Mises with a
  !> deviatoric tensor (J2 flow keeps the volume, so a plastic strain with a trace is no state
  !> the material can reach); a Drucker-Prager material, or elastic constants that depend on
  !> temperature (the stress -C : eps_0 would need C at the initial temperature), are
  !> refused. One message per data line.
  subroutine check_initial_plastic_strains(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: i, last_line
    character(len=:), allocatable :: problem
    if (.not. allocated(model%initial_plastic_strains)) return
    last_line = 0
    do i = 1, size(model%initial_plastic_strains)
      associate (item => model%initial_plastic_strains(i))
        if (model%element_section(item%element) < 1) cycle
        problem = plastic_strain_problem(item, &
          model%materials(model%sections(model%element_section(item%element))%material))
        if (len(problem) == 0 .or. item%loc%line == last_line) cycle
        last_line = item%loc%line
        call diag%report(item%loc, '*INITIAL CONDITIONS: TYPE=PLASTIC STRAIN at element ' // &
                         str(model%mesh%element_id(item%element)) // ': ' // problem)
      end associate
    end do
  end subroutine check_initial_plastic_strains

  !> Why material m cannot start from the plastic strain of `item` ('' if it can).
  function plastic_strain_problem(item, m) result(problem)
    type(initial_plastic_strain_t), intent(in) :: item
    type(material_def_t), intent(in) :: m
    character(len=:), allocatable :: problem
    real(dp) :: trace
    problem = ''
    if (m%plastic%model == PLASTICITY_DRUCKER_PRAGER) then
      problem = 'material ' // m%name // ' is Drucker-Prager; initial plastic strains are ' // &
                'available for elastic and von Mises materials'
    else if (m%thermal%elastic_varies()) then
      problem = 'the elastic constants of material ' // m%name // ' depend on temperature; ' // &
                'the initial stress -C : eps_0 is computed with constant ones'
    else if (m%plastic%model == PLASTICITY_MISES) then
      trace = sum(item%strain(1:3))
      if (abs(trace) > TRACE_TOLERANCE * maxval(abs(item%strain))) &
        problem = 'material ' // m%name // ' is von Mises, whose plastic strain is deviatoric ' // &
                  '(plastic flow keeps the volume), but exx + eyy + ezz = ' // str(trace) // &
                  '; give a traceless tensor, or an elastic material for an eigenstrain'
    end if
  end function plastic_strain_problem

  logical function current_material(card, state, diag) result(ok)
    type(card_t), intent(in) :: card
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    ok = state%material > 0
    if (.not. ok) call diag%report(card%loc, '*' // card%keyword // ' must follow a *MATERIAL line')
  end function current_material

  !> A material has one plasticity: *PLASTIC or *DRUCKER PRAGER, once.
  logical function plasticity_free(card, m, diag) result(ok)
    type(card_t), intent(in) :: card
    type(material_def_t), intent(in) :: m
    type(diagnostics_t), intent(inout) :: diag
    type(source_loc_t) :: earlier
    ok = m%plastic%model == PLASTICITY_NONE
    if (ok) return
    earlier = m%plastic_loc
    if (m%plastic%model == PLASTICITY_DRUCKER_PRAGER) earlier = m%drucker_prager_loc
    call diag%report(card%loc, '*' // card%keyword // ': material ' // m%name // ' already has ' // &
                     'its plasticity (line ' // str(earlier%line) // '); a material takes one ' // &
                     '*PLASTIC or one *DRUCKER PRAGER')
  end function plasticity_free

  !> The (stress, plastic strain) points of a hardening card: two numbers per line, stresses
  !> positive, strains from 0 and strictly increasing. `third` says why a third field is
  !> refused.
  logical function read_curve(card, stress_name, third, curve, diag) result(ok)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: stress_name, third
    type(hardening_table_t), intent(out) :: curve
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: stress(card%n_lines), strain(card%n_lines)
    integer :: i, n_before
    ok = .false.
    n_before = diag%count
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (.not. line_point(line, card%keyword, stress_name, third, stress(i), strain(i), diag)) cycle
        if (stress(i) <= 0.0_dp) then
          call diag%report(line%loc, '*' // card%keyword // ': the ' // stress_name // &
                           ' must be positive, not ' // str(stress(i)))
        else if (i == 1 .and. strain(i) /= 0.0_dp) then
          call diag%report(line%loc, '*' // card%keyword // ': the first point must be at ' // &
                           'plastic strain 0 (the initial yield stress), not ' // str(strain(i)))
        end if
      end associate
    end do
    if (diag%count > n_before) return
    do i = 2, card%n_lines
      if (strain(i) <= strain(i - 1)) call diag%report(card%lines(i)%loc, '*' // card%keyword // &
        ': the plastic strains must increase strictly from line to line (' // str(strain(i)) // &
        ' follows ' // str(strain(i - 1)) // ')')
    end do
    ok = diag%count == n_before
    if (ok) then
      curve%strain = strain
      curve%stress = stress
    end if
  end function read_curve

  !> Stress and plastic strain of one data line of a hardening curve.
  logical function line_point(line, keyword, stress_name, third, stress, strain, diag) result(ok)
    type(data_line_t), intent(in) :: line
    character(len=*), intent(in) :: keyword, stress_name, third
    real(dp), intent(out) :: stress, strain
    type(diagnostics_t), intent(inout) :: diag
    integer :: f
    ok = .false.
    stress = 0.0_dp
    strain = 0.0_dp
    do f = 3, size(line%fields)
      if (len(line%fields(f)%s) > 0) then
        call diag%report(line%loc, '*' // keyword // ': ' // third)
        return
      end if
    end do
    if (size(line%fields) < 2) then
      call diag%report(line%loc, '*' // keyword // ': expected ' // stress_name // ', plastic strain')
      return
    end if
    if (.not. line_real(line, 1, stress, stress_name, keyword, diag)) return
    if (.not. line_real(line, 2, strain, 'plastic strain', keyword, diag)) return
    if (strain < 0.0_dp) then
      call diag%report(line%loc, '*' // keyword // ': the plastic strain must not be negative, not ' // &
                       str(strain))
      return
    end if
    ok = .true.
  end function line_point

end module fcs_build_plasticity
