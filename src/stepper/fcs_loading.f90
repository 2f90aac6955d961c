!> Loading of one step as functions of the step time: prescribed displacements and
!> velocities, nodal forces and face pressures, following the Abaqus/CalculiX conventions
!> (*STATIC: values ramp linearly over the step from their values at its start, unless an
!> *AMPLITUDE is given, in which case value x a(t)). The stepper never lets an increment
!> cross a breakpoint (an amplitude point or an output time), so that within one increment
!> every load is linear in time and the R-minimum scaling of the increment is exact.
module fcs_loading
  use fcs_kinds, only: dp
  use fcs_model, only: model_t, step_t, amplitude_t, time_points_t, BC_VELOCITY, BC_FIXED, &
                       OUTPUT_NODE_FILE, OUTPUT_EL_FILE
  use fcs_sort, only: argsort_reals
  implicit none
  private
  public :: step_loading_t, build_step_loading, amplitude_value, amplitude_integral

  !> The loading of one step.
  type :: step_loading_t
    real(dp) :: period = 1.0_dp
    !> Total time at the start of the step (for amplitudes in total time).
    real(dp) :: start_time = 0.0_dp
    !> Prescribed degrees of freedom (global dof 3*(node-1)+direction).
    integer, allocatable :: bc_dof(:), bc_kind(:), bc_amplitude(:)
    real(dp), allocatable :: bc_value(:)
    !> Concentrated forces: value ramps from start to end (or end x amplitude).
    integer, allocatable :: force_dof(:), force_amplitude(:)
    real(dp), allocatable :: force_start(:), force_end(:)
    !> Face pressures, same rule.
    integer, allocatable :: face_element(:), face_number(:), face_amplitude(:)
    real(dp), allocatable :: pressure_start(:), pressure_end(:)
    !> Body loads (*DLOAD GRAV, CENTRIF): element, kind, amplitude, magnitude at the start and
    !> end of the step (same rule), direction or axis (fcs_model, body_load_t).
    integer, allocatable :: body_element(:), body_kind(:), body_amplitude(:)
    real(dp), allocatable :: body_start(:), body_end(:), body_vector(:, :)
    !> Nodal temperatures (models with temperatures only): each node's value at the start of
    !> the step, its target and amplitude (0: none), the same rule as the forces.
    real(dp), allocatable :: temperature_start(:), temperature_end(:)
    integer, allocatable :: temperature_amplitude(:)
    !> Step times inside (0, period) where an amplitude has a point.
    real(dp), allocatable :: breakpoints(:)
  contains
    procedure :: force_at => loading_force_at
    procedure :: pressure_at => loading_pressure_at
    procedure :: body_load_at => loading_body_load_at
    procedure :: temperature_at => loading_temperature_at
    procedure :: has_temperature => loading_has_temperature
    procedure :: prescribed_target => loading_prescribed_target
    procedure :: next_breakpoint => loading_next_breakpoint
  end type step_loading_t

