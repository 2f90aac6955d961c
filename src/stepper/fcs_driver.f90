!> The analysis driver: builds the model from the deck, sets up the state, the solver and the
!> outputs, runs every step increment by increment, and writes results at the output times.
module fcs_driver
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, fatal_error, input_error, add_context, EXIT_INTERRUPTED, EXIT_INPUT
  use fcs_deck_lexer, only: deck_t
  use fcs_model, only: model_t, friction_def_t, FORMULATION_BBAR
  use fcs_material, only: material_slot_t
  use fcs_model_builder, only: build_model
  use fcs_run_options, only: run_options_t
  use fcs_state, only: state_t
  use fcs_loading, only: build_step_loading
  use fcs_assembly, only: make_materials, apply_initial_stresses
  use fcs_static_explicit, only: analysis_t, take_increment, increment_record_t, build_pattern, &
                                 contact_positions, current_reactions, gather_element_fields
  use fcs_comm, only: comm_t
  use fcs_linear_system, only: linear_system_t
  use fcs_partition, only: partition_elements
  use fcs_solver_factory, only: create_linear_solver, solver_has_low_rank, low_rank_solver_names_text
  use fcs_linear_solver, only: solver_stats_t
  use fcs_factor_reuse, only: reuse_settings_t
  use fcs_contact_friction_change, only: apply_friction_changes, apply_behavior_changes
  use fcs_contact_adjust, only: adjust_report_t, adjust_pair_nodes
  use fcs_run_outputs, only: run_outputs_t, log_contact_totals
  use fcs_output_schedule, only: histories_due
  use fcs_echo, only: write_echo
  use fcs_log, only: logger_t, format_duration
  use fcs_timer, only: wall_time, peak_memory_mib
  use fcs_rmin_events, only: event_kind_name, EVENT_FULL_INCREMENT, EVENT_STRAIN_LIMIT, &
                             EVENT_ROTATION_LIMIT, EVENT_YIELD, EVENT_PLASTIC_STRAIN_LIMIT, &
                             CONTACT_EVENTS_NORMAL, CONTACT_EVENTS_CLOSING, contact_events_level
  use fcs_strings, only: str, to_upper
  use fcs_signals, only: install_signal_handlers, signal_received
  use fcs_heap_policy, only: keep_freed_memory
  use fcs_memory, only: prepare_memory, ensure_memory, set_activity, set_failure_log
  use fcs_run_checkpoint, only: save_checkpoint, restore_checkpoint
  use fcs_restart_options, only: take_checkpoint_options
  use fcs_command_line, only: result_options_text
  use fcs_checkpoint, only: checkpoint_info_t
  use fcs_monitors, only: monitors_t
  use fcs_version, only: FCS3D_IDENTITY
  use fcs_job_lock, only: job_lock_t
  implicit none
  private
  public :: run_job

  !> Everything open during a run.
  type :: run_t
    type(analysis_t) :: analysis
    type(logger_t) :: log
    type(run_outputs_t) :: outputs
    real(dp) :: started = 0.0_dp
    real(dp) :: total_time = 0.0_dp
    !> Path stem of the outputs, and wall time of the last checkpoint.
    character(len=:), allocatable :: job
    real(dp) :: last_checkpoint = 0.0_dp
    type(monitors_t) :: monitors
    !> Rank 0 of a parallel run writes every file and the terminal output.
    logical :: writer = .true.
    !> The job's lock (rank 0), held from before the first file is written to the end.
    type(job_lock_t) :: lock
    !> The result-changing command-line options in effect, as the checkpoints record them.
    character(len=:), allocatable :: options_record
  end type run_t

