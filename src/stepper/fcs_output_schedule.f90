!> The output schedule: which outputs and history samples are due after an increment, from
!> the step's output requests (FREQUENCY, TIME POINTS) and the state's time and counters. It
!> keeps no run state of its own (what it decides depends on the state's counters and on the
!> rows the histories already hold), so there is nothing for it to save in a checkpoint.
module fcs_output_schedule
  use fcs_kinds, only: dp
  use fcs_model, only: model_t, step_t, output_request_t, OUTPUT_NODE_FILE, OUTPUT_EL_FILE, &
                       OUTPUT_CONTACT_FILE
  use fcs_state, only: state_t
  use fcs_history, only: history_table_t
  implicit none
  private
  public :: is_due, at_time_point, histories_due, outputs_due

contains

  !> Whether a frame (`need_frame`: *NODE FILE, *EL FILE, *CONTACT FILE, and always at the
  !> end of a step) or a printed table (`need_print`) is due now. Output due on the last
  !> increment of a step is written once, by the end-of-step call.
  subroutine outputs_due(model, state, end_of_step, need_frame, need_print)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    logical, intent(in) :: end_of_step
    logical, intent(out) :: need_frame, need_print
    integer :: i
    need_frame = .false.
    need_print = .false.
    associate (step => model%steps(state%step))
      if (.not. end_of_step .and. state%step_time >= step%period * (1.0_dp - 1.0e-12_dp)) return
      need_frame = end_of_step
      do i = 1, size(step%outputs)
        if (.not. is_due(model, step, step%outputs(i), state, end_of_step)) cycle
        select case (step%outputs(i)%kind)
        case (OUTPUT_NODE_FILE, OUTPUT_EL_FILE, OUTPUT_CONTACT_FILE)
          need_frame = .true.
        case default
          need_print = .true.
        end select
      end do
    end associate
  end subroutine outputs_due

  !> The histories due after this increment (or at the end of the step: every history that
  !> has no row at this time yet), given their tables so far.
  function histories_due(model, tables, state, end_of_step) result(due)
    type(model_t), intent(in) :: model
    type(history_table_t), intent(in) :: tables(:)
    type(state_t), intent(in) :: state
    logical, intent(in) :: end_of_step
    logical :: due(size(model%histories))
    integer :: k
    do k = 1, size(model%histories)
      associate (h => model%histories(k), table => tables(k))
        due(k) = .false.
        if (table%n_rows > 0) then
          if (table%rows(1, table%n_rows) >= state%time) cycle
        end if
        if (end_of_step) then
          due(k) = .true.
        else if (h%frequency > 0) then
          due(k) = mod(state%step_increment, h%frequency) == 0
        end if
        if (.not. due(k) .and. h%time_points > 0) due(k) = at_time_point(model, h%time_points, &
          model%steps(state%step)%period, state)
      end associate
    end do
  end function histories_due

  !> Whether the state is at one of the times of list `k`.
  logical function at_time_point(model, k, period, state)
    type(model_t), intent(in) :: model
    integer, intent(in) :: k
    real(dp), intent(in) :: period
    type(state_t), intent(in) :: state
    real(dp) :: t
    integer :: i
    at_time_point = .false.
    associate (tp => model%time_points(k))
      do i = 1, size(tp%times)
        t = tp%times(i)
        if (tp%total_time) t = t - (state%time - state%step_time)
        if (abs(state%step_time - t) <= 1.0e-9_dp * period) at_time_point = .true.
      end do
    end associate
  end function at_time_point

  !> Whether output request `request` is due now.
  logical function is_due(model, step, request, state, end_of_step)
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(output_request_t), intent(in) :: request
    type(state_t), intent(in) :: state
    logical, intent(in) :: end_of_step
    real(dp) :: t, tolerance
    integer :: i
    is_due = end_of_step
    if (is_due) return
    if (request%frequency > 0) then
      is_due = mod(state%step_increment, request%frequency) == 0
      if (is_due) return
    end if
    if (request%time_points == 0) return
    tolerance = 1.0e-9_dp * step%period
    associate (tp => model%time_points(request%time_points))
      do i = 1, size(tp%times)
        t = tp%times(i)
        if (tp%total_time) t = t - (state%time - state%step_time)
        if (abs(state%step_time - t) <= tolerance) is_due = .true.
      end do
    end associate
  end function is_due

end module fcs_output_schedule
