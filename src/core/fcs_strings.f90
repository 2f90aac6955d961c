!> Small string utilities: case, splitting, strict number parsing, formatting, paths.
module fcs_strings
  use fcs_kinds, only: dp, i8
  implicit none
  private
  public :: string_t, to_upper, to_lower, collapse_spaces, split_fields, split_words
  public :: parse_real, parse_int, is_number_text, str, join_strings, name_index
  public :: dirname, basename, join_path, path_stem, file_exists, replace_all

  !> A variable-length string, for arrays of strings.
  type :: string_t
    character(len=:), allocatable :: s
  end type string_t

  !> Format a value as text (integer, 64-bit integer, real, logical).
  interface str
    module procedure str_int, str_i8, str_real, str_logical
  end interface str

contains

  !> Upper-case copy of `text` (ASCII letters only).
  pure function to_upper(text) result(out)
    character(len=*), intent(in) :: text
    character(len=len(text)) :: out
    integer :: i, c
    out = text
    do i = 1, len(text)
      c = iachar(text(i:i))
      if (c >= iachar('a') .and. c <= iachar('z')) out(i:i) = achar(c - 32)
    end do
  end function to_upper

  !> Lower-case copy of `text` (ASCII letters only).
  pure function to_lower(text) result(out)
    character(len=*), intent(in) :: text
    character(len=len(text)) :: out
    integer :: i, c
    out = text
    do i = 1, len(text)
      c = iachar(text(i:i))
      if (c >= iachar('A') .and. c <= iachar('Z')) out(i:i) = achar(c + 32)
    end do
  end function to_lower

  !> Trim `text` and collapse every run of blanks or tabs into one blank.
  pure function collapse_spaces(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: i
    logical :: in_blank
    out = ''
    in_blank = .false.
    do i = 1, len(text)
      if (text(i:i) == ' ' .or. text(i:i) == achar(9)) then
        in_blank = .true.
      else
        if (in_blank .and. len(out) > 0) out = out // ' '
        out = out // text(i:i)
        in_blank = .false.
      end if
    end do
  end function collapse_spaces

  !> Split `text` at commas; each field is trimmed of blanks and tabs. A trailing comma gives
  !> no empty last field (Abaqus convention for continued lines); empty inner fields are kept.
  pure subroutine split_fields(text, fields)
    character(len=*), intent(in) :: text
    type(string_t), allocatable, intent(out) :: fields(:)
    integer :: i, start, n, last
    type(string_t), allocatable :: tmp(:)
    last = len_trim(text)
    do while (last > 0)
      if (text(last:last) /= achar(9)) exit
      last = last - 1
    end do
    allocate (tmp(count_commas(text(1:last)) + 1))
    n = 0
    start = 1
    do i = 1, last + 1
      if (i > last) then
        n = n + 1
        tmp(n)%s = collapse_spaces(text(start:last))
      else if (text(i:i) == ',') then
        n = n + 1
        tmp(n)%s = collapse_spaces(text(start:i - 1))
        start = i + 1
      end if
    end do
    if (n > 0) then
      if (len(tmp(n)%s) == 0 .and. n > 1) n = n - 1
    end if
    fields = tmp(1:n)
  end subroutine split_fields

  !> The space-separated words of `text` (runs of spaces separate; none at either end).
  pure function split_words(text) result(out)
    character(len=*), intent(in) :: text
    type(string_t), allocatable :: out(:)
    integer :: i, start
    allocate (out(0))
    start = 0
    do i = 1, len(text) + 1
      if (i > len(text)) then
        if (start > 0) out = [out, string_t(text(start:len(text)))]
      else if (text(i:i) == ' ') then
        if (start > 0) out = [out, string_t(text(start:i - 1))]
        start = 0
      else if (start == 0) then
        start = i
      end if
    end do
  end function split_words

  pure integer function count_commas(text) result(n)
    character(len=*), intent(in) :: text
    integer :: i
    n = 0
    do i = 1, len(text)
      if (text(i:i) == ',') n = n + 1
    end do
  end function count_commas

  !> True when `text` is a plain decimal number: [sign] digits [. digits] [(e|d) [sign] digits].
  !> Fortran's list-directed read would accept far more (repeat counts, logicals), so the syntax
  !> is checked here first.
  pure logical function is_number_text(text) result(ok)
    character(len=*), intent(in) :: text
    integer :: i, n, digits_mantissa, digits_exponent
    character :: c
    ok = .false.
    n = len(text)
    if (n == 0) return
    i = 1
    if (text(i:i) == '+' .or. text(i:i) == '-') i = i + 1
    digits_mantissa = 0
    do while (i <= n)
      if (.not. is_digit(text(i:i))) exit
      digits_mantissa = digits_mantissa + 1
      i = i + 1
    end do
    if (i <= n) then
      if (text(i:i) == '.') then
        i = i + 1
        do while (i <= n)
          if (.not. is_digit(text(i:i))) exit
          digits_mantissa = digits_mantissa + 1
          i = i + 1
        end do
      end if
    end if
    if (digits_mantissa == 0) return
    if (i <= n) then
      c = text(i:i)
      if (.not. (c == 'e' .or. c == 'E' .or. c == 'd' .or. c == 'D')) return
      i = i + 1
      if (i <= n) then
        if (text(i:i) == '+' .or. text(i:i) == '-') i = i + 1
      end if
      digits_exponent = 0
      do while (i <= n)
        if (.not. is_digit(text(i:i))) exit
        digits_exponent = digits_exponent + 1
        i = i + 1
      end do
      if (digits_exponent == 0) return
    end if
    ok = (i > n)
  end function is_number_text

  pure logical function is_digit(c)
    character, intent(in) :: c
    is_digit = (c >= '0' .and. c <= '9')
  end function is_digit

  !> Parse a real number strictly; `ok` is false for anything but a finite decimal number.
  subroutine parse_real(text, value, ok)
    character(len=*), intent(in) :: text
    real(dp), intent(out) :: value
    logical, intent(out) :: ok
    integer :: stat
    character(len=:), allocatable :: t
    value = 0.0_dp
    t = trim(adjustl(text))
    ok = is_number_text(t)
    if (.not. ok) return
    ! Refused before the conversion, which would overflow (and trap in DEBUG builds).
    ok = decimal_exponent(t) <= range(value)
    if (.not. ok) return
    read (t, *, iostat=stat) value
    ok = (stat == 0)
    if (ok) ok = (abs(value) <= huge(value))
  end subroutine parse_real

  !> The decimal exponent of a number text that passed is_number_text: floor(log10|x|) up to
  !> one, from its digits and exponent field (-huge for zero). "12.5e3" gives 4.
  pure integer function decimal_exponent(t) result(e)
    character(len=*), intent(in) :: t
    integer :: i, point, first, mark, stat
    integer(i8) :: exponent
    point = 0
    first = 0
    mark = scan(t, 'eEdD')
    if (mark == 0) mark = len(t) + 1
    do i = 1, mark - 1
      if (t(i:i) == '.') point = i
      if (first == 0 .and. is_digit(t(i:i)) .and. t(i:i) /= '0') first = i
    end do
    if (first == 0) then
      e = -huge(e)
      return
    end if
    if (point == 0) point = mark
    if (first < point) then
      e = point - first - 1
    else
      e = point - first
    end if
    if (mark <= len(t)) then
      if (len(t) - mark > 12) then
        exponent = merge(-huge(1_i8), huge(1_i8), t(mark + 1:mark + 1) == '-')
      else
        read (t(mark + 1:), *, iostat=stat) exponent
        if (stat /= 0) exponent = 0
      end if
      e = int(max(-1000000_i8, min(1000000_i8, int(e, i8) + exponent)))
    end if
  end function decimal_exponent

  !> Parse an integer strictly ([sign] digits, within the default integer range).
  subroutine parse_int(text, value, ok)
    character(len=*), intent(in) :: text
    integer, intent(out) :: value
    logical, intent(out) :: ok
    integer :: i, start, stat
    integer(i8) :: wide
    character(len=:), allocatable :: t
    value = 0
    t = trim(adjustl(text))
    ok = .false.
    if (len(t) == 0 .or. len(t) > 18) return
    start = 1
    if (t(1:1) == '+' .or. t(1:1) == '-') start = 2
    if (start > len(t)) return
    do i = start, len(t)
      if (.not. is_digit(t(i:i))) return
    end do
    read (t, *, iostat=stat) wide
    if (stat /= 0) return
    if (abs(wide) > int(huge(value), i8)) return
    value = int(wide)
    ok = .true.
  end subroutine parse_int

  pure function str_int(value) result(out)
    integer, intent(in) :: value
    character(len=:), allocatable :: out
    character(len=24) :: buffer
    write (buffer, '(i0)') value
    out = trim(buffer)
  end function str_int

  pure function str_i8(value) result(out)
    integer(i8), intent(in) :: value
    character(len=:), allocatable :: out
    character(len=24) :: buffer
    write (buffer, '(i0)') value
    out = trim(buffer)
  end function str_i8

  !> Real as text: `digits` significant digits (default 6), no padding.
  pure function str_real(value, digits) result(out)
    real(dp), intent(in) :: value
    integer, intent(in), optional :: digits
    character(len=:), allocatable :: out
    character(len=40) :: buffer
    character(len=20) :: fmt
    integer :: d
    d = 6
    if (present(digits)) d = digits
    if (value /= value) then
      out = 'NaN'
      return
    end if
    if (abs(value) > huge(value)) then
      out = merge('+Inf', '-Inf', value > 0.0_dp)
      return
    end if
    write (fmt, '(a,i0,a,i0,a)') '(1pg', d + 8, '.', d, ')'
    write (buffer, fmt) value
    out = trim(adjustl(buffer))
    out = strip_exponent_padding(out)
  end function str_real

  pure function strip_exponent_padding(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: e, m
    out = trim(text)
    e = index(out, 'E')
    m = e - 1
    if (e == 0) m = len(out)
    if (index(out(1:m), '.') > 0) then
      do while (m > 1)
        if (out(m:m) /= '0') exit
        out = out(1:m - 1) // out(m + 1:)
        m = m - 1
      end do
      if (out(m:m) == '.') out = out(1:m - 1) // out(m + 1:)
    end if
  end function strip_exponent_padding

  pure function str_logical(value) result(out)
    logical, intent(in) :: value
    character(len=:), allocatable :: out
    out = merge('yes', 'no ', value)
    out = trim(out)
  end function str_logical

  !> Index of `name` among `names` (case and surrounding blanks ignored), 0 if it is not there:
  !> the look-up of the factories' registries (friction laws, materials, solvers).
  pure integer function name_index(names, name) result(index)
    type(string_t), intent(in) :: names(:)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: wanted
    wanted = to_upper(trim(adjustl(name)))
    do index = 1, size(names)
      if (to_upper(trim(adjustl(names(index)%s))) == wanted) return
    end do
    index = 0
  end function name_index

  !> Join strings with a separator.
  pure function join_strings(items, separator) result(out)
    type(string_t), intent(in) :: items(:)
    character(len=*), intent(in) :: separator
    character(len=:), allocatable :: out
    integer :: i
    out = ''
    do i = 1, size(items)
      if (i > 1) out = out // separator
      out = out // items(i)%s
    end do
  end function join_strings

  !> Replace every occurrence of `old` in `text` by `new`.
  pure function replace_all(text, old, new) result(out)
    character(len=*), intent(in) :: text, old, new
    character(len=:), allocatable :: out
    integer :: i
    out = ''
    i = 1
    do while (i <= len(text))
      if (i + len(old) - 1 <= len(text) .and. len(old) > 0) then
        if (text(i:i + len(old) - 1) == old) then
          out = out // new
          i = i + len(old)
          cycle
        end if
      end if
      out = out // text(i:i)
      i = i + 1
    end do
  end function replace_all

  !> Directory part of a path ('.' when there is none).
  pure function dirname(path) result(out)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: out
    integer :: k
    k = index(path, '/', back=.true.)
    if (k == 0) then
      out = '.'
    else if (k == 1) then
      out = '/'
    else
      out = path(1:k - 1)
    end if
  end function dirname

  !> File-name part of a path.
  pure function basename(path) result(out)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: out
    out = path(index(path, '/', back=.true.) + 1:)
  end function basename

  !> `name` relative to `directory`, unless `name` is absolute.
  pure function join_path(directory, name) result(out)
    character(len=*), intent(in) :: directory, name
    character(len=:), allocatable :: out
    if (len(name) > 0) then
      if (name(1:1) == '/') then
        out = name
        return
      end if
    end if
    if (directory == '.' .or. len(directory) == 0) then
      out = name
    else
      out = directory // '/' // name
    end if
  end function join_path

  !> Path without its last extension ("dir/job.inp" -> "dir/job").
  pure function path_stem(path) result(out)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: out
    integer :: dot, slash
    dot = index(path, '.', back=.true.)
    slash = index(path, '/', back=.true.)
    if (dot > slash + 1) then
      out = path(1:dot - 1)
    else
      out = path
    end if
  end function path_stem

  !> True when a regular file can be found at `path`.
  logical function file_exists(path)
    character(len=*), intent(in) :: path
    inquire (file=path, exist=file_exists)
  end function file_exists

end module fcs_strings
