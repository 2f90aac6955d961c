!> Checks of the finished model that no single card can make: every element has a section
!> with an elastic material, no element is inverted, the deck has steps.
module fcs_model_checks
  use fcs_kinds, only: dp
  use fcs_diagnostics, only: diagnostics_t
  use fcs_hex8_shape, only: hex8_min_jacobian_ratio
  use fcs_model, only: model_t
  use fcs_strings, only: str
  implicit none
  private
  public :: check_model

  !> How many offending entities are named in one message.
  integer, parameter :: MAX_NAMED = 5

contains

  subroutine check_model(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    call model%mesh%compact()
    if (model%mesh%n_elements == 0) then
      call diag%report_plain(model%deck_path // ': the model has no elements (*ELEMENT or *MESH)')
      return
    end if
    call assign_sections(model, diag)
    call check_materials(model, diag)
    call check_jacobians(model, diag)
    if (size(model%steps) == 0) then
      call diag%report_plain(model%deck_path // ': the deck defines no step (*STEP ... *END STEP): ' // &
                             'nothing to compute')
    end if
  end subroutine check_model

  !> element_section(e) from the *SOLID SECTIONs; an element in two sections or in none is an error.
  subroutine assign_sections(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
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
    call diag%report_plain(model%deck_path // ': ' // str(n_missing) // ' element(s) have no ' // &
                           '*SOLID SECTION (elements' // names(2:) // merge(', ...', '     ', &
                           n_missing > MAX_NAMED) // ')')
  end subroutine assign_sections

  subroutine check_materials(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: s
    do s = 1, size(model%sections)
      associate (m => model%materials(model%sections(s)%material))
        if (.not. m%has_elastic) call diag%report(m%loc, '*MATERIAL: material ' // m%name // &
                                                   ' is used by a section but has no *ELASTIC')
      end associate
    end do
  end subroutine check_materials

  !> Inverted or degenerate elements (det J <= 0 at a Gauss point or node).
  subroutine check_jacobians(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: e, n_bad
    real(dp) :: ratio
    character(len=:), allocatable :: names
    n_bad = 0
    names = ''
    do e = 1, model%mesh%n_elements
      ratio = hex8_min_jacobian_ratio(model%mesh%x(:, model%mesh%connectivity(:, e)))
      if (ratio > 0.0_dp) cycle
      n_bad = n_bad + 1
      if (n_bad <= MAX_NAMED) names = names // ', ' // str(model%mesh%element_id(e))
    end do
    if (n_bad == 0) return
    call diag%report_plain(model%deck_path // ': ' // str(n_bad) // ' element(s) are inverted or ' // &
      'degenerate (Jacobian determinant <= 0): elements ' // names(3:) // &
      merge(', ...', '     ', n_bad > MAX_NAMED) // '. C3D8 numbering: nodes 1-4 go around ' // &
      'one face and 5-8 around the opposite face in the same sense, so that 1-2-3-4 seen from ' // &
      'node 5 is clockwise')
  end subroutine check_jacobians

end module fcs_model_checks
