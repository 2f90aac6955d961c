!> The outputs of a run: the `.dat` tables and the results file (frames, history tables, the
!> event catalog), opened, continued after a restart, written when the output schedule says
!> so (fcs_output_schedule) and closed. The fields of a frame are collected here from the
!> analysis - the state, the element fields, the contact pairs' output fields - and handed to
!> the results writer as plain data (fcs_field); src/io/ knows nothing of where they come from.
module fcs_run_outputs
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t
  use fcs_model, only: model_t, OUTPUT_NODE_PRINT, OUTPUT_EL_PRINT, OUTPUT_CONTACT_PRINT
  use fcs_static_explicit, only: analysis_t, current_reactions, gather_element_fields
  use fcs_contact_system, only: contact_system_t, pair_totals_t
  use fcs_results, only: results_file_t, GRID_POINTS
  use fcs_xdmf, only: xdmf_cell_type
  use fcs_dat_output, only: dat_file_t
  use fcs_checkpoint, only: checkpoint_info_t
  use fcs_monitors, only: monitors_t
  use fcs_event_catalog, only: EVENT_COLUMNS
  use fcs_output_schedule, only: is_due, outputs_due
  use fcs_field, only: field_t, field, point_field, FIELD_NODES, FIELD_CELLS
  use fcs_element_loops, only: mises_stress
  use fcs_log, only: logger_t
  use fcs_files, only: truncate_file, file_size
  use fcs_memory, only: set_activity, ensure_memory
  use fcs_strings, only: str, to_lower, join_strings
  implicit none
  private
  public :: run_outputs_t, log_contact_totals

  !> The output files of a run; only the writer (rank 0) has them open.
  type :: run_outputs_t
    type(results_file_t) :: results
    type(dat_file_t) :: dat
    !> Path stem of the outputs.
    character(len=:), allocatable :: job
    logical :: writer = .true.
  contains
    procedure :: create => outputs_create
    procedure :: reopen => outputs_reopen
    procedure :: write_frame => outputs_write_frame
    procedure :: write_due => outputs_write_due
    procedure :: n_frames => outputs_n_frames
    procedure :: close => outputs_close
  end type run_outputs_t

