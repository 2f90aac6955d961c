!> `<job>.echo`: the deck as the builder understood it - every card of every included file, in
!> reading order, with every parameter default filled in, data lines normalised, and a
!> summary of the model.
!>
!> Written atomically (fcs_text_file): a failed write leaves the previous echo, if any.
module fcs_echo
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_text_file, only: text_file_t
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
    type(text_file_t) :: file
    integer :: i, j
    character(len=:), allocatable :: current_file
    call file%open(path, err, atomic=.true.)
    if (.not. allocated(err)) call write_summary(file, model, err)
    current_file = ''
    do i = 1, deck%n_cards
      if (allocated(err)) exit
      associate (card => deck%cards(i))
        if (card%loc%file /= current_file) then
          current_file = card%loc%file
          call file%write('** --- from ' // current_file // ' ---', err)
        end if
        if (.not. allocated(err)) call file%write(keyword_line(card), err)
        do j = 1, card%n_lines
          if (allocated(err)) exit
          call file%write(join_strings(card%lines(j)%fields, ', '), err)
        end do
      end associate
    end do
    if (.not. allocated(err)) call file%close(err)
    if (allocated(err)) call file%abandon()
  end subroutine write_echo

  !> The header: build, deck, model size, contact penalties.
  subroutine write_summary(file, model, err)
    type(text_file_t), intent(inout) :: file
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    integer :: i
    character(len=:), allocatable :: damping
    call file%write('** ' // FCS3D_IDENTITY, err)
    if (.not. allocated(err)) call file%write('** fcs3d echo of ' // model%deck_path // &
      ': the deck as read, with every default filled in', err)
    if (.not. allocated(err)) call file%write('** model: ' // str(model%mesh%n_nodes) // &
      ' nodes, ' // str(model%mesh%n_elements) // ' elements, ' // str(size(model%materials)) // &
      ' materials, ' // str(size(model%steps)) // ' steps; solver ' // model%solver_name, err)
    do i = 1, size(model%contact_pairs)
      if (allocated(err)) return
      associate (pair => model%contact_pairs(i))
        damping = ''
        if (pair%radiation_damping > 0.0_dp) damping = '; radiation damping eta = ' // &
          str(pair%radiation_damping) // ' [stress time/length]'
        call file%write('** contact pair ' // pair%name // merge(' (tied)', '       ', pair%tied) // &
          ': E_n = ' // str(pair%normal_stiffness) // ', E_t = ' // str(pair%stick_stiffness) // &
          ' [stress/length]; master elements: E = ' // str(pair%master_modulus) // ', mean ' // &
          'thickness h = ' // str(pair%master_thickness) // ' (default E_n = 10 E / h)' // damping, err)
      end associate
    end do
  end subroutine write_summary

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
