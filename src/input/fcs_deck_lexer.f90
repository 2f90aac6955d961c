!> The deck lexer: reads a keyword deck in the Abaqus/CalculiX conventions into cards.
!>
!> A card is one keyword line (`*KEYWORD, PARAM=value, FLAG`) with the data lines that follow
!> it. Conventions (Abaqus Keywords Reference, "Input syntax rules"; CalculiX ccx manual §6):
!> lines starting with `**` are comments; blank lines are skipped; keywords, parameter names
!> and (later, by the builder) set and material names are case-insensitive; a line that ends
!> with a comma does not run on into the next one, as in CalculiX: the comma is dropped and
!> the data line marked `continued`, which only an unfinished *ELEMENT record uses (the builder
!> joins it with the next line, `element_records`); `*INCLUDE, INPUT=file` inserts a
!> file, its path relative to the including file. Each card and data line keeps its source
!> location so that every later error can say `file:line:`. A tab counts as a blank (a keyword
!> or comment may be indented with tabs); a UTF-8 byte-order mark at the start of a file is
!> skipped. The deck and every included file must be regular files: a directory, a FIFO or a
!> device is refused before it is opened (a FIFO without a writer would block for ever).
module fcs_deck_lexer
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_diagnostics, only: source_loc_t, diagnostics_t
  use fcs_strings, only: string_t, split_fields, to_upper, collapse_spaces, dirname, join_path, &
                         str
  use fcs_files, only: file_kind, file_kind_name, FILE_REGULAR, FILE_MISSING
  implicit none
  private
  public :: deck_t, card_t, param_t, data_line_t, read_deck, MAX_INCLUDE_DEPTH

  !> Deepest nesting of *INCLUDE before the reader assumes a cycle it could not see.
  integer, parameter :: MAX_INCLUDE_DEPTH = 32
  !> Longest line accepted, in characters.
  integer, parameter :: MAX_LINE_LENGTH = 100000
  !> The UTF-8 byte-order mark, as byte values.
  integer, parameter :: UTF8_BOM(3) = [239, 187, 191]

  !> One parameter of a keyword line: upper-case name, value as written (trimmed).
  type :: param_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: value
    logical :: has_value = .false.
  end type param_t

  !> One data line split into comma-separated fields. `continued`: the line ended with a
  !> comma (dropped from the fields).
  type :: data_line_t
    type(string_t), allocatable :: fields(:)
    type(source_loc_t) :: loc
    logical :: continued = .false.
  end type data_line_t

  !> A keyword line and its data lines.
  type :: card_t
    character(len=:), allocatable :: keyword
    type(param_t), allocatable :: params(:)
    type(data_line_t), allocatable :: lines(:)
    integer :: n_lines = 0
    type(source_loc_t) :: loc
    !> The keyword line ended with a comma (dropped): its parameters end there.
    logical :: trailing_comma = .false.
  contains
    procedure :: find_param => card_find_param
  end type card_t

  !> The whole deck: cards in reading order and every file read (for the echo and hashes).
  type :: deck_t
    type(card_t), allocatable :: cards(:)
    integer :: n_cards = 0
    type(string_t), allocatable :: files(:)
  end type deck_t

  !> State while reading: the include stack (for cycle detection), and the number of the last
  !> line of the top-level file read.
  type :: reader_t
    type(string_t), allocatable :: stack(:)
    integer :: last_line = 0
  end type reader_t

