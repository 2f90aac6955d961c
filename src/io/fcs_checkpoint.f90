!> Checkpoints: everything needed to continue a run exactly, in one HDF5 file `<job>.rst.h5`,
!> with the deck's hashes. The file is an archive (fcs_archive, fcs_h5_archive) into which the
!> stepper asks every owner of run state to save itself (fcs_run_checkpoint, `save_owners`):
!> state, element fields, contact states, contact bookkeeping, monitors; this module knows none
!> of them. It opens and seals the file: the format and version checks, the /meta group (what
!> the checkpoint says about itself) and the checksum over every record.
!>
!> Written atomically: a temporary file is written, flushed to disk (fsync), the older
!> generations are shifted (`<job>.rst.1.h5`, `.rst.2.h5`, ...) and the temporary file is
!> renamed into place. Every dataset carries a checksum (FNV-1a, fcs_checksum) verified on
!> read, and the file a checksum over all of them, so a truncated or damaged checkpoint is
!> refused instead of silently continuing from wrong data.
module fcs_checkpoint
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, input_error, add_context, EXIT_INPUT
  use fcs_hdf5, only: h5_library_open
  use fcs_h5_archive, only: h5_archive_t
  use fcs_files, only: rename_file, remove_file, sync_file, file_kind, file_kind_name, &
    is_readable, file_size, FILE_MISSING, FILE_REGULAR
  use fcs_checksum, only: checksum_text
  use fcs_strings, only: str, dirname, file_exists
  implicit none
  private
  public :: checkpoint_info_t, h5_archive_t, begin_checkpoint, end_checkpoint
  public :: open_checkpoint, close_checkpoint, read_checkpoint_info
  public :: checkpoint_generation_path, CHECKPOINT_FORMAT, CHECKPOINT_VERSION

  character(len=*), parameter :: CHECKPOINT_FORMAT = 'fcs3d checkpoint'
  !> Version of the layout and checksums; a checkpoint of another version is refused.
  !> 2: checksums with the xor-shift step (fcs_checksum); the layouts since 418dfd4
  !> (friction step control in /state/scalars and /state/counters, the frame count in
  !> /meta/sizes), which version-1 files may lack.
  !> 3: the out-of-balance ratio of the last increment, the largest of the step and the
  !> step's force scale in /state/scalars, the increment that had the largest in
  !> /state/counters.
  !> 4: every owner of run state saves itself (fcs_archive): the contact search and pattern
  !> bookkeeping in /contact_system (pattern_face, grid_<k>, the pattern_dirty flag),
  !> separate from the contact states in /contact.
  !> 5: the /meta attribute `options`, the command-line options of the run that change its
  !> results (in the overall checksum). Version 4 is the same without it and is still read.
  integer, parameter :: CHECKPOINT_VERSION = 5
  !> The oldest version still read, and the first that records the options.
  integer, parameter :: OLDEST_CHECKPOINT_VERSION = 4, OPTIONS_VERSION = 5

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
    !> Whether the checkpoint records the run's command-line options (version 5 on), and the
    !> record: the options that change results as they would be written on the command line
    !> ("--contact-events CLOSING --reuse-tolerance 1E-10"; '' when none was given).
    logical :: records_options = .false.
    character(len=:), allocatable :: options
  end type checkpoint_info_t

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

  !> Start the checkpoint of `stem`: a temporary file `<stem>.rst.h5.tmp`, open for the owners
  !> of run state to save themselves into; `end_checkpoint` seals it and puts it in place.
  subroutine begin_checkpoint(stem, archive, err)
    character(len=*), intent(in) :: stem
    type(h5_archive_t), intent(out) :: archive
    type(error_t), allocatable, intent(out) :: err
    archive%path = checkpoint_generation_path(stem, 0) // '.tmp'
    archive%writing = .true.
    call h5_library_open(err)
    if (.not. allocated(err)) call archive%h5%create(archive%path, err)
  end subroutine begin_checkpoint

  !> Seal the checkpoint begun by `begin_checkpoint` (the /meta group and the overall
  !> checksum) and make it generation 0 of `stem`, keeping `generations` generations in all.
  !> If `err` comes in allocated (an owner could not save itself) or sealing fails, the
  !> temporary file is removed and the error says which checkpoint was being written.
  subroutine end_checkpoint(archive, stem, info, generations, err)
    type(h5_archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: stem
    type(checkpoint_info_t), intent(in) :: info
    integer, intent(in) :: generations
    type(error_t), allocatable, intent(inout) :: err
    character(len=:), allocatable :: final_path
    integer :: g
    final_path = checkpoint_generation_path(stem, 0)
    if (.not. allocated(err)) call write_meta(archive, info, err)
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
  end subroutine end_checkpoint

  !> Remove a temporary checkpoint that could not be written whole (it would only take space).
  subroutine discard(path)
    character(len=*), intent(in) :: path
    type(error_t), allocatable :: ignored
    call remove_file(path, ignored)
  end subroutine discard

  subroutine close_quietly(archive)
    type(h5_archive_t), intent(inout) :: archive
    type(error_t), allocatable :: ignored
    call archive%h5%close(ignored)
  end subroutine close_quietly

  subroutine write_meta(archive, info, err)
    type(h5_archive_t), intent(inout) :: archive
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
    if (.not. allocated(err)) call archive%h5%write_attribute('/meta', 'options', &
                                                              info%options // ' ', err)
    if (.not. allocated(err)) call archive%put('/meta/sizes', [info%n_nodes, info%n_elements, &
      info%n_slaves, info%n_material_state, info%step, info%increment, info%n_frames], err)
    if (.not. allocated(err)) call archive%put('/meta/values', [info%time, &
      real(info%dat_size, dp), info%step_time], err)
    call archive%total%add_text(meta_text(info))
    if (.not. allocated(err)) call archive%h5%write_attribute('/meta', 'checksum', &
                                                              checksum_text(archive%total%value), err)
  end subroutine write_meta

  !> The /meta text the overall checksum covers (a version-4 checkpoint's has no options,
  !> which read as '': the same text as version 4 wrote).
  pure function meta_text(info) result(text)
    type(checkpoint_info_t), intent(in) :: info
    character(len=:), allocatable :: text
    text = info%model_hash // info%step_hashes // info%build
    if (allocated(info%options)) text = text // info%options
  end function meta_text

  !> Read the /meta of a checkpoint (verified) without its data.
  subroutine read_checkpoint_info(path, info, err)
    character(len=*), intent(in) :: path
    type(checkpoint_info_t), intent(out) :: info
    type(error_t), allocatable, intent(out) :: err
    type(h5_archive_t) :: archive
    call open_checkpoint(path, archive, err)
    if (.not. allocated(err)) call read_meta(archive, info, err)
    if (archive%h5%is_open()) call close_quietly(archive)
    if (allocated(err)) call add_context(err, 'reading checkpoint ' // path)
  end subroutine read_checkpoint_info

  !> Open checkpoint `path` for the owners of run state to load themselves from, after
  !> checking that it is a checkpoint of this format version (`close_checkpoint` then reads
  !> its /meta and verifies the overall checksum). A checkpoint of another version is
  !> refused with a message naming both versions.
  subroutine open_checkpoint(path, archive, err)
    character(len=*), intent(in) :: path
    type(h5_archive_t), intent(out) :: archive
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: format
    integer :: version, kind
    archive%path = path
    archive%writing = .false.
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
    if (version < OLDEST_CHECKPOINT_VERSION .or. version > CHECKPOINT_VERSION) &
      call input_error(err, 'checkpoint format version ' // str(version) // &
      '; this fcs3d reads versions ' // str(OLDEST_CHECKPOINT_VERSION) // ' to ' // &
      str(CHECKPOINT_VERSION) // ' only (restart with the fcs3d that wrote it)')
  end subroutine open_checkpoint

  !> After the owners loaded themselves from `archive` (or failed to: `err` comes in
  !> allocated): read the /meta into `info`, verify the overall checksum and close the file.
  !> Whatever failed, the file is bad input to this run: exit status 2, and the error names
  !> the checkpoint.
  subroutine close_checkpoint(archive, info, err)
    type(h5_archive_t), intent(inout) :: archive
    type(checkpoint_info_t), intent(out) :: info
    type(error_t), allocatable, intent(inout) :: err
    character(len=:), allocatable :: stored
    if (.not. allocated(err)) call read_meta(archive, info, err)
    if (.not. allocated(err)) then
      call archive%total%add_text(meta_text(info))
      call archive%h5%read_attribute('/meta', 'checksum', stored, err)
      if (.not. allocated(err) .and. stored /= checksum_text(archive%total%value)) &
        call input_error(err, 'the overall checksum does not match (the file is damaged)')
    end if
    if (archive%h5%is_open()) call close_quietly(archive)
    if (allocated(err)) then
      ! Whatever failed (HDF5 could not open a damaged object, a checksum...), the file is
      ! bad input to this run, not an internal failure.
      err%exit_code = EXIT_INPUT
      call add_context(err, 'reading checkpoint ' // archive%path)
    end if
  end subroutine close_checkpoint

  subroutine read_meta(archive, info, err)
    type(h5_archive_t), intent(inout) :: archive
    type(checkpoint_info_t), intent(out) :: info
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: sizes(:)
    real(dp), allocatable :: values(:)
    integer :: version
    call archive%h5%read_attribute('/meta', 'version', version, err)
    if (.not. allocated(err)) call archive%h5%read_attribute('/meta', 'model_hash', info%model_hash, err)
    if (.not. allocated(err)) call archive%h5%read_attribute('/meta', 'step_hashes', info%step_hashes, err)
    if (.not. allocated(err)) call archive%h5%read_attribute('/meta', 'build', info%build, err)
    ! Version 4 did not record the options (read as "none recorded").
    info%records_options = version >= OPTIONS_VERSION
    info%options = ''
    if (.not. allocated(err) .and. info%records_options) &
      call archive%h5%read_attribute('/meta', 'options', info%options, err)
    if (allocated(err)) return
    info%step_hashes = trim(info%step_hashes)
    info%options = trim(info%options)
    allocate (sizes(7), values(3))
    call archive%get('/meta/sizes', sizes, err)
    if (.not. allocated(err)) call archive%get('/meta/values', values, err)
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

end module fcs_checkpoint