contains

  !> New output files: `<job>.dat` and `<job>.h5` with the mesh and the contact grids.
  subroutine outputs_create(this, model, a, err)
    class(run_outputs_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(analysis_t), intent(in) :: a
    type(error_t), allocatable, intent(out) :: err
    if (.not. this%writer) return
    call this%dat%open(this%job // '.dat', err)
    if (.not. allocated(err)) call this%results%create(this%job, model%mesh%node_id, model%mesh%x, &
      model%mesh%element_id, model%mesh%connectivity, err, cell_types(model))
    if (.not. allocated(err)) call define_contact_grids(this, a%contact, err)
  end subroutine outputs_create

  !> Cut the text and results files back to the checkpoint `info` and reopen them. Outputs
  !> that hold less than they held at the checkpoint (deleted, emptied, cut) are kept as they
  !> are and continued, with a warning in `log`: what they lack is lost (doc/restart.md).
  subroutine outputs_reopen(this, model, a, info, log, err)
    class(run_outputs_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(analysis_t), intent(in) :: a
    type(checkpoint_info_t), intent(in) :: info
    type(logger_t), intent(inout) :: log
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: dat_size
    dat_size = file_size(this%job // '.dat')
    if (dat_size >= info%dat_size) then
      call truncate_file(this%job // '.dat', info%dat_size, err)
    else if (info%dat_size > 0) then
      call log%warn(this%job // '.dat holds ' // str(max(dat_size, 0_i8)) // ' bytes, ' // &
        'fewer than the ' // str(info%dat_size) // ' it held at the checkpoint (deleted or ' // &
        'cut since?): the tables printed before the checkpoint are incomplete; the restart ' // &
        'appends its tables to what is there')
    end if
    if (.not. allocated(err)) call this%dat%open(this%job // '.dat', err, append=.true.)
    if (allocated(err)) return
    if (file_size(this%job // '.h5') >= 0) then
      call this%results%open_append(this%job, err, keep_frames=info%n_frames)
      if (.not. allocated(err) .and. this%results%n_frames() < info%n_frames) call log%warn( &
        this%job // '.h5 holds ' // str(this%results%n_frames()) // ' complete frame(s), fewer ' // &
        'than the ' // str(info%n_frames) // ' it held at the checkpoint: the missing frames ' // &
        'are lost; the restart adds its frames after the ones there')
    else
      if (info%n_frames > 0) call log%warn(this%job // '.h5 is missing: the ' // &
        str(info%n_frames) // ' frame(s) written before the checkpoint are lost; a new ' // &
        this%job // '.h5 holds the frames written from the checkpoint on')
      call this%results%create(this%job, model%mesh%node_id, model%mesh%x, model%mesh%element_id, &
                               model%mesh%connectivity, err, cell_types(model))
    end if
    if (.not. allocated(err)) call define_contact_grids(this, a%contact, err)
  end subroutine outputs_reopen

  !> Each element's XDMF cell type, from its kind's faces and nodes.
  function cell_types(model) result(types)
    type(model_t), intent(in) :: model
    integer, allocatable :: types(:)
    integer :: e
    allocate (types(model%mesh%n_elements))
    do e = 1, model%mesh%n_elements
      associate (kind => model%mesh%kinds(model%mesh%element_kind(e)))
        types(e) = xdmf_cell_type(kind%n_faces, kind%n_nodes)
      end associate
    end do
  end function cell_types

  !> Complete frames in the results file.
  integer function outputs_n_frames(this) result(n)
    class(run_outputs_t), intent(in) :: this
    n = this%results%n_frames()
  end function outputs_n_frames

  !> Print and write whatever is due after an increment (or at the end of the step).
  subroutine outputs_write_due(this, a, model, monitors, log, end_of_step, err)
    class(run_outputs_t), intent(inout) :: this
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(monitors_t), intent(in) :: monitors
    type(logger_t), intent(inout) :: log
    logical, intent(in) :: end_of_step
    type(error_t), allocatable, intent(out) :: err
    logical :: need_frame, need_print
    integer :: i
    call outputs_due(model, a%state, end_of_step, need_frame, need_print)
    if (.not. (need_frame .or. need_print)) return
    call a%timers%start('output')
    call current_reactions(a, model, a%state%reaction, err)
    if (allocated(err)) return
    call gather_element_fields(a)
    associate (step => model%steps(a%state%step))
      do i = 1, size(step%outputs)
        if (.not. this%writer) exit
        if (.not. is_due(model, step, step%outputs(i), a%state, end_of_step)) cycle
        call print_table(this, a, model, i, err)
        if (allocated(err)) return
      end do
    end associate
    if (need_frame) call this%write_frame(a, model, monitors, log, err)
    call a%timers%stop('output')
  end subroutine outputs_write_due

  !> Output request i of the current step into the .dat file, if it is a printed table.
  subroutine print_table(this, a, model, i, err)
    class(run_outputs_t), intent(inout) :: this
    type(analysis_t), intent(in) :: a
    type(model_t), intent(in) :: model
    integer, intent(in) :: i
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: peeq(:, :), plastic_strain(:, :, :), back_stress(:, :, :)
    real(dp), allocatable :: displacement(:, :), stress(:, :), volume(:, :), conjugate(:, :, :)
    integer :: v
    logical :: energy
    integer, allocatable :: node(:)
    logical, allocatable :: closed(:)
    associate (request => model%steps(a%state%step)%outputs(i), state => a%state)
      select case (request%kind)
      case (OUTPUT_NODE_PRINT)
        if (allocated(state%temperature)) then
          call this%dat%node_print(model, request, state%time, state%u, state%reaction, err, &
                                   state%temperature)
        else
          call this%dat%node_print(model, request, state%time, state%u, state%reaction, err)
        end if
      case (OUTPUT_EL_PRINT)
        call a%elements%plastic_fields(state%elements, peeq, plastic_strain, back_stress)
        ! Point volumes only for ELSE (an element loop over the whole mesh).
        if (any([(request%variables(v)%s == 'ELSE', v = 1, size(request%variables))])) then
          volume = a%elements%point_volumes()
        else
          allocate (volume(0, 0))
        end if
        energy = any([(request%variables(v)%s == 'ENER' .or. request%variables(v)%s == 'ELSE', &
                       v = 1, size(request%variables))])
        ! ENER/ELSE: the stress conjugate to the strain (St Venant-Kirchhoff under NLGEOM: S).
        if (energy) then
          conjugate = a%elements%energy_stresses(state%x, state%elements%stress, &
                                                 model%steps(state%step)%nlgeom, err)
          if (allocated(err)) return
        else
          conjugate = state%elements%stress
        end if
        if (.not. request%global .and. size(model%orientations) > 0) then
          ! GLOBAL=NO: S and E of oriented elements in their local axes (as CalculiX).
          call this%dat%el_print(model, request, state%time, &
            a%elements%to_material_axes(state%elements%stress, .false.), &
            a%elements%to_material_axes(state%elements%strain, .true.), peeq, &
            a%elements%point_counts(), volume, err, &
            energy_stress=a%elements%to_material_axes(conjugate, .false.))
        else if (allocated(state%temperature) .and. allocated(model%initial_temperature) .and. &
                 energy) then
          ! ENER/ELSE: the energy of the mechanical strain, less the thermal strain.
          call this%dat%el_print(model, request, state%time, state%elements%stress, &
                                 state%elements%strain, peeq, a%elements%point_counts(), volume, err, &
                                 a%elements%thermal_strains(model%initial_temperature, &
                                                            state%temperature), conjugate)
        else
          call this%dat%el_print(model, request, state%time, state%elements%stress, &
                                 state%elements%strain, peeq, a%elements%point_counts(), volume, &
                                 err, energy_stress=conjugate)
        end if
      case (OUTPUT_CONTACT_PRINT)
        call a%contact%print_values(a%x_contact, state%contact, node, closed, displacement, stress)
        call this%dat%contact_print(model, request, state%time, node, closed, displacement, stress, err)
      end select
    end associate
  end subroutine print_table

  !> A results frame: geometry, displacements, forces, stresses (integration points, nodal
  !> averages of the extrapolated values) and Mises stress, the plastic state, the contact
  !> fields; then the history tables and the event catalog, and a log line per contact pair.
  subroutine outputs_write_frame(this, a, model, monitors, log, err)
    class(run_outputs_t), intent(inout) :: this
    type(analysis_t), intent(inout) :: a
    type(model_t), intent(in) :: model
    type(monitors_t), intent(in) :: monitors
    type(logger_t), intent(inout) :: log
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: nodal(:, :), cell_mises(:, :), nodal_mises(:, :)
    integer :: q
    integer(i8) :: bytes
    call gather_element_fields(a)
    if (.not. this%writer) return
    ! Nodal averages, Mises values and the reordered copy of an integration-point field.
    bytes = 8_i8 * (8_i8 * int(model%mesh%n_nodes, i8) + int(model%mesh%n_elements, i8) * &
      (1_i8 + 6_i8 * int(a%elements%max_points, i8)))
    call set_activity('writing a results frame to ' // this%job // '.h5', bytes)
    call ensure_memory(bytes, 'writing a results frame to ' // this%job // '.h5', err)
    if (allocated(err)) return
    associate (state => a%state)
      call this%results%begin_frame(state%time, state%step, state%increment, err)
      if (allocated(err)) return
      call this%results%write_coordinates(state%x, err)
      if (.not. allocated(err)) call this%results%write_field(field('displacement', FIELD_NODES, state%u), err)
      if (.not. allocated(err)) call this%results%write_field(field('force', FIELD_NODES, state%reaction), err)
      if (.not. allocated(err) .and. allocated(state%temperature)) call this%results%write_field( &
        field('NT', FIELD_NODES, reshape(state%temperature, [1, size(state%temperature)])), err)
      if (allocated(err)) return
      nodal = a%elements%nodal_average(state%elements%stress, model%mesh%n_nodes)
      allocate (nodal_mises(1, size(nodal, 2)), cell_mises(1, model%mesh%n_elements))
      do q = 1, size(nodal, 2)
        nodal_mises(1, q) = mises_stress(nodal(:, q))
      end do
      do q = 1, model%mesh%n_elements
        cell_mises(1, q) = element_mean_mises(state%elements%stress(:, 1:a%elements%n_points(q), q))
      end do
      call this%results%write_field(field('stress', FIELD_NODES, nodal), err)
      if (.not. allocated(err)) call this%results%write_field(field('mises', FIELD_NODES, nodal_mises), err)
      if (.not. allocated(err)) call this%results%write_field(field('mises', FIELD_CELLS, cell_mises), err)
      if (.not. allocated(err)) call this%results%write_field(point_field('stress', state%elements%stress), err)
      if (.not. allocated(err)) call this%results%write_field(point_field('strain', state%elements%strain), err)
      if (.not. allocated(err) .and. a%elements%has_states()) &
        call write_plastic_fields(this, a, model, err)
      if (.not. allocated(err)) call write_contact_fields(this, a, err)
      if (.not. allocated(err)) call this%results%end_frame(err)
      if (.not. allocated(err)) call write_tables(this, monitors, err)
      call log_contact_totals(a, log, .true.)
    end associate
  end subroutine outputs_write_frame

  !> The plastic state in a frame, named as CalculiX (PEEQ, PE) and Abaqus (ALPHA, the back
  !> stress) name it: PEEQ at the integration points, averaged at the nodes and per element
  !> (cells); the plastic strain PE (tensor components) and ALPHA at the integration points
  !> and the nodes.
  subroutine write_plastic_fields(this, a, model, err)
    type(run_outputs_t), intent(inout) :: this
    type(analysis_t), intent(in) :: a
    type(model_t), intent(in) :: model
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: peeq(:, :), plastic_strain(:, :, :), back_stress(:, :, :), cell(:, :)
    integer :: e, n
    call a%elements%plastic_fields(a%state%elements, peeq, plastic_strain, back_stress)
    plastic_strain(4:6, :, :) = 0.5_dp * plastic_strain(4:6, :, :)
    allocate (cell(1, size(peeq, 2)))
    do e = 1, size(peeq, 2)
      n = a%elements%n_points(e)
      cell(1, e) = sum(peeq(1:n, e)) / n
    end do
    call this%results%write_field(point_field('PEEQ', reshape(peeq, [1, shape(peeq)])), err)
    if (.not. allocated(err)) call this%results%write_field(point_field('PE', plastic_strain), err)
    if (.not. allocated(err)) call this%results%write_field(point_field('ALPHA', back_stress), err)
    if (.not. allocated(err)) call this%results%write_field(field('PEEQ', FIELD_NODES, &
      a%elements%nodal_average(reshape(peeq, [1, shape(peeq)]), model%mesh%n_nodes)), err)
    if (.not. allocated(err)) call this%results%write_field(field('PEEQ', FIELD_CELLS, cell), err)
    if (.not. allocated(err)) call this%results%write_field(field('PE', FIELD_NODES, &
      a%elements%nodal_average(plastic_strain, model%mesh%n_nodes)), err)
    if (.not. allocated(err)) call this%results%write_field(field('ALPHA', FIELD_NODES, &
      a%elements%nodal_average(back_stress, model%mesh%n_nodes)), err)
  end subroutine write_plastic_fields

  !> One point grid per contact pair (its slave nodes) in the results.
  subroutine define_contact_grids(this, contact, err)
    type(run_outputs_t), intent(inout) :: this
    type(contact_system_t), intent(in) :: contact
    type(error_t), allocatable, intent(out) :: err
    integer :: k, m, i
    do k = 1, contact%n_pairs()
      m = size(contact%pair_slave_nodes(k))
      call this%results%define_surface_grid('contact_' // contact%pair_name(k), GRID_POINTS, &
                                            reshape([(i, i = 0, m - 1)], [1, m]), err)
      if (allocated(err)) return
    end do
  end subroutine define_contact_grids

  !> The contact fields of every pair for the current frame (the contact system's
  !> `pair_fields`), after the positions of its slave nodes.
  subroutine write_contact_fields(this, a, err)
    type(run_outputs_t), intent(inout) :: this
    type(analysis_t), intent(in) :: a
    type(error_t), allocatable, intent(out) :: err
    type(field_t), allocatable :: fields(:)
    character(len=:), allocatable :: grid
    integer :: k, j
    do k = 1, a%contact%n_pairs()
      grid = 'contact_' // a%contact%pair_name(k)
      call this%results%write_surface_coordinates(grid, a%contact%pair_positions(k, a%x_contact), err)
      if (allocated(err)) return
      fields = a%contact%pair_fields(k, a%x_contact, a%state%contact, grid)
      do j = 1, size(fields)
        call this%results%write_field(fields(j), err)
        if (allocated(err)) return
      end do
    end do
  end subroutine write_contact_fields

  !> History tables and the event catalog into the results file (h5py sees one row per
  !> sample or event: shape (rows, columns)).
  subroutine write_tables(this, monitors, err)
    type(run_outputs_t), intent(inout) :: this
    type(monitors_t), intent(in) :: monitors
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    do k = 1, size(monitors%tables)
      associate (table => monitors%tables(k))
        call this%results%write_table('history', to_lower(table%name), join_strings(table%columns, ','), &
                                      table%values(), err)
      end associate
      if (allocated(err)) return
    end do
    if (monitors%catalog_on) call this%results%write_table('events', 'catalog', EVENT_COLUMNS, &
      monitors%catalog%table(), err)
  end subroutine write_tables

  !> One log line per contact pair: states and total forces (a detail line, or with
  !> `detail_only` false an info line).
  subroutine log_contact_totals(a, log, detail_only)
    type(analysis_t), intent(in) :: a
    type(logger_t), intent(inout) :: log
    logical, intent(in) :: detail_only
    type(pair_totals_t) :: t
    character(len=:), allocatable :: line
    integer :: k
    do k = 1, a%contact%n_pairs()
      t = a%contact%totals(k, a%x_contact, a%state%contact)
      line = '  contact ' // a%contact%pair_name(k) // ': ' // str(t%n_stick) // ' stick, ' // &
        str(t%n_slip) // ' slip, ' // str(t%n_open) // ' open, ' // str(t%n_tied) // ' tied; ' // &
        'normal force ' // str(t%normal_force) // ', tangential force (' // &
        str(t%tangential_force(1)) // ', ' // str(t%tangential_force(2)) // ', ' // &
        str(t%tangential_force(3)) // ')'
      if (detail_only) then
        call log%detail(line)
      else
        call log%info(line)
      end if
    end do
  end subroutine log_contact_totals

  !> Close the output files; a failed close becomes the run's error if it has none.
  subroutine outputs_close(this, err)
    class(run_outputs_t), intent(inout) :: this
    type(error_t), allocatable, intent(inout) :: err
    type(error_t), allocatable :: dat_err, results_err
    call this%dat%close(dat_err)
    if (this%results%is_open()) call this%results%close(results_err)
    if (.not. allocated(err) .and. allocated(dat_err)) call move_alloc(dat_err, err)
    if (.not. allocated(err) .and. allocated(results_err)) call move_alloc(results_err, err)
  end subroutine outputs_close

  pure real(dp) function element_mean_mises(stress) result(m)
    real(dp), intent(in) :: stress(:, :)
    integer :: q
    m = 0.0_dp
    do q = 1, size(stress, 2)
      m = m + mises_stress(stress(:, q))
    end do
    m = m / size(stress, 2)
  end function element_mean_mises


end module fcs_run_outputs
