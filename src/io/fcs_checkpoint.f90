!> Checkpoints: everything needed to continue a run exactly, in one HDF5 file `<job>.rst.h5`
!> (the run state of doc/architecture.md: coordinates, displacements, stresses and material
!> state, contact pairing, states, forces, slip and friction state, the contact search and
!> pattern bookkeeping, step, time and R-minimum bookkeeping) with the deck's hashes.
!>
!> Written atomically: a temporary file is written, flushed to disk (fsync), the older
!> generations are shifted (`<job>.rst.1.h5`, `.rst.2.h5`, ...) and the temporary file is
!> renamed into place. Every dataset carries a checksum (FNV-1a, fcs_checksum) verified on
!> read, and the file a checksum over all of them, so a truncated or damaged checkpoint is
!> refused instead of silently continuing from wrong data.
module fcs_checkpoint
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, fatal_error, input_error, add_context, EXIT_INPUT
  use fcs_hdf5, only: h5_file_t, h5_library_open
  use fcs_files, only: rename_file, remove_file, sync_file, file_kind, file_kind_name, &
    is_readable, file_size, FILE_MISSING, FILE_REGULAR
  use fcs_checksum, only: checksum_t, checksum_text
  use fcs_state, only: state_t
  use fcs_contact_system, only: contact_system_t
  use fcs_history, only: history_table_t
  use fcs_event_catalog, only: event_catalog_t, slip_event_t
  use fcs_strings, only: str, dirname, file_exists
  implicit none
  private
  public :: checkpoint_info_t, write_checkpoint, read_checkpoint, read_checkpoint_info
  public :: checkpoint_generation_path, CHECKPOINT_FORMAT

  character(len=*), parameter :: CHECKPOINT_FORMAT = 'fcs3d checkpoint'
  !> Version of the layout and checksums; a checkpoint of another version is refused.
  !> 2: checksums with the xor-shift step (fcs_checksum); the layouts since 418dfd4
  !> (friction step control in /state/scalars and /state/counters, the frame count in
  !> /meta/sizes), which version-1 files may lack.
  !> 3: the out-of-balance ratio of the last increment, the largest of the step and the
  !> step's force scale in /state/scalars, the increment that had the largest in
  !> /state/counters.
  integer, parameter :: CHECKPOINT_VERSION = 3

  !> What a checkpoint says about itself (the /meta attributes).
  type :: checkpoint_info_t
    !> Hash of the model definition part of the echoed deck, and of each step's cards.
    character(len=:), allocatable :: model_hash
    character(len=:), allocatable :: step_hashes
    !> Version and git revision of the build that wrote it.
    character(len=:), allocatable :: build
    integer :: n_nodes = 0, n_elements = 0, n_slaves = 0, n_material_state = 0
    real(dp) :: time = 0.0_dp
    !> Time within the step (0: the checkpoint is at the start of `step`).
    real(dp) :: step_time = 0.0_dp
    integer :: step = 0, increment = 0
    !> Size of the job's text outputs when the checkpoint was written [bytes], and the number
    !> of complete frames in its results file.
    integer(i8) :: dat_size = 0
    integer :: n_frames = 0
  end type checkpoint_info_t

  !> The file being written or read, with the running checksum over all datasets.
  type :: archive_t
    type(h5_file_t) :: h5
    type(checksum_t) :: total
    character(len=:), allocatable :: path
  end type archive_t

