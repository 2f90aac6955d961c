!> Checkpoints of a running analysis and restarts from them. A checkpoint is "save every owner
!> of run state" (`save_owners`) and a restart "load every owner" (`load_owners`), each owner
!> through its own `save`/`load` over the archive (fcs_archive); this module adds what the
!> checkpoint records about itself (the deck's hashes, the build, the size of the text
!> outputs) and the checks a restart makes before it continues (same model, same steps up to
!> the checkpoint; further steps may be added).
module fcs_run_checkpoint
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, input_error, add_context
  use fcs_state, only: state_t
  use fcs_contact_system, only: contact_system_t
  use fcs_model, only: model_t
  use fcs_static_explicit, only: analysis_t, build_pattern, contact_positions
  use fcs_checkpoint, only: checkpoint_info_t, h5_archive_t, begin_checkpoint, end_checkpoint, &
                            open_checkpoint, close_checkpoint, checkpoint_generation_path
  use fcs_archive, only: archive_t
  use fcs_files, only: file_size
  use fcs_monitors, only: monitors_t
  use fcs_strings, only: str, join_strings, string_t, parse_int, file_exists, split_words
  use fcs_version, only: FCS3D_VERSION, FCS3D_REVISION
  implicit none
  private
  public :: save_checkpoint, restore_checkpoint, build_id

