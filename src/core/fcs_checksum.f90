!> 64-bit checksums of arrays (FNV-1a over 64-bit words, each step followed by a xor-shift),
!> to verify checkpoint data on read. Not cryptographic: it detects truncation, bit flips and
!> mismatched data, which is its job.
!>
!> Plain word-wise FNV-1a (xor, then multiply by an odd prime modulo 2**64) only carries a
!> change of bit k of a word into bits k..63 of the hash: a change of the top bits (the sign
!> and high exponent bits of a real) was detected with a probability of 1/2 (sign) to 1/2**9,
!> e.g. an even number of sign flips never. The xor-shift folds the high half into the low
!> half at every word, so that every bit of every word reaches every bit of the result.
module fcs_checksum
  use fcs_kinds, only: dp, i8
  implicit none
  private
  public :: checksum_t, checksum_text

  !> FNV-1a 64-bit parameters (Fowler, Noll, Vo).
  integer(i8), parameter :: FNV_OFFSET = -3750763034362895579_i8
  integer(i8), parameter :: FNV_PRIME = 1099511628211_i8

  !> A running checksum; add arrays, then read `value` or `checksum_text`.
  type :: checksum_t
    integer(i8) :: value = FNV_OFFSET
  contains
    procedure :: add_real => checksum_add_real
    procedure :: add_int => checksum_add_int
    procedure :: add_text => checksum_add_text
  end type checksum_t

contains

  !> Mix one 64-bit word (FNV-1a applied word-wise, integer overflow wraps as intended; then
  !> h xor (h >> 32), which carries high bits down).
  elemental integer(i8) function mix(h, word)
    integer(i8), intent(in) :: h, word
    mix = ieor(h, word) * FNV_PRIME
    mix = ieor(mix, shiftr(mix, 32))
  end function mix

  !> Add the bit patterns of real values.
  pure subroutine checksum_add_real(this, values)
    class(checksum_t), intent(inout) :: this
    real(dp), intent(in) :: values(:)
    integer :: i
    do i = 1, size(values)
      this%value = mix(this%value, transfer(values(i), 1_i8))
    end do
  end subroutine checksum_add_real

  pure subroutine checksum_add_int(this, values)
    class(checksum_t), intent(inout) :: this
    integer, intent(in) :: values(:)
    integer :: i
    do i = 1, size(values)
      this%value = mix(this%value, int(values(i), i8))
    end do
  end subroutine checksum_add_int

  pure subroutine checksum_add_text(this, text)
    class(checksum_t), intent(inout) :: this
    character(len=*), intent(in) :: text
    integer :: i
    do i = 1, len(text)
      this%value = mix(this%value, int(iachar(text(i:i)), i8))
    end do
  end subroutine checksum_add_text

  !> The value as 16 hexadecimal digits.
  pure function checksum_text(value) result(text)
    integer(i8), intent(in) :: value
    character(len=16) :: text
    write (text, '(z16.16)') value
  end function checksum_text

end module fcs_checksum
