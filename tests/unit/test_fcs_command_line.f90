!> Unit test of the record of result-changing options that a checkpoint keeps
!> (fcs_command_line: result_options_text, parse_result_options): the text lists exactly the
!> options given, reads back to the same settings (tolerances to the last bit, in the fewest
!> digits), and a record the command line would refuse is refused.
program test_fcs_command_line
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_run_options, only: run_options_t
  use fcs_command_line, only: result_options_text, parse_result_options, result_option_value
  use fcs_strings, only: split_words, string_t
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite

  suite%name = 'fcs_command_line'
  call check_split_words(suite)
  call check_none_given(suite)
  call check_round_trip(suite)
  call check_refused(suite)
  call suite%report()

contains

  !> Options with nothing given, as parse_command_line leaves them.
  function no_options() result(options)
    type(run_options_t) :: options
    options%solver = ''
    options%contact_events = ''
    options%restart_file = ''
  end function no_options

  subroutine check_split_words(suite)
    type(test_suite_t), intent(inout) :: suite
    type(string_t), allocatable :: words(:)
    words = split_words('  --solver  MUMPS --contact-events CLOSING ')
    call suite%equal_int(size(words), 4, 'split_words: four words')
    if (size(words) == 4) call suite%check(words(1)%s == '--solver' .and. words(2)%s == 'MUMPS' &
      .and. words(4)%s == 'CLOSING', 'split_words: the words, without spaces')
    call suite%equal_int(size(split_words('')), 0, 'split_words of an empty text')
  end subroutine check_split_words

  subroutine check_none_given(suite)
    type(test_suite_t), intent(inout) :: suite
    type(run_options_t) :: options
    type(error_t), allocatable :: err
    options = no_options()
    call suite%check(result_options_text(options) == '', 'no option given: an empty record')
    options%solver = 'UMFPACK'
    options%reuse_tolerance = 1.0e-10_dp
    call parse_result_options('', options, err)
    call suite%check(.not. allocated(err), 'an empty record is read')
    call suite%check(options%solver == '' .and. options%reuse_tolerance < 0.0_dp, &
                     'an empty record: no option given (earlier settings cleared)')
  end subroutine check_none_given

  !> Each setting written and read back gives the same setting and the same text.
  subroutine check_round_trip(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: tolerances(*) = [0.0_dp, 1.0e-10_dp, 1.0e-3_dp, 2.5e-7_dp, &
      0.1234567890123457e-4_dp, 1.0e-3_dp / 3.0_dp]
    type(run_options_t) :: options, back
    type(error_t), allocatable :: err
    character(len=:), allocatable :: text
    integer :: k
    do k = 1, size(tolerances)
      options = no_options()
      options%reuse_tolerance = tolerances(k)
      options%low_rank_tolerance = tolerances(size(tolerances) + 1 - k) * 10.0_dp
      options%contact_events = 'CLOSING'
      if (mod(k, 2) == 0) options%solver = 'MUMPS'
      text = result_options_text(options)
      back = no_options()
      call parse_result_options(text, back, err)
      call suite%check(.not. allocated(err), 'the record "' // text // '" is read')
      if (allocated(err)) cycle
      call suite%check(back%reuse_tolerance == options%reuse_tolerance .and. &
        back%low_rank_tolerance == options%low_rank_tolerance .and. &
        back%contact_events == 'CLOSING' .and. back%solver == options%solver, &
        'the record "' // text // '" reads back to the same settings, to the last bit')
      call suite%check(result_options_text(back) == text, 'the record "' // text // &
                       '" is written the same again')
    end do
    options = no_options()
    options%reuse_tolerance = 1.0e-10_dp
    options%contact_events = 'closing'
    call suite%check(result_options_text(options) == '--reuse-tolerance 1E-10 --contact-events CLOSING', &
      'the record of --reuse-tolerance 1e-10 --contact-events closing: "' // &
      result_options_text(options) // '" (fewest digits, capitals)')
    call suite%check(result_option_value(options, '--solver') == '', 'an option not given has no value')
  end subroutine check_round_trip

  subroutine check_refused(suite)
    type(test_suite_t), intent(inout) :: suite
    character(len=40), parameter :: bad(*) = [character(len=40) :: '--contact-events', &
      '--contact-events SOMETIMES', '--restart job.rst.h5', '--reuse-tolerance 1', &
      '--solver PARDISO', '--low-rank-tolerance x']
    type(run_options_t) :: options
    type(error_t), allocatable :: err
    integer :: k
    do k = 1, size(bad)
      options = no_options()
      call parse_result_options(trim(bad(k)), options, err)
      call suite%check(allocated(err), 'the record "' // trim(bad(k)) // '" is refused')
    end do
  end subroutine check_refused

end program test_fcs_command_line
