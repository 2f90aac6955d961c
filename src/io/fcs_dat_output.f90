!> Text tables of results in `<job>.dat`, in CalculiX's layout (ccx 2.20: "displacements
!> (vx,vy,vz) for set X and time t" blocks), so that printed results of classic decks can be
!> compared line by line with CalculiX's.
!>
!> Conventions: forces (RF) are the reactions at prescribed degrees of freedom and, as
!> CalculiX prints them, the internal forces (the applied load) at free ones (the caller
!> computes them: fcs_static_explicit, current_reactions); strains are printed as tensor
!> components (exy = gamma_xy / 2), as CalculiX. Rows are in ascending id order.
module fcs_dat_output
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  use fcs_model, only: model_t, output_request_t, TOTALS_NO, TOTALS_ONLY
  use fcs_sort, only: argsort_integers
  use fcs_hex8_shape, only: N_GAUSS_HEX8
  use fcs_contact_system, only: contact_system_t
  use fcs_contact_state, only: contact_state_t
  use fcs_contact_element, only: CONTACT_OPEN
  implicit none
  private
  public :: dat_file_t

  type :: dat_file_t
    integer :: unit = -1
  contains
    procedure :: open => dat_open
    procedure :: close => dat_close
    procedure :: node_print => dat_node_print
    procedure :: el_print => dat_el_print
    procedure :: contact_print => dat_contact_print
  end type dat_file_t

