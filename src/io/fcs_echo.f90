!> `<job>.echo`: the deck as the builder understood it - every card of every included file, in
!> reading order, with every parameter default filled in, data lines normalised, and a
!> summary of the model.
module fcs_echo
  use fcs_error, only: error_t, fatal_error
  use fcs_deck_lexer, only: deck_t, card_t
  use fcs_model, only: model_t
  use fcs_strings, only: str, join_strings
  use fcs_version, only: FCS3D_IDENTITY
  implicit none
  private
  public :: write_echo

contains

  subroutine write_echo(path, deck, model, err)
    character(len=*), intent(in) :: path
    type(deck_t), intent(in) :: deck
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    integer :: unit, stat, i, j
    character(len=256) :: msg
    character(len=:), allocatable :: current_file
    open (newunit=unit, file=path, action='write', iostat=stat, iomsg=msg)
    if (stat /= 0) then
      call fatal_error(err, 'writing the echo ' // path // ': ' // trim(msg))
      return
    end if
    write (unit, '(a)') '** ' // FCS3D_IDENTITY
    write (unit, '(a)') '** fcs3d echo of ' // model%deck_path // ': the deck as read, with ' // &
                        'every default filled in'
    write (unit, '(a)') '** model: ' // str(model%mesh%n_nodes) // ' nodes, ' // &
      str(model%mesh%n_elements) // ' elements, ' // str(size(model%materials)) // &
      ' materials, ' // str(size(model%steps)) // ' steps; solver ' // model%solver_name
    do i = 1, size(model%contact_pairs)
      associate (pair => model%contact_pairs(i))
        write (unit, '(a)') '** contact pair ' // pair%name // merge(' (tied)', '       ', pair%tied) // &
          ': E_n = ' // str(pair%normal_stiffness) // ', E_t = ' // str(pair%stick_stiffness) // &
          ' [stress/length]; master elements: E = ' // str(pair%master_modulus) // ', mean ' // &
          'thickness h = ' // str(pair%master_thickness) // ' (default E_n = 10 E / h)'
      end associate
    end do
    current_file = ''
    do i = 1, deck%n_cards
      associate (card => deck%cards(i))
        if (card%loc%file /= current_file) then
          current_file = card%loc%file
          write (unit, '(a)') '** --- from ' // current_file // ' ---'
        end if
        write (unit, '(a)') keyword_line(card)
        do j = 1, card%n_lines
          write (unit, '(a)') join_strings(card%lines(j)%fields, ', ')
        end do
      end associate
    end do
    close (unit)
  end subroutine write_echo

  function keyword_line(card) result(line)
    type(card_t), intent(in) :: card
    character(len=:), allocatable :: line
    integer :: k
    line = '*' // card%keyword
    do k = 1, size(card%params)
      line = line // ', ' // card%params(k)%name
      if (card%params(k)%has_value) line = line // '=' // card%params(k)%value
    end do
  end function keyword_line

end module fcs_echo
