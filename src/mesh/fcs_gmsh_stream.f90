!> Buffered reading of a gmsh `.msh` file: text lines split into blank-separated tokens, and the
!> raw data of binary files, with the position (line, or byte in binary files) kept for messages.
!>
!> The file is opened with stream access and read in chunks of CHUNK_SIZE bytes, so that a text
!> line costs one `index` search and one copy; binary items are read straight into typed arrays
!> after checking that the file holds enough bytes. Numbers are parsed by hand: integers exactly,
!> reals with Clinger's fast path (W. D. Clinger, "How to read floating point numbers
!> accurately", PLDI 1990: a mantissa below 2**53 times or divided by an exact power of ten
!> up to 1e22 is one correctly rounded operation), falling back to Fortran's own conversion
!> otherwise. Used by `fcs_gmsh_reader`.
module fcs_gmsh_stream
  use, intrinsic :: iso_fortran_env, only: int32
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, input_error
  use fcs_files, only: file_kind, file_kind_name, FILE_REGULAR
  use fcs_strings, only: str
  implicit none
  private
  public :: msh_stream_t, parse_int8, parse_real_fast, is_finite_bits

  !> Bytes read from the file at a time.
  integer, parameter :: CHUNK_SIZE = 1048576
  character(len=1), parameter :: LF = achar(10), CR = achar(13), TAB = achar(9)
  !> Exact powers of ten for the fast path (10**22 is the largest exact in binary64).
  real(dp), parameter :: POW10(0:22) = [1.0e0_dp, 1.0e1_dp, 1.0e2_dp, 1.0e3_dp, 1.0e4_dp, &
    1.0e5_dp, 1.0e6_dp, 1.0e7_dp, 1.0e8_dp, 1.0e9_dp, 1.0e10_dp, 1.0e11_dp, 1.0e12_dp, &
    1.0e13_dp, 1.0e14_dp, 1.0e15_dp, 1.0e16_dp, 1.0e17_dp, 1.0e18_dp, 1.0e19_dp, 1.0e20_dp, &
    1.0e21_dp, 1.0e22_dp]
  !> 2**53: mantissas up to this value convert to binary64 exactly.
  integer(i8), parameter :: EXACT_MANTISSA = 9007199254740992_i8

  !> An open `.msh` file. `line(1:line_length)` is the current text line, split into
  !> `n_tokens` tokens `line(token_start(i):token_end(i))`.
  type :: msh_stream_t
    character(len=:), allocatable :: path
    !> Section being read ("$Nodes"), for messages; empty outside sections.
    character(len=:), allocatable :: section
    !> True once $MeshFormat said the file is binary: messages then give byte offsets.
    logical :: binary = .false.
    integer :: line_number = 0
    character(len=:), allocatable :: line
    integer :: line_length = 0
    integer :: n_tokens = 0
    integer, allocatable :: token_start(:), token_end(:)
    integer :: unit = -1
    integer(i8) :: file_size = 0
    character(len=:), allocatable :: chunk
    integer :: pos = 1
    integer :: fill = 0
    integer(i8) :: chunk_start = 1
    integer(i8) :: item_offset = 0
    logical :: read_failed = .false.
  contains
    procedure :: open => stream_open
    procedure :: close => stream_close
    procedure :: next_line => stream_next_line
    procedure :: token => stream_token
    procedure :: get_int => stream_get_int
    procedure :: get_real => stream_get_real
    procedure :: remaining => stream_remaining
    procedure :: read_int32 => stream_read_int32
    procedure :: read_size => stream_read_size
    procedure :: read_int32_array => stream_read_int32_array
    procedure :: read_size_array => stream_read_size_array
    procedure :: read_real_array => stream_read_real_array
    procedure :: skip_bytes => stream_skip_bytes
    procedure :: fail => stream_fail
  end type msh_stream_t

