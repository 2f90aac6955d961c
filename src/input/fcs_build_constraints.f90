!> Handlers of the constraint keywords: *EQUATION (linear equations between displacement
!> components), stored in model%equations as fcs_linear_constraints' plain data. Their
!> resolution (dependent degrees of freedom, cascades) is checked when the model is finished
!> (fcs_model_checks), their elimination done by the stepper (doc/theory.md, 6.2).
module fcs_build_constraints
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t, data_line_t
  use fcs_diagnostics, only: diagnostics_t
  use fcs_deck_fields, only: line_int, line_real, is_integer_text
  use fcs_model, only: model_t
  use fcs_linear_constraints, only: constraint_term_t, linear_equation_t
  use fcs_strings, only: str
  implicit none
  private
  public :: handle_equation

  !> Terms per data line of *EQUATION, as CalculiX reads them (12 entries per line).
  integer, parameter :: MAX_TERMS_PER_LINE = 4

contains

  !> *EQUATION: per equation a line with the number of terms N, then the N terms (node,
  !> direction, coefficient), at most four per line (ccx manual, *EQUATION). The first term's
  !> degree of freedom is the dependent one (eliminated).
  subroutine handle_equation(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(linear_equation_t) :: equation
    integer :: i, n_terms, n_read, n_errors
    logical :: ok
    i = 1
    do while (i <= card%n_lines)
      associate (line => card%lines(i))
        if (size(line%fields) /= 1) then
          call diag%report(line%loc, '*EQUATION: expected the number of terms of the next ' // &
            'equation alone on its line (then node, direction, coefficient for each term, at ' // &
            'most four terms per line)')
          return
        end if
        if (.not. line_int(line, 1, n_terms, 'number of terms', 'EQUATION', diag)) return
        if (n_terms < 1) then
          call diag%report(line%loc, '*EQUATION: the number of terms must be at least 1, not ' // &
                           str(n_terms))
          return
        end if
      end associate
      allocate (equation%terms(n_terms))
      n_read = 0
      n_errors = diag%count
      i = i + 1
      do while (n_read < n_terms)
        if (i > card%n_lines) then
          call diag%report(card%lines(card%n_lines)%loc, '*EQUATION: the equation announces ' // &
            str(n_terms) // ' terms, ' // str(n_read) // ' follow')
          return
        end if
        if (n_read == 0) equation%loc = card%lines(i)%loc
        call read_terms(card%lines(i), model, n_terms, equation%terms, n_read, ok, diag)
        if (.not. ok) return
        i = i + 1
      end do
      if (diag%count > n_errors) then
        deallocate (equation%terms)
        cycle
      end if
      if (equation%terms(1)%coefficient == 0.0_dp) then
        call diag%report(equation%loc, '*EQUATION: the coefficient of the first term (the ' // &
          'dependent degree of freedom) must not be zero')
      else
        equation%origin = '*EQUATION'
        model%equations = [model%equations, equation]
      end if
      deallocate (equation%terms)
    end do
  end subroutine handle_equation

  !> The terms of one data line (node, direction, coefficient, ...) into terms(n_read+1:).
  !> `ok` is false when the line's shape is wrong (the rest of the card cannot be read).
  subroutine read_terms(line, model, n_terms, terms, n_read, ok, diag)
    type(data_line_t), intent(in) :: line
    type(model_t), intent(in) :: model
    integer, intent(in) :: n_terms
    type(constraint_term_t), intent(inout) :: terms(:)
    integer, intent(inout) :: n_read
    logical, intent(out) :: ok
    type(diagnostics_t), intent(inout) :: diag
    integer :: n_fields, k, id, node, dof
    real(dp) :: coefficient
    n_fields = size(line%fields)
    ok = .false.
    if (n_fields == 0 .or. mod(n_fields, 3) /= 0 .or. n_fields > 3 * MAX_TERMS_PER_LINE) then
      call diag%report(line%loc, '*EQUATION: expected node, direction, coefficient for each ' // &
        'term, at most four terms per line (' // str(n_fields) // ' fields)')
      return
    end if
    if (n_read + n_fields / 3 > n_terms) then
      call diag%report(line%loc, '*EQUATION: more terms than the ' // str(n_terms) // &
                       ' the equation announces')
      return
    end if
    ok = .true.
    do k = 1, n_fields / 3
      n_read = n_read + 1
      if (.not. is_integer_text(line%fields(3 * k - 2)%s)) then
        call diag%report(line%loc, '*EQUATION: term ' // str(n_read) // ': expected a node ' // &
          'number, not "' // line%fields(3 * k - 2)%s // '" (a node set is not a term of ' // &
          '*EQUATION, in CalculiX 2.20 either)')
        cycle
      end if
      if (.not. line_int(line, 3 * k - 2, id, 'node', 'EQUATION', diag)) cycle
      node = model%mesh%node_index(id)
      if (node == 0) then
        call diag%report(line%loc, '*EQUATION: term ' // str(n_read) // ': node ' // str(id) // &
                         ' is not defined')
        cycle
      end if
      if (.not. line_int(line, 3 * k - 1, dof, 'direction', 'EQUATION', diag)) cycle
      if (dof < 1 .or. dof > 3) then
        call diag%report(line%loc, '*EQUATION: term ' // str(n_read) // ': direction ' // &
          str(dof) // ' is not a displacement component of a solid node (1, 2 or 3)')
        cycle
      end if
      if (.not. line_real(line, 3 * k, coefficient, 'coefficient', 'EQUATION', diag)) cycle
      terms(n_read) = constraint_term_t(node, dof, coefficient)
    end do
  end subroutine read_terms

end module fcs_build_constraints
