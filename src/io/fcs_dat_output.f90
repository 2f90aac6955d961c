!> Text tables of results in `<job>.dat`, in CalculiX's layout (ccx 2.20: "displacements
!> (vx,vy,vz) for set X and time t" blocks), so that printed results of classic decks can be
!> compared line by line with CalculiX's.
!>
!> Conventions: forces (RF) are the reactions at prescribed degrees of freedom and, as
!> CalculiX prints them, the internal forces (the applied load) at free ones (the caller
!> computes them: fcs_static_explicit, current_reactions); strains are printed as tensor
!> components (exy = gamma_xy / 2), as CalculiX; PE and PEEQ print the equivalent plastic
!> strain under CalculiX's header. Rows are in ascending id order.
!>
!> Each print request is one block, committed whole (fcs_text_file): a failed write leaves the
!> file ending with the last complete block and returns the error.
module fcs_dat_output
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_text_file, only: text_file_t
  use fcs_model, only: model_t, output_request_t, TOTALS_NO, TOTALS_ONLY
  use fcs_sort, only: argsort_integers
  implicit none
  private
  public :: dat_file_t

  type :: dat_file_t
    type(text_file_t) :: file
  contains
    procedure :: open => dat_open
    procedure :: close => dat_close
    procedure :: node_print => dat_node_print
    procedure :: el_print => dat_el_print
    procedure :: contact_print => dat_contact_print
  end type dat_file_t