contains

  !> Build the loading of step `k` starting at total time `start_time`. Forces and pressures
  !> start from the values they had at the end of step k-1, temperatures from
  !> `start_temperature` (the nodal temperatures at the start of the step; models with
  !> temperatures).
  subroutine build_step_loading(model, k, start_time, loading, start_temperature)
    type(model_t), intent(in) :: model
    integer, intent(in) :: k
    real(dp), intent(in) :: start_time
    type(step_loading_t), intent(out) :: loading
    real(dp), intent(in), optional :: start_temperature(:)
    integer :: i
    associate (step => model%steps(k))
      if (model%has_temperature .and. present(start_temperature)) then
        loading%temperature_start = start_temperature
        loading%temperature_end = step%temperature
        loading%temperature_amplitude = step%temperature_amplitude
      end if
      loading%period = step%period
      loading%start_time = start_time
      allocate (loading%bc_dof(size(step%boundary)), loading%bc_kind(size(step%boundary)), &
                loading%bc_amplitude(size(step%boundary)), loading%bc_value(size(step%boundary)))
      do i = 1, size(step%boundary)
        loading%bc_dof(i) = 3 * (step%boundary(i)%node - 1) + step%boundary(i)%dof
        loading%bc_kind(i) = step%boundary(i)%kind
        loading%bc_amplitude(i) = step%boundary(i)%amplitude
        loading%bc_value(i) = step%boundary(i)%value
      end do
      allocate (loading%force_dof(size(step%loads)), loading%force_amplitude(size(step%loads)), &
                loading%force_start(size(step%loads)), loading%force_end(size(step%loads)))
      do i = 1, size(step%loads)
        loading%force_dof(i) = 3 * (step%loads(i)%node - 1) + step%loads(i)%dof
        loading%force_amplitude(i) = step%loads(i)%amplitude
        loading%force_end(i) = step%loads(i)%value
        loading%force_start(i) = previous_force(model, k, step%loads(i)%node, step%loads(i)%dof, &
                                                start_time)
      end do
      allocate (loading%face_element(size(step%pressures)), loading%face_number(size(step%pressures)), &
                loading%face_amplitude(size(step%pressures)), &
                loading%pressure_start(size(step%pressures)), loading%pressure_end(size(step%pressures)))
      do i = 1, size(step%pressures)
        loading%face_element(i) = step%pressures(i)%element
        loading%face_number(i) = step%pressures(i)%face
        loading%face_amplitude(i) = step%pressures(i)%amplitude
        loading%pressure_end(i) = step%pressures(i)%pressure
        loading%pressure_start(i) = previous_pressure(model, k, step%pressures(i)%element, &
                                                      step%pressures(i)%face, start_time)
      end do
      call body_loads(model, k, start_time, loading)
      call collect_breakpoints(model, step, start_time, loading)
    end associate
  end subroutine build_step_loading

  !> The body loads of step k, each magnitude starting from its value at the end of step k-1
  !> (0 if that step did not have it).
  subroutine body_loads(model, k, start_time, loading)
    type(model_t), intent(in) :: model
    integer, intent(in) :: k
    real(dp), intent(in) :: start_time
    type(step_loading_t), intent(inout) :: loading
    integer :: i, j, n
    n = 0
    if (allocated(model%steps(k)%body_loads)) n = size(model%steps(k)%body_loads)
    allocate (loading%body_element(n), loading%body_kind(n), loading%body_amplitude(n), &
              loading%body_start(n), loading%body_end(n), loading%body_vector(6, n))
    do i = 1, n
      associate (b => model%steps(k)%body_loads(i))
        loading%body_element(i) = b%element
        loading%body_kind(i) = b%kind
        loading%body_amplitude(i) = b%amplitude
        loading%body_end(i) = b%magnitude
        loading%body_vector(:, i) = b%vector
        loading%body_start(i) = 0.0_dp
        if (k == 1) cycle
        if (.not. allocated(model%steps(k - 1)%body_loads)) cycle
        associate (previous => model%steps(k - 1)%body_loads)
          do j = 1, size(previous)
            if (previous(j)%element /= b%element .or. previous(j)%kind /= b%kind) cycle
            loading%body_start(i) = previous(j)%magnitude
            if (previous(j)%amplitude > 0) loading%body_start(i) = loading%body_start(i) * &
              amplitude_value(model%amplitudes(previous(j)%amplitude), &
                              model%steps(k - 1)%period, start_time - model%steps(k - 1)%period)
            exit
          end do
        end associate
      end associate
    end do
  end subroutine body_loads

  !> Value of a concentrated force at the end of step k-1 (0 if it was not loaded).
  real(dp) function previous_force(model, k, node, dof, start_time) result(value)
    type(model_t), intent(in) :: model
    integer, intent(in) :: k, node, dof
    real(dp), intent(in) :: start_time
    integer :: i
    value = 0.0_dp
    if (k == 1) return
    associate (loads => model%steps(k - 1)%loads)
      do i = 1, size(loads)
        if (loads(i)%node == node .and. loads(i)%dof == dof) then
          value = loads(i)%value
          if (loads(i)%amplitude > 0) value = value * amplitude_value(model%amplitudes( &
            loads(i)%amplitude), model%steps(k - 1)%period, start_time - model%steps(k - 1)%period)
          return
        end if
      end do
    end associate
  end function previous_force

  !> Pressure on a face at the end of step k-1 (0 if it was not loaded).
  real(dp) function previous_pressure(model, k, element, face, start_time) result(value)
    type(model_t), intent(in) :: model
    integer, intent(in) :: k, element, face
    real(dp), intent(in) :: start_time
    integer :: i
    value = 0.0_dp
    if (k == 1) return
    associate (pressures => model%steps(k - 1)%pressures)
      do i = 1, size(pressures)
        if (pressures(i)%element == element .and. pressures(i)%face == face) then
          value = pressures(i)%pressure
          if (pressures(i)%amplitude > 0) value = value * amplitude_value(model%amplitudes( &
            pressures(i)%amplitude), model%steps(k - 1)%period, start_time - model%steps(k - 1)%period)
          return
        end if
      end do
    end associate
  end function previous_pressure

  !> Breakpoints: amplitude points of every amplitude the step uses, and the output times of
  !> its requests, as step times in (0, period), sorted and unique.
  subroutine collect_breakpoints(model, step, start_time, loading)
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    real(dp), intent(in) :: start_time
    type(step_loading_t), intent(inout) :: loading
    real(dp), allocatable :: times(:)
    logical, allocatable :: used(:)
    integer :: i, a
    allocate (used(size(model%amplitudes)), times(0))
    used = .false.
    do i = 1, size(step%boundary)
      if (step%boundary(i)%amplitude > 0) used(step%boundary(i)%amplitude) = .true.
    end do
    do i = 1, size(step%loads)
      if (step%loads(i)%amplitude > 0) used(step%loads(i)%amplitude) = .true.
    end do
    do i = 1, size(step%pressures)
      if (step%pressures(i)%amplitude > 0) used(step%pressures(i)%amplitude) = .true.
    end do
    if (allocated(step%body_loads)) then
      do i = 1, size(step%body_loads)
        if (step%body_loads(i)%amplitude > 0) used(step%body_loads(i)%amplitude) = .true.
      end do
    end if
    if (allocated(step%temperature_amplitude)) then
      do i = 1, size(step%temperature_amplitude)
        if (step%temperature_amplitude(i) > 0) used(step%temperature_amplitude(i)) = .true.
      end do
    end if
    do a = 1, size(model%amplitudes)
      if (.not. used(a)) cycle
      if (model%amplitudes(a)%total_time) then
        times = [times, model%amplitudes(a)%time - start_time]
      else
        times = [times, model%amplitudes(a)%time]
      end if
    end do
    do i = 1, size(step%outputs)
      if (step%outputs(i)%time_points > 0) &
        call add_time_points(model%time_points(step%outputs(i)%time_points), start_time, times)
    end do
    ! History samples at time points hold through every step.
    do i = 1, size(model%histories)
      if (model%histories(i)%time_points > 0) &
        call add_time_points(model%time_points(model%histories(i)%time_points), start_time, times)
    end do
    loading%breakpoints = sorted_inside(times, step%period)
  end subroutine collect_breakpoints

  !> Append the times of a *TIME POINTS list, as step times of a step starting at start_time.
  subroutine add_time_points(points, start_time, times)
    type(time_points_t), intent(in) :: points
    real(dp), intent(in) :: start_time
    real(dp), allocatable, intent(inout) :: times(:)
    if (points%total_time) then
      times = [times, points%times - start_time]
    else
      times = [times, points%times]
    end if
  end subroutine add_time_points

  !> Sorted values strictly inside (0, period), duplicates (within 1e-12 period) removed.
  function sorted_inside(times, period) result(out)
    real(dp), intent(in) :: times(:), period
    real(dp), allocatable :: out(:)
    integer, allocatable :: order(:)
    integer :: i, n
    real(dp) :: tolerance
    tolerance = 1.0e-12_dp * period
    order = argsort_reals(times)
    allocate (out(size(times)))
    n = 0
    do i = 1, size(order)
      associate (t => times(order(i)))
        if (t <= tolerance .or. t >= period - tolerance) cycle
        if (n > 0) then
          if (t - out(n) <= tolerance) cycle
        end if
        n = n + 1
        out(n) = t
      end associate
    end do
    out = out(1:n)
  end function sorted_inside

  !> First breakpoint after step time t (the period if none).
  pure real(dp) function loading_next_breakpoint(this, t) result(next)
    class(step_loading_t), intent(in) :: this
    real(dp), intent(in) :: t
    integer :: i
    next = this%period
    do i = 1, size(this%breakpoints)
      if (this%breakpoints(i) > t * (1.0_dp + 1.0e-12_dp) + 1.0e-300_dp) then
        next = this%breakpoints(i)
        return
      end if
    end do
  end function loading_next_breakpoint

  !> Ramp or amplitude factor rule: start + (end - start) t/T, or end x a(t).
  pure real(dp) function ramped(start, finish, amplitude, amplitudes, t, period, start_time)
    real(dp), intent(in) :: start, finish, t, period, start_time
    integer, intent(in) :: amplitude
    type(amplitude_t), intent(in) :: amplitudes(:)
    if (amplitude > 0) then
      ramped = finish * amplitude_value(amplitudes(amplitude), t, start_time)
    else
      ramped = start + (finish - start) * min(max(t / period, 0.0_dp), 1.0_dp)
    end if
  end function ramped

  !> Concentrated forces at step time t, added into f(3*n_nodes).
  subroutine loading_force_at(this, amplitudes, t, f)
    class(step_loading_t), intent(in) :: this
    type(amplitude_t), intent(in) :: amplitudes(:)
    real(dp), intent(in) :: t
    real(dp), intent(inout) :: f(:)
    integer :: i
    do i = 1, size(this%force_dof)
      f(this%force_dof(i)) = f(this%force_dof(i)) + ramped(this%force_start(i), this%force_end(i), &
        this%force_amplitude(i), amplitudes, t, this%period, this%start_time)
    end do
  end subroutine loading_force_at

  !> Pressure on face i of the list at step time t.
  pure real(dp) function loading_pressure_at(this, amplitudes, i, t) result(p)
    class(step_loading_t), intent(in) :: this
    type(amplitude_t), intent(in) :: amplitudes(:)
    integer, intent(in) :: i
    real(dp), intent(in) :: t
    p = ramped(this%pressure_start(i), this%pressure_end(i), this%face_amplitude(i), amplitudes, &
               t, this%period, this%start_time)
  end function loading_pressure_at

  !> Magnitude of body load i of the list at step time t.
  pure real(dp) function loading_body_load_at(this, amplitudes, i, t) result(value)
    class(step_loading_t), intent(in) :: this
    type(amplitude_t), intent(in) :: amplitudes(:)
    integer, intent(in) :: i
    real(dp), intent(in) :: t
    value = ramped(this%body_start(i), this%body_end(i), this%body_amplitude(i), amplitudes, &
                   t, this%period, this%start_time)
  end function loading_body_load_at

  !> Whether the step has nodal temperatures.
  pure logical function loading_has_temperature(this) result(has)
    class(step_loading_t), intent(in) :: this
    has = allocated(this%temperature_end)
  end function loading_has_temperature

  !> Nodal temperatures at step time t (ramp from the step's start, or value x amplitude: the
  !> rule of the forces, CalculiX's tempload.f).
  subroutine loading_temperature_at(this, amplitudes, t, temperature)
    class(step_loading_t), intent(in) :: this
    type(amplitude_t), intent(in) :: amplitudes(:)
    real(dp), intent(in) :: t
    real(dp), intent(out) :: temperature(:)
    integer :: i
    do i = 1, size(this%temperature_end)
      temperature(i) = ramped(this%temperature_start(i), this%temperature_end(i), &
        this%temperature_amplitude(i), amplitudes, t, this%period, this%start_time)
    end do
  end subroutine loading_temperature_at

  !> Target increment of prescribed dof i from step time t0 to t1, given the current
  !> displacement `current` of that dof and its value `step_start` at the start of the step.
  pure real(dp) function loading_prescribed_target(this, amplitudes, i, t0, t1, current, &
                                                   step_start) result(du)
    class(step_loading_t), intent(in) :: this
    type(amplitude_t), intent(in) :: amplitudes(:)
    integer, intent(in) :: i
    real(dp), intent(in) :: t0, t1, current, step_start
    real(dp) :: target
    if (this%bc_kind(i) == BC_FIXED) then
      du = 0.0_dp
    else if (this%bc_kind(i) == BC_VELOCITY) then
      if (this%bc_amplitude(i) > 0) then
        du = this%bc_value(i) * (amplitude_integral(amplitudes(this%bc_amplitude(i)), t1, &
             this%start_time) - amplitude_integral(amplitudes(this%bc_amplitude(i)), t0, this%start_time))
      else
        du = this%bc_value(i) * (t1 - t0)
      end if
    else
      target = ramped(step_start, this%bc_value(i), this%bc_amplitude(i), amplitudes, t1, &
                      this%period, this%start_time)
      du = target - current
    end if
  end function loading_prescribed_target

  !> a(t) at step time t: linear between points, constant beyond the ends.
  pure real(dp) function amplitude_value(amplitude, t, start_time) result(a)
    type(amplitude_t), intent(in) :: amplitude
    real(dp), intent(in) :: t, start_time
    real(dp) :: time, w
    integer :: i, n
    time = t
    if (amplitude%total_time) time = t + start_time
    if (amplitude%quadratic) then
      a = time**2
      return
    end if
    n = size(amplitude%time)
    if (time <= amplitude%time(1)) then
      a = amplitude%value(1)
    else if (time >= amplitude%time(n)) then
      a = amplitude%value(n)
    else
      do i = 2, n
        if (time <= amplitude%time(i)) exit
      end do
      w = (time - amplitude%time(i - 1)) / (amplitude%time(i) - amplitude%time(i - 1))
      a = (1.0_dp - w) * amplitude%value(i - 1) + w * amplitude%value(i)
    end if
  end function amplitude_value

  !> Integral of a(s) ds from the amplitude's time origin to step time t (exact for the
  !> piecewise-linear amplitude; differences of it give velocity-driven displacements).
  pure real(dp) function amplitude_integral(amplitude, t, start_time) result(total)
    type(amplitude_t), intent(in) :: amplitude
    real(dp), intent(in) :: t, start_time
    real(dp) :: time, t_hi
    integer :: i, n
    time = t
    if (amplitude%total_time) time = t + start_time
    if (amplitude%quadratic) then
      total = time**3 / 3.0_dp
      return
    end if
    n = size(amplitude%time)
    total = amplitude%value(1) * min(time, amplitude%time(1))
    do i = 2, n
      if (time <= amplitude%time(i - 1)) exit
      t_hi = min(time, amplitude%time(i))
      total = total + 0.5_dp * (amplitude%value(i - 1) + amplitude_value_local(amplitude, i, t_hi)) * &
              (t_hi - amplitude%time(i - 1))
    end do
    if (time > amplitude%time(n)) total = total + amplitude%value(n) * (time - amplitude%time(n))
  end function amplitude_integral

  pure real(dp) function amplitude_value_local(amplitude, i, t) result(a)
    type(amplitude_t), intent(in) :: amplitude
    integer, intent(in) :: i
    real(dp), intent(in) :: t
    real(dp) :: w
    w = (t - amplitude%time(i - 1)) / (amplitude%time(i) - amplitude%time(i - 1))
    a = (1.0_dp - w) * amplitude%value(i - 1) + w * amplitude%value(i)
  end function amplitude_value_local

end module fcs_loading
