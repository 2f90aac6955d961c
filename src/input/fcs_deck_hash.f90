!> Checksums of a deck for restarts: one over the model definition (every card before the
!> first *STEP, as read, plus the mesh's coordinates and connectivity, so that a changed
!> mesh file counts) and one per step (its cards). A restart refuses a deck whose model hash
!> differs from the checkpoint's; steps may be added after the checkpoint's step.
module fcs_deck_hash
  use fcs_checksum, only: checksum_t, checksum_text
  use fcs_deck_lexer, only: deck_t, card_t
  use fcs_model, only: model_t
  use fcs_strings, only: string_t
  implicit none
  private
  public :: hash_deck

contains

  subroutine hash_deck(deck, model)
    type(deck_t), intent(in) :: deck
    type(model_t), intent(inout) :: model
    type(checksum_t) :: model_sum, step_sum
    integer :: i
    logical :: after_first_step
    ! Cards between two steps (an *AMPLITUDE for the next one, say) count with the next step,
    ! so that adding steps after a checkpoint's step leaves the hashes before it unchanged.
    after_first_step = .false.
    allocate (model%step_hashes(0))
    do i = 1, deck%n_cards
      associate (card => deck%cards(i))
        if (card%keyword == 'STEP') after_first_step = .true.
        if (after_first_step) then
          call add_card(step_sum, card)
        else
          call add_card(model_sum, card)
        end if
        if (card%keyword == 'END STEP') then
          model%step_hashes = [model%step_hashes, string_t(checksum_text(step_sum%value))]
          step_sum = checksum_t()
        end if
      end associate
    end do
    call model_sum%add_real(reshape(model%mesh%x, [size(model%mesh%x)]))
    call model_sum%add_int(reshape(model%mesh%connectivity, [size(model%mesh%connectivity)]))
    model%model_hash = checksum_text(model_sum%value)
  end subroutine hash_deck

  !> The card as the echo writes it: keyword, parameters (with defaults), data fields.
  subroutine add_card(sum, card)
    type(checksum_t), intent(inout) :: sum
    type(card_t), intent(in) :: card
    integer :: k, j, f
    call sum%add_text('*' // card%keyword)
    do k = 1, size(card%params)
      call sum%add_text(',' // card%params(k)%name // '=' // card%params(k)%value)
    end do
    do j = 1, card%n_lines
      do f = 1, size(card%lines(j)%fields)
        call sum%add_text(',' // card%lines(j)%fields(f)%s)
      end do
      call sum%add_text(new_line('a'))
    end do
  end subroutine add_card

end module fcs_deck_hash