contains

  !> `<stem>.rst.h5` for generation 0, `<stem>.rst.<g>.h5` for older generations.
  pure function checkpoint_generation_path(stem, generation) result(path)
    character(len=*), intent(in) :: stem
    integer, intent(in) :: generation
    character(len=:), allocatable :: path
    if (generation == 0) then
      path = stem // '.rst.h5'
    else
      path = stem // '.rst.' // str(generation) // '.h5'
    end if
  end function checkpoint_generation_path

  !> Write the checkpoint of `state` (and the contact bookkeeping) as generation 0 of `stem`,
  !> keeping `generations` generations in all.
  subroutine write_checkpoint(stem, state, contact, tables, catalog, info, generations, err)
    character(len=*), intent(in) :: stem
    type(state_t), intent(in) :: state
    type(contact_system_t), intent(in) :: contact
    type(history_table_t), intent(in) :: tables(:)
    type(event_catalog_t), intent(in) :: catalog
    type(checkpoint_info_t), intent(in) :: info
    integer, intent(in) :: generations
    type(error_t), allocatable, intent(out) :: err
    type(archive_t) :: archive
    character(len=:), allocatable :: final_path
    integer :: g
    final_path = checkpoint_generation_path(stem, 0)
    archive%path = final_path // '.tmp'
    call h5_library_open(err)
    if (.not. allocated(err)) call archive%h5%create(archive%path, err)
    if (.not. allocated(err)) call write_contents(archive, state, contact, info, err)
    if (.not. allocated(err)) call write_monitors(archive, tables, catalog, err)
    if (.not. allocated(err)) call seal(archive, info, err)
    if (allocated(err)) then
      if (archive%h5%is_open()) call close_quietly(archive)
      call discard(archive%path)
      call add_context(err, 'writing checkpoint ' // final_path)
      return
    end if
    call archive%h5%close(err)
    if (allocated(err)) call discard(archive%path)
    if (.not. allocated(err)) call sync_file(archive%path, err)
    do g = generations - 1, 1, -1
      if (allocated(err)) exit
      if (file_exists(checkpoint_generation_path(stem, g - 1))) &
        call rename_file(checkpoint_generation_path(stem, g - 1), checkpoint_generation_path(stem, g), err)
    end do
    if (.not. allocated(err)) call rename_file(archive%path, final_path, err)
    if (.not. allocated(err)) call sync_file(dirname(final_path), err)
    if (allocated(err)) call add_context(err, 'writing checkpoint ' // final_path)
  end subroutine write_checkpoint

  !> Remove a temporary checkpoint that could not be written whole (it would only take space).
  subroutine discard(path)
    character(len=*), intent(in) :: path
    type(error_t), allocatable :: ignored
    call remove_file(path, ignored)
  end subroutine discard

  subroutine close_quietly(archive)
    type(archive_t), intent(inout) :: archive
    type(error_t), allocatable :: ignored
    call archive%h5%close(ignored)
  end subroutine close_quietly

  subroutine write_contents(archive, state, contact, info, err)
    type(archive_t), intent(inout) :: archive
    type(state_t), intent(in) :: state
    type(contact_system_t), intent(in) :: contact
    type(checkpoint_info_t), intent(in) :: info
    type(error_t), allocatable, intent(out) :: err
    call archive%h5%create_group('/state', err)
    if (.not. allocated(err)) call put_real2(archive, '/state/x', state%x, err)
    if (.not. allocated(err)) call put_real2(archive, '/state/u', state%u, err)
    if (.not. allocated(err)) call put_real2(archive, '/state/reaction', state%reaction, err)
    if (.not. allocated(err)) call put_real2(archive, '/state/step_start_u', state%step_start_u, err)
    if (.not. allocated(err)) call put_real3(archive, '/state/stress', state%stress, err)
    if (.not. allocated(err)) call put_real3(archive, '/state/strain', state%strain, err)
    if (.not. allocated(err) .and. size(state%material_state, 1) > 0) &
      call put_real3(archive, '/state/material_state', state%material_state, err)
    if (.not. allocated(err)) call put_real1(archive, '/state/scalars', state_scalars(state), err)
    if (.not. allocated(err)) call put_int1(archive, '/state/counters', &
      [state%step, state%increment, state%step_increment, state%friction_kind, state%friction_node, &
       state%step_worst_residual_increment], err)
    if (.not. allocated(err) .and. contact%n_slaves() > 0) &
      call write_contact(archive, state, contact, err)
  end subroutine write_contents

  !> History rows and the event catalog (watched pairs and events so far).
  subroutine write_monitors(archive, tables, catalog, err)
    type(archive_t), intent(inout) :: archive
    type(history_table_t), intent(in) :: tables(:)
    type(event_catalog_t), intent(in) :: catalog
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    call archive%h5%create_group('/monitors', err)
    do k = 1, size(tables)
      if (allocated(err)) return
      call put_real2(archive, '/monitors/history_' // str(k), tables(k)%values(), err)
    end do
    if (allocated(err) .or. .not. allocated(catalog%watch)) return
    call put_real2(archive, '/monitors/events', events_to_table(catalog), err)
    do k = 1, size(catalog%watch)
      if (allocated(err)) return
      call put_real2(archive, '/monitors/watch_' // str(k), watch_to_table(catalog, k), err)
    end do
  end subroutine write_monitors

  !> Events as rows of reals (the slip_event_t fields in order).
  pure function events_to_table(catalog) result(table)
    type(event_catalog_t), intent(in) :: catalog
    real(dp), allocatable :: table(:, :)
    integer :: i
    allocate (table(12, catalog%n_events))
    do i = 1, catalog%n_events
      table(:, i) = event_values(catalog%events(i))
    end do
  end function events_to_table

  pure function event_values(e) result(v)
    type(slip_event_t), intent(in) :: e
    real(dp) :: v(12)
    v = [real(e%pair, dp), e%onset, e%finish, real(e%n_nodes, dp), e%peak_rate, e%max_slip, &
         e%mean_slip, e%stress_drop, real(e%hypocentre, dp), e%location]
  end function event_values

  pure function values_event(v) result(e)
    real(dp), intent(in) :: v(12)
    type(slip_event_t) :: e
    e = slip_event_t(nint(v(1)), v(2), v(3), nint(v(4)), v(5), v(6), v(7), v(8), nint(v(9)), v(10:12))
  end function values_event

  !> The watch of pair k as one column: per-node involved flags, slip and shear at onset,
  !> last slip and shear (5 n values), then the active flag and the event under way (13).
  pure function watch_to_table(catalog, k) result(table)
    type(event_catalog_t), intent(in) :: catalog
    integer, intent(in) :: k
    real(dp), allocatable :: table(:, :)
    associate (w => catalog%watch(k))
      table = reshape([merge(1.0_dp, 0.0_dp, w%involved), w%slip_start, w%shear_start, &
                       w%last_slip, w%last_shear, merge(1.0_dp, 0.0_dp, w%active), &
                       event_values(w%event)], [5 * size(w%involved) + 13, 1])
    end associate
  end function watch_to_table

  !> The /meta group and the overall checksum: written last.
  subroutine seal(archive, info, err)
    type(archive_t), intent(inout) :: archive
    type(checkpoint_info_t), intent(in) :: info
    type(error_t), allocatable, intent(out) :: err
    call write_meta(archive, info, err)
  end subroutine seal

  pure function state_scalars(state) result(values)
    type(state_t), intent(in) :: state
    real(dp) :: values(8)
    values = [state%time, state%step_time, state%last_increment, state%last_r, state%residual_norm, &
              state%friction_dt, state%step_worst_residual, state%force_scale]
  end function state_scalars

  subroutine write_contact(archive, state, contact, err)
    type(archive_t), intent(inout) :: archive
    type(state_t), intent(in) :: state
    type(contact_system_t), intent(in) :: contact
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    associate (c => state%contact)
      call archive%h5%create_group('/contact', err)
      if (.not. allocated(err)) call put_int1(archive, '/contact/status', c%status, err)
      if (.not. allocated(err)) call put_int1(archive, '/contact/face', c%face, err)
      if (.not. allocated(err)) call put_int1(archive, '/contact/pattern_face', contact%pattern_face, err)
      if (.not. allocated(err)) call put_real2(archive, '/contact/xi', c%xi, err)
      if (.not. allocated(err)) call put_real2(archive, '/contact/friction', c%friction, err)
      if (.not. allocated(err)) call put_real2(archive, '/contact/tangential_displacement', &
                                               c%tangential_displacement, err)
      if (.not. allocated(err)) call put_real2(archive, '/contact/scalars', reshape([c%gap, &
        c%normal_force, c%trial_norm, c%slip, c%slip_rate, c%mu, c%friction_state, c%tied_gap, &
        c%work], [c%n, 9]), err)
      do k = 1, size(contact%pairs)
        if (allocated(err)) return
        call put_real3(archive, '/contact/grid_' // str(k), contact%pairs(k)%grid%built_x, err)
      end do
      if (.not. allocated(err)) call archive%h5%write_attribute('/contact', 'pattern_dirty', &
        merge(1, 0, contact%pattern_dirty), err)
    end associate
  end subroutine write_contact

  subroutine write_meta(archive, info, err)
    type(archive_t), intent(inout) :: archive
    type(checkpoint_info_t), intent(in) :: info
    type(error_t), allocatable, intent(out) :: err
    call archive%h5%create_group('/meta', err)
    if (allocated(err)) return
    call archive%h5%write_attribute('/meta', 'format', CHECKPOINT_FORMAT, err)
    if (.not. allocated(err)) call archive%h5%write_attribute('/meta', 'version', CHECKPOINT_VERSION, err)
    if (.not. allocated(err)) call archive%h5%write_attribute('/meta', 'model_hash', info%model_hash, err)
    if (.not. allocated(err)) call archive%h5%write_attribute('/meta', 'step_hashes', &
                                                              info%step_hashes // ' ', err)
    if (.not. allocated(err)) call archive%h5%write_attribute('/meta', 'build', info%build, err)
    if (.not. allocated(err)) call put_int1(archive, '/meta/sizes', [info%n_nodes, info%n_elements, &
      info%n_slaves, info%n_material_state, info%step, info%increment, info%n_frames], err)
    if (.not. allocated(err)) call put_real1(archive, '/meta/values', [info%time, &
      real(info%dat_size, dp), info%step_time], err)
    call archive%total%add_text(info%model_hash // info%step_hashes // info%build)
    if (.not. allocated(err)) call archive%h5%write_attribute('/meta', 'checksum', &
                                                              checksum_text(archive%total%value), err)
  end subroutine write_meta

  !> Read the /meta of a checkpoint (verified) without its data.
  subroutine read_checkpoint_info(path, info, err)
    character(len=*), intent(in) :: path
    type(checkpoint_info_t), intent(out) :: info
    type(error_t), allocatable, intent(out) :: err
    type(archive_t) :: archive
    call open_archive(archive, path, err)
    if (.not. allocated(err)) call read_meta(archive, info, err)
    if (archive%h5%is_open()) call close_quietly(archive)
    if (allocated(err)) call add_context(err, 'reading checkpoint ' // path)
  end subroutine read_checkpoint_info

  subroutine open_archive(archive, path, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: format
    integer :: version, kind
    archive%path = path
    kind = file_kind(path)
    if (kind == FILE_MISSING) then
      call input_error(err, 'the file does not exist')
      return
    else if (kind /= FILE_REGULAR) then
      call input_error(err, 'it is ' // file_kind_name(kind) // ', not a checkpoint file')
      return
    else if (.not. is_readable(path)) then
      call input_error(err, 'the file cannot be read (no read permission)')
      return
    else if (file_size(path) == 0) then
      call input_error(err, 'the file is empty (0 bytes): not a checkpoint')
      return
    end if
    call h5_library_open(err)
    if (allocated(err)) return
    call archive%h5%open(path, .false., err)
    if (allocated(err)) then
      call input_error(err, 'not a readable HDF5 file (truncated or damaged?)')
      return
    end if
    if (.not. archive%h5%has_attribute('/meta', 'format')) then
      call input_error(err, 'not an fcs3d checkpoint (no /meta format attribute)')
      return
    end if
    call archive%h5%read_attribute('/meta', 'format', format, err)
    if (allocated(err)) return
    if (format /= CHECKPOINT_FORMAT) then
      call input_error(err, 'not an fcs3d checkpoint ("' // format // '")')
      return
    end if
    call archive%h5%read_attribute('/meta', 'version', version, err)
    if (allocated(err)) return
    if (version /= CHECKPOINT_VERSION) call input_error(err, 'checkpoint format version ' // &
      str(version) // '; this fcs3d reads version ' // str(CHECKPOINT_VERSION) // &
      ' only (restart with the fcs3d that wrote it)')
  end subroutine open_archive

  !> Read and verify a checkpoint into `state` (already set up for the model, so that its
  !> sizes are checked) and the contact bookkeeping.
  subroutine read_checkpoint(path, state, contact, tables, catalog, info, err)
    character(len=*), intent(in) :: path
    type(state_t), intent(inout) :: state
    type(contact_system_t), intent(inout) :: contact
    type(history_table_t), intent(inout) :: tables(:)
    type(event_catalog_t), intent(inout) :: catalog
    type(checkpoint_info_t), intent(out) :: info
    type(error_t), allocatable, intent(out) :: err
    type(archive_t) :: archive
    character(len=:), allocatable :: stored
    call open_archive(archive, path, err)
    if (.not. allocated(err)) call read_state(archive, state, err)
    if (.not. allocated(err) .and. contact%n_slaves() > 0) call read_contact(archive, state, contact, err)
    if (.not. allocated(err)) call read_monitors(archive, tables, catalog, err)
    if (.not. allocated(err)) call read_meta(archive, info, err)
    if (.not. allocated(err)) then
      call archive%total%add_text(info%model_hash // info%step_hashes // info%build)
      call archive%h5%read_attribute('/meta', 'checksum', stored, err)
      if (.not. allocated(err) .and. stored /= checksum_text(archive%total%value)) &
        call input_error(err, 'the overall checksum does not match (the file is damaged)')
    end if
    if (archive%h5%is_open()) call close_quietly(archive)
    if (allocated(err)) then
      ! Whatever failed (HDF5 could not open a damaged object, a checksum...), the file is
      ! bad input to this run, not an internal failure.
      err%exit_code = EXIT_INPUT
      call add_context(err, 'reading checkpoint ' // path)
    end if
  end subroutine read_checkpoint

  subroutine read_state(archive, state, err)
    type(archive_t), intent(inout) :: archive
    type(state_t), intent(inout) :: state
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: scalars(:)
    integer, allocatable :: counters(:)
    call get_real2(archive, '/state/x', state%x, err)
    if (.not. allocated(err)) call get_real2(archive, '/state/u', state%u, err)
    if (.not. allocated(err)) call get_real2(archive, '/state/reaction', state%reaction, err)
    if (.not. allocated(err)) call get_real2(archive, '/state/step_start_u', state%step_start_u, err)
    if (.not. allocated(err)) call get_real3(archive, '/state/stress', state%stress, err)
    if (.not. allocated(err)) call get_real3(archive, '/state/strain', state%strain, err)
    if (.not. allocated(err) .and. size(state%material_state, 1) > 0) &
      call get_real3(archive, '/state/material_state', state%material_state, err)
    if (allocated(err)) return
    allocate (scalars(8), counters(6))
    call get_real1(archive, '/state/scalars', scalars, err)
    if (.not. allocated(err)) call get_int1(archive, '/state/counters', counters, err)
    if (allocated(err)) return
    state%time = scalars(1)
    state%step_time = scalars(2)
    state%last_increment = scalars(3)
    state%last_r = scalars(4)
    state%residual_norm = scalars(5)
    state%friction_dt = scalars(6)
    state%step_worst_residual = scalars(7)
    state%force_scale = scalars(8)
    state%step = counters(1)
    state%increment = counters(2)
    state%step_increment = counters(3)
    state%friction_kind = counters(4)
    state%friction_node = counters(5)
    state%step_worst_residual_increment = counters(6)
  end subroutine read_state

  subroutine read_contact(archive, state, contact, err)
    type(archive_t), intent(inout) :: archive
    type(state_t), intent(inout) :: state
    type(contact_system_t), intent(inout) :: contact
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: scalars(:, :), grid(:, :, :)
    integer :: k, dirty
    associate (c => state%contact)
      call get_int1(archive, '/contact/status', c%status, err)
      if (.not. allocated(err)) call get_int1(archive, '/contact/face', c%face, err)
      if (.not. allocated(err)) call get_int1(archive, '/contact/pattern_face', contact%pattern_face, err)
      if (.not. allocated(err)) call get_real2(archive, '/contact/xi', c%xi, err)
      if (.not. allocated(err)) call get_real2(archive, '/contact/friction', c%friction, err)
      if (.not. allocated(err)) call get_real2(archive, '/contact/tangential_displacement', &
                                               c%tangential_displacement, err)
      if (allocated(err)) return
      allocate (scalars(c%n, 9))
      call get_real2(archive, '/contact/scalars', scalars, err)
      if (allocated(err)) return
      c%gap = scalars(:, 1)
      c%normal_force = scalars(:, 2)
      c%trial_norm = scalars(:, 3)
      c%slip = scalars(:, 4)
      c%slip_rate = scalars(:, 5)
      c%mu = scalars(:, 6)
      c%friction_state = scalars(:, 7)
      c%tied_gap = scalars(:, 8)
      c%work = scalars(:, 9)
      do k = 1, size(contact%pairs)
        allocate (grid, mold=contact%pairs(k)%grid%built_x)
        call get_real3(archive, '/contact/grid_' // str(k), grid, err)
        if (allocated(err)) return
        call contact%pairs(k)%grid%build(grid, contact%pairs(k)%reach)
        deallocate (grid)
      end do
      call archive%h5%read_attribute('/contact', 'pattern_dirty', dirty, err)
      contact%pattern_dirty = dirty /= 0
    end associate
  end subroutine read_contact

  subroutine read_monitors(archive, tables, catalog, err)
    type(archive_t), intent(inout) :: archive
    type(history_table_t), intent(inout) :: tables(:)
    type(event_catalog_t), intent(inout) :: catalog
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: rows(:, :)
    integer(i8), allocatable :: dims(:)
    integer :: k, i, n
    do k = 1, size(tables)
      if (.not. archive%h5%exists('/monitors/history_' // str(k))) then
        call input_error(err, 'the checkpoint has no history ' // tables(k)%name // ' (was *HISTORY added?)')
        return
      end if
      call archive%h5%dataset_shape('/monitors/history_' // str(k), dims, err)
      if (allocated(err)) return
      allocate (rows(size(tables(k)%columns), dims(2)))
      call get_real2(archive, '/monitors/history_' // str(k), rows, err)
      if (.not. allocated(err)) call tables(k)%set_rows(rows, err)
      deallocate (rows)
      if (allocated(err)) return
    end do
    if (.not. allocated(catalog%watch)) return
    if (.not. archive%h5%exists('/monitors/events')) then
      call input_error(err, 'the checkpoint has no event catalog (was *EVENT CATALOG added?)')
      return
    end if
    call archive%h5%dataset_shape('/monitors/events', dims, err)
    if (allocated(err)) return
    allocate (rows(12, dims(2)))
    call get_real2(archive, '/monitors/events', rows, err)
    if (allocated(err)) return
    n = size(rows, 2)
    deallocate (catalog%events)
    allocate (catalog%events(max(16, n)))
    do i = 1, n
      catalog%events(i) = values_event(rows(:, i))
    end do
    catalog%n_events = n
    deallocate (rows)
    do k = 1, size(catalog%watch)
      call read_watch(archive, catalog, k, err)
      if (allocated(err)) return
    end do
  end subroutine read_monitors

  subroutine read_watch(archive, catalog, k, err)
    type(archive_t), intent(inout) :: archive
    type(event_catalog_t), intent(inout) :: catalog
    integer, intent(in) :: k
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: table(:, :), flat(:)
    integer :: n
    associate (w => catalog%watch(k))
      n = size(w%involved)
      allocate (table(5 * n + 13, 1))
      call get_real2(archive, '/monitors/watch_' // str(k), table, err)
      if (allocated(err)) return
      flat = table(:, 1)
      w%involved = flat(1:n) > 0.5_dp
      w%slip_start = flat(n + 1:2 * n)
      w%shear_start = flat(2 * n + 1:3 * n)
      w%last_slip = flat(3 * n + 1:4 * n)
      w%last_shear = flat(4 * n + 1:5 * n)
      w%active = flat(5 * n + 1) > 0.5_dp
      w%event = values_event(flat(5 * n + 2:5 * n + 13))
    end associate
  end subroutine read_watch

  subroutine read_meta(archive, info, err)
    type(archive_t), intent(inout) :: archive
    type(checkpoint_info_t), intent(out) :: info
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: sizes(:)
    real(dp), allocatable :: values(:)
    call archive%h5%read_attribute('/meta', 'model_hash', info%model_hash, err)
    if (.not. allocated(err)) call archive%h5%read_attribute('/meta', 'step_hashes', info%step_hashes, err)
    if (.not. allocated(err)) call archive%h5%read_attribute('/meta', 'build', info%build, err)
    if (allocated(err)) return
    info%step_hashes = trim(info%step_hashes)
    allocate (sizes(7), values(3))
    call get_int1(archive, '/meta/sizes', sizes, err)
    if (.not. allocated(err)) call get_real1(archive, '/meta/values', values, err)
    if (allocated(err)) return
    info%n_nodes = sizes(1)
    info%n_elements = sizes(2)
    info%n_slaves = sizes(3)
    info%n_material_state = sizes(4)
    info%step = sizes(5)
    info%increment = sizes(6)
    info%n_frames = sizes(7)
    info%time = values(1)
    info%dat_size = int(values(2), i8)
    info%step_time = values(3)
  end subroutine read_meta

  ! Each dataset goes with a checksum attribute; reading checks shape and checksum.

  subroutine put_real1(archive, path, values, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    call archive%h5%write_dataset(path, values, err)
    if (.not. allocated(err)) call sign_real(archive, path, values, err)
  end subroutine put_real1

  subroutine put_real2(archive, path, values, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    call archive%h5%write_dataset(path, values, err)
    if (.not. allocated(err)) call sign_real(archive, path, reshape(values, [size(values)]), err)
  end subroutine put_real2

  subroutine put_real3(archive, path, values, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    call archive%h5%write_dataset(path, values, err)
    if (.not. allocated(err)) call sign_real(archive, path, reshape(values, [size(values)]), err)
  end subroutine put_real3

  subroutine put_int1(archive, path, values, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    integer, intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    type(checksum_t) :: c
    call archive%h5%write_dataset(path, values, err)
    if (allocated(err)) return
    call c%add_int(values)
    call archive%total%add_text(checksum_text(c%value))
    call archive%h5%write_attribute(path, 'checksum', checksum_text(c%value), err)
  end subroutine put_int1

  subroutine sign_real(archive, path, flat, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: flat(:)
    type(error_t), allocatable, intent(out) :: err
    type(checksum_t) :: c
    call c%add_real(flat)
    call archive%total%add_text(checksum_text(c%value))
    call archive%h5%write_attribute(path, 'checksum', checksum_text(c%value), err)
  end subroutine sign_real

  subroutine get_real1(archive, path, values, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    real(dp), intent(inout) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: stored(:)
    call archive%h5%read_dataset(path, stored, err, shape(values))
    if (.not. allocated(err)) call verify_real(archive, path, stored, err)
    if (.not. allocated(err)) values = stored
  end subroutine get_real1

  subroutine get_real2(archive, path, values, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    real(dp), intent(inout) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: stored(:, :)
    call archive%h5%read_dataset(path, stored, err, shape(values))
    if (.not. allocated(err)) call verify_real(archive, path, reshape(stored, [size(stored)]), err)
    if (.not. allocated(err)) values = stored
  end subroutine get_real2

  subroutine get_real3(archive, path, values, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    real(dp), intent(inout) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: stored(:, :, :)
    call archive%h5%read_dataset(path, stored, err, shape(values))
    if (.not. allocated(err)) call verify_real(archive, path, reshape(stored, [size(stored)]), err)
    if (.not. allocated(err)) values = stored
  end subroutine get_real3

  subroutine get_int1(archive, path, values, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    integer, intent(inout) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: stored(:)
    type(checksum_t) :: c
    call archive%h5%read_dataset(path, stored, err, shape(values))
    if (allocated(err)) then
      call size_error(path, err)
      return
    end if
    call c%add_int(stored)
    call check_sum(archive, path, c, err)
    if (.not. allocated(err)) values = stored
  end subroutine get_int1

  subroutine verify_real(archive, path, flat, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: flat(:)
    type(error_t), allocatable, intent(out) :: err
    type(checksum_t) :: c
    call c%add_real(flat)
    call check_sum(archive, path, c, err)
  end subroutine verify_real

  subroutine check_sum(archive, path, c, err)
    type(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    type(checksum_t), intent(in) :: c
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: stored
    call archive%h5%read_attribute(path, 'checksum', stored, err)
    if (allocated(err)) return
    if (stored /= checksum_text(c%value)) then
      call input_error(err, path // ': checksum mismatch (stored ' // stored // ', data ' // &
                       checksum_text(c%value) // '): the checkpoint is damaged')
      return
    end if
    call archive%total%add_text(stored)
  end subroutine check_sum

  subroutine size_error(path, err)
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(inout) :: err
    err%message = path // ': ' // err%message
    err%exit_code = 2
  end subroutine size_error

end module fcs_checkpoint
