!> Text renderings of the keyword table: the plain list printed by `fcs3d --list-keywords`
!> and the Markdown deck reference `doc/deck_reference.md` (`--list-keywords --markdown`).
module fcs_keyword_docs
  use, intrinsic :: iso_fortran_env, only: output_unit
  use fcs_keywords, only: keyword_spec_t, keyword_table, param_kind_name, context_name, &
                          PARAM_CHOICE, PARAM_FLAG
  use fcs_strings, only: join_strings
  implicit none
  private
  public :: print_keyword_list, print_keyword_reference

contains

  !> One block per keyword: name, origin, where it goes, parameters.
  subroutine print_keyword_list()
    type(keyword_spec_t), allocatable :: table(:)
    integer :: k, j
    table = keyword_table()
    do k = 1, size(table)
      write (output_unit, '(a)') '*' // table(k)%name // '  [' // table(k)%origin // ', ' // &
        context_name(table(k)%context) // ']  ' // table(k)%summary
      do j = 1, size(table(k)%params)
        write (output_unit, '(a)') '    ' // param_line(table(k), j)
      end do
      if (len(table(k)%data) > 0) write (output_unit, '(a)') '    data: ' // table(k)%data
    end do
  end subroutine print_keyword_list

  function param_line(spec, j) result(line)
    type(keyword_spec_t), intent(in) :: spec
    integer, intent(in) :: j
    character(len=:), allocatable :: line
    associate (p => spec%params(j))
      line = p%name
      if (p%kind /= PARAM_FLAG) line = line // '=<' // param_kind_name(p%kind) // '>'
      if (p%required) line = line // ' (required)'
      if (len(p%default) > 0) line = line // ' (default ' // p%default // ')'
      if (p%kind == PARAM_CHOICE) line = line // ' one of ' // join_strings(p%choices, ', ')
      if (len(p%unit) > 0) line = line // ' [' // p%unit // ']'
      if (len(p%description) > 0) line = line // ': ' // p%description
    end associate
  end function param_line

  !> The deck reference in Markdown, generated from the table.
  subroutine print_keyword_reference()
    type(keyword_spec_t), allocatable :: table(:)
    integer :: k, j
    table = keyword_table()
    call put('# fcs3d deck reference')
    call put('')
    call put('Generated from the keyword table of the code by `fcs3d --list-keywords --markdown`;')
    call put('do not edit by hand (`make doc` regenerates it). Keywords, parameter names and set,')
    call put('surface and material names are case-insensitive. Units are the deck''s own: any')
    call put('consistent set (the fault-bend model uses mm, s, MPa, N).')
    call put('"CalculiX" keywords keep their CalculiX/Abaqus meaning, "Abaqus" keywords their Abaqus ' // &
             'meaning; "fcs3d" marks our extensions.')
    call put('')
    call put('| keyword | origin | where | summary |')
    call put('|---|---|---|---|')
    do k = 1, size(table)
      call put('| [`*' // table(k)%name // '`](#' // anchor(table(k)%name) // ') | ' // &
               table(k)%origin // ' | ' // context_name(table(k)%context) // ' | ' // &
               table(k)%summary // ' |')
    end do
    do k = 1, size(table)
      call put('')
      call put('## *' // table(k)%name)
      call put('')
      call put(table(k)%summary // ' (' // table(k)%origin // '; ' // &
               context_name(table(k)%context) // '.)')
      call put('')
      if (size(table(k)%params) > 0) then
        call put('| parameter | value | default | description |')
        call put('|---|---|---|---|')
        do j = 1, size(table(k)%params)
          call put(param_row(table(k), j))
        end do
        call put('')
      end if
      if (len(table(k)%data) > 0) then
        call put('Data lines' // merge(' (required)', '           ', table(k)%data_required) // &
                 ': ' // table(k)%data)
      else
        call put('No data lines.')
      end if
    end do
  end subroutine print_keyword_reference

  function param_row(spec, j) result(row)
    type(keyword_spec_t), intent(in) :: spec
    integer, intent(in) :: j
    character(len=:), allocatable :: row, value, default
    associate (p => spec%params(j))
      if (p%kind == PARAM_CHOICE) then
        value = join_strings(p%choices, ', ')
        if (len(p%flag_value) > 0) value = value // ' (bare flag = ' // p%flag_value // ')'
      else
        value = param_kind_name(p%kind)
      end if
      if (len(p%unit) > 0) value = value // ' [' // p%unit // ']'
      default = p%default
      if (p%required) default = 'required'
      if (len(default) == 0) default = '-'
      row = '| `' // p%name // '` | ' // value // ' | ' // default // ' | ' // p%description // ' |'
    end associate
  end function param_row

  pure function anchor(name) result(out)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: out
    integer :: i
    out = ''
    do i = 1, len(name)
      if (name(i:i) == ' ') then
        out = out // '-'
      else if (name(i:i) >= 'A' .and. name(i:i) <= 'Z') then
        out = out // achar(iachar(name(i:i)) + 32)
      else
        out = out // name(i:i)
      end if
    end do
  end function anchor

  subroutine put(line)
    character(len=*), intent(in) :: line
    write (output_unit, '(a)') line
  end subroutine put

end module fcs_keyword_docs