contains

  !> Open `path` (replaced, or appended to when `append`).
  subroutine dat_open(this, path, err, append)
    class(dat_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: append
    call this%file%open(path, err, append=append)
  end subroutine dat_open

  subroutine dat_close(this, err)
    class(dat_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    call this%file%close(err)
  end subroutine dat_close

  !> *NODE PRINT: U, RF (and totals) and/or NT of the request's node set; NT prints the nodal
  !> `temperature` (0 for a model without temperatures, as CalculiX prints it).
  subroutine dat_node_print(this, model, request, time, u, rf, err, temperature)
    class(dat_file_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(output_request_t), intent(in) :: request
    real(dp), intent(in) :: time, u(:, :), rf(:, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp), intent(in), optional :: temperature(:)
    real(dp), allocatable :: nt(:, :)
    integer :: v
    integer, allocatable :: nodes(:)
    associate (set => model%mesh%node_sets(request%set))
      nodes = set%members(argsort_integers(model%mesh%node_id(set%members)))
      do v = 1, size(request%variables)
        select case (request%variables(v)%s)
        case ('U')
          call node_block(this%file, 'displacements (vx,vy,vz)', set%name, time, model, nodes, u, &
                          request%totals, request%global, err)
        case ('RF')
          call node_block(this%file, 'forces (fx,fy,fz)', set%name, time, model, nodes, rf, &
                          request%totals, request%global, err)
        case ('NT')
          allocate (nt(1, size(u, 2)))
          nt = 0.0_dp
          if (present(temperature)) nt(1, :) = temperature
          ! A scalar: no local axes.
          call node_block(this%file, 'temperatures', set%name, time, model, nodes, nt, &
                          TOTALS_NO, .true., err)
          deallocate (nt)
        end select
        if (allocated(err)) return
      end do
    end associate
    call this%file%commit(err)
  end subroutine dat_node_print

  subroutine node_block(file, title, set_name, time, model, nodes, values, totals, global, err)
    type(text_file_t), intent(inout) :: file
    character(len=*), intent(in) :: title, set_name
    real(dp), intent(in) :: time, values(:, :)
    type(model_t), intent(in) :: model
    integer, intent(in) :: nodes(:), totals
    !> Global axes at every node (GLOBAL=YES); else local ones where a node has them.
    logical, intent(in) :: global
    type(error_t), allocatable, intent(out) :: err
    character(len=64) :: line
    integer :: i
    logical :: frames
    frames = .false.
    if (allocated(model%transformed) .and. .not. global) frames = any(model%transformed)
    if (totals /= TOTALS_ONLY) then
      call header(file, title, set_name, time, err)
      do i = 1, size(nodes)
        if (allocated(err)) return
        ! A node with local axes (*TRANSFORM) is printed in them, marked L, as CalculiX does.
        if (in_local_axes(frames, model, nodes(i))) then
          write (line, '(i10,3es14.6,a)') model%mesh%node_id(nodes(i)), &
            matmul(transpose(model%node_frame(:, :, nodes(i))), values(:, nodes(i))), ' L'
        else
          write (line, '(i10,3es14.6)') model%mesh%node_id(nodes(i)), values(:, nodes(i))
        end if
        call file%write(trim(line), err)
      end do
    end if
    if (allocated(err)) return
    if (totals /= TOTALS_NO .and. index(title, 'forces') == 1) then
      call header(file, 'total force (fx,fy,fz)', set_name, time, err)
      if (allocated(err)) return
      write (line, '(6x,3es14.6)') sum(values(:, nodes), dim=2)
      call file%write(trim(line), err)
    end if
  end subroutine node_block

  !> True when `node` has local axes and they are printed (`frames`).
  logical function in_local_axes(frames, model, node)
    logical, intent(in) :: frames
    type(model_t), intent(in) :: model
    integer, intent(in) :: node
    in_local_axes = .false.
    if (frames) in_local_axes = model%transformed(node)
  end function in_local_axes

  !> *EL PRINT: S, E, PEEQ (PE), ENER and/or ELSE at the integration points (ELSE: per element)
  !> of the request's element set; peeq(q, e) is the equivalent plastic strain; element e has
  !> n_points(e) integration points of volume volume(q, e) (needed for ELSE only). ENER is the
  !> energy density 1/2 S:(E - E_th) (engineering shears; E_th the thermal strain, when given),
  !> which for an elastic material is CalculiX's internal energy density (the elastic strain
  !> energy at the current temperature's constants; exact for linear elasticity at small
  !> strain), ELSE its integral over the element (sum of ENER x point volume), as CalculiX's
  !> "internal energy (element, energy)"; the input refuses both with plasticity
  !> (fcs_build_output). With `energy_stress`, ENER and ELSE take it instead of `stress` (the
  !> second Piola-Kirchhoff stress of St Venant-Kirchhoff points under NLGEOM, whose strain is
  !> Green-Lagrange: CalculiX's energy per reference volume).
  subroutine dat_el_print(this, model, request, time, stress, strain, peeq, n_points, volume, err, &
                          thermal_strain, energy_stress)
    class(dat_file_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(output_request_t), intent(in) :: request
    real(dp), intent(in) :: time, stress(:, :, :), strain(:, :, :), peeq(:, :), volume(:, :)
    integer, intent(in) :: n_points(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), intent(in), optional :: thermal_strain(:, :, :), energy_stress(:, :, :)
    real(dp), allocatable :: elastic(:, :, :), conjugate(:, :, :)
    character(len=32) :: stamp
    integer :: v
    integer, allocatable :: elements(:)
    elastic = strain
    if (present(thermal_strain)) elastic = strain - thermal_strain
    if (present(energy_stress)) then
      conjugate = energy_stress
    else
      conjugate = stress
    end if
    associate (set => model%mesh%element_sets(request%set))
      elements = set%members(argsort_integers(model%mesh%element_id(set%members)))
      do v = 1, size(request%variables)
        select case (request%variables(v)%s)
        case ('S')
          call header(this%file, 'stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)', &
                      set%name, time, err)
          if (.not. allocated(err)) call ip_rows(this%file, model, elements, n_points, stress, .false., &
                                                 .not. request%global, err)
        case ('E')
          call header(this%file, 'strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)', &
                      set%name, time, err)
          if (.not. allocated(err)) call ip_rows(this%file, model, elements, n_points, strain, .true., &
                                                 .not. request%global, err)
        case ('PEEQ', 'PE')
          ! ccx 2.20 writes this header without a blank before "for".
          write (stamp, '(e14.7)') time
          call this%file%write('', err)
          if (.not. allocated(err)) call this%file%write(' equivalent plastic strain (elem, ' // &
            'integ.pnt.,pe)for set ' // set%name // ' and time ' // trim(stamp), err)
          if (.not. allocated(err)) call this%file%write('', err)
          if (.not. allocated(err)) call point_rows(this%file, model, elements, n_points, peeq, err)
        case ('ENER')
          call header(this%file, 'internal energy density (elem, integ.pnt.,energy)', &
                      set%name, time, err)
          if (.not. allocated(err)) call point_rows(this%file, model, elements, n_points, &
            energy_density(conjugate, elastic), err)
        case ('ELSE')
          call header(this%file, 'internal energy (element, energy)', set%name, time, err)
          if (.not. allocated(err)) call element_energy_rows(this%file, model, elements, &
            n_points, energy_density(conjugate, elastic) * volume, err)
        end select
        if (allocated(err)) return
      end do
    end associate
    call this%file%commit(err)
  end subroutine dat_el_print

  !> 1/2 S:E at every integration point (strain with engineering shears).
  pure function energy_density(stress, strain) result(density)
    real(dp), intent(in) :: stress(:, :, :), strain(:, :, :)
    real(dp) :: density(size(stress, 2), size(stress, 3))
    density = 0.5_dp * sum(stress * strain, dim=1)
  end function energy_density

  !> One row per element of `elements`: the sum of its points' energies.
  subroutine element_energy_rows(file, model, elements, n_points, energy, err)
    type(text_file_t), intent(inout) :: file
    type(model_t), intent(in) :: model
    integer, intent(in) :: elements(:), n_points(:)
    real(dp), intent(in) :: energy(:, :)
    type(error_t), allocatable, intent(out) :: err
    character(len=64) :: line
    integer :: i, e
    do i = 1, size(elements)
      e = elements(i)
      write (line, '(i10,es14.6)') model%mesh%element_id(e), sum(energy(1:n_points(e), e))
      call file%write(trim(line), err)
      if (allocated(err)) return
    end do
  end subroutine element_energy_rows

  !> One row per integration point of `elements`: a scalar (the equivalent plastic strain, the
  !> energy density).
  subroutine point_rows(file, model, elements, n_points, peeq, err)
    type(text_file_t), intent(inout) :: file
    type(model_t), intent(in) :: model
    integer, intent(in) :: elements(:), n_points(:)
    real(dp), intent(in) :: peeq(:, :)
    type(error_t), allocatable, intent(out) :: err
    character(len=64) :: line
    integer :: i, q, e
    do i = 1, size(elements)
      e = elements(i)
      do q = 1, n_points(e)
        write (line, '(i10,i4,es14.6)') model%mesh%element_id(e), q, peeq(q, e)
        call file%write(trim(line), err)
        if (allocated(err)) return
      end do
    end do
  end subroutine point_rows

  !> One row per integration point of `elements`; `tensor_shear` halves the shear components
  !> (engineering to tensor strains). With `local` (*EL PRINT, GLOBAL=NO) the rows of
  !> elements with an *ORIENTATION (whose values the caller gives in its axes) end with the
  !> orientation's name, as CalculiX writes them.
  subroutine ip_rows(file, model, elements, n_points, values, tensor_shear, local, err)
    type(text_file_t), intent(inout) :: file
    type(model_t), intent(in) :: model
    integer, intent(in) :: elements(:), n_points(:)
    real(dp), intent(in) :: values(:, :, :)
    logical, intent(in) :: tensor_shear, local
    type(error_t), allocatable, intent(out) :: err
    character(len=160) :: line
    character(len=:), allocatable :: label
    real(dp) :: row(6)
    integer :: i, q, e, k
    do i = 1, size(elements)
      e = elements(i)
      label = ''
      if (local .and. size(model%orientations) > 0) then
        k = model%sections(model%element_section(e))%orientation
        if (k > 0) label = ' ' // model%orientations(k)%axes%name
      end if
      do q = 1, n_points(e)
        row = values(:, q, e)
        if (tensor_shear) row(4:6) = 0.5_dp * row(4:6)
        write (line, '(i10,i4,6es14.6)') model%mesh%element_id(e), q, row
        call file%write(trim(line) // label, err)
        if (allocated(err)) return
      end do
    end do
  end subroutine ip_rows

  !> *CONTACT PRINT: CDIS and/or CSTR of every closed contact node (all pairs), as CalculiX
  !> prints them ("for all contact elements"): for each slave entry its node index, whether it
  !> is closed, and its relative displacement and stress in the local frame of its master face
  !> (the contact system's `print_values`).
  subroutine dat_contact_print(this, model, request, time, node, closed, displacement, stress, err)
    class(dat_file_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(output_request_t), intent(in) :: request
    real(dp), intent(in) :: time, displacement(:, :), stress(:, :)
    integer, intent(in) :: node(:)
    logical, intent(in) :: closed(:)
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: order(:)
    character(len=128) :: line
    integer :: v, i, s
    order = argsort_integers(model%mesh%node_id(node))
    do v = 1, size(request%variables)
      if (request%variables(v)%s == 'CDIS') then
        write (line, '(a,e14.7)') ' relative contact displacement (slave node,normal,tang1,' // &
          'tang2) for all contact elements and time', time
      else
        write (line, '(a,e14.7)') ' contact stress (slave node,press,tang1,tang2) for all ' // &
          'contact elements and time', time
      end if
      call this%file%write('', err)
      if (.not. allocated(err)) call this%file%write(trim(line), err)
      if (.not. allocated(err)) call this%file%write('', err)
      do i = 1, size(order)
        if (allocated(err)) return
        s = order(i)
        if (.not. closed(s)) cycle
        ! An internal write (to `line`); the file write below is the checked one.
        write (line, '(i10,3es14.6)') model%mesh%node_id(node(s)), &
          merge(displacement(:, s), stress(:, s), request%variables(v)%s == 'CDIS')
        call this%file%write(trim(line), err)
      end do
      if (allocated(err)) return
    end do
    call this%file%commit(err)
  end subroutine dat_contact_print

  subroutine header(file, title, set_name, time, err)
    type(text_file_t), intent(inout) :: file
    character(len=*), intent(in) :: title, set_name
    real(dp), intent(in) :: time
    type(error_t), allocatable, intent(out) :: err
    character(len=32) :: stamp
    write (stamp, '(e14.7)') time
    call file%write('', err)
    if (.not. allocated(err)) call file%write(' ' // title // ' for set ' // set_name // &
                                              ' and time ' // trim(stamp), err)
    if (.not. allocated(err)) call file%write('', err)
  end subroutine header

end module fcs_dat_output