contains

  subroutine dat_open(this, path, err, append)
    class(dat_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: append
    integer :: stat
    character(len=256) :: msg
    logical :: appending
    appending = .false.
    if (present(append)) appending = append
    ! A new run replaces an earlier run's file at once: opened without status='replace', the
    ! old contents would stay until the first table is written, and a checkpoint written
    ! before that would record their size as this run's (a restart then kept them).
    if (appending) then
      open (newunit=this%unit, file=path, action='write', position='append', iostat=stat, &
            iomsg=msg)
    else
      open (newunit=this%unit, file=path, action='write', status='replace', iostat=stat, &
            iomsg=msg)
    end if
    if (stat /= 0) call fatal_error(err, 'opening ' // path // ': ' // trim(msg))
  end subroutine dat_open

  subroutine dat_close(this)
    class(dat_file_t), intent(inout) :: this
    if (this%unit /= -1) close (this%unit)
    this%unit = -1
  end subroutine dat_close

  !> *NODE PRINT: U and/or RF (and totals) of the request's node set.
  subroutine dat_node_print(this, model, request, time, u, rf)
    class(dat_file_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(output_request_t), intent(in) :: request
    real(dp), intent(in) :: time, u(:, :), rf(:, :)
    integer :: v
    integer, allocatable :: nodes(:)
    associate (set => model%mesh%node_sets(request%set))
      nodes = set%members(argsort_integers(model%mesh%node_id(set%members)))
      do v = 1, size(request%variables)
        select case (request%variables(v)%s)
        case ('U')
          call node_block(this%unit, 'displacements (vx,vy,vz)', set%name, time, model, nodes, u, &
                          request%totals)
        case ('RF')
          call node_block(this%unit, 'forces (fx,fy,fz)', set%name, time, model, nodes, rf, &
                          request%totals)
        end select
      end do
    end associate
    flush (this%unit)
  end subroutine dat_node_print

  subroutine node_block(unit, title, set_name, time, model, nodes, values, totals)
    integer, intent(in) :: unit, totals
    character(len=*), intent(in) :: title, set_name
    real(dp), intent(in) :: time, values(:, :)
    type(model_t), intent(in) :: model
    integer, intent(in) :: nodes(:)
    integer :: i
    if (totals /= TOTALS_ONLY) then
      call header(unit, title, set_name, time)
      do i = 1, size(nodes)
        write (unit, '(i10,3es14.6)') model%mesh%node_id(nodes(i)), values(:, nodes(i))
      end do
    end if
    if (totals /= TOTALS_NO .and. index(title, 'forces') == 1) then
      call header(unit, 'total force (fx,fy,fz)', set_name, time)
      write (unit, '(6x,3es14.6)') sum(values(:, nodes), dim=2)
    end if
  end subroutine node_block

  !> *EL PRINT: S, E and/or PEEQ (PE) at the integration points of the request's element set;
  !> peeq(q, e) is the equivalent plastic strain. CalculiX prints PE and PEEQ alike, as one
  !> column under the header "equivalent plastic strain (elem, integ.pnt.,pe)for set ..."
  !> (without a blank before "for", as ccx 2.20 writes it).
  subroutine dat_el_print(this, model, request, time, stress, strain, peeq)
    class(dat_file_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(output_request_t), intent(in) :: request
    real(dp), intent(in) :: time, stress(:, :, :), strain(:, :, :), peeq(:, :)
    integer :: v, i, q, e
    integer, allocatable :: elements(:)
    real(dp) :: tensor_strain(6)
    associate (set => model%mesh%element_sets(request%set))
      elements = set%members(argsort_integers(model%mesh%element_id(set%members)))
      do v = 1, size(request%variables)
        select case (request%variables(v)%s)
        case ('S')
          call header(this%unit, 'stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)', &
                      set%name, time)
          do i = 1, size(elements)
            e = elements(i)
            do q = 1, N_GAUSS_HEX8
              write (this%unit, '(i10,i4,6es14.6)') model%mesh%element_id(e), q, stress(:, q, e)
            end do
          end do
        case ('E')
          call header(this%unit, 'strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)', &
                      set%name, time)
          do i = 1, size(elements)
            e = elements(i)
            do q = 1, N_GAUSS_HEX8
              tensor_strain = strain(:, q, e)
              tensor_strain(4:6) = 0.5_dp * tensor_strain(4:6)
              write (this%unit, '(i10,i4,6es14.6)') model%mesh%element_id(e), q, tensor_strain
            end do
          end do
        case ('PEEQ', 'PE')
          write (this%unit, '(a)') ''
          write (this%unit, '(a,e14.7)') ' equivalent plastic strain (elem, integ.pnt.,pe)for set ' // &
            set%name // ' and time ', time
          write (this%unit, '(a)') ''
          do i = 1, size(elements)
            e = elements(i)
            do q = 1, N_GAUSS_HEX8
              write (this%unit, '(i10,i4,es14.6)') model%mesh%element_id(e), q, peeq(q, e)
            end do
          end do
        end select
      end do
    end associate
    flush (this%unit)
  end subroutine dat_el_print

  !> *CONTACT PRINT: CDIS and/or CSTR of every closed contact node (all pairs), as CalculiX
  !> prints them ("for all contact elements").
  subroutine dat_contact_print(this, model, request, time, contact, cstate, x)
    class(dat_file_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    type(output_request_t), intent(in) :: request
    real(dp), intent(in) :: time, x(:, :)
    type(contact_system_t), intent(in) :: contact
    type(contact_state_t), intent(in) :: cstate
    integer, allocatable :: order(:)
    real(dp) :: displacement(3), stress(3)
    integer :: v, i, s
    order = argsort_integers(model%mesh%node_id(contact%slave_node))
    do v = 1, size(request%variables)
      write (this%unit, '(a)') ''
      if (request%variables(v)%s == 'CDIS') then
        write (this%unit, '(a,e14.7)') ' relative contact displacement (slave node,normal,tang1,' // &
          'tang2) for all contact elements and time', time
      else
        write (this%unit, '(a,e14.7)') ' contact stress (slave node,press,tang1,tang2) for all ' // &
          'contact elements and time', time
      end if
      write (this%unit, '(a)') ''
      do i = 1, size(order)
        s = order(i)
        if (cstate%status(s) == CONTACT_OPEN) cycle
        call contact%local_values(s, x, cstate, displacement, stress)
        if (request%variables(v)%s == 'CDIS') then
          write (this%unit, '(i10,3es14.6)') model%mesh%node_id(contact%slave_node(s)), displacement
        else
          write (this%unit, '(i10,3es14.6)') model%mesh%node_id(contact%slave_node(s)), stress
        end if
      end do
    end do
    flush (this%unit)
  end subroutine dat_contact_print

  subroutine header(unit, title, set_name, time)
    integer, intent(in) :: unit
    character(len=*), intent(in) :: title, set_name
    real(dp), intent(in) :: time
    write (unit, '(a)') ''
    write (unit, '(a,e14.7)') ' ' // title // ' for set ' // set_name // ' and time ', time
    write (unit, '(a)') ''
  end subroutine header

end module fcs_dat_output
