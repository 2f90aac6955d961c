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
  use fcs_linear_solver, only: linear_solver_t
  use fcs_factor_reuse, only: factor_reuse_t
  use fcs_mumps, only: mumps_solver_t
  use fcs_metis_order, only: metis_equation_order
  use fcs_loading, only: step_loading_t
  use fcs_assembly, only: material_slot_t, assemble_elements, assemble_pressures, &
                          element_configuration, inverted_element_error
  use fcs_hex8_element, only: hex8_geometry_t, hex8_geometry, hex8_strain_increments, &
                              hex8_rotate_stress
  use fcs_hex8_shape, only: N_GAUSS_HEX8
  use fcs_model, only: FORMULATION_BBAR
  use fcs_rmin_events, only: rmin_collector_t, rmin_event_t, EVENT_STRAIN_LIMIT, &
                             EVENT_ROTATION_LIMIT, EVENT_YIELD, event_kind_name, EVENT_NONE, &
                             EVENT_FULL_INCREMENT, EVENT_SLIP_RATE_CHANGE, EVENT_FRICTION_CHANGE, &
                             EVENT_STATE_CHANGE, EVENT_PLASTIC_STRAIN_LIMIT, EVENT_SLIP_INCREMENT
  use fcs_material, only: material_t
  use fcs_voigt, only: spin_rotation, rotate_stress_like, rotate_strain_like
  use fcs_timer, only: phase_timer_t
  use fcs_contact_system, only: contact_system_t
  use fcs_assembly, only: element_cliques
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

  !> Working storage of the analysis, allocated once and reused every increment.
  type :: analysis_t
    type(state_t) :: state
    type(material_slot_t), allocatable :: materials(:)
    logical :: materials_have_states = .false.
    type(sparse_matrix_t) :: matrix
    class(linear_solver_t), allocatable :: solver
    !> Reuse of the solver's factors across tangents (GMRES preconditioned by them).
    type(factor_reuse_t) :: reuse
    type(step_loading_t) :: loading
    real(dp), allocatable :: f_int(:), f_ext0(:), f_ext1(:), rhs(:), du(:), prescribed(:)
    !> The two parts of the trial solution: du_load for the load increment over the trial
    !> time increment (scaled by r), du_residual for the out-of-balance force of the current
    !> state (applied in full, so that equilibrium errors do not linger); rhs_residual its
    !> right-hand side.
    real(dp), allocatable :: du_load(:), du_residual(:), rhs_residual(:)
    !> Equilibrium iterations: external forces at the end of the increment, nodal force
    !> flux (the force scale, per node), the correction of one iteration.
    real(dp), allocatable :: f_ext_end(:), flux(:), correction(:)
    logical, allocatable :: constrained(:)
    type(rmin_collector_t) :: collector
    type(phase_timer_t) :: timers
    !> Node-to-point contact pairs, and their nodal forces (3*n_nodes).
    type(contact_system_t) :: contact
    real(dp), allocatable :: f_contact(:)
    !> Coordinates the contact search and elements use (current positions X + u).
    real(dp), allocatable :: x_contact(:, :)
    !> The processes of the run and the work of this one (replicated state, distributed
    !> work): the elements it assembles and updates, and the contact slaves it assembles.
    !> Everything else (displacements, contact states) is the same on every process.
    type(comm_t) :: comm
    integer, allocatable :: my_elements(:)
    logical, allocatable :: owns_slave(:)
    !> Nodes loaded by face pressures in any step (their load stiffness goes to rank 0).
    integer, allocatable :: pressure_cliques(:, :)
    !> A distributed run's pattern changed: the solver needs the whole model's ordering.
    logical :: ordering_due = .false.
    !> Integration points on their yield surface that the trial increment unloads (q, e):
    !> assembled with the elastic tangent for the rest of the increment.
    logical, allocatable :: unloading(:, :)
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
    type(state_t) :: start
    real(dp) :: t0, dt, r
    logical :: limited_by_friction, converged
    integer(i8) :: krylov_before
    krylov_before = a%reuse%stats%krylov_iterations
    associate (step => model%steps(a%state%step))
      call trial_time_increment(a, step, t0, dt, limited_by_friction)
      record%trial_increment = dt
      call external_forces(a, model, step%nlgeom, t0, t0 + dt)
      call prescribed_increments(a, model, t0, t0 + dt)
      call ensure_pattern(a, model, err)
      if (allocated(err)) return
      call trial_solution(a, model, step, t0, dt, record, err)
      if (allocated(err)) return
      call a%timers%start('r-minimum')
      call choose_fraction(a, model, step, dt, limited_by_friction, record, r, err)
      call a%timers%stop('r-minimum')
      if (allocated(err)) return
      start = a%state
      do
        a%du = a%du_residual + r * a%du_load
        ! The increment as the R-minimum strategy chose it must keep every element valid
        ! and every contact node within the penetration limit: if not, the deformation or
        ! the penalty is wrong, not the increment.
        call apply_increment(a, model, step, t0, dt, r, err, .true.)
        if (allocated(err)) then
          a%state = start
          return
        end if
        if (a%contact%n_slaves() > 0) call a%contact%hold_states(a%state%contact)
        call equilibrate(a, model, step, start, t0, dt, r, record, converged, err)
        if (a%contact%n_slaves() > 0) call a%contact%release_states(a%state%contact)
        if (.not. allocated(err) .and. converged .and. a%contact%n_slaves() > 0) &
          call a%contact%check_gaps(model%mesh%node_id, a%state%contact, err)
        if (allocated(err)) then
          a%state = start
          return
        end if
        ! Iterations that do not converge cut the increment (NO EQUILIBRIUM=STOP), or the
        ! increment is taken as the static-explicit scheme takes it, without iterations, its
        ! out-of-balance force carried into the next (NO EQUILIBRIUM=CARRY: an unstable slip
        ! event has no equilibrium to cut towards).
        if (converged) exit
        if (step%rmin%carry_unbalanced) then
          a%state = start
          a%du = a%du_residual + r * a%du_load
          call apply_increment(a, model, step, t0, dt, r, err, .true.)
          if (.not. allocated(err)) call out_of_balance(a, model, step, record, err)
          if (allocated(err)) then
            a%state = start
            return
          end if
          record%carried = .true.
          exit
        end if
        call cut_increment(a, model, step, start, dt, record, r, err)
        if (allocated(err)) return
      end do
      record%r = r
      record%n_events_taken = count_taken(a, r)
      record%krylov_iterations = int(a%reuse%stats%krylov_iterations - krylov_before)
      a%state%residual_norm = record%residual_ratio
      a%state%increment = a%state%increment + 1
      a%state%force_scale = a%state%force_scale + (record%force_scale - a%state%force_scale) / &
                            a%state%increment
      if (record%residual_ratio >= a%state%step_worst_residual) then
        a%state%step_worst_residual = record%residual_ratio
        a%state%step_worst_residual_increment = a%state%increment
      end if
      a%state%step_increment = a%state%step_increment + 1
    end associate
  end subroutine take_increment

  !> The trial time increment from t0: the step's maximum (its initial increment first), or
  !> less if the friction-rate limits of the last increment say so (not below the minimum),
  !> cut at the next breakpoint of the loading.
  subroutine trial_time_increment(a, step, t0, dt, limited_by_friction)
    type(analysis_t), intent(in) :: a
    type(step_t), intent(in) :: step
    real(dp), intent(out) :: t0, dt
    logical, intent(out) :: limited_by_friction
    t0 = a%state%step_time
    dt = step%max_increment
    if (a%state%step_increment == 0) dt = step%initial_increment
    limited_by_friction = .false.
    if (a%state%friction_dt > 0.0_dp .and. max(a%state%friction_dt, step%min_increment) < dt) then
      dt = max(a%state%friction_dt, step%min_increment)
      limited_by_friction = .true.
    end if
    dt = min(dt, a%loading%next_breakpoint(t0) - t0)
  end subroutine trial_time_increment

  !> Rebuild the sparse pattern when the contact elements have moved out of it (and, in a
  !> distributed run, give MUMPS the whole model's ordering).
  subroutine ensure_pattern(a, model, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    if (a%contact%pattern_dirty) call build_pattern(a, model)
    if (a%ordering_due) then
      call give_global_ordering(a, model, err)
      call a%comm%agree_error(err)
    end if
  end subroutine ensure_pattern

  !> The trial solution du_residual + du_load on the current state (10a-b), solved again
  !> with switched tangents while contact nodes switch between stick and slip at its start.
  subroutine trial_solution(a, model, step, t0, dt, record, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    real(dp), intent(in) :: t0, dt
    type(increment_record_t), intent(inout) :: record
    type(error_t), allocatable, intent(out) :: err
    integer :: pass, n_switched
    if (a%materials_have_states) call reset_unloading(a)
    do pass = 1, MAX_STATE_PASSES
      call a%timers%start('assembly')
      call assemble_system(a, model, step, t0, dt, err)
      call a%timers%stop('assembly')
      if (allocated(err)) return
      a%rhs_residual = merge(0.0_dp, a%f_ext0 + a%f_contact - a%f_int, a%constrained)
      call impose_constraints(a)
      call solve_system(a, model%mesh%node_id, err)
      call a%comm%agree_error(err)
      if (allocated(err)) return
      if (a%contact%n_slaves() == 0 .and. .not. a%materials_have_states) exit
      a%du = a%du_residual + a%du_load
      n_switched = 0
      if (a%contact%n_slaves() > 0) &
        call a%contact%switch_states(a%x_contact, a%state%contact, a%du, n_switched)
      if (a%materials_have_states) call switch_unloading(a, model, step%nlgeom, n_switched)
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
    call collect_events(a, model, step, err)
    call a%comm%agree_error(err)
    if (allocated(err)) return
    call global_fraction(a, step%rmin%event_tolerance, r)
    record%limiting = a%collector%limiting
    if (limited_by_friction .and. record%limiting%kind == EVENT_FULL_INCREMENT) &
      record%limiting = rmin_event_t(1.0_dp, a%state%friction_kind, a%state%friction_node, 0)
    if (r * dt < step%min_increment .and. r < 1.0_dp) then
      if (a%collector%limiting%kind == EVENT_STRAIN_LIMIT .or. &
          a%collector%limiting%kind == EVENT_ROTATION_LIMIT) then
        call fatal_error(err, 'the ' // event_kind_name(a%collector%limiting%kind) // &
          ' cuts the time increment to ' // str(r * dt) // ', below the minimum ' // &
          str(step%min_increment) // ' of *STATIC (element ' // &
          str(model%mesh%element_id(a%collector%limiting%entity)) // '): the deformation ' // &
          'is too fast for the time scale; lower the minimum increment or check the loading')
        return
      end if
      r = min(1.0_dp, step%min_increment / dt)
      record%floored = .true.
    end if
  end subroutine choose_fraction

  !> Apply the increment a%du (fraction r of the trial increment over [t0, t0 + dt]) to the
  !> state: stresses, displacements, positions, time, and the contact states decided on the
  !> new positions. Nothing changes before every element is known to stay valid.
  subroutine apply_increment(a, model, step, t0, dt, r, err, predict_penetration)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    real(dp), intent(in) :: t0, dt, r
    type(error_t), allocatable, intent(out) :: err
    !> Check the penetration the increment predicts (the first application; the iterates of
    !> the equilibrium iterations are checked on their result instead).
    logical, intent(in) :: predict_penetration
    call a%timers%start('update')
    associate (state => a%state)
      if (step%nlgeom) call check_new_geometry(a, model, err)
      call a%comm%agree_error(err)
      if (.not. allocated(err) .and. a%contact%n_slaves() > 0 .and. predict_penetration) &
        call a%contact%check_penetration(model%mesh%node_id, a%x_contact, state%contact, a%du, err)
      if (.not. allocated(err)) call update_elements(a, model, step, err)
      call a%comm%agree_error(err)
      if (allocated(err)) then
        call a%timers%stop('update')
        return
      end if
      state%u = state%u + reshape(a%du, shape(state%u))
      if (step%nlgeom) state%x = state%x + reshape(a%du, shape(state%x))
      if (r >= 1.0_dp) then
        state%step_time = t0 + dt
      else
        state%step_time = t0 + r * dt
      end if
      call contact_positions(a, model)
      if (a%contact%n_slaves() > 0) then
        call a%contact%update(a%x_contact, state%contact, state%step_time - t0, r)
        call friction_step_control(a, step, state%step_time - t0)
      end if
      state%time = state%time + (state%step_time - t0)
      state%last_increment = state%step_time - t0
      state%last_r = r
    end associate
    call a%timers%stop('update')
  end subroutine apply_increment

  !> Equilibrium iterations on the increment just applied: while the out-of-balance force
  !> at its end exceeds the step's EQUILIBRIUM TOLERANCE, solve K dc = R with the tangent of
  !> the current iterate (prescribed values held), add dc to the increment and apply it
  !> again from the state `start` at the start of the increment, so that stresses, contact
  !> and friction states are decided on the corrected solution (Newton's method on the
  !> increment, as in an implicit step; the R-minimum choice of the increment keeps the
  !> state changes within it small). `converged` is false when the iterations did not reach
  !> the tolerance within MAX ITERATIONS or started to diverge: the caller cuts the increment.
  subroutine equilibrate(a, model, step, start, t0, dt, r, record, converged, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(state_t), intent(in) :: start
    real(dp), intent(in) :: t0, dt, r
    type(increment_record_t), intent(inout) :: record
    logical, intent(out) :: converged
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: base(:)
    real(dp) :: norm, trial_norm, step_length, previous(2)
    integer :: iteration, search, n_growing, n_changed
    converged = .false.
    n_growing = 0
    previous = huge(1.0_dp)
    call out_of_balance(a, model, step, record, err)
    if (allocated(err)) return
    norm = norm2(a%rhs_residual)
    do iteration = 1, step%rmin%max_iterations + 1
      if (record%residual_ratio <= step%rmin%equilibrium_tolerance) then
        ! In equilibrium with the held contact states: are they still right?
        n_changed = 0
        if (a%contact%n_slaves() > 0) call a%contact%check_held(a%state%contact, n_changed)
        if (n_changed == 0) then
          converged = .true.
          return
        end if
        a%state = start
        call apply_increment(a, model, step, t0, dt, r, err, .false.)
        if (.not. allocated(err)) call out_of_balance(a, model, step, record, err)
        if (allocated(err)) return
        norm = norm2(a%rhs_residual)
        n_growing = 0
        previous = huge(1.0_dp)
      end if
      if (iteration > step%rmin%max_iterations) return
      ! A correction that cannot be solved (the iterate lost the contact that supported a
      ! body: a singular tangent) is a failed iteration: the increment is cut.
      call correction(a, model, step, t0, a%state%step_time - t0, err)
      if (allocated(err)) then
        deallocate (err)
        return
      end if
      record%iterations = record%iterations + 1
      ! Backtracking on the norm of the out-of-balance force: the contact and friction
      ! states make the residual only piecewise smooth, and a full Newton step across a
      ! change of state can overshoot.
      base = a%du
      step_length = 1.0_dp
      do search = 1, MAX_LINE_SEARCH
        a%du = base + step_length * a%correction
        a%state = start
        call apply_increment(a, model, step, t0, dt, r, err, .false.)
        if (.not. allocated(err)) call out_of_balance(a, model, step, record, err)
        if (allocated(err)) return
        trial_norm = norm2(a%rhs_residual)
        if (trial_norm < norm .or. search == MAX_LINE_SEARCH) exit
        step_length = 0.5_dp * step_length
      end do
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

  !> The out-of-balance force R = f_ext + f_c - f_int of the current state at its time (free
  !> degrees of freedom, into a%rhs_residual) and its size: the largest nodal |R| over the
  !> mean nodal force flux of the elements (nodes that carry force).
  subroutine out_of_balance(a, model, step, record, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(increment_record_t), intent(inout) :: record
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: worst, scale, node_norm, sums(2)
    integer :: node
    call a%timers%start('equilibrium')
    call assemble_elements(model, a%state, a%materials, step%nlgeom, a%my_elements, a%f_int, err, &
                           flux=a%flux)
    call a%comm%agree_error(err)
    if (allocated(err)) then
      call a%timers%stop('equilibrium')
      return
    end if
    call a%comm%sum_real(a%f_int)
    call a%comm%sum_real(a%flux)
    a%f_contact = 0.0_dp
    if (a%contact%n_slaves() > 0) call a%contact%forces(a%x_contact, a%state%contact, a%f_contact)
    call external_force_at(a, model, step%nlgeom, a%state%step_time, a%f_ext_end)
    a%rhs_residual = merge(0.0_dp, a%f_ext_end + a%f_contact - a%f_int, a%constrained)
    worst = 0.0_dp
    record%residual_node = 0
    do node = 1, model%mesh%n_nodes
      node_norm = norm2(a%rhs_residual(3 * node - 2:3 * node))
      if (node_norm > worst) then
        worst = node_norm
        record%residual_node = node
        record%residual_direction = maxloc(abs(a%rhs_residual(3 * node - 2:3 * node)), 1)
      end if
    end do
    sums = [sum(a%flux, mask=a%flux > 0.0_dp), real(count(a%flux > 0.0_dp), dp)]
    record%force_scale = 0.0_dp
    if (sums(2) > 0.0_dp) record%force_scale = sums(1) / sums(2)
    ! The scale is never below the mean over the increments of the run so far (CalculiX
    ! averages its force scale over the increments of a step): a body unloaded to nearly no
    ! stress keeps a tolerance relative to the forces it carried, not to its round-off.
    scale = max(record%force_scale, a%state%force_scale)
    record%residual_ratio = 0.0_dp
    if (worst > 0.0_dp) record%residual_ratio = worst / max(scale, tiny(1.0_dp))
    call a%timers%stop('equilibrium')
  end subroutine out_of_balance

  !> One equilibrium correction: K dc = R (a%rhs_residual) with K the tangent of the current
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
    residual = a%rhs_residual
    call a%timers%start('assembly')
    call assemble_system(a, model, step, t0, dt, err)
    call a%timers%stop('assembly')
    if (allocated(err)) return
    a%correction = 0.0_dp
    call constrain_system(a, a%correction)
    a%rhs = merge(0.0_dp, residual, a%constrained)
    call a%reuse%prepare(a%solver, a%matrix, a%timers, err)
    if (.not. allocated(err)) call a%reuse%solve(a%solver, a%matrix, a%rhs, a%correction, a%timers, err)
    if (.not. allocated(err)) call check_finite(a%correction, model%mesh%node_id, err)
    call a%comm%agree_error(err)
  end subroutine correction

  !> The equilibrium iterations of the increment did not converge: go back to its start and
  !> take CUT_FACTOR of it (not less than the step's minimum increment); at the minimum the
  !> run stops, naming where the out-of-balance force is largest.
  subroutine cut_increment(a, model, step, start, dt, record, r, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(state_t), intent(in) :: start
    real(dp), intent(in) :: dt
    type(increment_record_t), intent(inout) :: record
    real(dp), intent(inout) :: r
    type(error_t), allocatable, intent(out) :: err
    character(len=1), parameter :: AXIS(3) = ['x', 'y', 'z']
    a%state = start
    if (record%cuts >= MAX_CUTS .or. r * dt <= step%min_increment * (1.0_dp + 1.0e-12_dp)) then
      call fatal_error(err, 'no equilibrium: after ' // str(record%iterations) // ' iteration(s) ' // &
        'and ' // str(record%cuts) // ' cut(s) of the increment (to ' // str(r * dt) // &
        '), the out-of-balance force is still ' // str(record%residual_ratio) // ' of the force ' // &
        'scale (tolerance ' // str(step%rmin%equilibrium_tolerance) // '), largest at node ' // &
        str(model%mesh%node_id(max(record%residual_node, 1))) // ' in ' // &
        AXIS(max(record%residual_direction, 1)) // distortion_note(a, model, step%nlgeom) // &
        '; check the loading and the supports, or raise EQUILIBRIUM TOLERANCE or MAX ' // &
        'ITERATIONS on *RMIN')
      return
    end if
    record%cuts = record%cuts + 1
    r = max(r * CUT_FACTOR, step%min_increment / dt)
  end subroutine cut_increment

  !> The trial time increment for the next increment from the friction changes over the last
  !> one (duration dt): each change of ln V, mu, state at a slipping node may be at most its
  !> *RMIN limit, and with MAX SLIP INCREMENT = xi the slip of a slipping node at most xi L
  !> (L the characteristic slip of its rate-and-state law), so that the next increment is at
  !> most xi L / V_max (Lapusta et al. 2000, eq. 17 with a constant xi); the increment grows
  !> by at most a factor 2 when the changes are small, and is not limited when no node slips.
  !> Scaling an increment does not change its slip rate, so rate effects are controlled
  !> through the time increment (method notes 1.6).
  subroutine friction_step_control(a, step, dt)
    type(analysis_t), intent(inout) :: a
    type(step_t), intent(in) :: step
    real(dp), intent(in) :: dt
    real(dp) :: limits(4), factors(4), changes(4)
    integer :: i, worst
    integer, parameter :: kinds(4) = [EVENT_SLIP_RATE_CHANGE, EVENT_FRICTION_CHANGE, EVENT_STATE_CHANGE, &
                                      EVENT_SLIP_INCREMENT]
    changes = a%contact%change
    ! MAX SLIP INCREMENT is an option (0: none).
    if (step%rmin%max_slip_increment <= 0.0_dp) changes(4) = 0.0_dp
    if (all(changes <= 0.0_dp) .or. dt <= 0.0_dp) then
      a%state%friction_dt = 0.0_dp
      return
    end if
    limits = [step%rmin%max_log_rate_change, step%rmin%max_friction_change, step%rmin%max_state_change, &
              step%rmin%max_slip_increment]
    factors = 2.0_dp
    do i = 1, 4
      if (changes(i) > 0.0_dp) factors(i) = min(2.0_dp, limits(i) / changes(i))
    end do
    worst = minloc(factors, 1)
    a%state%friction_dt = dt * factors(worst)
    a%state%friction_kind = kinds(worst)
    a%state%friction_node = a%contact%change_node(worst)
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
    call a%matrix%zero()
    if (a%materials_have_states) then
      call assemble_elements(model, a%state, a%materials, step%nlgeom, a%my_elements, a%f_int, err, &
                             a%matrix, a%unloading)
    else
      call assemble_elements(model, a%state, a%materials, step%nlgeom, a%my_elements, a%f_int, err, &
                             a%matrix)
    end if
    call a%comm%agree_error(err)
    if (allocated(err)) return
    if (step%nlgeom .and. a%comm%is_root()) then
      allocate (scratch(size(a%f_int)))
      scratch = 0.0_dp
      call assemble_pressures(model, a%loading, t0, a%state, .true., scratch, a%matrix)
    end if
    a%f_contact = 0.0_dp
    if (a%contact%n_slaves() > 0) call a%contact%assemble(a%x_contact, a%state%contact, dt, &
                                                          a%matrix, a%f_contact, err, a%owns_slave)
    call a%comm%agree_error(err)
    if (allocated(err)) return
    call a%comm%sum_real(a%f_int)
    call a%comm%sum_real(a%f_contact)
  end subroutine assemble_system

  !> The nodal forces printed as RF, (3, n_nodes): at a prescribed degree of freedom the
  !> reaction, the force the support exerts: internal force less contact force less the load
  !> applied there at the current time (CalculiX prints the internal force, which also holds
  !> that load); at a free degree of freedom, as CalculiX prints it, the internal force less
  !> the contact force, i.e. the load applied there (up to the equilibrium tolerance). Leaves
  !> the internal and contact forces in a%f_int, a%f_contact.
  subroutine current_reactions(a, model, reaction, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    real(dp), intent(out) :: reaction(:, :)
    type(error_t), allocatable, intent(out) :: err
    logical :: nlgeom
    nlgeom = model%steps(min(a%state%step, size(model%steps)))%nlgeom
    call internal_forces(a, model, nlgeom, a%f_int, err)
    if (allocated(err)) return
    a%f_contact = 0.0_dp
    if (a%contact%n_slaves() > 0) call a%contact%forces(a%x_contact, a%state%contact, a%f_contact)
    a%f_ext_end = 0.0_dp
    if (allocated(a%loading%bc_dof)) call external_force_at(a, model, nlgeom, a%state%step_time, a%f_ext_end)
    where (.not. supported_dofs(a, model)) a%f_ext_end = 0.0_dp
    reaction = reshape(a%f_int - a%f_contact - a%f_ext_end, shape(reaction))
  end subroutine current_reactions

  !> The degrees of freedom the current step prescribes (and those of nodes in no element).
  function supported_dofs(a, model) result(supported)
    type(analysis_t), intent(in) :: a
    type(model_t), intent(in) :: model
    logical :: supported(3 * model%mesh%n_nodes)
    integer :: node
    supported = .false.
    do node = 1, model%mesh%n_nodes
      if (model%free_node(node)) supported(3 * node - 2:3 * node) = .true.
    end do
    if (allocated(a%loading%bc_dof)) supported(a%loading%bc_dof) = .true.
  end function supported_dofs

  !> Internal forces of the current state (all elements, summed over the processes).
  subroutine internal_forces(a, model, nlgeom, f_int, err)
    type(analysis_t), intent(in) :: a
    type(model_t), intent(in) :: model
    logical, intent(in) :: nlgeom
    real(dp), intent(out) :: f_int(:)
    type(error_t), allocatable, intent(out) :: err
    call assemble_elements(model, a%state, a%materials, nlgeom, a%my_elements, f_int, err)
    call a%comm%agree_error(err)
    if (.not. allocated(err)) call a%comm%sum_real(f_int)
  end subroutine internal_forces

  !> Make the integration-point fields complete on every process: each process holds
  !> current values for its own elements only; their sum with zeros elsewhere is exact.
  subroutine gather_element_fields(a)
    type(analysis_t), intent(inout) :: a
    logical, allocatable :: mine(:)
    integer :: e
    if (a%comm%size == 1) return
    allocate (mine(a%state%n_elements))
    mine = .false.
    mine(a%my_elements) = .true.
    do e = 1, a%state%n_elements
      if (mine(e)) cycle
      a%state%stress(:, :, e) = 0.0_dp
      a%state%strain(:, :, e) = 0.0_dp
      a%state%material_state(:, :, e) = 0.0_dp
    end do
    call a%comm%sum_real(a%state%stress)
    call a%comm%sum_real(a%state%strain)
    if (size(a%state%material_state) > 0) call a%comm%sum_real(a%state%material_state)
  end subroutine gather_element_fields

  !> Prescribed values on a system spread over processes: each eliminates the known values
  !> from its own entries (their right-hand-side parts are summed), rank 0 puts `scale` on
  !> the constrained diagonals, scale being the mean absolute diagonal of the free rows of
  !> the summed matrix (approximated by the sum of the processes' diagonals).
  subroutine impose_constraints(a)
    type(analysis_t), intent(inout) :: a
    call constrain_system(a, a%prescribed)
    where (.not. a%constrained) a%rhs = a%rhs + a%f_ext1 - a%f_ext0
  end subroutine impose_constraints

  !> Eliminate the prescribed degrees of freedom (values `values`) from the matrix: a%rhs gets
  !> the eliminated columns' contribution on the free rows and scale * value on the
  !> constrained ones, whose diagonals become `scale`.
  subroutine constrain_system(a, values)
    type(analysis_t), intent(inout) :: a
    real(dp), intent(in) :: values(:)
    real(dp) :: total(2), scale
    integer :: n_free
    call a%matrix%free_diagonal_sum(a%constrained, total(1), n_free)
    total(2) = real(n_free, dp)
    call a%comm%sum_real(total)
    scale = 1.0_dp
    if (total(2) > 0.0_dp) scale = total(1) / (total(2) / a%comm%size)
    if (.not. (scale > 0.0_dp)) scale = 1.0_dp
    a%rhs = 0.0_dp
    call a%matrix%eliminate(a%constrained, values, a%rhs)
    call a%comm%sum_real(a%rhs)
    where (a%constrained) a%rhs = scale * values
    if (a%comm%is_root()) call a%matrix%set_diagonal(a%constrained, scale)
  end subroutine constrain_system

  !> The fraction of the trial increment taken, over all processes: the smallest event
  !> fraction (and its event, from the process that has it), widened to the near-simultaneous
  !> discrete events within `tolerance`, never beyond a strain or rotation limit.
  subroutine global_fraction(a, tolerance, r)
    type(analysis_t), intent(inout) :: a
    real(dp), intent(in) :: tolerance
    real(dp), intent(out) :: r
    real(dp) :: r_min, band, limit
    integer :: owner, event(4)
    r_min = a%collector%r_min
    call a%comm%min_real(r_min, owner)
    event = [a%collector%limiting%kind, a%collector%limiting%entity, a%collector%limiting%detail, 0]
    call a%comm%broadcast_int(event, owner)
    a%collector%r_min = r_min
    a%collector%limiting = rmin_event_t(r_min, event(1), event(2), event(3))
    band = a%collector%band_fraction(tolerance)
    limit = a%collector%limit_fraction()
    call a%comm%max_real(band)
    call a%comm%min_real(limit)
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
    integer :: k, node, n_nodes, n_faces, last
    call element_cliques(model, a%my_elements, clique_ptr, clique_nodes)
    if (a%contact%n_slaves() > 0) call a%contact%cliques(a%state%contact, clique_ptr, clique_nodes, &
                                                         keep_centres, a%owns_slave)
    if (a%comm%size > 1 .and. a%comm%is_root()) then
      ! Rank 0 also holds every diagonal (constrained rows) and the pressure load stiffness:
      ! a one-node clique per node, then the 4-node pressure faces (appended in one go).
      n_nodes = model%mesh%n_nodes
      n_faces = size(a%pressure_cliques, 2)
      last = clique_ptr(size(clique_ptr))
      clique_nodes = [clique_nodes, [(node, node = 1, n_nodes)], &
                      reshape(a%pressure_cliques, [4 * n_faces])]
      clique_ptr = [clique_ptr, [(last + node, node = 1, n_nodes)], &
                    [(last + n_nodes + 4 * k, k = 1, n_faces)]]
    end if
    call a%matrix%build(model%mesh%n_nodes, clique_ptr, clique_nodes)
    a%ordering_due = a%comm%size > 1
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
    a%ordering_due = .false.
    if (.not. a%comm%is_root()) return
    select type (solver => a%solver)
    type is (mumps_solver_t)
      call element_cliques(model, [(e, e = 1, model%mesh%n_elements)], clique_ptr, clique_nodes)
      if (a%contact%n_slaves() > 0) call a%contact%cliques(a%state%contact, clique_ptr, &
                                                           clique_nodes, keep_centres=.true.)
      call whole%build(model%mesh%n_nodes, clique_ptr, clique_nodes)
      call metis_equation_order(whole, position, err)
      call whole%free()
      if (allocated(err)) return
      call solver%set_ordering(position)
    end select
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
    a%f_ext0 = 0.0_dp
    a%f_ext1 = 0.0_dp
    call a%loading%force_at(model%amplitudes, t0, a%f_ext0)
    call a%loading%force_at(model%amplitudes, t1, a%f_ext1)
    call assemble_pressures(model, a%loading, t0, a%state, nlgeom, a%f_ext0)
    call assemble_pressures(model, a%loading, t1, a%state, nlgeom, a%f_ext1)
  end subroutine external_forces

  !> The external forces at step time t on the current geometry.
  subroutine external_force_at(a, model, nlgeom, t, f_ext)
    type(analysis_t), intent(in) :: a
    type(model_t), intent(in) :: model
    logical, intent(in) :: nlgeom
    real(dp), intent(in) :: t
    real(dp), intent(out) :: f_ext(:)
    f_ext = 0.0_dp
    call a%loading%force_at(model%amplitudes, t, f_ext)
    call assemble_pressures(model, a%loading, t, a%state, nlgeom, f_ext)
  end subroutine external_force_at

  !> Constrained degrees of freedom and their prescribed increments over [t0, t1]. Nodes in
  !> no element are held where they are.
  subroutine prescribed_increments(a, model, t0, t1)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    real(dp), intent(in) :: t0, t1
    integer :: i, dof, node, direction
    a%constrained = .false.
    a%prescribed = 0.0_dp
    do node = 1, model%mesh%n_nodes
      if (model%free_node(node)) a%constrained(3 * node - 2:3 * node) = .true.
    end do
    do i = 1, size(a%loading%bc_dof)
      dof = a%loading%bc_dof(i)
      node = (dof - 1) / 3 + 1
      direction = dof - 3 * (node - 1)
      a%constrained(dof) = .true.
      a%prescribed(dof) = a%loading%prescribed_target(model%amplitudes, i, t0, t1, &
        a%state%u(direction, node), a%state%step_start_u(direction, node))
    end do
  end subroutine prescribed_increments

  !> Factorise once (or reuse the factors, `fcs_factor_reuse`) and solve for both parts of the
  !> trial increment; a non-finite solution is an error. With reused factors the out-of-balance
  !> part, which is added to the load part, is solved to the tolerance relative to the load
  !> part's right-hand side.
  subroutine solve_system(a, node_id, err)
    type(analysis_t), intent(inout) :: a
    integer, intent(in) :: node_id(:)
    type(error_t), allocatable, intent(out) :: err
    call a%reuse%prepare(a%solver, a%matrix, a%timers, err)
    if (allocated(err)) return
    call a%reuse%solve(a%solver, a%matrix, a%rhs, a%du_load, a%timers, err)
    if (.not. allocated(err)) &
      call a%reuse%solve(a%solver, a%matrix, a%rhs_residual, a%du_residual, a%timers, err, &
                         reference_norm=norm2(a%rhs))
    if (allocated(err)) return
    call check_finite(a%du_load, node_id, err)
    if (.not. allocated(err)) call check_finite(a%du_residual, node_id, err)
  end subroutine solve_system

  subroutine check_finite(du, node_id, err)
    real(dp), intent(in) :: du(:)
    integer, intent(in) :: node_id(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: i
    do i = 1, size(du)
      if (.not. (abs(du(i)) <= huge(1.0_dp))) then
        call fatal_error(err, 'the solution is not finite (NaN or Inf) at node ' // &
          str(node_id((i - 1) / 3 + 1)) // ', direction ' // str(i - 3 * ((i - 1) / 3)) // &
          ': a load or prescribed value overflows, or the system is badly conditioned (a ' // &
          'penalty stiffness far larger than the material stiffness)')
        return
      end if
    end do
  end subroutine check_finite

  !> Offer every event and limit of the trial increment to the collector.
  subroutine collect_events(a, model, step, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(error_t), allocatable, intent(out) :: err
    type(hex8_geometry_t) :: geo
    real(dp) :: strain(6, N_GAUSS_HEX8), spin(3, 3, N_GAUSS_HEX8), equivalent(N_GAUSS_HEX8)
    real(dp) :: angle(N_GAUSS_HEX8), du(3, 8), strain_fixed(6, N_GAUSS_HEX8)
    real(dp) :: r_yield, r_plastic
    integer :: e, q, s, i
    logical :: ok, bbar
    call a%collector%reset()
    if (a%contact%n_slaves() > 0) call a%contact%events(a%x_contact, a%state%contact, a%du_residual, &
                                                        a%du_load, a%collector)
    if (.not. (step%nlgeom .or. a%materials_have_states)) return
    do i = 1, size(a%my_elements)
      e = a%my_elements(i)
      call hex8_geometry(element_configuration(model, a%state, e, step%nlgeom), geo, ok)
      if (.not. ok) then
        call inverted_element_error(model, e, err)
        return
      end if
      s = model%element_section(e)
      bbar = model%sections(s)%formulation == FORMULATION_BBAR
      du = element_increment(a%du_load, model%mesh%connectivity(:, e))
      call hex8_strain_increments(geo, du, bbar, strain, spin, equivalent, angle)
      if (step%nlgeom) then
        if (maxval(equivalent) > 0.0_dp) call a%collector%offer(step%rmin%max_strain_increment / &
          maxval(equivalent), EVENT_STRAIN_LIMIT, e, maxloc(equivalent, 1))
        if (maxval(angle) > 0.0_dp) call a%collector%offer(step%rmin%max_rotation_increment / &
          maxval(angle), EVENT_ROTATION_LIMIT, e, maxloc(angle, 1))
      end if
      if (.not. a%materials_have_states) cycle
      du = element_increment(a%du_residual, model%mesh%connectivity(:, e))
      call hex8_strain_increments(geo, du, bbar, strain_fixed, spin, equivalent, angle)
      associate (material => a%materials(model%sections(s)%material)%m)
        do q = 1, N_GAUSS_HEX8
          call material%point_events(a%state%stress(:, q, e), a%state%material_state(:, q, e), &
                                     strain_fixed(:, q), strain(:, q), &
                                     step%rmin%max_plastic_strain_increment, r_yield, r_plastic)
          call a%collector%offer(r_yield, EVENT_YIELD, e, q)
          call a%collector%offer(r_plastic, EVENT_PLASTIC_STRAIN_LIMIT, e, q)
        end do
      end associate
    end do
  end subroutine collect_events

  !> No point unloads at the start of an increment.
  subroutine reset_unloading(a)
    type(analysis_t), intent(inout) :: a
    if (.not. allocated(a%unloading)) allocate (a%unloading(N_GAUSS_HEX8, a%state%n_elements))
    a%unloading = .false.
  end subroutine reset_unloading

  !> Elastic unloading as a state switch (doc/theory.md 6.3; Yamada, Yoshimura & Sakurai
  !> 1968): every point on its yield surface that the trial increment a%du moves inwards
  !> (material%unloads, strain increment on the start configuration) takes the elastic tangent
  !> for the rest of the increment; `n_switched` grows by the number of new such points over
  !> all processes (the increment is then solved again).
  subroutine switch_unloading(a, model, nlgeom, n_switched)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    logical, intent(in) :: nlgeom
    integer, intent(inout) :: n_switched
    type(hex8_geometry_t) :: geo
    real(dp) :: strain(6, N_GAUSS_HEX8), spin(3, 3, N_GAUSS_HEX8), equivalent(N_GAUSS_HEX8)
    real(dp) :: angle(N_GAUSS_HEX8), count(1)
    integer :: e, q, s, i
    logical :: ok
    count = 0.0_dp
    do i = 1, size(a%my_elements)
      e = a%my_elements(i)
      s = model%element_section(e)
      call hex8_geometry(element_configuration(model, a%state, e, nlgeom), geo, ok)
      if (.not. ok) cycle
      call hex8_strain_increments(geo, element_increment(a%du, model%mesh%connectivity(:, e)), &
                                  model%sections(s)%formulation == FORMULATION_BBAR, strain, spin, &
                                  equivalent, angle)
      associate (material => a%materials(model%sections(s)%material)%m)
        do q = 1, N_GAUSS_HEX8
          if (a%unloading(q, e)) cycle
          if (.not. material%unloads(a%state%stress(:, q, e), a%state%material_state(:, q, e), &
                                     strain(:, q))) cycle
          a%unloading(q, e) = .true.
          count = count + 1.0_dp
        end do
      end associate
    end do
    call a%comm%sum_real(count)
    n_switched = n_switched + nint(count(1))
  end subroutine switch_unloading

  !> Nodal displacement increments of one element.
  pure function element_increment(du, nodes) result(du_e)
    real(dp), intent(in) :: du(:)
    integer, intent(in) :: nodes(8)
    real(dp) :: du_e(3, 8)
    integer :: a
    do a = 1, 8
      du_e(:, a) = du(3 * nodes(a) - 2:3 * nodes(a))
    end do
  end function element_increment

  !> Stress and strain update for the (scaled) increment: gradients on the mid-increment
  !> configuration, objective rotation (Hughes & Winget 1980), then the material law.
  subroutine update_elements(a, model, step, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    type(error_t), allocatable, intent(out) :: err
    type(hex8_geometry_t) :: geo
    real(dp) :: strain(6, N_GAUSS_HEX8), spin(3, 3, N_GAUSS_HEX8), equivalent(N_GAUSS_HEX8)
    real(dp) :: angle(N_GAUSS_HEX8), du(3, 8), x(3, 8)
    integer :: e, q, s, i
    logical :: ok, bbar, nlgeom
    nlgeom = step%nlgeom
    do i = 1, size(a%my_elements)
      e = a%my_elements(i)
      du = element_increment(a%du, model%mesh%connectivity(:, e))
      x = element_configuration(model, a%state, e, nlgeom)
      if (nlgeom) x = x + 0.5_dp * du
      call hex8_geometry(x, geo, ok)
      if (.not. ok) then
        call inverted_element_error(model, e, err)
        return
      end if
      s = model%element_section(e)
      bbar = model%sections(s)%formulation == FORMULATION_BBAR
      call hex8_strain_increments(geo, du, bbar, strain, spin, equivalent, angle)
      associate (material => a%materials(model%sections(s)%material)%m)
        do q = 1, N_GAUSS_HEX8
          call update_point(material, nlgeom, strain(:, q), spin(:, :, q), a%state%stress(:, q, e), &
                            a%state%strain(:, q, e), a%state%material_state(:, q, e))
        end do
      end associate
    end do
  end subroutine update_elements

  !> The objective update of one integration point (doc/theory.md, 1.4): strain increment
  !> and spin increment on the mid-increment configuration; `stress`, `strain` (accumulated,
  !> output only) and the material's `state` go from the start to the end of the increment and
  !> depend on nothing else, so an increment recomputed from its saved start gives the same
  !> result.
  !> * A material without internal variables: the midpoint Hughes-Winget update (1f), half of
  !>   the constitutive increment before the rotation and half after, second order in the
  !>   increment and exact under rigid rotation.
  !> * A material with internal variables (a yield surface): the stress and the tensor-valued
  !>   variables are rotated first, Q sigma Q^T, and the material's update (return mapping)
  !>   then works in the rotated frame (1g; Simo & Hughes 1998, section 8.3), so that the
  !>   stress it returns lies on the yield surface; the midpoint split would move the returned
  !>   stress off the surface by the rotation of half an increment (second order).
  !> Without NLGEOM there is no rotation: sigma + the material's increment.
  !> With `tangent`, also the material's consistent tangent d(sigma)/d(strain_increment) of
  !> this update (in the rotated frame), for equilibrium iterations.
  pure subroutine update_point(material, nlgeom, strain_increment, spin, stress, strain, state, &
                               tangent)
    class(material_t), intent(in) :: material
    logical, intent(in) :: nlgeom
    real(dp), intent(in) :: strain_increment(6), spin(3, 3)
    real(dp), intent(inout) :: stress(6), strain(6), state(:)
    real(dp), intent(out), optional :: tangent(6, 6)
    real(dp) :: updated(6), increment(6), q(3, 3)
    if (nlgeom .and. material%n_state() > 0) then
      q = spin_rotation(spin)
      stress = rotate_stress_like(stress, q)
      call material%rotate_state(state, q)
      call material%update(stress, strain_increment, state, tangent)
      strain = rotate_strain_like(strain, q) + strain_increment
    else if (nlgeom) then
      updated = stress
      call material%update(updated, strain_increment, state, tangent)
      increment = updated - stress
      stress = hex8_rotate_stress(stress + 0.5_dp * increment, spin) + 0.5_dp * increment
      strain = rotate_strain(strain + 0.5_dp * strain_increment, spin) + 0.5_dp * strain_increment
    else
      call material%update(stress, strain_increment, state, tangent)
      strain = strain + strain_increment
    end if
  end subroutine update_point

  !> Every element must keep a positive Jacobian on the mid-increment and the end
  !> configurations of the increment about to be applied.
  subroutine check_new_geometry(a, model, err)
    type(analysis_t), intent(in) :: a
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    type(hex8_geometry_t) :: geo
    real(dp) :: du(3, 8), x(3, 8)
    integer :: e, i
    logical :: ok_mid, ok_end
    do i = 1, size(a%my_elements)
      e = a%my_elements(i)
      du = element_increment(a%du, model%mesh%connectivity(:, e))
      x = element_configuration(model, a%state, e, .true.)
      call hex8_geometry(x + 0.5_dp * du, geo, ok_mid)
      call hex8_geometry(x + du, geo, ok_end)
      if (.not. (ok_mid .and. ok_end)) then
        call inverted_element_error(model, e, err)
        return
      end if
    end do
  end subroutine check_new_geometry

  !> Rotate an engineering-shear strain like a stress (tensor shear in between).
  pure function rotate_strain(strain, spin) result(rotated)
    real(dp), intent(in) :: strain(6), spin(3, 3)
    real(dp) :: rotated(6)
    real(dp) :: tensor(6)
    tensor = strain
    tensor(4:6) = 0.5_dp * tensor(4:6)
    rotated = hex8_rotate_stress(tensor, spin)
    rotated(4:6) = 2.0_dp * rotated(4:6)
  end function rotate_strain

  !> For the message of an increment without equilibrium: the most distorted element of
  !> the current configuration when it is nearly inverted (its Jacobian determinant varies by
  !> more than a factor 20 over its integration points), else nothing.
  function distortion_note(a, model, nlgeom) result(note)
    type(analysis_t), intent(in) :: a
    type(model_t), intent(in) :: model
    logical, intent(in) :: nlgeom
    character(len=:), allocatable :: note
    type(hex8_geometry_t) :: geo
    real(dp) :: ratio, worst
    integer :: i, e, worst_element
    logical :: ok
    note = ''
    if (.not. nlgeom) return
    worst = huge(1.0_dp)
    worst_element = 0
    do i = 1, size(a%my_elements)
      e = a%my_elements(i)
      call hex8_geometry(element_configuration(model, a%state, e, .true.), geo, ok)
      ratio = 0.0_dp
      if (ok) ratio = minval(geo%dv) / maxval(geo%dv)
      if (ratio < worst) then
        worst = ratio
        worst_element = e
      end if
    end do
    if (worst_element == 0 .or. worst >= 0.05_dp) return
    note = '; element ' // str(model%mesh%element_id(worst_element)) // ' is nearly inverted ' // &
      '(its Jacobian determinant varies by a factor ' // str(1.0_dp / max(worst, tiny(1.0_dp))) // &
      ' over its integration points): the mesh cannot follow the deformation there'
  end function distortion_note

  !> How many discrete events fall within the increment taken (near-simultaneous ones).
  integer function count_taken(a, r) result(n)
    type(analysis_t), intent(in) :: a
    real(dp), intent(in) :: r
    integer :: i
    n = 0
    do i = 1, a%collector%n_events
      if (a%collector%events(i)%kind == EVENT_STRAIN_LIMIT .or. &
          a%collector%events(i)%kind == EVENT_ROTATION_LIMIT .or. &
          a%collector%events(i)%kind == EVENT_PLASTIC_STRAIN_LIMIT) cycle
      if (a%collector%events(i)%r <= r) n = n + 1
    end do
  end function count_taken

end module fcs_static_explicit