contains

  !> Read `path` and every file it includes into `deck`. Problems go to `diag`; an unreadable
  !> top-level file is reported there too.
  subroutine read_deck(path, deck, diag)
    character(len=*), intent(in) :: path
    type(deck_t), intent(out) :: deck
    type(diagnostics_t), intent(inout) :: diag
    type(reader_t) :: reader
    type(source_loc_t) :: nowhere
    allocate (deck%cards(16), deck%files(0), reader%stack(0))
    call read_file(reader, path, nowhere, deck, diag)
    deck%cards = deck%cards(1:deck%n_cards)
    if (deck%n_cards == 0 .and. .not. diag%has_errors()) then
      call diag%report(loc_of(path, max(1, reader%last_line), ''), 'the deck is empty: it ' // &
        'holds no keyword lines (a deck starts with a line such as *HEADING or *NODE)')
    end if
  end subroutine read_deck

  recursive subroutine read_file(reader, path, included_from, deck, diag)
    type(reader_t), intent(inout) :: reader
    character(len=*), intent(in) :: path
    type(source_loc_t), intent(in) :: included_from
    type(deck_t), intent(inout) :: deck
    type(diagnostics_t), intent(inout) :: diag
    integer :: unit, stat, line_no, i
    character(len=256) :: msg
    character(len=:), allocatable :: line
    logical :: eof, already_open
    do i = 1, size(reader%stack)
      if (reader%stack(i)%s == path) then
        call diag%report(included_from, '*INCLUDE: "' // path // '" includes itself ' // &
                         '(include cycle: ' // stack_text(reader) // ' -> ' // path // ')')
        return
      end if
    end do
    ! The same file under another spelling ("dir/../deck.inp"): it is still open for reading.
    inquire (file=path, opened=already_open)
    if (already_open) then
      call diag%report(included_from, '*INCLUDE: "' // path // '" includes itself ' // &
                       '(include cycle: ' // stack_text(reader) // ' -> ' // path // ')')
      return
    end if
    if (size(reader%stack) >= MAX_INCLUDE_DEPTH) then
      call diag%report(included_from, '*INCLUDE: nested more than ' // str(MAX_INCLUDE_DEPTH) // &
                       ' levels deep')
      return
    end if
    if (.not. is_regular(path, included_from, diag)) return
    open (newunit=unit, file=path, action='read', status='old', access='sequential', &
          form='formatted', iostat=stat, iomsg=msg)
    if (stat /= 0) then
      if (allocated(included_from%file)) then
        call diag%report(included_from, '*INCLUDE: cannot open "' // path // '": ' // trim(msg))
      else
        call diag%report_plain(path // ': cannot open the deck: ' // trim(msg))
      end if
      return
    end if
    reader%stack = [reader%stack, string_t(path)]
    deck%files = [deck%files, string_t(path)]
    line_no = 0
    do
      call read_line(unit, line, eof, stat)
      if (eof) exit
      line_no = line_no + 1
      if (line_no == 1 .and. stat == 0) call skip_byte_order_mark(line)
      if (stat /= 0) then
        call diag%report(loc_of(path, line_no, ''), 'cannot read this line (longer than ' // &
                         str(MAX_LINE_LENGTH) // ' characters, or not text)')
        exit
      end if
      call clean_line(line)
      if (is_comment_or_blank(line)) cycle
      if (.not. check_ascii(line, loc_of(path, line_no, line), diag)) cycle
      call handle_line(reader, trim(adjustl(line)), loc_of(path, line_no, line), deck, diag)
      if (diag%is_full()) exit
    end do
    close (unit)
    reader%stack = reader%stack(1:size(reader%stack) - 1)
    if (size(reader%stack) == 0) reader%last_line = line_no
  end subroutine read_file

  !> The deck or an included file must be a regular file (checked before it is opened: opening
  !> a FIFO without a writer would block, a directory reads as an empty file).
  logical function is_regular(path, included_from, diag) result(ok)
    character(len=*), intent(in) :: path
    type(source_loc_t), intent(in) :: included_from
    type(diagnostics_t), intent(inout) :: diag
    integer :: kind
    character(len=:), allocatable :: what
    kind = file_kind(path)
    ok = kind == FILE_REGULAR .or. kind == FILE_MISSING
    if (ok) return
    what = '"' // path // '" is ' // file_kind_name(kind) // ', not a file'
    if (allocated(included_from%file)) then
      call diag%report(included_from, '*INCLUDE: ' // what // ' (INPUT= names a file to read)')
    else
      call diag%report_plain(path // ': cannot read the deck: ' // what)
    end if
  end function is_regular

  !> Remove a UTF-8 byte-order mark from the start of a file's first line.
  subroutine skip_byte_order_mark(line)
    character(len=:), allocatable, intent(inout) :: line
    integer :: i
    if (len(line) < size(UTF8_BOM)) return
    do i = 1, size(UTF8_BOM)
      if (ichar(line(i:i)) /= UTF8_BOM(i)) return
    end do
    line = line(size(UTF8_BOM) + 1:)
  end subroutine skip_byte_order_mark

  !> Dispatch one logical line: keyword line (or *INCLUDE), or data line of the current card.
  recursive subroutine handle_line(reader, line, loc, deck, diag)
    type(reader_t), intent(inout) :: reader
    character(len=*), intent(in) :: line
    type(source_loc_t), intent(in) :: loc
    type(deck_t), intent(inout) :: deck
    type(diagnostics_t), intent(inout) :: diag
    type(card_t) :: card
    character(len=:), allocatable :: target
    integer :: k
    if (line(1:1) == '*') then
      call parse_keyword_line(without_trailing_comma(line), loc, card, diag)
      card%trailing_comma = ends_with_comma(line)
      if (.not. allocated(card%keyword)) return
      if (card%keyword == 'INCLUDE') then
        k = card%find_param('INPUT')
        if (k == 0) then
          call diag%report(loc, '*INCLUDE: missing required parameter INPUT=<file>')
          return
        end if
        if (.not. card%params(k)%has_value .or. len(card%params(k)%value) == 0) then
          call diag%report(loc, '*INCLUDE: INPUT= needs a file name')
          return
        end if
        target = join_path(dirname(loc%file), unquote(card%params(k)%value))
        call read_file(reader, target, loc, deck, diag)
        return
      end if
      call append_card(deck, card)
    else
      if (deck%n_cards == 0) then
        call diag%report(loc, 'data line before the first keyword line ' // &
                         '(a deck starts with a keyword such as *HEADING or *NODE)')
        return
      end if
      call append_data_line(deck%cards(deck%n_cards), line, loc, diag)
    end if
  end subroutine handle_line

  !> Split `*KEYWORD, A=1, B` into the keyword and its parameters.
  subroutine parse_keyword_line(line, loc, card, diag)
    character(len=*), intent(in) :: line
    type(source_loc_t), intent(in) :: loc
    type(card_t), intent(out) :: card
    type(diagnostics_t), intent(inout) :: diag
    type(string_t), allocatable :: fields(:)
    integer :: i, eq, j
    call split_fields(line(2:), fields)
    if (size(fields) == 0) then
      call diag%report(loc, 'empty keyword line: a "*" must be followed by a keyword')
      return
    end if
    if (len(fields(1)%s) == 0) then
      call diag%report(loc, 'empty keyword line: a "*" must be followed by a keyword')
      return
    end if
    card%keyword = to_upper(collapse_spaces(fields(1)%s))
    card%loc = loc
    allocate (card%params(size(fields) - 1), card%lines(4))
    do i = 2, size(fields)
      associate (p => card%params(i - 1))
        eq = index(fields(i)%s, '=')
        if (eq == 0) then
          p%name = to_upper(collapse_spaces(fields(i)%s))
          p%value = ''
          p%has_value = .false.
        else
          p%name = to_upper(collapse_spaces(fields(i)%s(1:eq - 1)))
          p%value = collapse_spaces(fields(i)%s(eq + 1:))
          p%has_value = .true.
        end if
        if (len(p%name) == 0) then
          call diag%report(loc, '*' // card%keyword // ': empty parameter (two commas in a row, ' // &
                           'or "=" without a name)')
        end if
        do j = 1, i - 2
          if (card%params(j)%name == p%name .and. len(p%name) > 0) then
            call diag%report(loc, '*' // card%keyword // ': parameter ' // p%name // &
                             ' is given more than once')
          end if
        end do
      end associate
    end do
  end subroutine parse_keyword_line

  subroutine append_card(deck, card)
    type(deck_t), intent(inout) :: deck
    type(card_t), intent(in) :: card
    type(card_t), allocatable :: grown(:)
    if (deck%n_cards == size(deck%cards)) then
      allocate (grown(2 * size(deck%cards)))
      grown(1:deck%n_cards) = deck%cards(1:deck%n_cards)
      call move_alloc(grown, deck%cards)
    end if
    deck%n_cards = deck%n_cards + 1
    deck%cards(deck%n_cards) = card
  end subroutine append_card

  !> Add a data line to `card`. A first data line that holds parameters (`NAME=value`) after
  !> a keyword line ending in a comma is an error: keyword lines do not continue.
  subroutine append_data_line(card, line, loc, diag)
    type(card_t), intent(inout) :: card
    character(len=*), intent(in) :: line
    type(source_loc_t), intent(in) :: loc
    type(diagnostics_t), intent(inout) :: diag
    type(data_line_t), allocatable :: grown(:)
    if (card%n_lines == size(card%lines)) then
      allocate (grown(2 * size(card%lines)))
      grown(1:card%n_lines) = card%lines(1:card%n_lines)
      call move_alloc(grown, card%lines)
    end if
    card%n_lines = card%n_lines + 1
    associate (data => card%lines(card%n_lines))
      call split_fields(without_trailing_comma(line), data%fields)
      data%loc = loc
      data%continued = ends_with_comma(line)
      if (card%n_lines == 1 .and. card%trailing_comma .and. size(data%fields) > 0) then
        if (index(data%fields(1)%s, '=') > 0) call diag%report(loc, '*' // card%keyword // &
          ': this line continues the keyword line above (' // card%loc%file // ':' // &
          str(card%loc%line) // '), but keyword lines do not continue, as in CalculiX: ' // &
          'write the parameters on the keyword line')
      end if
    end associate
  end subroutine append_data_line

  !> `line` without one trailing comma (and the blanks before it).
  pure function without_trailing_comma(line) result(out)
    character(len=*), intent(in) :: line
    character(len=:), allocatable :: out
    integer :: n
    n = len_trim(line)
    out = line(1:n)
    if (n > 0) then
      if (line(n:n) == ',') out = trim(line(1:n - 1))
    end if
  end function without_trailing_comma

  !> Index of parameter `name` on the card, 0 if absent.
  pure integer function card_find_param(this, name) result(k)
    class(card_t), intent(in) :: this
    character(len=*), intent(in) :: name
    do k = 1, size(this%params)
      if (this%params(k)%name == name) return
    end do
    k = 0
  end function card_find_param

  !> Read one line of any length. `eof` at end of file; `stat` /= 0 on a read error.
  subroutine read_line(unit, line, eof, stat)
    integer, intent(in) :: unit
    character(len=:), allocatable, intent(out) :: line
    logical, intent(out) :: eof
    integer, intent(out) :: stat
    character(len=512) :: chunk
    integer :: got
    line = ''
    eof = .false.
    do
      read (unit, '(a)', advance='no', iostat=stat, size=got) chunk
      if (is_iostat_eor(stat)) then
        line = line // chunk(1:got)
        stat = 0
        return
      else if (is_iostat_end(stat)) then
        if (len(line) == 0 .and. got == 0) then
          eof = .true.
        else
          line = line // chunk(1:got)
        end if
        stat = 0
        return
      else if (stat /= 0) then
        return
      end if
      line = line // chunk(1:got)
      if (len(line) > MAX_LINE_LENGTH) then
        stat = 1
        return
      end if
    end do
  end subroutine read_line

  !> Strip a carriage return (DOS line ends), turn tabs into blanks, strip trailing blanks.
  subroutine clean_line(line)
    character(len=:), allocatable, intent(inout) :: line
    integer :: n, i
    n = len(line)
    if (n > 0) then
      if (line(n:n) == achar(13)) line = line(1:n - 1)
    end if
    do i = 1, len(line)
      if (line(i:i) == achar(9)) line(i:i) = ' '
    end do
    line = trim(line)
  end subroutine clean_line

  pure logical function is_comment_or_blank(line)
    character(len=*), intent(in) :: line
    character(len=:), allocatable :: t
    t = adjustl(line)
    is_comment_or_blank = len_trim(t) == 0
    if (.not. is_comment_or_blank .and. len_trim(t) >= 2) is_comment_or_blank = t(1:2) == '**'
  end function is_comment_or_blank

  !> Non-ASCII bytes are refused outside comments: they cannot be part of a keyword, name or
  !> number, and a silent misreading would be worse than an error.
  logical function check_ascii(line, loc, diag) result(ok)
    character(len=*), intent(in) :: line
    type(source_loc_t), intent(in) :: loc
    type(diagnostics_t), intent(inout) :: diag
    integer :: i, c
    ok = .true.
    do i = 1, len(line)
      c = iachar(line(i:i))
      if (c > 126 .or. (c < 32 .and. c /= 9)) then
        call diag%report(loc, 'non-ASCII or control character at column ' // str(i) // &
                         ' (keywords, names and numbers must be plain ASCII)')
        ok = .false.
        return
      end if
    end do
  end function check_ascii

  pure logical function ends_with_comma(line)
    character(len=*), intent(in) :: line
    integer :: n
    n = len_trim(line)
    ends_with_comma = .false.
    if (n > 0) ends_with_comma = line(n:n) == ','
  end function ends_with_comma

  function stack_text(reader) result(text)
    type(reader_t), intent(in) :: reader
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, size(reader%stack)
      if (i > 1) text = text // ' -> '
      text = text // reader%stack(i)%s
    end do
  end function stack_text

  pure function loc_of(path, line_no, text) result(loc)
    character(len=*), intent(in) :: path, text
    integer, intent(in) :: line_no
    type(source_loc_t) :: loc
    loc%file = path
    loc%line = line_no
    loc%text = text
  end function loc_of

  !> Remove surrounding double quotes from a file name.
  pure function unquote(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: n
    out = trim(adjustl(text))
    n = len(out)
    if (n >= 2) then
      if (out(1:1) == '"' .and. out(n:n) == '"') out = out(2:n - 1)
    end if
  end function unquote

end module fcs_deck_lexer