contains

  !> Open `path` for reading. On failure `err` is an input error naming the file.
  subroutine stream_open(this, path, err)
    class(msh_stream_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    integer :: stat
    character(len=256) :: message
    logical :: exists
    this%path = path
    this%section = ''
    this%binary = .false.
    this%line_number = 0
    this%line_length = 0
    this%n_tokens = 0
    this%pos = 1
    this%fill = 0
    this%chunk_start = 1
    this%item_offset = 0
    this%read_failed = .false.
    inquire (file=path, exist=exists)
    if (.not. exists) then
      call input_error(err, path // ': the gmsh mesh file does not exist')
      return
    end if
    if (file_kind(path) /= FILE_REGULAR) then
      call input_error(err, path // ': is ' // file_kind_name(file_kind(path)) // &
        ', not a gmsh mesh file')
      return
    end if
    open (newunit=this%unit, file=path, access='stream', form='unformatted', status='old', &
      action='read', iostat=stat, iomsg=message)
    if (stat /= 0) then
      this%unit = -1
      call input_error(err, path // ': cannot open the gmsh mesh file: ' // trim(message))
      return
    end if
    inquire (unit=this%unit, size=this%file_size)
    if (this%file_size < 0) this%file_size = 0
    if (.not. allocated(this%chunk)) allocate (character(len=CHUNK_SIZE) :: this%chunk)
    if (.not. allocated(this%line)) allocate (character(len=256) :: this%line)
    if (.not. allocated(this%token_start)) allocate (this%token_start(16), this%token_end(16))
  end subroutine stream_open

  !> Close the file (if open).
  subroutine stream_close(this)
    class(msh_stream_t), intent(inout) :: this
    if (this%unit /= -1) close (this%unit)
    this%unit = -1
  end subroutine stream_close

  !> 1-based file position of the next unread byte.
  pure integer(i8) function position(this)
    type(msh_stream_t), intent(in) :: this
    position = this%chunk_start + this%pos - 1
  end function position

  !> Number of bytes not yet read.
  pure integer(i8) function stream_remaining(this) result(left)
    class(msh_stream_t), intent(in) :: this
    left = max(0_i8, this%file_size - position(this) + 1)
  end function stream_remaining

  !> Read the next text line into `line` (without its LF or CRLF) and split it into tokens.
  !> `found` is false at the end of the file.
  subroutine stream_next_line(this, found)
    class(msh_stream_t), intent(inout) :: this
    logical, intent(out) :: found
    integer :: k
    this%line_length = 0
    this%n_tokens = 0
    this%item_offset = position(this) - 1
    found = .false.
    do
      if (this%pos > this%fill) then
        call refill(this)
        if (this%fill == 0) exit
      end if
      found = .true.
      k = index(this%chunk(this%pos:this%fill), LF)
      if (k == 0) then
        call append_to_line(this, this%pos, this%fill)
        this%pos = this%fill + 1
      else
        call append_to_line(this, this%pos, this%pos + k - 2)
        this%pos = this%pos + k
        exit
      end if
    end do
    if (.not. found) return
    this%line_number = this%line_number + 1
    if (this%line_length > 0) then
      if (this%line(this%line_length:this%line_length) == CR) this%line_length = this%line_length - 1
    end if
    call split_tokens(this)
  end subroutine stream_next_line

  !> Move past the consumed chunk and read the next one (fill = 0 at the end of the file).
  subroutine refill(this)
    type(msh_stream_t), intent(inout) :: this
    integer(i8) :: left
    integer :: n, stat
    this%chunk_start = this%chunk_start + this%fill
    this%pos = 1
    this%fill = 0
    left = this%file_size - this%chunk_start + 1
    if (left <= 0 .or. this%read_failed) return
    n = int(min(int(CHUNK_SIZE, i8), left))
    read (this%unit, pos=this%chunk_start, iostat=stat) this%chunk(1:n)
    if (stat /= 0) then
      this%read_failed = .true.
      return
    end if
    this%fill = n
  end subroutine refill

  !> Append chunk(first:last) to the current line, growing the line buffer as needed.
  subroutine append_to_line(this, first, last)
    type(msh_stream_t), intent(inout) :: this
    integer, intent(in) :: first, last
    character(len=:), allocatable :: grown
    integer :: n
    n = last - first + 1
    if (n <= 0) return
    if (this%line_length + n > len(this%line)) then
      allocate (character(len=max(2 * len(this%line), this%line_length + n)) :: grown)
      grown(1:this%line_length) = this%line(1:this%line_length)
      call move_alloc(grown, this%line)
    end if
    this%line(this%line_length + 1:this%line_length + n) = this%chunk(first:last)
    this%line_length = this%line_length + n
  end subroutine append_to_line

  !> Split the current line at blanks and tabs.
  subroutine split_tokens(this)
    type(msh_stream_t), intent(inout) :: this
    integer :: i
    logical :: in_token
    character :: c
    in_token = .false.
    do i = 1, this%line_length
      c = this%line(i:i)
      if (c == ' ' .or. c == TAB .or. c == CR) then
        if (in_token) this%token_end(this%n_tokens) = i - 1
        in_token = .false.
      else if (.not. in_token) then
        if (this%n_tokens == size(this%token_start)) call grow_tokens(this)
        this%n_tokens = this%n_tokens + 1
        this%token_start(this%n_tokens) = i
        in_token = .true.
      end if
    end do
    if (in_token) this%token_end(this%n_tokens) = this%line_length
  end subroutine split_tokens

  subroutine grow_tokens(this)
    type(msh_stream_t), intent(inout) :: this
    integer, allocatable :: grown(:)
    allocate (grown(2 * size(this%token_start)))
    grown(1:size(this%token_start)) = this%token_start
    call move_alloc(grown, this%token_start)
    allocate (grown(2 * size(this%token_end)))
    grown(1:size(this%token_end)) = this%token_end
    call move_alloc(grown, this%token_end)
  end subroutine grow_tokens

  !> Copy of token `i` of the current line ('' if there is none).
  function stream_token(this, i) result(text)
    class(msh_stream_t), intent(in) :: this
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    if (i < 1 .or. i > this%n_tokens) then
      text = ''
    else
      text = this%line(this%token_start(i):this%token_end(i))
    end if
  end function stream_token

  !> Token `i` as an integer; `ok` is false if missing or not an integer.
  subroutine stream_get_int(this, i, value, ok)
    class(msh_stream_t), intent(in) :: this
    integer, intent(in) :: i
    integer(i8), intent(out) :: value
    logical, intent(out) :: ok
    value = 0
    ok = .false.
    if (i < 1 .or. i > this%n_tokens) return
    call parse_int8(this%line(this%token_start(i):this%token_end(i)), value, ok)
  end subroutine stream_get_int

  !> Token `i` as a finite real; `ok` is false if missing or not a number.
  subroutine stream_get_real(this, i, value, ok)
    class(msh_stream_t), intent(in) :: this
    integer, intent(in) :: i
    real(dp), intent(out) :: value
    logical, intent(out) :: ok
    value = 0.0_dp
    ok = .false.
    if (i < 1 .or. i > this%n_tokens) return
    call parse_real_fast(this%line(this%token_start(i):this%token_end(i)), value, ok)
  end subroutine stream_get_real

  !> Parse a decimal integer ([sign] digits) into a 64-bit integer, rejecting overflow.
  pure subroutine parse_int8(text, value, ok)
    character(len=*), intent(in) :: text
    integer(i8), intent(out) :: value
    logical, intent(out) :: ok
    integer :: i, first, digit
    logical :: negative
    value = 0
    ok = .false.
    if (len(text) == 0) return
    negative = text(1:1) == '-'
    first = 1
    if (text(1:1) == '-' .or. text(1:1) == '+') first = 2
    if (first > len(text)) return
    do i = first, len(text)
      digit = iachar(text(i:i)) - iachar('0')
      if (digit < 0 .or. digit > 9) return
      if (value > (huge(value) - digit) / 10) return
      value = 10 * value + digit
    end do
    if (negative) value = -value
    ok = .true.
  end subroutine parse_int8

  !> Parse a decimal real: [sign] digits [. digits] [(e|E) [sign] digits] (a mantissa digit is
  !> required before or after the point). `ok` is false for anything else and for magnitudes
  !> of 1e308 or more (rejected before conversion, so that no overflow trap can fire); values
  !> below 1e-345 are zero.
  subroutine parse_real_fast(text, value, ok)
    character(len=*), intent(in) :: text
    real(dp), intent(out) :: value
    logical, intent(out) :: ok
    integer(i8) :: mantissa
    integer :: i, n, exponent, digits, stat, magnitude
    logical :: negative, exact
    value = 0.0_dp
    n = len(text)
    call scan_decimal(text, mantissa, exponent, i, digits, exact)
    ok = digits > 0 .and. i == n + 1
    if (.not. ok) return
    negative = text(1:1) == '-'
    if (mantissa == 0) return
    magnitude = exponent + digits_of(mantissa) - 1
    if (magnitude >= 308) then
      ok = .false.
      return
    else if (magnitude < -345) then
      return
    end if
    if (exact .and. mantissa <= EXACT_MANTISSA .and. abs(exponent) <= 22) then
      if (exponent >= 0) then
        value = real(mantissa, dp) * POW10(exponent)
      else
        value = real(mantissa, dp) / POW10(-exponent)
      end if
      if (negative) value = -value
      return
    end if
    read (text, *, iostat=stat) value
    ok = stat == 0
    if (ok) ok = abs(value) <= huge(value)
  end subroutine parse_real_fast

  !> True if `x` is finite, decided from its exponent bits (binary64: finite unless all 11 are
  !> set), so that no comparison touches a NaN read from a corrupt binary file: with
  !> floating-point traps enabled a signalling NaN would stop the program.
  elemental logical function is_finite_bits(x)
    real(dp), intent(in) :: x
    is_finite_bits = iand(ishft(transfer(x, 0_i8), -52), 2047_i8) /= 2047_i8
  end function is_finite_bits

  !> Number of decimal digits of a positive integer.
  pure integer function digits_of(value) result(n)
    integer(i8), intent(in) :: value
    integer(i8) :: rest
    n = 0
    rest = value
    do while (rest > 0)
      n = n + 1
      rest = rest / 10
    end do
  end function digits_of

  !> Scan a decimal real from the start of `text`: mantissa digits as an integer, the decimal
  !> exponent that goes with it, the position after the number, the number of mantissa digits,
  !> and whether the mantissa was kept exactly (false if it has too many digits).
  pure subroutine scan_decimal(text, mantissa, exponent, next, digits, exact)
    character(len=*), intent(in) :: text
    integer(i8), intent(out) :: mantissa
    integer, intent(out) :: exponent, next, digits
    logical, intent(out) :: exact
    integer :: i, n, digit, exponent_digits, exponent_value
    logical :: after_point, negative_exponent
    mantissa = 0
    exponent = 0
    digits = 0
    exact = .true.
    after_point = .false.
    n = len(text)
    i = 1
    if (n > 0) then
      if (text(1:1) == '-' .or. text(1:1) == '+') i = 2
    end if
    do while (i <= n)
      if (text(i:i) == '.' .and. .not. after_point) then
        after_point = .true.
      else
        digit = iachar(text(i:i)) - iachar('0')
        if (digit < 0 .or. digit > 9) exit
        digits = digits + 1
        if (mantissa < 100000000000000000_i8) then
          mantissa = 10 * mantissa + digit
          if (after_point) exponent = exponent - 1
        else
          exact = .false.
          if (.not. after_point) exponent = exponent + 1
        end if
      end if
      i = i + 1
    end do
    next = i
    if (i > n .or. digits == 0) return
    if (text(i:i) /= 'e' .and. text(i:i) /= 'E') return
    i = i + 1
    negative_exponent = .false.
    if (i <= n) then
      negative_exponent = text(i:i) == '-'
      if (text(i:i) == '-' .or. text(i:i) == '+') i = i + 1
    end if
    exponent_digits = 0
    exponent_value = 0
    do while (i <= n)
      digit = iachar(text(i:i)) - iachar('0')
      if (digit < 0 .or. digit > 9) exit
      exponent_digits = exponent_digits + 1
      if (exponent_value < 100000) exponent_value = 10 * exponent_value + digit
      i = i + 1
    end do
    if (exponent_digits == 0) return
    if (negative_exponent) exponent_value = -exponent_value
    exponent = exponent + exponent_value
    next = i
  end subroutine scan_decimal

  !> Check that `n_bytes` remain and note where the binary item starts.
  subroutine begin_binary(this, n_bytes, start, ok)
    type(msh_stream_t), intent(inout) :: this
    integer(i8), intent(in) :: n_bytes
    integer(i8), intent(out) :: start
    logical, intent(out) :: ok
    start = position(this)
    this%item_offset = start - 1
    ok = n_bytes >= 0 .and. n_bytes <= this%file_size - start + 1
  end subroutine begin_binary

  !> Continue after a binary item of `n_bytes` read directly from the file.
  subroutine end_binary(this, start, n_bytes)
    type(msh_stream_t), intent(inout) :: this
    integer(i8), intent(in) :: start, n_bytes
    this%chunk_start = start + n_bytes
    this%pos = 1
    this%fill = 0
  end subroutine end_binary

  !> Read a 4-byte binary integer (gmsh `int`). `ok` is false if the file ends first.
  subroutine stream_read_int32(this, value, ok)
    class(msh_stream_t), intent(inout) :: this
    integer, intent(out) :: value
    logical, intent(out) :: ok
    integer(int32) :: buffer(1)
    call this%read_int32_array(buffer, ok)
    value = int(buffer(1))
  end subroutine stream_read_int32

  !> Read an 8-byte binary unsigned size (gmsh `size_t`); `ok` is false if the file ends first
  !> or the value does not fit a signed 64-bit integer.
  subroutine stream_read_size(this, value, ok)
    class(msh_stream_t), intent(inout) :: this
    integer(i8), intent(out) :: value
    logical, intent(out) :: ok
    integer(i8) :: buffer(1, 1)
    call this%read_size_array(buffer, ok)
    value = buffer(1, 1)
    if (ok) ok = value >= 0
  end subroutine stream_read_size

  !> Read 4-byte binary integers into `values`.
  subroutine stream_read_int32_array(this, values, ok)
    class(msh_stream_t), intent(inout) :: this
    integer(int32), intent(out) :: values(:)
    logical, intent(out) :: ok
    integer(i8) :: start, n_bytes
    integer :: stat
    values = 0
    n_bytes = 4_i8 * size(values, kind=i8)
    call begin_binary(this, n_bytes, start, ok)
    if (.not. ok .or. n_bytes == 0) return
    read (this%unit, pos=start, iostat=stat) values
    ok = stat == 0
    call end_binary(this, start, n_bytes)
  end subroutine stream_read_int32_array

  !> Read 8-byte binary integers (gmsh `size_t`) into `values` (column-major order).
  subroutine stream_read_size_array(this, values, ok)
    class(msh_stream_t), intent(inout) :: this
    integer(i8), intent(out) :: values(:, :)
    logical, intent(out) :: ok
    integer(i8) :: start, n_bytes
    integer :: stat
    values = 0
    n_bytes = 8_i8 * size(values, kind=i8)
    call begin_binary(this, n_bytes, start, ok)
    if (.not. ok .or. n_bytes == 0) return
    read (this%unit, pos=start, iostat=stat) values
    ok = stat == 0
    call end_binary(this, start, n_bytes)
  end subroutine stream_read_size_array

  !> Read 8-byte binary reals into `values` (column-major order).
  subroutine stream_read_real_array(this, values, ok)
    class(msh_stream_t), intent(inout) :: this
    real(dp), intent(out) :: values(:, :)
    logical, intent(out) :: ok
    integer(i8) :: start, n_bytes
    integer :: stat
    values = 0.0_dp
    n_bytes = 8_i8 * size(values, kind=i8)
    call begin_binary(this, n_bytes, start, ok)
    if (.not. ok .or. n_bytes == 0) return
    read (this%unit, pos=start, iostat=stat) values
    ok = stat == 0
    call end_binary(this, start, n_bytes)
  end subroutine stream_read_real_array

  !> Skip `n_bytes` of binary data; `ok` is false if the file is shorter.
  subroutine stream_skip_bytes(this, n_bytes, ok)
    class(msh_stream_t), intent(inout) :: this
    integer(i8), intent(in) :: n_bytes
    logical, intent(out) :: ok
    integer(i8) :: start
    call begin_binary(this, n_bytes, start, ok)
    if (ok) call end_binary(this, start, n_bytes)
  end subroutine stream_skip_bytes

  !> Input error at the current position: "path:line: message" in text files,
  !> "path: $Section (byte N): message" in binary files.
  subroutine stream_fail(this, err, message)
    class(msh_stream_t), intent(in) :: this
    type(error_t), allocatable, intent(out) :: err
    character(len=*), intent(in) :: message
    character(len=:), allocatable :: where
    if (this%binary) then
      where = this%path // ':'
      if (len(this%section) > 0) where = where // ' ' // this%section
      where = where // ' (byte ' // str(this%item_offset) // ')'
    else
      where = this%path // ':' // str(this%line_number)
    end if
    if (this%read_failed) then
      call input_error(err, where // ': ' // message // ' (a read error occurred on the file)')
    else
      call input_error(err, where // ': ' // message)
    end if
  end subroutine stream_fail

end module fcs_gmsh_stream