contains

  !> Run the job described by `options`.
  subroutine run_job(options, err)
    type(run_options_t), intent(in) :: options
    type(error_t), allocatable, intent(out) :: err
    type(model_t) :: model
    type(deck_t) :: deck
    type(run_t) :: run
    real(dp) :: t_start
    character(len=:), allocatable :: memory_note
    t_start = wall_time()
    call keep_freed_memory(err)
    if (.not. allocated(err)) call prepare_memory(memory_note, err)
    if (allocated(err)) return
    call run%analysis%share%comm%init(err)
    if (allocated(err)) return
    run%writer = run%analysis%share%comm%is_root()
    call run_job_on_ranks(options, run, model, deck, t_start, memory_note, err)
    call run%analysis%share%comm%agree_error(err)
    ! Every rank of a parallel run returns the same error; rank 0 reports it.
    if (allocated(err) .and. .not. run%writer) err%silent = .true.
    call end_log(run, err)
    call run%lock%release()
    call run%analysis%share%comm%finalize()
  end subroutine run_job

  !> Take the job's lock, then open the log (appended to on a restart): both before anything
  !> is read or written, so that the log records input errors too and a second run of the job
  !> is refused before it touches a file.
  subroutine start_log(options, run, memory_note, err)
    type(run_options_t), intent(in) :: options
    type(run_t), intent(inout) :: run
    character(len=*), intent(in) :: memory_note
    type(error_t), allocatable, intent(out) :: err
    if (run%writer) call run%lock%acquire(options%job, err)
    call run%analysis%share%comm%agree_error(err)
    if (allocated(err)) return
    if (run%writer) then
      call run%log%open(options%job // '.log', options%quiet, err, append=len(options%restart_file) > 0)
    else
      run%log%terminal = .false.
    end if
    call run%analysis%share%comm%agree_error(err)
    if (allocated(err)) return
    if (run%writer) call set_failure_log(options%job // '.log')
    call run%log%detail(FCS3D_IDENTITY)
    if (len(memory_note) > 0) call run%log%detail('note: ' // memory_note)
    if (len(run%lock%previous_holder) > 0) call run%log%detail('note: ' // options%job // &
      '.lock was left by a run that ended without removing it (' // run%lock%previous_holder // &
      '); taken over')
  end subroutine start_log

  !> The run's outcome into the log (an error message and the exit status), then close it; a
  !> failed write to the log becomes the run's error if it has none.
  subroutine end_log(run, err)
    type(run_t), intent(inout) :: run
    type(error_t), allocatable, intent(inout) :: err
    type(error_t), allocatable :: log_err
    if (allocated(err)) then
      if (err%exit_code /= EXIT_INTERRUPTED) then
        call run%log%detail('fcs3d: ' // err%message)
        call run%log%detail('exit status ' // str(err%exit_code) // ' (' // &
          trim(merge('bad input  ', 'run failure', err%exit_code == EXIT_INPUT)) // ')')
      end if
    end if
    call run%log%close(log_err)
    if (.not. allocated(err) .and. allocated(log_err)) call move_alloc(log_err, err)
  end subroutine end_log

  !> The run on every process: the log, the model, the set-up, the steps, the summary and
  !> the closing of the outputs. A restart takes the result-changing options it is not given
  !> from the checkpoint before the model is built, where the command line's are applied.
  subroutine run_job_on_ranks(given, run, model, deck, t_start, memory_note, err)
    type(run_options_t), intent(in) :: given
    type(run_t), intent(inout) :: run
    type(model_t), intent(out) :: model
    type(deck_t), intent(out) :: deck
    real(dp), intent(in) :: t_start
    character(len=*), intent(in) :: memory_note
    type(error_t), allocatable, intent(out) :: err
    type(run_options_t) :: options
    options = given
    call start_log(options, run, memory_note, err)
    if (.not. allocated(err)) call take_checkpoint_options(options, run%log, err)
    run%options_record = result_options_text(options)
    call run%analysis%share%comm%agree_error(err)
    if (.not. allocated(err)) call read_model(options, run, model, deck, err)
    if (allocated(err)) return
    if (options%check_only) then
      call run%log%info('check: the deck and the model are valid (echo in ' // options%job // '.echo)')
      return
    end if
    run%started = t_start
    run%job = options%job
    run%outputs%job = options%job
    run%outputs%writer = run%writer
    call setup(run, model, err)
    if (.not. allocated(err)) then
      if (len(options%restart_file) > 0) then
        call resume_outputs(run, model, options%restart_file, err)
      else
        call open_outputs(run, model, err)
      end if
    end if
    if (.not. allocated(err)) then
      call install_signal_handlers()
      run%last_checkpoint = wall_time()
      call run_steps(run, model, err)
    end if
    ! A run stopped by SIGINT/SIGTERM also reports its phase times and solver figures.
    if (.not. allocated(err)) then
      call summary(run, model, 'done')
    else if (err%exit_code == EXIT_INTERRUPTED) then
      call summary(run, model, 'stopped')
    end if
    call close_outputs(run, err)
  end subroutine run_job_on_ranks

  !> The model from the deck, with the command line's solver choices applied; its echo
  !> written, its warnings and a description of it in the log.
  subroutine read_model(options, run, model, deck, err)
    type(run_options_t), intent(in) :: options
    type(run_t), intent(inout) :: run
    type(model_t), intent(out) :: model
    type(deck_t), intent(out) :: deck
    type(error_t), allocatable, intent(out) :: err
    integer :: i
    call set_activity('reading the deck ' // options%deck_path)
    call build_model(options%deck_path, model, deck, err)
    if (allocated(err)) return
    do i = 1, size(model%warnings)
      call run%log%warn(model%warnings(i)%s)
    end do
    call adjust_contact_nodes(run%log, model)
    if (len(options%solver) > 0) model%solver_name = to_upper(options%solver)
    if (options%reuse_tolerance >= 0.0_dp) model%reuse_tolerance = options%reuse_tolerance
    if (len(options%contact_events) > 0) &
      model%steps(:)%rmin%contact_events = contact_events_level(options%contact_events)
    if (options%low_rank_tolerance >= 0.0_dp) model%low_rank_tolerance = options%low_rank_tolerance
    if (run%analysis%share%comm%size > 1 .and. len(options%solver) == 0 .and. .not. model%solver_chosen) &
      model%solver_name = 'MUMPS'
    call check_low_rank(model, err)
    if (run%writer .and. .not. allocated(err)) call write_echo(options%job // '.echo', deck, model, err)
    call run%analysis%share%comm%agree_error(err)
    if (allocated(err)) return
    call describe_model(run%log, model, options)
    if (run%analysis%share%comm%size > 1) call run%log%info('parallel run on ' // &
      str(run%analysis%share%comm%size) // ' processes (elements partitioned by METIS, solver ' // &
      model%solver_name // ')')
  end subroutine read_model

  !> A block low-rank factorisation (*SOLVER, LOW RANK TOLERANCE or --low-rank-tolerance) needs
  !> a solver that has one; the deck's own *SOLVER card is checked when it is read, this sees
  !> the command line's choices too.
  subroutine check_low_rank(model, err)
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    if (model%low_rank_tolerance <= 0.0_dp) return
    if (solver_has_low_rank(model%solver_name)) return
    call input_error(err, 'a block low-rank factorisation (--low-rank-tolerance ' // &
      str(model%low_rank_tolerance) // ' or *SOLVER, LOW RANK TOLERANCE) needs the ' // &
      low_rank_solver_names_text() // ' solver (--solver ' // low_rank_solver_names_text() // &
      '); this run''s solver is ' // model%solver_name)
  end subroutine check_low_rank

  !> *CONTACT PAIR, ADJUST=: the slave nodes moved onto their master surfaces, pair by pair
  !> in deck order, before anything is built on the coordinates (state, contact search,
  !> results geometry), so that every output and a restart see the moved mesh.
  subroutine adjust_contact_nodes(log, model)
    type(logger_t), intent(inout) :: log
    type(model_t), intent(inout) :: model
    type(adjust_report_t) :: report
    integer :: p
    character(len=32) :: largest
    integer :: ios
    do p = 1, size(model%contact_pairs)
      associate (def => model%contact_pairs(p))
        if (def%adjust_distance < 0.0_dp .and. def%adjust_set == 0) cycle
        call adjust_pair_nodes(def, model%mesh, report)
        if (report%moved == 0) then
          call log%info('*CONTACT PAIR ' // def%name // ', ADJUST: no slave node moved')
          cycle
        end if
        write (largest, '(es12.5)', iostat=ios) report%largest
        if (ios /= 0) largest = '?'
        call log%info('*CONTACT PAIR ' // def%name // ', ADJUST: ' // str(report%moved) // &
          ' slave node(s) moved onto the master surface, largest move ' // trim(adjustl(largest)) // &
          ' (node ' // str(model%mesh%node_id(report%largest_node)) // ')')
      end associate
    end do
  end subroutine adjust_contact_nodes

  subroutine describe_model(log, model, options)
    type(logger_t), intent(inout) :: log
    type(model_t), intent(in) :: model
    type(run_options_t), intent(in) :: options
    if (len(model%title) > 0) then
      call log%info('fcs3d: ' // options%deck_path // ': ' // model%title)
    else
      call log%info('fcs3d: ' // options%deck_path)
    end if
    call log%info('model: ' // str(model%mesh%n_nodes) // ' nodes, ' // &
                  str(model%mesh%n_elements) // ' elements (' // kind_counts(model) // '), ' // &
                  str(3 * model%mesh%n_nodes) // &
                  ' degrees of freedom, ' // str(size(model%steps)) // ' step(s); solver ' // &
                  model%solver_name)
    if (count(model%free_node) > 0) call log%info('note: ' // str(count(model%free_node)) // &
      ' node(s) belong to no element (node ' // str(model%mesh%node_id(findloc(model%free_node, &
      .true., 1))) // ' first); they are held fixed')
  end subroutine describe_model

  !> "C3D20R 32" or "C3D8 12, C3D6 8": the element count of each kind the mesh has.
  function kind_counts(model) result(text)
    type(model_t), intent(in) :: model
    character(len=:), allocatable :: text
    integer :: k, n
    text = ''
    do k = 1, size(model%mesh%kinds)
      n = count(model%mesh%element_kind(1:model%mesh%n_elements) == k)
      if (n == 0) cycle
      if (len(text) > 0) text = text // ', '
      text = text // model%mesh%kinds(k)%name // ' ' // str(n)
    end do
  end function kind_counts

  !> State, materials, contact, sparse pattern, solver.
  subroutine setup(run, model, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    associate (a => run%analysis)
      call setup_state(a, model, err)
      if (allocated(err)) return
      call contact_positions(a, model)
      if (size(model%contact_pairs) > 0) then
        call a%contact%init(model%contact_pairs, pair_frictions(model), model%mesh, a%x_contact, &
                            a%state%contact, err)
        if (allocated(err)) return
        call note_tied_slaves(run)
      end if
      call distribute_work(run, model, err)
      if (allocated(err)) return
      call a%sys%links%init(model%equations, model%mesh%n_nodes, model%mesh%node_id, err, &
                            model%node_frame, model%transformed)
      if (allocated(err)) return
      if (size(model%nonlinear_constraints) > 0) call a%sys%nonlinear%init( &
        model%nonlinear_constraints, model%equations, model%mesh%x(:, 1:model%mesh%n_nodes))
      call build_pattern(a, model)
      call setup_solver(a%sys, a%share%comm, model, err)
      if (allocated(err)) return
    end associate
    run%total_time = sum(model%steps(:)%period)
  end subroutine setup

  !> The element loops with their materials, and the state they start from (initial
  !> temperatures and stresses), once the memory they take is known to be there.
  subroutine setup_state(a, model, err)
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    type(material_slot_t), allocatable :: materials(:)
    integer :: n_state
    call make_materials(model, materials, err)
    if (.not. allocated(err)) call a%elements%init(model%element_kinds, model%mesh, &
      model%sections(model%element_section)%material, &
      model%sections(model%element_section)%formulation == FORMULATION_BBAR, materials, err)
    if (allocated(err)) return
    if (size(model%orientations) > 0) call a%elements%set_orientations( &
      model%orientations%axes, model%sections(model%element_section)%orientation)
    n_state = a%elements%n_material_state()
    call set_activity('setting up the analysis', setup_bytes(model, a%elements%max_points, n_state))
    call ensure_memory(setup_bytes(model, a%elements%max_points, n_state), &
                       'setting up the analysis', err)
    if (allocated(err)) return
    call a%state%init(model%mesh%x, model%mesh%n_elements, a%elements%max_points, n_state)
    if (model%has_temperature) call a%state%init_temperature(model%initial_temperature)
    call apply_initial_stresses(a%elements, model, a%state%elements)
  end subroutine setup_state

  !> The model's linear solver on the run's processes (a parallel run needs MUMPS), the reuse
  !> of its factors, and the vectors of the system.
  subroutine setup_solver(sys, comm, model, err)
    type(linear_system_t), intent(inout) :: sys
    type(comm_t), intent(in) :: comm
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    call create_linear_solver(model%solver_name, sys%solver, err)
    if (allocated(err)) return
    sys%solver%node_id = model%mesh%node_id(1:model%mesh%n_nodes)
    call sys%reuse%init(reuse_settings_t(tolerance=model%reuse_tolerance), comm)
    call sys%solver%set_low_rank_tolerance(model%low_rank_tolerance)
    if (comm%size > 1 .and. .not. sys%solver%runs_in_parallel()) then
      call input_error(err, 'a parallel run needs the MUMPS solver (*SOLVER, TYPE=MUMPS or ' // &
                       '--solver MUMPS); ' // model%solver_name // ' runs on one process only')
      return
    end if
    call sys%solver%set_comm(comm)
    call sys%allocate_vectors(model%mesh%n_nodes)
  end subroutine setup_solver

  !> The friction law of each contact pair: its interaction's *FRICTION, or frictionless
  !> Coulomb (mu = 0) when it has none.
  function pair_frictions(model) result(frictions)
    type(model_t), intent(in) :: model
    type(friction_def_t), allocatable :: frictions(:)
    integer :: k
    allocate (frictions(size(model%contact_pairs)))
    do k = 1, size(model%contact_pairs)
      frictions(k)%law = 'COULOMB'
      frictions(k)%mu0 = 0.0_dp
      associate (interaction => model%contact_pairs(k)%interaction)
        if (interaction > 0) then
          if (model%interactions(interaction)%has_friction) frictions(k) = model%interactions(interaction)%friction
        end if
      end associate
    end do
  end function pair_frictions

  !> About the memory the set-up allocates [bytes]: state and force vectors, integration-point
  !> arrays (max_points per element), element cliques, and the sparse pattern (about 27
  !> neighbours per node of a hexahedral mesh, 3 x 3 entries of 12 bytes each).
  pure integer(i8) function setup_bytes(model, max_points, n_state) result(bytes)
    type(model_t), intent(in) :: model
    integer, intent(in) :: max_points, n_state
    integer(i8) :: nodes, elements
    nodes = int(model%mesh%n_nodes, i8)
    elements = int(model%mesh%n_elements, i8)
    bytes = 8_i8 * 3_i8 * nodes * 15_i8 + 8_i8 * int(max_points, i8) * elements * &
      (12_i8 + int(n_state, i8)) + 4_i8 * int(size(model%mesh%connectivity, 1), i8) * elements + &
      9_i8 * 27_i8 * 12_i8 * nodes
  end function setup_bytes

  !> This process's share of the work: its elements (METIS partition), its contact slaves
  !> (equal consecutive blocks), and the pressure faces whose load stiffness rank 0 adds.
  subroutine distribute_work(run, model, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: owner(:), nodes(:)
    integer :: e, k, i
    associate (a => run%analysis)
      call partition_elements(a%share%comm, model%mesh%connectivity, model%mesh%n_nodes, owner, err)
      if (allocated(err)) return
      call a%elements%set_share(pack([(e, e = 1, model%mesh%n_elements)], owner == a%share%comm%rank))
      call a%share%share_slaves(a%contact%n_slaves())
      do k = 1, size(model%steps)
        do i = 1, size(model%steps(k)%pressures)
          nodes = a%elements%face_nodes(model%steps(k)%pressures(i)%element, &
                                        model%steps(k)%pressures(i)%face)
          call a%share%add_pressure_face(nodes)
        end do
      end do
    end associate
  end subroutine distribute_work

  !> New output files, with the initial frame.
  subroutine open_outputs(run, model, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    call run%outputs%create(model, run%analysis, err)
    call run%analysis%share%comm%agree_error(err)
    if (allocated(err)) return
    call run%monitors%init(model, run%analysis, run%job, err)
    if (.not. allocated(err)) call run%monitors%write_files(err)
    if (allocated(err)) return
    call run%monitors%sample(model, run%analysis, spread(.true., 1, size(model%histories)), err)
    if (allocated(err)) return
    call run%outputs%write_frame(run%analysis, model, run%monitors, run%log, err)
  end subroutine open_outputs

  !> Continue from a checkpoint: restore the analysis, and cut the outputs back to what they
  !> held when the checkpoint was written (a killed run may have written more after it).
  !> Nothing is written before the checkpoint is read and accepted: a refused restart leaves
  !> the outputs of the earlier run as they were.
  subroutine resume_outputs(run, model, path, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    type(checkpoint_info_t) :: info
    character(len=:), allocatable :: warning
    call run%monitors%init(model, run%analysis, run%job, err)
    if (allocated(err)) return
    call restore_checkpoint(path, run%analysis, run%monitors, model, info, warning, err)
    if (allocated(err)) return
    if (len(warning) > 0) call run%log%warn(warning)
    call run%log%info('restart from ' // path // ': time ' // str(info%time) // ', step ' // &
                      str(info%step) // ', increment ' // str(info%increment))
    if (run%writer) then
      call run%monitors%write_files(err)
      if (.not. allocated(err)) call run%outputs%reopen(model, run%analysis, info, run%log, err)
    end if
    call run%analysis%share%comm%agree_error(err)
  end subroutine resume_outputs


  !> Write a checkpoint now and note the time.
  subroutine checkpoint(run, model, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    call set_activity('writing the checkpoint ' // run%job // '.rst.h5')
    call gather_element_fields(run%analysis)
    if (run%writer) call save_checkpoint(run%job, run%options_record, run%analysis, run%monitors, &
                                         model, run%outputs%n_frames(), err)
    call run%analysis%share%comm%agree_error(err)
    run%last_checkpoint = wall_time()
    if (.not. allocated(err)) call run%log%detail('checkpoint written: ' // run%job // '.rst.h5 ' // &
      '(time ' // str(run%analysis%state%time) // ', increment ' // str(run%analysis%state%increment) // ')')
  end subroutine checkpoint

  !> True on every rank when `flag` is true on some rank (signals and wall-clock checks
  !> differ between processes; all must act together).
  logical function any_rank(run, flag)
    type(run_t), intent(in) :: run
    logical, intent(in) :: flag
    real(dp) :: value
    value = merge(1.0_dp, 0.0_dp, flag)
    call run%analysis%share%comm%max_real(value)
    any_rank = value > 0.0_dp
  end function any_rank

  !> Whether a periodic checkpoint is due after this increment.
  logical function checkpoint_due(run, model)
    type(run_t), intent(in) :: run
    type(model_t), intent(in) :: model
    checkpoint_due = .false.
    associate (c => model%checkpoint)
      if (c%frequency > 0) checkpoint_due = mod(run%analysis%state%increment, c%frequency) == 0
      if (c%interval > 0.0_dp) then
        if (wall_time() - run%last_checkpoint >= c%interval) checkpoint_due = .true.
      end if
    end associate
  end function checkpoint_due



  !> A note for each contact pair whose slave surface shares nodes with a tie: the tie holds
  !> them, and they are not checked for contact (fcs_contact_system, tied_nodes).
  subroutine note_tied_slaves(run)
    type(run_t), intent(inout) :: run
    integer :: k
    associate (contact => run%analysis%contact)
      do k = 1, contact%n_pairs()
        if (contact%held_by_tie(k) > 0) call run%log%info('note: contact pair ' // &
          contact%pair_name(k) // ': ' // str(contact%held_by_tie(k)) // ' slave node(s) also ' // &
          'tied by a *TIE are left to the tie (not checked for contact)')
      end do
    end associate
  end subroutine note_tied_slaves


  !> All steps, increment by increment.
  subroutine run_steps(run, model, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    associate (state => run%analysis%state)
      do while (state%step <= size(model%steps))
        k = state%step
        call begin_step(run, model, k, err)
        if (.not. allocated(err)) call run_increments(run, model, k, err)
        if (allocated(err)) return
        state%step_time = model%steps(k)%period
        call sample_histories(run, model, .true., err)
        if (.not. allocated(err)) call run%outputs%write_due(run%analysis, model, run%monitors, &
                                                             run%log, .true., err)
        call run%analysis%share%comm%agree_error(err)
        if (allocated(err)) return
        call run%log%info('end of step ' // str(k) // ' ("' // model%steps(k)%name // '") at time ' // &
                          str(state%time) // ' after ' // str(state%step_increment) // ' increment(s)' // &
                          '; largest out-of-balance ' // str(state%step_worst_residual) // &
                          ' (increment ' // str(state%step_worst_residual_increment) // ')')
        call log_contact_totals(run%analysis, run%log, .false.)
        state%step = k + 1
        state%step_time = 0.0_dp
        state%step_increment = 0
        state%step_worst_residual = 0.0_dp
        state%step_worst_residual_increment = 0
        call checkpoint(run, model, err)
        if (allocated(err)) return
      end do
    end associate
  end subroutine run_steps

  !> The increments of step k, with their outputs, periodic checkpoints, and the clean stop
  !> on SIGTERM/SIGINT (checkpoint, then exit status 3).
  subroutine run_increments(run, model, k, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    integer, intent(in) :: k
    type(error_t), allocatable, intent(out) :: err
    type(increment_record_t) :: record
    associate (a => run%analysis, state => run%analysis%state)
      do while (state%step_time < model%steps(k)%period * (1.0_dp - 1.0e-12_dp))
        if (state%step_increment >= model%steps(k)%max_increments) then
          call fatal_error(err, 'step ' // str(k) // ' ("' // model%steps(k)%name // '") needs ' // &
            'more than INC=' // str(model%steps(k)%max_increments) // ' increments; raise INC ' // &
            'on *STEP or the R-minimum limits')
          exit
        end if
        call set_activity('computing increment ' // str(state%increment + 1) // ' (step ' // &
                          str(k) // ', time ' // str(state%time) // ')')
        call take_increment(a, model, record, err)
        if (allocated(err)) then
          call save_last_good(run, model, err)
          exit
        end if
        call log_increment(run, model, record)
        call run%outputs%write_due(run%analysis, model, run%monitors, run%log, .false., err)
        if (.not. allocated(err)) call run%monitors%watch_events(model, a, state%time - &
                                                                 state%last_increment, run%log, err)
        if (.not. allocated(err)) call sample_histories(run, model, .false., err)
        if (.not. allocated(err)) call run%log%check(err)
        call run%analysis%share%comm%agree_error(err)
        if (allocated(err)) exit
        if (any_rank(run, signal_received() /= 0)) then
          call stop_on_signal(run, model, err)
          return
        end if
        if (any_rank(run, checkpoint_due(run, model))) call checkpoint(run, model, err)
        if (allocated(err)) exit
      end do
      if (allocated(err)) call add_context(err, 'step ' // str(k) // ', increment ' // &
                                           str(state%increment + 1) // ', time ' // str(state%time))
    end associate
  end subroutine run_increments

  !> An increment failed (the state is still that of the last good increment): write a
  !> checkpoint and a results frame of that state, and say so in the error message.
  subroutine save_last_good(run, model, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    type(error_t), intent(inout) :: err
    type(error_t), allocatable :: secondary
    call run%outputs%write_frame(run%analysis, model, run%monitors, run%log, secondary)
    if (.not. allocated(secondary)) call checkpoint(run, model, secondary)
    if (allocated(secondary)) then
      err%message = err%message // new_line('a') // '(saving the last good state also failed: ' // &
                    secondary%message // ')'
    else
      err%message = err%message // new_line('a') // 'the state of the last good increment (' // &
        str(run%analysis%state%increment) // ', time ' // str(run%analysis%state%time) // &
        ') is in the last frame of ' // run%job // '.h5 and in the checkpoint ' // run%job // '.rst.h5'
    end if
  end subroutine save_last_good

  !> SIGTERM or SIGINT: the increment is complete; write a checkpoint and stop.
  subroutine stop_on_signal(run, model, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    integer :: signal
    signal = max(signal_received(), 0)
    call checkpoint(run, model, err)
    if (allocated(err)) return
    allocate (err)
    err%exit_code = EXIT_INTERRUPTED
    err%message = 'stopped by signal ' // str(signal) // ' after increment ' // &
      str(run%analysis%state%increment) // ' (time ' // str(run%analysis%state%time) // &
      '); checkpoint written to ' // run%job // '.rst.h5; continue with --restart ' // run%job // '.rst.h5'
    call run%log%detail(err%message)
  end subroutine stop_on_signal

  subroutine begin_step(run, model, k, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    integer, intent(in) :: k
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: onsets
    associate (state => run%analysis%state)
      if (model%has_temperature .and. state%step_time == 0.0_dp) &
        state%step_start_temperature = state%temperature
      if (model%has_temperature) then
        call build_step_loading(model, k, state%time - state%step_time, run%analysis%loading, &
                                state%step_start_temperature)
      else
        call build_step_loading(model, k, state%time - state%step_time, run%analysis%loading)
      end if
      ! *CHANGE SURFACE BEHAVIOR and *CHANGE FRICTION of this and the earlier steps (again
      ! when resuming within the step).
      if (run%analysis%contact%n_slaves() > 0) then
        call apply_behavior_changes(run%analysis%contact, model, k, state%contact)
        call apply_friction_changes(run%analysis%contact, model, k, state%contact, err)
      end if
      if (allocated(err)) return
      if (state%step_time == 0.0_dp) then
        state%step_start_u = state%u
        state%step_increment = 0
      end if
      onsets = ''
      select case (model%steps(k)%rmin%contact_events)
      case (CONTACT_EVENTS_NORMAL)
        onsets = ', onsets of slip and segment hand-overs left to the equilibrium iterations ' // &
                 '(CONTACT EVENTS=NORMAL)'
      case (CONTACT_EVENTS_CLOSING)
        onsets = ', onsets of slip, segment hand-overs and openings left to the equilibrium ' // &
                 'iterations (CONTACT EVENTS=CLOSING)'
      end select
      call run%log%info('step ' // str(k) // ' ("' // model%steps(k)%name // '"): period ' // &
        str(model%steps(k)%period) // ', increments between ' // str(model%steps(k)%min_increment) // &
        ' and ' // str(model%steps(k)%max_increment) // trim(merge(', NLGEOM', '        ', &
        model%steps(k)%nlgeom)) // onsets)
    end associate
  end subroutine begin_step

  !> One log line per increment (log file), and a progress line on the terminal.
  subroutine log_increment(run, model, record)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    type(increment_record_t), intent(in) :: record
    character(len=:), allocatable :: line, entity
    associate (state => run%analysis%state)
      entity = ''
      select case (record%limiting%kind)
      case (EVENT_STRAIN_LIMIT, EVENT_ROTATION_LIMIT, EVENT_YIELD, EVENT_PLASTIC_STRAIN_LIMIT)
        entity = ' element ' // str(model%mesh%element_id(record%limiting%entity)) // ' ip ' // &
                 str(record%limiting%detail)
      case (EVENT_FULL_INCREMENT)
        entity = ''
      case default
        if (record%limiting%entity > 0) entity = ' node ' // str(model%mesh%node_id(record%limiting%entity))
      end select
      line = 'inc ' // str(state%increment) // ' step ' // str(state%step) // ' time ' // &
        str(state%time, 10) // ' dt ' // str(state%last_increment) // ' r ' // str(record%r) // &
        ' limit ' // event_kind_name(record%limiting%kind) // entity // &
        trim(merge(' (floor)', '        ', record%floored)) // ' events ' // &
        str(record%n_events_taken) // optional_count(' switches ', record%n_switches) // &
        optional_count(' iterations ', record%iterations) // optional_count(' cuts ', record%cuts) // &
        optional_count(' krylov ', record%krylov_iterations) // &
        ' residual ' // str(record%residual_ratio) // trim(merge(' (carried)', '          ', record%carried))
      call run%log%detail(trim(line))
      call run%log%progress('time ' // str(state%time) // ' of ' // str(run%total_time) // ', inc ' // &
        str(state%increment) // ', dt ' // str(state%last_increment) // ' (' // &
        event_kind_name(record%limiting%kind) // ')', state%time / max(run%total_time, tiny(1.0_dp)), &
        wall_time() - run%started)
    end associate
  end subroutine log_increment

  !> " <label> n" when n > 0, else nothing.
  pure function optional_count(label, n) result(text)
    character(len=*), intent(in) :: label
    integer, intent(in) :: n
    character(len=:), allocatable :: text
    text = ''
    if (n > 0) text = label // str(n)
  end function optional_count


  !> Sample the histories due after this increment (or at the end of the step).
  subroutine sample_histories(run, model, end_of_step, err)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    logical, intent(in) :: end_of_step
    type(error_t), allocatable, intent(out) :: err
    call run%monitors%sample(model, run%analysis, histories_due(model, run%monitors%tables, &
                             run%analysis%state, end_of_step), err)
  end subroutine sample_histories








  !> A memory figure in MiB: 4 significant digits below 1000, whole MiB above (no exponent).
  function memory_text(mib) result(text)
    real(dp), intent(in) :: mib
    character(len=:), allocatable :: text
    if (mib < 1000.0_dp) then
      text = str(mib, 4)
    else
      text = str(nint(mib, i8))
    end if
  end function memory_text

  !> Run summary: size, solver, increments, time per phase, memory; `outcome` opens the line
  !> ('done', or 'stopped' for a run stopped by a signal).
  subroutine summary(run, model, outcome)
    type(run_t), intent(inout) :: run
    type(model_t), intent(in) :: model
    character(len=*), intent(in) :: outcome
    character(len=*), parameter :: phases(6) = [character(len=13) :: 'assembly', 'factorisation', &
                                                'solve', 'r-minimum', 'update', 'output']
    integer :: i
    associate (a => run%analysis)
      call run%log%info(outcome // ': ' // str(a%state%increment) // ' increment(s), time ' // &
        str(a%state%time) // ', wall ' // format_duration(wall_time() - run%started) // &
        ', peak memory ' // memory_text(peak_memory_mib()) // ' MiB; solver ' // a%sys%solver%name())
      do i = 1, size(phases)
        call run%log%info('  ' // phases(i) // ': ' // format_duration(a%timers%total(trim(phases(i)))))
      end do
      call log_solver_stats(run, a%sys%solver%stats)
      call run%log%info('  ' // a%sys%reuse%summary())
      call run%monitors%report_open_events(a%contact, run%log)
    end associate
  end subroutine summary

  !> The linear solver's counts and the size of its last factorisation.
  subroutine log_solver_stats(run, stats)
    type(run_t), intent(inout) :: run
    type(solver_stats_t), intent(in) :: stats
    character(len=:), allocatable :: line
    line = '  linear solver: ' // str(stats%n_analyses) // ' analysis(es), ' // &
      str(stats%n_factorisations) // ' factorisation(s)'
    if (len_trim(stats%ordering) > 0) line = line // ', ordering ' // trim(stats%ordering)
    line = line // '; last factor ' // str(stats%factor_entries, 3) // ' entries'
    if (stats%factor_flops > 0.0_dp) line = line // ', ' // str(stats%factor_flops, 3) // ' flops'
    if (stats%factor_memory_mib > 0.0_dp) line = line // ', ' // &
      memory_text(stats%factor_memory_mib) // ' MiB working memory'
    if (stats%low_rank_tolerance > 0.0_dp) line = line // '; ' // low_rank_text(stats)
    call run%log%info(line)
  end subroutine log_solver_stats

  !> "block low-rank (eps 1E-08) on: 1.23E+06 entries (45.6% of full rank), 7.89E+09 flops
  !> (12.3%)": what the compression of the last factorisation kept (MUMPS's INFOG(35) and
  !> RINFOG(14) against the full-rank INFOG(29) and RINFOG(3)).
  function low_rank_text(stats) result(text)
    type(solver_stats_t), intent(in) :: stats
    character(len=:), allocatable :: text
    text = 'block low-rank (eps ' // str(stats%low_rank_tolerance, 3) // ') on: ' // &
      str(stats%low_rank_entries, 3) // ' entries'
    if (stats%factor_entries > 0.0_dp) text = text // ' (' // &
      str(100.0_dp * stats%low_rank_entries / stats%factor_entries, 3) // '% of full rank)'
    text = text // ', ' // str(stats%low_rank_flops, 3) // ' flops'
    if (stats%factor_flops > 0.0_dp) text = text // ' (' // &
      str(100.0_dp * stats%low_rank_flops / stats%factor_flops, 3) // '%)'
  end function low_rank_text

  !> Close the output files and free the solver; a failed close becomes the run's error if it
  !> has none.
  subroutine close_outputs(run, err)
    type(run_t), intent(inout) :: run
    type(error_t), allocatable, intent(inout) :: err
    call run%outputs%close(err)
    if (allocated(run%analysis%sys%solver)) call run%analysis%sys%solver%free()
  end subroutine close_outputs

end module fcs_driver
