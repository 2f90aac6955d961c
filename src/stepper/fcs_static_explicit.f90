!> The static-explicit increment with the R-minimum strategy (Xing, Mora & Makinouchi 2003,
!> eq. 10; Xing & Makinouchi 2002, CMAME 191; method notes 1.5-1.6):
!>   1. assemble the tangent K (+ K_f, + load stiffness) and the internal forces on the
!>      current configuration;
!>   2. solve once, without equilibrium iterations, for a trial increment driven by the load
!>      increment over a trial time increment plus the out-of-balance force
!>      (K + K_f) du = dF + (F_ext - F_int), the latter carrying the equilibrium error of the
!>      previous increments into this one;
!>   3. collect from every module the fraction r of the trial increment at which its next
!>      event happens (yield, contact, stick/slip ...) and the strain and rotation limits;
!>   4. scale the increment by r_min and update stresses (Hughes-Winget), geometry and time.
module fcs_static_explicit
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, fatal_error
  use fcs_model, only: model_t, step_t
  use fcs_state, only: state_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_linear_system, only: linear_system_t
  use fcs_work_share, only: work_share_t
  use fcs_increment_trial, only: increment_trial_t
  use fcs_metis_order, only: metis_equation_order
  use fcs_loading, only: step_loading_t
  use fcs_assembly, only: assemble_pressures, assemble_body_loads
  use fcs_element_loops, only: element_loops_t, event_limits_t
  use fcs_rmin_events, only: rmin_collector_t, rmin_event_t, EVENT_STRAIN_LIMIT, &
                             EVENT_ROTATION_LIMIT, event_kind_name, &
                             EVENT_FULL_INCREMENT, EVENT_SLIP_RATE_CHANGE, EVENT_FRICTION_CHANGE, &
                             EVENT_STATE_CHANGE, EVENT_PLASTIC_STRAIN_LIMIT, EVENT_SLIP_INCREMENT, &
                             CONTACT_EVENTS_ALL
  use fcs_timer, only: phase_timer_t
  use fcs_contact_system, only: contact_system_t
  use fcs_comm, only: comm_t
  use fcs_strings, only: str
  implicit none
  private
  public :: analysis_t, take_increment, increment_record_t, build_pattern, contact_positions
  public :: gather_element_fields, current_reactions

  !> What one increment did, for the log.
  type :: increment_record_t
    real(dp) :: trial_increment = 0.0_dp
    real(dp) :: r = 1.0_dp
    type(rmin_event_t) :: limiting
    integer :: n_events_taken = 0
    logical :: floored = .false.
    !> Contact tangents switched at the start of the increment (stick/slip, re-solved).
    integer :: n_switches = 0
    !> Equilibrium iterations after the increment, and cuts of the increment when they did
    !> not converge.
    integer :: iterations = 0
    integer :: cuts = 0
    !> GMRES iterations of the increment's solves with reused factors (fcs_factor_reuse).
    integer :: krylov_iterations = 0
    !> Out-of-balance force left at the end of the increment: its ratio to the force scale,
    !> and where it is largest (node index, direction 1..3).
    real(dp) :: residual_ratio = 0.0_dp
    !> Taken without converged equilibrium iterations (NO EQUILIBRIUM=CARRY).
    logical :: carried = .false.
    !> The mean nodal force flux at the end of the increment (the force scale).
    real(dp) :: force_scale = 0.0_dp
    integer :: residual_node = 0
    integer :: residual_direction = 0
  end type increment_record_t

  !> The increment being taken: the state at its start, its start time t0 in the step, the
  !> trial time increment dt, and the fraction r of it taken.
  type :: increment_t
    type(state_t) :: start
    real(dp) :: t0 = 0.0_dp
    real(dp) :: dt = 0.0_dp
    real(dp) :: r = 1.0_dp
  contains
    procedure :: end_time => increment_end_time
  end type increment_t

  !> Largest number of solves of one increment while contact tangents are switched.
  integer, parameter :: MAX_STATE_PASSES = 12
  !> Largest number of cuts (by CUT_FACTOR each) of one increment whose equilibrium
  !> iterations do not converge.
  integer, parameter :: MAX_CUTS = 8
  real(dp), parameter :: CUT_FACTOR = 0.25_dp
  !> Largest number of trial step lengths (1, 1/2, 1/4, ...) of one equilibrium iteration.
  integer, parameter :: MAX_LINE_SEARCH = 4
  !> Under NO EQUILIBRIUM=CARRY, equilibrium iterations stop when two of them reduce |R| by
  !> less than this factor.
  real(dp), parameter :: STAGNATION = 0.5_dp

  !> The analysis: the run state and what acts on it. Each part is documented in its own
  !> module; a routine takes the parts it uses.
  type :: analysis_t
    !> The run state (saved by checkpoints, with the contact system's bookkeeping).
    type(state_t) :: state
    !> The element loops: kinds, nodes, materials and formulation of every element, and the
    !> elements of this process.
    type(element_loops_t) :: elements
    !> Node-to-point contact pairs (their per-node states are in state%contact).
    type(contact_system_t) :: contact
    !> Coordinates the contact search and elements use (current positions X + u).
    real(dp), allocatable :: x_contact(:, :)
    !> The loads, supports and temperatures of the current step.
    type(step_loading_t) :: loading
    !> The sparse system, its solver, force and increment vectors (fcs_linear_system).
    type(linear_system_t) :: sys
    !> The processes of the run and the work of this one (fcs_work_share).
    type(work_share_t) :: share
    !> What the trial solution of the current increment found (fcs_increment_trial).
    type(increment_trial_t) :: trial
    type(phase_timer_t) :: timers
  end type analysis_t

contains

  !> One static-explicit increment of the current step. On return the state has advanced by
  !> r_min times the trial increment (less if it had to be cut), in equilibrium within the
  !> step's EQUILIBRIUM TOLERANCE; `record` says what limited it.
  subroutine take_increment(a, model, record, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(increment_record_t), intent(out) :: record
    type(error_t), allocatable, intent(out) :: err
    type(increment_t) :: inc
    logical :: limited_by_friction
    integer(i8) :: krylov_before
    krylov_before = a%sys%reuse%stats%krylov_iterations
    associate (step => model%steps(a%state%step))
      call follow_constraints(a, model, step%nlgeom, err)
      if (allocated(err)) return
      call trial_time_increment(a%state, a%loading, step, inc%t0, inc%dt, limited_by_friction)
      record%trial_increment = inc%dt
      call external_forces(a, model, step%nlgeom, inc%t0, inc%t0 + inc%dt)
      call prescribed_increments(a, model, inc%t0, inc%t0 + inc%dt)
      call ensure_pattern(a, model, err)
      if (allocated(err)) return
      call trial_solution(a, model, step, inc%t0, inc%dt, record, err)
      if (allocated(err)) return
      call a%timers%start('r-minimum')
      call choose_fraction(a, model, step, inc%dt, limited_by_friction, record, inc%r, err)
      call a%timers%stop('r-minimum')
      if (allocated(err)) return
      inc%start = a%state
      call take_fraction(a, model, step, inc, record, err)
      if (allocated(err)) return
      record%r = inc%r
      record%n_events_taken = count_taken(a%trial%collector, inc%r)
      record%krylov_iterations = int(a%sys%reuse%stats%krylov_iterations - krylov_before)
      call count_increment(a%state, record)
    end associate
  end subroutine take_increment

  !> Take the fraction inc%r of the trial increment from the state inc%start, in equilibrium:
  !> apply it, iterate to equilibrium with the contact states held, and cut it while the
  !> iterations do not converge. Iterations that do not converge cut the increment (NO
  !> EQUILIBRIUM=STOP), or the increment is taken as the static-explicit scheme takes it,
  !> without iterations, its out-of-balance force carried into the next (NO
  !> EQUILIBRIUM=CARRY: an unstable slip event has no equilibrium to cut towards). On an
  !> error the state is inc%start.
  subroutine take_fraction(a, model, step, inc, record, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(increment_t), intent(inout) :: inc
    type(increment_record_t), intent(inout) :: record
    type(error_t), allocatable, intent(out) :: err
    logical :: converged
    do
      a%sys%du = a%sys%du_residual + inc%r * a%sys%du_load
      ! The increment as the R-minimum strategy chose it must keep every element valid
      ! and every contact node within the penetration limit: if not, the deformation or
      ! the penalty is wrong, not the increment.
      call apply_increment(a, model, step, inc, err, predict_penetration=.true.)
      if (.not. allocated(err)) call equilibrate_held(a, model, step, inc, record, converged, err)
      if (allocated(err)) then
        a%state = inc%start
        return
      end if
      if (converged) exit
      if (step%rmin%carry_unbalanced) then
        a%state = inc%start
        a%sys%du = a%sys%du_residual + inc%r * a%sys%du_load
        call apply_increment(a, model, step, inc, err, predict_penetration=.true.)
        if (.not. allocated(err)) call out_of_balance(a, model, step, record, err)
        if (allocated(err)) then
          a%state = inc%start
          return
        end if
        record%carried = .true.
        exit
      end if
      call cut_increment(a, model, step, inc, record, err)
      if (allocated(err)) return
    end do
  end subroutine take_fraction

  !> Equilibrium iterations (`equilibrate`) with the contact states held, then the gaps of
  !> the converged solution checked.
  subroutine equilibrate_held(a, model, step, inc, record, converged, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(increment_t), intent(in) :: inc
    type(increment_record_t), intent(inout) :: record
    logical, intent(out) :: converged
    type(error_t), allocatable, intent(out) :: err
    if (a%contact%n_slaves() > 0) call a%contact%hold_states(a%state%contact)
    call equilibrate(a, model, step, inc, record, converged, err)
    if (a%contact%n_slaves() > 0) call a%contact%release_states(a%state%contact)
    if (.not. allocated(err) .and. converged .and. a%contact%n_slaves() > 0) &
      call a%contact%check_gaps(model%mesh%node_id, a%state%contact, err)
  end subroutine equilibrate_held

  !> The run's counters after an increment was taken: increments (of the run and of the
  !> step), the out-of-balance force left, the mean force scale, the step's worst residual.
  subroutine count_increment(state, record)
    type(state_t), intent(inout) :: state
    type(increment_record_t), intent(in) :: record
    state%residual_norm = record%residual_ratio
    state%increment = state%increment + 1
    state%force_scale = state%force_scale + (record%force_scale - state%force_scale) / &
                        state%increment
    if (record%residual_ratio >= state%step_worst_residual) then
      state%step_worst_residual = record%residual_ratio
      state%step_worst_residual_increment = state%increment
    end if
    state%step_increment = state%step_increment + 1
  end subroutine count_increment

  !> Step time at the end of the increment: t0 + r dt (t0 + dt exactly when r = 1).
  pure real(dp) function increment_end_time(this) result(t_end)
    class(increment_t), intent(in) :: this
    if (this%r >= 1.0_dp) then
      t_end = this%t0 + this%dt
    else
      t_end = this%t0 + this%r * this%dt
    end if
  end function increment_end_time

  !> The trial time increment from t0: the step's maximum (its initial increment first), or
  !> less if the friction-rate limits of the last increment say so (not below the minimum),
  !> cut at the next breakpoint of the loading.
  subroutine trial_time_increment(state, loading, step, t0, dt, limited_by_friction)
    type(state_t), intent(in) :: state
    type(step_loading_t), intent(in) :: loading
    type(step_t), intent(in) :: step
    real(dp), intent(out) :: t0, dt
    logical, intent(out) :: limited_by_friction
    t0 = state%step_time
    dt = step%max_increment
    if (state%step_increment == 0) dt = step%initial_increment
    limited_by_friction = .false.
    if (state%friction_dt > 0.0_dp .and. max(state%friction_dt, step%min_increment) < dt) then
      dt = max(state%friction_dt, step%min_increment)
      limited_by_friction = .true.
    end if
    dt = min(dt, loading%next_breakpoint(t0) - t0)
  end subroutine trial_time_increment

  !> Rebuild the sparse pattern when the contact elements have moved out of it (and, in a
  !> distributed run, give MUMPS the whole model's ordering).
  subroutine ensure_pattern(a, model, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    if (a%contact%needs_pattern()) call build_pattern(a, model)
    if (a%sys%ordering_due) then
      call give_global_ordering(a, model, err)
      call a%share%comm%agree_error(err)
    end if
  end subroutine ensure_pattern

  !> The trial solution du_residual + du_load on the current state (10a-b), solved again
  !> with switched tangents while contact nodes switch between stick and slip at its start
  !> (not under CONTACT EVENTS=NORMAL or CLOSING, where the equilibrium iterations decide
  !> stick and slip: doc/theory.md 6.3) or plastic points unload.
  subroutine trial_solution(a, model, step, t0, dt, record, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    real(dp), intent(in) :: t0, dt
    type(increment_record_t), intent(inout) :: record
    type(error_t), allocatable, intent(out) :: err
    integer :: pass, n_switched
    if (a%elements%has_states()) call a%trial%reset_unloading(a%elements%max_points, a%state%n_elements)
    do pass = 1, MAX_STATE_PASSES
      call a%timers%start('assembly')
      call assemble_system(a, model, step, t0, dt, err)
      call a%timers%stop('assembly')
      if (allocated(err)) return
      a%sys%rhs_residual = a%sys%f_ext0 + a%sys%f_contact - a%sys%f_int
      call a%sys%links%reduce_vector(a%sys%rhs_residual)
      where (a%sys%constrained) a%sys%rhs_residual = 0.0_dp
      call a%sys%constrain_trial(a%share%comm, err)
      if (allocated(err)) return
      call a%sys%solve_trial(a%timers, model%mesh%node_id, err)
      call a%share%comm%agree_error(err)
      if (allocated(err)) return
      if (a%contact%n_slaves() == 0 .and. .not. a%elements%has_states()) exit
      a%sys%du = a%sys%du_residual + a%sys%du_load
      n_switched = 0
      if (a%contact%n_slaves() > 0 .and. step%rmin%contact_events == CONTACT_EVENTS_ALL) &
        call a%contact%switch_states(a%x_contact, a%state%contact, a%sys%du, n_switched)
      if (a%elements%has_states()) call switch_unloading(a, step%nlgeom, n_switched)
      record%n_switches = record%n_switches + n_switched
      if (n_switched == 0) exit
    end do
  end subroutine trial_solution

  !> Collect the events of the trial increment and choose the fraction r to take (10e),
  !> floored at the step's minimum increment unless a strain or rotation limit cuts it.
  subroutine choose_fraction(a, model, step, dt, limited_by_friction, record, r, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    real(dp), intent(in) :: dt
    logical, intent(in) :: limited_by_friction
    type(increment_record_t), intent(inout) :: record
    real(dp), intent(out) :: r
    type(error_t), allocatable, intent(out) :: err
    call collect_events(a, step, err)
    call a%share%comm%agree_error(err)
    if (allocated(err)) return
    call global_fraction(a%trial%collector, a%share%comm, step%rmin%event_tolerance, r)
    record%limiting = a%trial%collector%limiting
    if (limited_by_friction .and. record%limiting%kind == EVENT_FULL_INCREMENT) &
      record%limiting = rmin_event_t(1.0_dp, a%state%friction_kind, a%state%friction_node, 0)
    if (r * dt < step%min_increment .and. r < 1.0_dp) then
      if (a%trial%collector%limiting%kind == EVENT_STRAIN_LIMIT .or. &
          a%trial%collector%limiting%kind == EVENT_ROTATION_LIMIT) then
        call fatal_error(err, 'the ' // event_kind_name(a%trial%collector%limiting%kind) // &
          ' cuts the time increment to ' // str(r * dt) // ', below the minimum ' // &
          str(step%min_increment) // ' of *STATIC (element ' // &
          str(model%mesh%element_id(a%trial%collector%limiting%entity)) // '): the deformation ' // &
          'is too fast for the time scale; lower the minimum increment or check the loading')
        return
      end if
      r = min(1.0_dp, step%min_increment / dt)
      record%floored = .true.
    end if
  end subroutine choose_fraction

  !> Apply the increment a%sys%du (fraction inc%r of the trial increment over [t0, t0 + dt])
  !> to the state: stresses, displacements, positions, time, and the contact states decided
  !> on the new positions. Nothing changes before every element is known to stay valid.
  subroutine apply_increment(a, model, step, inc, err, predict_penetration)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(increment_t), intent(in) :: inc
    type(error_t), allocatable, intent(out) :: err
    !> Check the penetration the increment predicts (the first application; the iterates of
    !> the equilibrium iterations are checked on their result instead).
    logical, intent(in) :: predict_penetration
    call a%timers%start('update')
    associate (state => a%state)
      ! Nonlinear constraints hold exactly at the end of the increment (doc/theory.md 6.2.3).
      if (step%nlgeom .and. a%sys%nonlinear%active()) &
        call a%sys%nonlinear%project(model%mesh%x, state%u, a%sys%du)
      if (step%nlgeom) call a%elements%check_geometry(state%x, a%sys%du, err)
      call a%share%comm%agree_error(err)
      if (.not. allocated(err) .and. a%contact%n_slaves() > 0 .and. predict_penetration) &
        call a%contact%check_penetration(model%mesh%node_id, a%x_contact, state%contact, a%sys%du, err)
      if (.not. allocated(err)) then
        if (allocated(state%temperature)) then
          call end_temperatures(a, model, inc%end_time())
          call a%elements%update(state%x, a%sys%du, state%elements, step%nlgeom, err, &
                                 state%temperature, a%trial%temperature, model%initial_temperature)
        else
          call a%elements%update(state%x, a%sys%du, state%elements, step%nlgeom, err)
        end if
      end if
      call a%share%comm%agree_error(err)
      if (allocated(err)) then
        call a%timers%stop('update')
        return
      end if
      if (allocated(state%temperature)) state%temperature = a%trial%temperature
      state%u = state%u + reshape(a%sys%du, shape(state%u))
      if (step%nlgeom) state%x = state%x + reshape(a%sys%du, shape(state%x))
      state%step_time = inc%end_time()
      call contact_positions(a, model)
      if (a%contact%n_slaves() > 0) then
        call a%contact%update(a%x_contact, state%contact, state%step_time - inc%t0, inc%r)
        call friction_step_control(a%contact, step, state%step_time - inc%t0, state)
      end if
      state%time = state%time + (state%step_time - inc%t0)
      state%last_increment = state%step_time - inc%t0
      state%last_r = inc%r
    end associate
    call follow_constraints(a, model, step%nlgeom, err)
    call a%timers%stop('update')
  end subroutine apply_increment

  !> Under NLGEOM, the elimination of the nonlinear constraints linearised at the current
  !> state (fcs_nonlinear_constraints; doc/theory.md 6.2.3), so that the tangent and the
  !> out-of-balance force of this state are reduced with the constraints' tangent space here.
  subroutine follow_constraints(a, model, nlgeom, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    logical, intent(in) :: nlgeom
    type(error_t), allocatable, intent(out) :: err
    if (.not. (nlgeom .and. a%sys%nonlinear%active())) return
    call a%sys%nonlinear%relinearise(model%mesh%x, a%state%u, a%sys%links, model%mesh%n_nodes, &
                                     model%mesh%node_id, model%node_frame, model%transformed, err)
  end subroutine follow_constraints

  !> The nodal temperatures at step time t_end (the end of the increment), into
  !> a%trial%temperature.
  subroutine end_temperatures(a, model, t_end)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    real(dp), intent(in) :: t_end
    if (.not. allocated(a%trial%temperature)) allocate (a%trial%temperature(size(a%state%temperature)))
    call a%loading%temperature_at(model%amplitudes, t_end, a%trial%temperature)
  end subroutine end_temperatures

  !> Equilibrium iterations on the increment just applied: while the out-of-balance force
  !> at its end exceeds the step's EQUILIBRIUM TOLERANCE, solve K dc = R with the tangent of
  !> the current iterate (prescribed values held), add dc to the increment and apply it
  !> again from the state inc%start at the start of the increment, so that stresses, contact
  !> and friction states are decided on the corrected solution (Newton's method on the
  !> increment, as in an implicit step; the R-minimum choice of the increment keeps the
  !> state changes within it small). `converged` is false when the iterations did not reach
  !> the tolerance within MAX ITERATIONS or started to diverge: the caller cuts the increment.
  subroutine equilibrate(a, model, step, inc, record, converged, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(increment_t), intent(in) :: inc
    type(increment_record_t), intent(inout) :: record
    logical, intent(out) :: converged
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: norm, trial_norm, previous(2)
    integer :: iteration, n_growing
    converged = .false.
    n_growing = 0
    previous = huge(1.0_dp)
    call out_of_balance(a, model, step, record, err)
    if (allocated(err)) return
    norm = norm2(a%sys%rhs_residual)
    do iteration = 1, step%rmin%max_iterations + 1
      if (record%residual_ratio <= step%rmin%equilibrium_tolerance) then
        call recheck_held_states(a, model, step, inc, record, converged, err)
        if (converged .or. allocated(err)) return
        norm = norm2(a%sys%rhs_residual)
        n_growing = 0
        previous = huge(1.0_dp)
      end if
      if (iteration > step%rmin%max_iterations) return
      ! A correction that cannot be solved (the iterate lost the contact that supported a
      ! body: a singular tangent) is a failed iteration: the increment is cut.
      call correction(a, model, step, inc%t0, a%state%step_time - inc%t0, err)
      if (allocated(err)) then
        deallocate (err)
        return
      end if
      record%iterations = record%iterations + 1
      call line_search(a, model, step, inc, record, norm, trial_norm, err)
      if (allocated(err)) return
      if (trial_norm >= norm) then
        n_growing = n_growing + 1
        if (n_growing >= 2) return
      end if
      ! Under NO EQUILIBRIUM=CARRY, stagnation ends the iterations: less than a halving of
      ! |R| over two iterations (a slip event on a weakening interface has no equilibrium to
      ! converge to, and the increment will be carried anyway).
      previous(1) = previous(2)
      previous(2) = norm
      if (step%rmin%carry_unbalanced .and. trial_norm > STAGNATION * previous(1)) return
      norm = trial_norm
    end do
  end subroutine equilibrate

  !> In equilibrium with the held contact states: are they still right? `settled` when no
  !> held state changed; else the increment is applied again from inc%start with the changed
  !> states and its out-of-balance force computed anew.
  subroutine recheck_held_states(a, model, step, inc, record, settled, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(increment_t), intent(in) :: inc
    type(increment_record_t), intent(inout) :: record
    logical, intent(out) :: settled
    type(error_t), allocatable, intent(out) :: err
    integer :: n_changed
    n_changed = 0
    if (a%contact%n_slaves() > 0) call a%contact%check_held(a%state%contact, n_changed)
    settled = n_changed == 0
    if (settled) return
    a%state = inc%start
    call apply_increment(a, model, step, inc, err, predict_penetration=.false.)
    if (.not. allocated(err)) call out_of_balance(a, model, step, record, err)
  end subroutine recheck_held_states

  !> Backtracking on the norm of the out-of-balance force: the correction a%sys%correction
  !> added to the increment with step lengths 1, 1/2, 1/4, ... (MAX_LINE_SEARCH of them),
  !> each applied from inc%start, until |R| falls below `norm`; `trial_norm` is |R| of the
  !> last one, which is the state left. The contact and friction states make the residual
  !> only piecewise smooth, and a full Newton step across a change of state can overshoot.
  subroutine line_search(a, model, step, inc, record, norm, trial_norm, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(increment_t), intent(in) :: inc
    type(increment_record_t), intent(inout) :: record
    real(dp), intent(in) :: norm
    real(dp), intent(out) :: trial_norm
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: base(:)
    real(dp) :: step_length
    integer :: search
    base = a%sys%du
    step_length = 1.0_dp
    do search = 1, MAX_LINE_SEARCH
      a%sys%du = base + step_length * a%sys%correction
      a%state = inc%start
      call apply_increment(a, model, step, inc, err, predict_penetration=.false.)
      if (.not. allocated(err)) call out_of_balance(a, model, step, record, err)
      if (allocated(err)) return
      trial_norm = norm2(a%sys%rhs_residual)
      if (trial_norm < norm .or. search == MAX_LINE_SEARCH) exit
      step_length = 0.5_dp * step_length
    end do
  end subroutine line_search

  !> The out-of-balance force R = f_ext + f_c - f_int of the current state at its time (free
  !> degrees of freedom, into a%sys%rhs_residual) and its size: the largest nodal |R| over the
  !> mean nodal force flux of the elements (nodes that carry force).
  subroutine out_of_balance(a, model, step, record, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(increment_record_t), intent(inout) :: record
    type(error_t), allocatable, intent(out) :: err
    call a%timers%start('equilibrium')
    call a%elements%assemble(a%state%x, a%state%elements, step%nlgeom, a%sys%f_int, err, flux=a%sys%flux)
    call a%share%comm%agree_error(err)
    if (allocated(err)) then
      call a%timers%stop('equilibrium')
      return
    end if
    call a%share%comm%sum_real(a%sys%f_int)
    call a%share%comm%sum_real(a%sys%flux)
    a%sys%f_contact = 0.0_dp
    if (a%contact%n_slaves() > 0) call a%contact%forces(a%x_contact, a%state%contact, a%sys%f_contact)
    call external_force_at(a, model, step%nlgeom, a%state%step_time, a%sys%f_ext_end)
    a%sys%rhs_residual = a%sys%f_ext_end + a%sys%f_contact - a%sys%f_int
    call a%sys%links%reduce_vector(a%sys%rhs_residual)
    where (a%sys%constrained) a%sys%rhs_residual = 0.0_dp
    call measure_residual(a%sys, a%state%force_scale, record)
    call a%timers%stop('equilibrium')
  end subroutine out_of_balance

  !> The size of the out-of-balance force sys%rhs_residual into `record`: where its nodal
  !> norm is largest, the force scale (the mean nodal force flux sys%flux of the nodes that
  !> carry force, at least the thermal load's scale) and the ratio of the largest nodal norm
  !> to that scale, or to the run's mean force scale `run_scale` when that is larger.
  subroutine measure_residual(sys, run_scale, record)
    type(linear_system_t), intent(in) :: sys
    real(dp), intent(in) :: run_scale
    type(increment_record_t), intent(inout) :: record
    real(dp) :: worst, scale, node_norm, sums(2)
    integer :: node
    worst = 0.0_dp
    record%residual_node = 0
    do node = 1, size(sys%flux)
      node_norm = norm2(sys%rhs_residual(3 * node - 2:3 * node))
      if (node_norm > worst) then
        worst = node_norm
        record%residual_node = node
        record%residual_direction = maxloc(abs(sys%rhs_residual(3 * node - 2:3 * node)), 1)
      end if
    end do
    sums = [sum(sys%flux, mask=sys%flux > 0.0_dp), real(count(sys%flux > 0.0_dp), dp)]
    record%force_scale = 0.0_dp
    if (sums(2) > 0.0_dp) record%force_scale = sums(1) / sums(2)
    record%force_scale = max(record%force_scale, sys%thermal_scale)
    ! The scale is never below the mean over the increments of the run so far (CalculiX
    ! averages its force scale over the increments of a step): a body unloaded to nearly no
    ! stress keeps a tolerance relative to the forces it carried, not to its round-off.
    scale = max(record%force_scale, run_scale)
    record%residual_ratio = 0.0_dp
    if (worst > 0.0_dp) record%residual_ratio = worst / max(scale, tiny(1.0_dp))
  end subroutine measure_residual

  !> One equilibrium correction: K dc = R (a%sys%rhs_residual) with K the tangent of the current
  !> state and dc = 0 on the prescribed degrees of freedom; dt is the duration of the
  !> increment (the rate term of the friction tangent).
  subroutine correction(a, model, step, t0, dt, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    real(dp), intent(in) :: t0, dt
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: residual(:)
    call ensure_pattern(a, model, err)
    if (allocated(err)) return
    residual = a%sys%rhs_residual
    call a%timers%start('assembly')
    call assemble_system(a, model, step, t0, dt, err)
    call a%timers%stop('assembly')
    if (allocated(err)) return
    a%sys%correction = 0.0_dp
    call a%sys%constrain(a%share%comm, a%sys%correction, err)
    if (allocated(err)) return
    a%sys%rhs = merge(0.0_dp, residual, a%sys%constrained)
    call a%sys%solve_correction(a%timers, model%mesh%node_id, err)
    call a%share%comm%agree_error(err)
  end subroutine correction

  !> The equilibrium iterations of the increment did not converge: go back to its start and
  !> take CUT_FACTOR of it (not less than the step's minimum increment); at the minimum the
  !> run stops, naming where the out-of-balance force is largest.
  subroutine cut_increment(a, model, step, inc, record, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(increment_t), intent(inout) :: inc
    type(increment_record_t), intent(inout) :: record
    type(error_t), allocatable, intent(out) :: err
    character(len=1), parameter :: AXIS(3) = ['x', 'y', 'z']
    a%state = inc%start
    if (record%cuts >= MAX_CUTS .or. inc%r * inc%dt <= step%min_increment * (1.0_dp + 1.0e-12_dp)) then
      call fatal_error(err, 'no equilibrium: after ' // str(record%iterations) // ' iteration(s) ' // &
        'and ' // str(record%cuts) // ' cut(s) of the increment (to ' // str(inc%r * inc%dt) // &
        '), the out-of-balance force is still ' // str(record%residual_ratio) // ' of the force ' // &
        'scale (tolerance ' // str(step%rmin%equilibrium_tolerance) // '), largest at node ' // &
        str(model%mesh%node_id(max(record%residual_node, 1))) // ' in ' // &
        AXIS(max(record%residual_direction, 1)) // &
        distortion_note(a%elements, a%state%x, model, step%nlgeom) // &
        '; check the loading and the supports, or raise EQUILIBRIUM TOLERANCE or MAX ' // &
        'ITERATIONS on *RMIN')
      return
    end if
    record%cuts = record%cuts + 1
    inc%r = max(inc%r * CUT_FACTOR, step%min_increment / inc%dt)
  end subroutine cut_increment

  !> The trial time increment for the next increment from the friction changes over the last
  !> one (duration dt): each change of ln V, mu, state at a slipping node may be at most its
  !> *RMIN limit, and with MAX SLIP INCREMENT = xi the slip of a slipping node at most xi L
  !> (L the characteristic slip of its rate-and-state law), so that the next increment is at
  !> most xi L / V_max (Lapusta et al. 2000, eq. 17 with a constant xi); the increment grows
  !> by at most a factor 2 when the changes are small, and is not limited when no node slips.
  !> Scaling an increment does not change its slip rate, so rate effects are controlled
  !> through the time increment (method notes 1.6).
  subroutine friction_step_control(contact, step, dt, state)
    type(contact_system_t), intent(in) :: contact
    type(step_t), intent(in) :: step
    real(dp), intent(in) :: dt
    type(state_t), intent(inout) :: state
    real(dp) :: limits(4), factors(4), change(4)
    integer :: i, worst, change_node(4)
    integer, parameter :: kinds(4) = [EVENT_SLIP_RATE_CHANGE, EVENT_FRICTION_CHANGE, EVENT_STATE_CHANGE, &
                                      EVENT_SLIP_INCREMENT]
    call contact%friction_changes(change, change_node)
    ! MAX SLIP INCREMENT is an option (0: none).
    if (step%rmin%max_slip_increment <= 0.0_dp) change(4) = 0.0_dp
    if (all(change <= 0.0_dp) .or. dt <= 0.0_dp) then
      state%friction_dt = 0.0_dp
      return
    end if
    limits = [step%rmin%max_log_rate_change, step%rmin%max_friction_change, step%rmin%max_state_change, &
              step%rmin%max_slip_increment]
    factors = 2.0_dp
    do i = 1, 4
      if (change(i) > 0.0_dp) factors(i) = min(2.0_dp, limits(i) / change(i))
    end do
    worst = minloc(factors, 1)
    state%friction_dt = dt * factors(worst)
    state%friction_kind = kinds(worst)
    state%friction_node = change_node(worst)
  end subroutine friction_step_control

  !> K + K_f + load stiffness and the internal, contact forces on the current state. Each
  !> process adds its elements and contact slaves to its own matrix (the solver sums the
  !> processes' entries) and the forces are summed over the processes; the load stiffness of
  !> pressures is added once, by rank 0.
  subroutine assemble_system(a, model, step, t0, dt, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    real(dp), intent(in) :: t0, dt
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: scratch(:)
    call a%sys%matrix%zero()
    if (a%elements%has_states()) then
      call a%elements%assemble(a%state%x, a%state%elements, step%nlgeom, a%sys%f_int, err, a%sys%matrix, &
                               a%trial%unloading)
    else if (allocated(a%state%temperature)) then
      call a%elements%assemble(a%state%x, a%state%elements, step%nlgeom, a%sys%f_int, err, a%sys%matrix, &
                               temperature=a%state%temperature)
    else
      call a%elements%assemble(a%state%x, a%state%elements, step%nlgeom, a%sys%f_int, err, a%sys%matrix)
    end if
    call a%share%comm%agree_error(err)
    if (allocated(err)) return
    if (step%nlgeom .and. a%share%comm%is_root()) then
      allocate (scratch(size(a%sys%f_int)))
      scratch = 0.0_dp
      call assemble_pressures(a%elements, a%loading, model, t0, a%state%x, .true., scratch, a%sys%matrix)
    end if
    a%sys%f_contact = 0.0_dp
    if (a%contact%n_slaves() > 0) call a%contact%assemble(a%x_contact, a%state%contact, dt, &
                                                          a%sys%matrix, a%sys%f_contact, err, a%share%owns_slave)
    call a%share%comm%agree_error(err)
    if (allocated(err)) return
    call a%share%comm%sum_real(a%sys%f_int)
    call a%share%comm%sum_real(a%sys%f_contact)
  end subroutine assemble_system

  !> The nodal forces printed as RF, (3, n_nodes): at a prescribed degree of freedom the
  !> reaction, the force the support exerts: internal force less contact force less the load
  !> applied there at the current time (CalculiX prints the internal force, which also holds
  !> that load); at a free degree of freedom, as CalculiX prints it, the internal force less
  !> the contact force, i.e. the load applied there (up to the equilibrium tolerance). Leaves
  !> the internal and contact forces in a%sys%f_int, a%sys%f_contact.
  subroutine current_reactions(a, model, reaction, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    real(dp), intent(out) :: reaction(:, :)
    type(error_t), allocatable, intent(out) :: err
    logical :: nlgeom
    nlgeom = model%steps(min(a%state%step, size(model%steps)))%nlgeom
    call internal_forces(a, nlgeom, a%sys%f_int, err)
    if (allocated(err)) return
    a%sys%f_contact = 0.0_dp
    if (a%contact%n_slaves() > 0) call a%contact%forces(a%x_contact, a%state%contact, a%sys%f_contact)
    a%sys%f_ext_end = 0.0_dp
    if (allocated(a%loading%bc_dof)) call external_force_at(a, model, nlgeom, a%state%step_time, a%sys%f_ext_end)
    where (.not. supported_dofs(a%loading, model)) a%sys%f_ext_end = 0.0_dp
    reaction = reshape(a%sys%f_int - a%sys%f_contact - a%sys%f_ext_end, shape(reaction))
    call local_axes_reactions(a, model, reaction)
    call transmitted_reactions(a%sys, model, reaction)
  end subroutine current_reactions

  !> At a node with local axes (*TRANSFORM) the prescribed degrees of freedom are local
  !> components: the load taken off is that of the prescribed local directions,
  !> R (f_int - f_c - P R^T f_ext) with P the projection on them.
  subroutine local_axes_reactions(a, model, reaction)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    real(dp), intent(inout) :: reaction(:, :)
    real(dp) :: local(3), load(3)
    logical, allocatable :: prescribed(:)
    integer :: node, i
    if (.not. any(model%transformed)) return
    call external_force_at(a, model, model%steps(min(a%state%step, size(model%steps)))%nlgeom, &
                           a%state%step_time, a%sys%f_ext_end)
    allocate (prescribed(3 * model%mesh%n_nodes))
    prescribed = .false.
    if (allocated(a%loading%bc_dof)) prescribed(a%loading%bc_dof) = .true.
    do node = 1, model%mesh%n_nodes
      if (.not. model%transformed(node)) cycle
      associate (frame => model%node_frame(:, :, node))
        local = matmul(transpose(frame), a%sys%f_int(3 * node - 2:3 * node) - a%sys%f_contact(3 * node - 2:3 * node))
        load = matmul(transpose(frame), a%sys%f_ext_end(3 * node - 2:3 * node))
        do i = 1, 3
          if (prescribed(3 * node - 3 + i)) local(i) = local(i) - load(i)
        end do
        reaction(:, node) = matmul(frame, local)
      end associate
    end do
  end subroutine local_axes_reactions

  !> At the nodes outside the structure that constraints transmit force to (the reference and
  !> rotation nodes of a *RIGID BODY), RF is the force (moment) the constraint transmits:
  !> T^T (f_int - f_c) there (L2), less the load applied there at a prescribed degree of
  !> freedom, as CalculiX prints RF at the nodes of its RIGID MPCs (resultsforc: their
  !> constraint forces are left on those nodes).
  subroutine transmitted_reactions(sys, model, reaction)
    type(linear_system_t), intent(in) :: sys
    type(model_t), intent(in) :: model
    real(dp), intent(inout) :: reaction(:, :)
    real(dp), allocatable :: transmitted(:)
    integer :: k, j, node
    if (.not. any(model%equations(:)%transmits)) return
    transmitted = sys%f_int - sys%f_contact
    call sys%links%reduce_vector(transmitted)
    do k = 1, size(model%equations)
      if (.not. model%equations(k)%transmits) cycle
      do j = model%equations(k)%first_transmitting, size(model%equations(k)%terms)
        node = model%equations(k)%terms(j)%node
        reaction(:, node) = transmitted(3 * node - 2:3 * node) - sys%f_ext_end(3 * node - 2:3 * node)
      end do
    end do
  end subroutine transmitted_reactions

  !> The degrees of freedom the current step prescribes (and those of nodes in no element).
  function supported_dofs(loading, model) result(supported)
    type(step_loading_t), intent(in) :: loading
    type(model_t), intent(in) :: model
    logical :: supported(3 * model%mesh%n_nodes)
    integer :: node
    supported = .false.
    do node = 1, model%mesh%n_nodes
      if (model%free_node(node)) supported(3 * node - 2:3 * node) = .true.
    end do
    supported = supported .or. model%idle_dof
    if (allocated(loading%bc_dof)) supported(loading%bc_dof) = .true.
  end function supported_dofs

  !> Internal forces of the current state (all elements, summed over the processes).
  subroutine internal_forces(a, nlgeom, f_int, err)
    type(analysis_t), intent(in) :: a
    logical, intent(in) :: nlgeom
    real(dp), intent(out) :: f_int(:)
    type(error_t), allocatable, intent(out) :: err
    call a%elements%assemble(a%state%x, a%state%elements, nlgeom, f_int, err)
    call a%share%comm%agree_error(err)
    if (.not. allocated(err)) call a%share%comm%sum_real(f_int)
  end subroutine internal_forces

  !> Make the integration-point fields complete on every process: each process holds
  !> current values for its own elements only; their sum with zeros elsewhere is exact.
  subroutine gather_element_fields(a)
    type(analysis_t), intent(inout) :: a
    logical, allocatable :: mine(:)
    integer :: e
    if (a%share%comm%size == 1) return
    allocate (mine(a%state%n_elements))
    mine = .false.
    mine(a%elements%mine) = .true.
    associate (fields => a%state%elements)
      do e = 1, a%state%n_elements
        if (mine(e)) cycle
        fields%stress(:, :, e) = 0.0_dp
        fields%strain(:, :, e) = 0.0_dp
        fields%material_state(:, :, e) = 0.0_dp
      end do
      call a%share%comm%sum_real(fields%stress)
      call a%share%comm%sum_real(fields%strain)
      if (size(fields%material_state) > 0) call a%share%comm%sum_real(fields%material_state)
    end associate
  end subroutine gather_element_fields

  !> The fraction of the trial increment taken, over all processes: the smallest event
  !> fraction (and its event, from the process that has it), widened to the near-simultaneous
  !> discrete events within `tolerance`, never beyond a strain or rotation limit.
  subroutine global_fraction(collector, comm, tolerance, r)
    type(rmin_collector_t), intent(inout) :: collector
    type(comm_t), intent(in) :: comm
    real(dp), intent(in) :: tolerance
    real(dp), intent(out) :: r
    real(dp) :: r_min, band, limit
    integer :: owner, event(4)
    r_min = collector%r_min
    call comm%min_real(r_min, owner)
    event = [collector%limiting%kind, collector%limiting%entity, collector%limiting%detail, 0]
    call comm%broadcast_int(event, owner)
    collector%r_min = r_min
    collector%limiting = rmin_event_t(r_min, event(1), event(2), event(3))
    band = collector%band_fraction(tolerance)
    limit = collector%limit_fraction()
    call comm%max_real(band)
    call comm%min_real(limit)
    r = min(band, limit)
    if (event(1) == EVENT_STRAIN_LIMIT .or. event(1) == EVENT_ROTATION_LIMIT .or. &
        event(1) == EVENT_FULL_INCREMENT) r = r_min
  end subroutine global_fraction

  !> Sparse pattern from the element cliques and the contact cliques (slave node with the
  !> nodes of its master face and the neighbouring faces).
  subroutine build_pattern(a, model, keep_centres)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    logical, intent(in), optional :: keep_centres
    integer, allocatable :: clique_ptr(:), clique_nodes(:)
    integer :: node, n_nodes, last
    call a%elements%cliques(a%elements%mine, clique_ptr, clique_nodes)
    if (a%contact%n_slaves() > 0) call a%contact%cliques(a%state%contact, clique_ptr, clique_nodes, &
                                                         keep_centres, a%share%owns_slave)
    if (a%share%comm%size > 1 .and. a%share%comm%is_root()) then
      ! Rank 0 also holds every diagonal (constrained rows) and the pressure load stiffness:
      ! a one-node clique per node, then the pressure faces (appended in one go).
      n_nodes = model%mesh%n_nodes
      last = clique_ptr(size(clique_ptr))
      clique_nodes = [clique_nodes, [(node, node = 1, n_nodes)], a%share%pressure_nodes]
      clique_ptr = [clique_ptr, [(last + node, node = 1, n_nodes)], &
                    last + n_nodes + a%share%pressure_ptr(2:) - 1]
    end if
    call a%sys%links%expand_cliques(clique_ptr, clique_nodes)
    call a%sys%matrix%build(model%mesh%n_nodes, clique_ptr, clique_nodes)
    a%sys%ordering_due = a%share%comm%size > 1
  end subroutine build_pattern

  !> Distributed runs: the fill-reducing ordering of the whole model's graph (every element
  !> and contact clique, not only this process's share), computed on rank 0 and given to
  !> MUMPS for its next analysis. The host's own matrix holds only its share of the
  !> couplings: ordered alone, it gave 5 times the factor entries and 30 times the flops of
  !> the serial run on the contact benchmark. The whole pattern is built as the serial run
  !> builds it (pressure faces are element faces, and every node couples to itself), and
  !> ordered as the serial run orders it, so the order is the serial run's.
  subroutine give_global_ordering(a, model, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: clique_ptr(:), clique_nodes(:), position(:)
    type(sparse_matrix_t) :: whole
    integer :: e
    a%sys%ordering_due = .false.
    if (.not. a%share%comm%is_root() .or. .not. a%sys%solver%takes_ordering()) return
    call a%elements%cliques([(e, e = 1, model%mesh%n_elements)], clique_ptr, clique_nodes)
    if (a%contact%n_slaves() > 0) call a%contact%cliques(a%state%contact, clique_ptr, &
                                                         clique_nodes, keep_centres=.true.)
    call a%sys%links%expand_cliques(clique_ptr, clique_nodes)
    call whole%build(model%mesh%n_nodes, clique_ptr, clique_nodes)
    call metis_equation_order(whole, position, err)
    call whole%free()
    if (allocated(err)) return
    call a%sys%solver%set_ordering(position)
  end subroutine give_global_ordering

  !> Current positions X + u for the contact search and elements (also without NLGEOM:
  !> contact is geometrically nonlinear in any case).
  subroutine contact_positions(a, model)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    a%x_contact = model%mesh%x + a%state%u
  end subroutine contact_positions

  !> f_ext0 = F(t0), f_ext1 = F(t1): concentrated forces and pressures on the current
  !> geometry (the follower load stiffness is added during assembly).
  subroutine external_forces(a, model, nlgeom, t0, t1)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    logical, intent(in) :: nlgeom
    real(dp), intent(in) :: t0, t1
    a%sys%f_ext0 = 0.0_dp
    a%sys%f_ext1 = 0.0_dp
    call a%loading%force_at(model%amplitudes, t0, a%sys%f_ext0)
    call a%loading%force_at(model%amplitudes, t1, a%sys%f_ext1)
    ! Concentrated loads on nodes with local axes (*TRANSFORM) are given in those axes.
    call a%sys%links%to_global(a%sys%f_ext0)
    call a%sys%links%to_global(a%sys%f_ext1)
    call assemble_pressures(a%elements, a%loading, model, t0, a%state%x, nlgeom, a%sys%f_ext0)
    call assemble_pressures(a%elements, a%loading, model, t1, a%state%x, nlgeom, a%sys%f_ext1)
    if (size(a%loading%body_element) > 0) then
      call assemble_body_loads(a%elements, a%loading, model, t0, a%state%x, nlgeom, a%sys%f_ext0)
      call assemble_body_loads(a%elements, a%loading, model, t1, a%state%x, nlgeom, a%sys%f_ext1)
    end if
    if (allocated(a%state%temperature)) call thermal_load(a, model, nlgeom, t1)
  end subroutine external_forces

  !> The thermal load of the trial increment (fcs_element_loops, thermal_forces: the
  !> temperatures going from the state's to those at step time t1) added to f_ext1, so that
  !> it enters the load part du_load of the trial solution and is scaled by r with the other
  !> loads (doc/theory.md 2.5); the end temperatures are kept in a%trial%temperature for the
  !> events of the trial. f_ext0 and the out-of-balance force hold no thermal term: the
  !> internal forces of the updated stresses carry it.
  subroutine thermal_load(a, model, nlgeom, t1)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    logical, intent(in) :: nlgeom
    real(dp), intent(in) :: t1
    type(error_t), allocatable :: err
    if (.not. allocated(a%trial%temperature)) allocate (a%trial%temperature(size(a%state%temperature)))
    call a%loading%temperature_at(model%amplitudes, t1, a%trial%temperature)
    if (.not. a%elements%has_thermal()) return
    if (.not. allocated(a%sys%f_thermal)) allocate (a%sys%f_thermal(size(a%sys%f_ext1)))
    call a%elements%thermal_forces(a%state%x, a%state%elements, nlgeom, a%state%temperature, &
                                   a%trial%temperature, a%sys%f_thermal, err)
    ! An inverted element is reported by the assembly that follows on the same configuration.
    if (allocated(err)) a%sys%f_thermal = 0.0_dp
    call a%share%comm%sum_real(a%sys%f_thermal)
    a%sys%f_ext1 = a%sys%f_ext1 + a%sys%f_thermal
    a%sys%thermal_scale = nodal_mean_norm(a%sys%f_thermal)
  end subroutine thermal_load

  !> Mean over the nodes with a nonzero force of the norm of the nodal force f (3 n_nodes).
  pure real(dp) function nodal_mean_norm(f) result(mean)
    real(dp), intent(in) :: f(:)
    real(dp) :: size_of
    integer :: node, n
    mean = 0.0_dp
    n = 0
    do node = 1, size(f) / 3
      size_of = norm2(f(3 * node - 2:3 * node))
      if (size_of > 0.0_dp) then
        mean = mean + size_of
        n = n + 1
      end if
    end do
    if (n > 0) mean = mean / n
  end function nodal_mean_norm



  !> The external forces at step time t on the current geometry.
  subroutine external_force_at(a, model, nlgeom, t, f_ext)
    type(analysis_t), intent(in) :: a
    type(model_t), intent(in) :: model
    logical, intent(in) :: nlgeom
    real(dp), intent(in) :: t
    real(dp), intent(out) :: f_ext(:)
    f_ext = 0.0_dp
    call a%loading%force_at(model%amplitudes, t, f_ext)
    call a%sys%links%to_global(f_ext)
    call assemble_pressures(a%elements, a%loading, model, t, a%state%x, nlgeom, f_ext)
    if (size(a%loading%body_element) > 0) &
      call assemble_body_loads(a%elements, a%loading, model, t, a%state%x, nlgeom, f_ext)
  end subroutine external_force_at

  !> Constrained degrees of freedom and their prescribed increments over [t0, t1]. Nodes in
  !> no element are held where they are.
  subroutine prescribed_increments(a, model, t0, t1)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    real(dp), intent(in) :: t0, t1
    integer :: i, dof, node, direction
    a%sys%constrained = .false.
    a%sys%prescribed = 0.0_dp
    do node = 1, model%mesh%n_nodes
      if (model%free_node(node)) a%sys%constrained(3 * node - 2:3 * node) = .true.
    end do
    a%sys%constrained = a%sys%constrained .or. model%idle_dof
    if (a%sys%links%active()) a%sys%constrained = a%sys%constrained .or. a%sys%links%dependent
    do i = 1, size(a%loading%bc_dof)
      dof = a%loading%bc_dof(i)
      node = (dof - 1) / 3 + 1
      direction = dof - 3 * (node - 1)
      a%sys%constrained(dof) = .true.
      ! At a node with local axes (*TRANSFORM) the unknowns, and so the prescribed values,
      ! are the local components.
      a%sys%prescribed(dof) = a%loading%prescribed_target(model%amplitudes, i, t0, t1, &
        a%sys%links%to_local(a%state%u(:, node), node, direction), &
        a%sys%links%to_local(a%state%step_start_u(:, node), node, direction))
    end do
  end subroutine prescribed_increments

  !> Offer every event and limit of the trial increment to the collector: the contact
  !> events, then the element limits and events (fcs_element_loops).
  subroutine collect_events(a, step, err)
    type(analysis_t), intent(inout) :: a
    type(step_t), intent(in) :: step
    type(error_t), allocatable, intent(out) :: err
    call a%trial%collector%reset()
    if (a%contact%n_slaves() > 0) call a%contact%events(a%x_contact, a%state%contact, a%sys%du_residual, &
      a%sys%du_load, a%trial%collector, step%rmin%contact_events)
    if (allocated(a%state%temperature) .and. allocated(a%trial%temperature)) then
      call a%elements%collect_events(a%state%x, a%sys%du_load, a%sys%du_residual, a%state%elements, &
        step%nlgeom, event_limits_t(step%rmin%max_strain_increment, &
        step%rmin%max_rotation_increment, step%rmin%max_plastic_strain_increment), a%trial%collector, &
        err, a%state%temperature, a%trial%temperature)
    else
      call a%elements%collect_events(a%state%x, a%sys%du_load, a%sys%du_residual, a%state%elements, &
        step%nlgeom, event_limits_t(step%rmin%max_strain_increment, &
        step%rmin%max_rotation_increment, step%rmin%max_plastic_strain_increment), a%trial%collector, err)
    end if
  end subroutine collect_events

  !> Elastic unloading as a state switch (doc/theory.md 6.3; Yamada, Yoshimura & Sakurai
  !> 1968): every point on its yield surface that the trial increment a%sys%du moves inwards
  !> takes the elastic tangent for the rest of the increment (fcs_element_loops,
  !> count_unloading); `n_switched` grows by the number of new such points over all processes
  !> (the increment is then solved again).
  subroutine switch_unloading(a, nlgeom, n_switched)
    type(analysis_t), intent(inout) :: a
    logical, intent(in) :: nlgeom
    integer, intent(inout) :: n_switched
    real(dp) :: count(1)
    count = a%elements%count_unloading(a%state%x, a%sys%du, a%state%elements, nlgeom, a%trial%unloading)
    call a%share%comm%sum_real(count)
    n_switched = n_switched + nint(count(1))
  end subroutine switch_unloading






  !> For the message of an increment without equilibrium: the most distorted element of
  !> the current configuration when it is nearly inverted (its Jacobian determinant varies by
  !> more than a factor 20 over its integration points), else nothing.
  function distortion_note(elements, x, model, nlgeom) result(note)
    type(element_loops_t), intent(in) :: elements
    !> Current coordinates (3, n_nodes).
    real(dp), intent(in) :: x(:, :)
    type(model_t), intent(in) :: model
    logical, intent(in) :: nlgeom
    character(len=:), allocatable :: note
    real(dp) :: worst
    integer :: worst_element
    note = ''
    if (.not. nlgeom) return
    call elements%most_distorted(x, worst_element, worst)
    if (worst_element == 0 .or. worst >= 0.05_dp) return
    note = '; element ' // str(model%mesh%element_id(worst_element)) // ' is nearly inverted ' // &
      '(its Jacobian determinant varies by a factor ' // str(1.0_dp / max(worst, tiny(1.0_dp))) // &
      ' over its integration points): the mesh cannot follow the deformation there'
  end function distortion_note

  !> How many discrete events fall within the increment taken (near-simultaneous ones).
  integer function count_taken(collector, r) result(n)
    type(rmin_collector_t), intent(in) :: collector
    real(dp), intent(in) :: r
    integer :: i
    n = 0
    do i = 1, collector%n_events
      if (collector%events(i)%kind == EVENT_STRAIN_LIMIT .or. &
          collector%events(i)%kind == EVENT_ROTATION_LIMIT .or. &
          collector%events(i)%kind == EVENT_PLASTIC_STRAIN_LIMIT) cycle
      if (collector%events(i)%r <= r) n = n + 1
    end do
  end function count_taken

end module fcs_static_explicit