contains

  !> Version and revision of this build.
  pure function build_id() result(id)
    character(len=:), allocatable :: id
    id = FCS3D_VERSION // ' (git ' // FCS3D_REVISION // ')'
  end function build_id

  !> Write the checkpoint of the analysis now (generation 0 of `<job>.rst.h5`); `options` is
  !> the run's record of its result-changing command-line options (fcs_restart_options).
  subroutine save_checkpoint(job, options, a, monitors, model, n_frames, err)
    character(len=*), intent(in) :: job, options
    type(analysis_t), intent(in) :: a
    type(monitors_t), intent(in) :: monitors
    type(model_t), intent(in) :: model
    integer, intent(in) :: n_frames
    type(error_t), allocatable, intent(out) :: err
    type(checkpoint_info_t) :: info
    type(h5_archive_t) :: archive
    info%model_hash = model%model_hash
    info%step_hashes = join_strings(model%step_hashes, ' ')
    info%build = build_id()
    info%records_options = .true.
    info%options = options
    info%n_nodes = a%state%n_nodes
    info%n_elements = a%state%n_elements
    info%n_slaves = a%contact%n_slaves()
    info%n_material_state = size(a%state%elements%material_state, 1)
    info%time = a%state%time
    info%step_time = a%state%step_time
    info%step = a%state%step
    info%increment = a%state%increment
    info%dat_size = max(0_i8, file_size(job // '.dat'))
    info%n_frames = n_frames
    call begin_checkpoint(job, archive, err)
    if (.not. allocated(err)) call save_owners(archive, a%state, a%contact, monitors, err)
    call end_checkpoint(archive, job, info, model%checkpoint%generations, err)
  end subroutine save_checkpoint

  !> Every owner of run state saves itself into `archive`: the state (coordinates,
  !> displacements, integration-point fields, counters), the contact states, the contact
  !> system's search and pattern bookkeeping, the monitors (histories, event catalog).
  subroutine save_owners(archive, state, contact, monitors, err)
    class(archive_t), intent(inout) :: archive
    type(state_t), intent(in) :: state
    type(contact_system_t), intent(in) :: contact
    type(monitors_t), intent(in) :: monitors
    type(error_t), allocatable, intent(out) :: err
    call state%save(archive, err)
    if (.not. allocated(err)) call state%elements%save(archive, '/state', err)
    if (.not. allocated(err)) call state%contact%save(archive, err)
    if (.not. allocated(err)) call contact%save(archive, err)
    if (.not. allocated(err)) call monitors%save(archive, err)
  end subroutine save_owners

  !> Every owner of run state loads itself from `archive`, in the order `save_owners` saved.
  subroutine load_owners(archive, state, contact, monitors, err)
    class(archive_t), intent(inout) :: archive
    type(state_t), intent(inout) :: state
    type(contact_system_t), intent(inout) :: contact
    type(monitors_t), intent(inout) :: monitors
    type(error_t), allocatable, intent(out) :: err
    call state%load(archive, err)
    if (.not. allocated(err)) call state%elements%load(archive, '/state', err)
    if (.not. allocated(err)) call state%contact%load(archive, err)
    if (.not. allocated(err)) call contact%load(archive, err)
    if (.not. allocated(err)) call monitors%load(archive, err)
  end subroutine load_owners

  !> Read checkpoint `path` into the owners (set up for the model), verified as a whole.
  subroutine read_checkpoint(path, state, contact, monitors, info, err)
    character(len=*), intent(in) :: path
    type(state_t), intent(inout) :: state
    type(contact_system_t), intent(inout) :: contact
    type(monitors_t), intent(inout) :: monitors
    type(checkpoint_info_t), intent(out) :: info
    type(error_t), allocatable, intent(out) :: err
    type(h5_archive_t) :: archive
    call open_checkpoint(path, archive, err)
    if (.not. allocated(err)) call load_owners(archive, state, contact, monitors, err)
    call close_checkpoint(archive, info, err)
  end subroutine read_checkpoint

  !> Restore the analysis from checkpoint `path`, after checking that the deck still
  !> describes its model; the sparse pattern is rebuilt as it was. `warning` is set when the
  !> build differs (results may then differ in the last digits).
  subroutine restore_checkpoint(path, a, monitors, model, info, warning, err)
    character(len=*), intent(in) :: path
    type(analysis_t), intent(inout) :: a
    type(monitors_t), intent(inout) :: monitors
    type(model_t), intent(in) :: model
    type(checkpoint_info_t), intent(out) :: info
    character(len=:), allocatable, intent(out) :: warning
    type(error_t), allocatable, intent(out) :: err
    warning = ''
    call read_checkpoint(path, a%state, a%contact, monitors, info, err)
    if (allocated(err)) then
      call offer_older_generation(path, a%state, a%contact, monitors, err)
      return
    end if
    call check_deck(model, info, err)
    if (allocated(err)) then
      call add_context(err, 'restart from ' // path)
      return
    end if
    if (info%build /= build_id()) warning = 'the checkpoint ' // path // ' was written by fcs3d ' // &
      info%build // ', this is ' // build_id() // ': results may differ in the last digits'
    call contact_positions(a, model)
    if (a%contact%n_slaves() > 0) call build_pattern(a, model, keep_centres=.true.)
  end subroutine restore_checkpoint

  !> The deck must have the checkpoint's model and the same steps up to the checkpoint.
  subroutine check_deck(model, info, err)
    type(model_t), intent(in) :: model
    type(checkpoint_info_t), intent(in) :: info
    type(error_t), allocatable, intent(out) :: err
    type(string_t), allocatable :: saved(:)
    integer :: k, n_done
    if (info%model_hash /= model%model_hash) then
      call input_error(err, 'the model definition (the cards before the first *STEP, and the ' // &
        'mesh) differs from the one the checkpoint was written for (hash ' // info%model_hash // &
        ' there, ' // model%model_hash // ' here); a restart continues the same model, only ' // &
        'steps may be added after the checkpoint''s step')
      return
    end if
    saved = split_words(info%step_hashes)
    ! Steps begun before the checkpoint must be unchanged.
    n_done = info%step - 1
    if (info%step_time > 0.0_dp) n_done = info%step
    if (n_done > size(model%steps)) then
      call input_error(err, 'the checkpoint is after step ' // str(n_done) // ' but the deck has ' // &
                       'only ' // str(size(model%steps)) // ' step(s)')
      return
    end if
    do k = 1, min(n_done, size(saved))
      if (saved(k)%s /= model%step_hashes(k)%s) then
        call input_error(err, 'step ' // str(k) // ' of the deck differs from the step the ' // &
          'checkpoint ran (steps up to the checkpoint''s step ' // str(info%step) // ' must be ' // &
          'unchanged; later steps may be changed or added)')
        return
      end if
    end do
  end subroutine check_deck

  !> When a checkpoint cannot be read, name the newest OLDER generation that can be read in
  !> full: read as a restart reads it (every dataset and the overall checksum verified) into
  !> scratch copies of the state, contact bookkeeping and monitors.
  subroutine offer_older_generation(path, state, contact, monitors, err)
    character(len=*), intent(in) :: path
    type(state_t), intent(in) :: state
    type(contact_system_t), intent(in) :: contact
    type(monitors_t), intent(in) :: monitors
    type(error_t), intent(inout) :: err
    type(checkpoint_info_t) :: info
    type(error_t), allocatable :: other_err
    type(state_t) :: scratch_state
    type(contact_system_t) :: scratch_contact
    type(monitors_t) :: scratch
    character(len=:), allocatable :: stem, candidate
    integer :: g, k, own
    k = index(path, '.rst.', back=.true.)
    if (k == 0) return
    stem = path(1:k - 1)
    own = generation_of(path(k + 5:))
    if (own < 0) return
    do g = own + 1, own + 100
      candidate = checkpoint_generation_path(stem, g)
      if (.not. file_exists(candidate)) exit
      scratch_state = state
      scratch_contact = contact
      scratch = monitors
      call read_checkpoint(candidate, scratch_state, scratch_contact, scratch, info, other_err)
      if (allocated(other_err)) then
        deallocate (other_err)
        cycle
      end if
      err%message = err%message // new_line('a') // 'an older checkpoint is readable: ' // &
        candidate // ' (time ' // str(info%time) // ', increment ' // str(info%increment) // &
        '); restart from it with --restart ' // candidate
      return
    end do
  end subroutine offer_older_generation

  !> The generation of a checkpoint from its name after ".rst.": "h5" is 0, "<g>.h5" is g;
  !> -1 for anything else.
  integer function generation_of(tail) result(g)
    character(len=*), intent(in) :: tail
    logical :: ok
    g = -1
    if (tail == 'h5') then
      g = 0
    else if (len(tail) > 3) then
      if (tail(len(tail) - 2:) /= '.h5') return
      call parse_int(tail(1:len(tail) - 3), g, ok)
      if (.not. ok .or. g < 1) g = -1
    end if
  end function generation_of

end module fcs_run_checkpoint
