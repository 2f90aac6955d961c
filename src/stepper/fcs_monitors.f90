!> Monitors of a run: the history tables (*HISTORY) and the slip-event catalog (*EVENT
!> CATALOG), sampled after increments from the analysis state.
module fcs_monitors
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_model, only: model_t, history_request_t, HISTORY_NSET_U, HISTORY_NSET_RF, &
                       HISTORY_CONTACT, HISTORY_ENERGY, HISTORY_RESIDUAL
  use fcs_static_explicit, only: analysis_t, current_reactions
  use fcs_history, only: history_table_t
  use fcs_event_catalog, only: event_catalog_t
  use fcs_contact_system, only: contact_system_t, pair_totals_t
  use fcs_element_loops, only: element_loops_t
  use fcs_element_state, only: element_state_t
  use fcs_log, only: logger_t
  use fcs_strings, only: string_t, str
  use fcs_archive, only: archive_t
  implicit none
  private
  public :: monitors_t

  type :: monitors_t
    !> Only this process writes the files (rank 0); every process keeps the same rows.
    logical :: writer = .true.
    type(history_table_t), allocatable :: tables(:)
    logical :: catalog_on = .false.
    type(event_catalog_t) :: catalog
    !> Reference volume of each integration point (strain energy), computed once.
    real(dp), allocatable :: volume(:, :)
  contains
    procedure :: init => monitors_init
    procedure :: write_files => monitors_write_files
    procedure :: sample => monitors_sample
    procedure :: watch_events => monitors_watch_events
    procedure :: report_open_events => monitors_report_open_events
    procedure :: save => monitors_save
    procedure :: load => monitors_load
  end type monitors_t

contains

  subroutine monitors_init(this, model, a, job, err)
    class(monitors_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(analysis_t), intent(in) :: a
    character(len=*), intent(in) :: job
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    integer, allocatable :: sizes(:)
    this%writer = a%share%comm%is_root()
    allocate (this%tables(size(model%histories)))
    do k = 1, size(model%histories)
      call this%tables(k)%create(model%histories(k)%name, job // '_' // to_lower_name( &
        model%histories(k)%name) // '.csv', column_names(model, model%histories(k)), err, this%writer)
      if (allocated(err)) return
    end do
    this%catalog_on = model%event_threshold > 0.0_dp .and. a%contact%n_slaves() > 0
    if (this%catalog_on) then
      allocate (sizes(a%contact%n_pairs()))
      do k = 1, a%contact%n_pairs()
        sizes(k) = size(a%contact%pair_slave_nodes(k))
      end do
      call this%catalog%init(model%event_threshold, model%event_min_slip, sizes, job // '_events.csv', &
                             err, this%writer)
    end if
    if (any([(has_energy(model%histories(k)), k = 1, size(model%histories))])) &
      this%volume = a%elements%point_volumes()
  end subroutine monitors_init

  !> Write the rows of every history and the event catalog into group /monitors of `archive`.
  subroutine monitors_save(this, archive, err)
    class(monitors_t), intent(in) :: this
    class(archive_t), intent(inout) :: archive
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    call archive%group('/monitors', err)
    do k = 1, size(this%tables)
      if (allocated(err)) return
      call this%tables(k)%save(archive, '/monitors/history_' // str(k), err)
    end do
    if (.not. allocated(err)) call this%catalog%save(archive, '/monitors', err)
  end subroutine monitors_save

  !> Read what `save` wrote into monitors set up for the model (`init`).
  subroutine monitors_load(this, archive, err)
    class(monitors_t), intent(inout) :: this
    class(archive_t), intent(inout) :: archive
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    do k = 1, size(this%tables)
      call this%tables(k)%load(archive, '/monitors/history_' // str(k), err)
      if (allocated(err)) return
    end do
    call this%catalog%load(archive, '/monitors', err)
  end subroutine monitors_load

  !> Write every history CSV and the event catalog CSV whole from what is in memory: at the
  !> start of a new run (headers), or after a restart was accepted (the checkpoint's rows).
  subroutine monitors_write_files(this, err)
    class(monitors_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    do k = 1, size(this%tables)
      call this%tables(k)%rewrite_csv(err)
      if (allocated(err)) return
    end do
    if (this%catalog_on) call this%catalog%rewrite_csv(err)
  end subroutine monitors_write_files

  pure logical function has_energy(history)
    type(history_request_t), intent(in) :: history
    integer :: i
    has_energy = .false.
    do i = 1, size(history%items)
      if (history%items(i)%kind == HISTORY_ENERGY) has_energy = .true.
    end do
  end function has_energy

  pure function to_lower_name(name) result(out)
    character(len=*), intent(in) :: name
    character(len=len(name)) :: out
    integer :: i
    out = name
    do i = 1, len(name)
      if (name(i:i) >= 'A' .and. name(i:i) <= 'Z') out(i:i) = achar(iachar(name(i:i)) + 32)
      if (name(i:i) == ' ') out(i:i) = '_'
    end do
  end function to_lower_name

  !> Column names of a history: time, then each item's quantities.
  function column_names(model, history) result(columns)
    type(model_t), intent(in) :: model
    type(history_request_t), intent(in) :: history
    type(string_t), allocatable :: columns(:)
    character(len=:), allocatable :: p
    integer :: i
    columns = [string_t('time')]
    do i = 1, size(history%items)
      associate (item => history%items(i))
        select case (item%kind)
        case (HISTORY_NSET_U)
          p = model%mesh%node_sets(item%target)%name
          columns = [columns, string_t(p // '_U1'), string_t(p // '_U2'), string_t(p // '_U3')]
        case (HISTORY_NSET_RF)
          p = model%mesh%node_sets(item%target)%name
          columns = [columns, string_t(p // '_RF1'), string_t(p // '_RF2'), string_t(p // '_RF3')]
        case (HISTORY_CONTACT)
          p = model%contact_pairs(item%target)%name
          columns = [columns, string_t(p // '_FN'), string_t(p // '_FT1'), string_t(p // '_FT2'), &
                     string_t(p // '_FT3'), string_t(p // '_STICK'), string_t(p // '_SLIP'), &
                     string_t(p // '_OPEN'), string_t(p // '_SLIP_MEAN'), string_t(p // '_SLIP_MAX'), &
                     string_t(p // '_RATE_MAX'), string_t(p // '_PRESSURE_MEAN'), &
                     string_t(p // '_SHEAR_MEAN')]
        case (HISTORY_ENERGY)
          columns = [columns, string_t('STRAIN_ENERGY'), string_t('FRICTION_WORK')]
        case (HISTORY_RESIDUAL)
          columns = [columns, string_t('RESIDUAL')]
        end select
      end associate
    end do
  end function column_names


  !> Sample the histories due now (`due(k)` for history k).
  subroutine monitors_sample(this, model, a, due, err)
    class(monitors_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(analysis_t), intent(inout) :: a
    logical, intent(in) :: due(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: row(:), reaction(:, :)
    integer :: k, i
    if (.not. any(due)) return
    allocate (reaction(3, model%mesh%n_nodes))
    call current_reactions(a, model, reaction, err)
    if (allocated(err)) return
    do k = 1, size(this%tables)
      if (.not. due(k)) cycle
      row = [a%state%time]
      do i = 1, size(model%histories(k)%items)
        row = [row, item_values(this, model, a, model%histories(k)%items(i)%kind, &
                                model%histories(k)%items(i)%target, reaction)]
      end do
      call this%tables(k)%append(row, err)
      if (allocated(err)) return
    end do
  end subroutine monitors_sample


  function item_values(this, model, a, kind, target, reaction) result(values)
    type(monitors_t), intent(in) :: this
    type(model_t), intent(in) :: model
    type(analysis_t), intent(in) :: a
    integer, intent(in) :: kind, target
    real(dp), intent(in) :: reaction(:, :)
    real(dp), allocatable :: values(:)
    select case (kind)
    case (HISTORY_NSET_U)
      associate (m => model%mesh%node_sets(target)%members)
        values = sum(a%state%u(:, m), dim=2) / max(1, size(m))
      end associate
    case (HISTORY_NSET_RF)
      values = sum(reaction(:, model%mesh%node_sets(target)%members), dim=2)
    case (HISTORY_CONTACT)
      values = contact_values(a, target)
    case (HISTORY_RESIDUAL)
      values = [a%state%residual_norm]
    case default
      values = [strain_energy(this, a%elements, a%state%elements), a%contact%frictional_work(a%state%contact)]
    end select
  end function item_values

  !> Totals of contact pair k: forces, counts, slip, slip rate, mean tractions of closed nodes.
  function contact_values(a, k) result(values)
    type(analysis_t), intent(in) :: a
    integer, intent(in) :: k
    real(dp) :: values(12)
    type(pair_totals_t) :: t
    t = a%contact%totals(k, a%x_contact, a%state%contact)
    values = [t%normal_force, t%tangential_force, real(t%n_stick + t%n_tied, dp), real(t%n_slip, dp), &
              real(t%n_open, dp), t%slip_mean, t%slip_max, t%rate_max, t%pressure_mean, t%shear_mean]
  end function contact_values

  !> 1/2 sum sigma:eps_e dV over the integration points (reference volumes; the elastic strain
  !> energy at small strains), eps_e = eps - eps_p the elastic part of the strain when a
  !> material is plastic.
  real(dp) function strain_energy(this, elements, fields)
    type(monitors_t), intent(in) :: this
    type(element_loops_t), intent(in) :: elements
    type(element_state_t), intent(in) :: fields
    real(dp), allocatable :: peeq(:, :), plastic_strain(:, :, :), back_stress(:, :, :)
    if (elements%has_states()) then
      call elements%plastic_fields(fields, peeq, plastic_strain, back_stress)
      strain_energy = 0.5_dp * sum(sum(fields%stress * (fields%strain - plastic_strain), dim=1) * &
                                   this%volume)
    else
      strain_energy = 0.5_dp * sum(sum(fields%stress * fields%strain, dim=1) * this%volume)
    end if
  end function strain_energy

  !> Feed the event catalog after an increment that started at t_start; log ended events.
  subroutine monitors_watch_events(this, model, a, t_start, log, err)
    class(monitors_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(analysis_t), intent(in) :: a
    real(dp), intent(in) :: t_start
    type(logger_t), intent(inout) :: log
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: rate(:), slip(:), shear(:)
    integer, allocatable :: nodes(:)
    integer :: k, ended
    if (.not. this%catalog_on) return
    do k = 1, a%contact%n_pairs()
      if (a%contact%pair_is_tied(k)) cycle
      nodes = a%contact%pair_slave_nodes(k)
      call a%contact%pair_slip(k, a%x_contact, a%state%contact, rate, slip, shear)
      call this%catalog%update(k, t_start, a%state%time, rate, slip, shear, model%mesh%node_id(nodes), &
                               a%x_contact(:, nodes), ended, err)
      if (allocated(err)) return
      if (ended > 0) then
        associate (e => this%catalog%events(ended))
          call log%info('slip event ' // str(ended) // ' on ' // a%contact%pair_name(k) // ': ' // &
            'onset ' // str(e%onset) // ', end ' // str(e%finish) // ', ' // str(e%n_nodes) // &
            ' nodes, peak slip rate ' // str(e%peak_rate) // ', largest slip ' // str(e%max_slip) // &
            ', mean stress drop ' // str(e%stress_drop) // ', hypocentre node ' // str(e%hypocentre))
        end associate
      end if
    end do
  end subroutine monitors_watch_events

  !> At the end of a run: say in the log which pairs have a slip event under way. Such an
  !> event is not catalogued (its end is unknown); the checkpoint holds it, so a restart with
  !> added steps completes it (doc/restart.md, "Event catalog").
  subroutine monitors_report_open_events(this, contact, log)
    class(monitors_t), intent(in) :: this
    type(contact_system_t), intent(in) :: contact
    type(logger_t), intent(inout) :: log
    integer :: k
    if (.not. this%catalog_on) return
    do k = 1, size(this%catalog%watch)
      associate (w => this%catalog%watch(k))
        if (.not. w%active) cycle
        call log%info('slip event under way on ' // contact%pair_name(k) // ' at the end ' // &
          'of the run (onset ' // str(w%event%onset) // ', ' // str(count(w%involved)) // &
          ' nodes so far, hypocentre node ' // str(w%event%hypocentre) // '): not in the ' // &
          'catalog; a restart with added steps completes it')
      end associate
    end do
  end subroutine monitors_report_open_events

end module fcs_monitors
