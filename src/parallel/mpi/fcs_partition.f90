!> Partition of the elements over the processes with METIS (Karypis & Kumar 1998), through
!> METIS_PartMeshDual on the element dual graph (elements sharing a face, 4 nodes, are
!> neighbours). Computed on rank 0 and broadcast, so that every rank has the same partition
!> whatever the library's internals; METIS's default options use a fixed seed, so the
!> partition, and with it the results, are the same from run to run.
module fcs_partition
  use, intrinsic :: iso_c_binding, only: c_int, c_ptr, c_null_ptr
  use fcs_error, only: error_t, fatal_error
  use fcs_comm, only: comm_t
  use fcs_strings, only: str
  implicit none
  private
  public :: partition_elements

  !> METIS_OK from metis.h (METIS 5.1.0, Debian libmetis-dev; idx_t is a 32-bit int there).
  integer(c_int), parameter :: METIS_OK = 1

  interface
    function metis_part_mesh_dual(ne, nn, eptr, eind, vwgt, vsize, ncommon, nparts, tpwgts, &
                                  options, objval, epart, npart) bind(c, name='METIS_PartMeshDual') &
                                  result(status)
      import :: c_int, c_ptr
      integer(c_int), intent(in) :: ne, nn, ncommon, nparts
      integer(c_int), intent(in) :: eptr(*), eind(*)
      type(c_ptr), value :: vwgt, vsize, tpwgts, options
      integer(c_int), intent(out) :: objval
      integer(c_int), intent(out) :: epart(*), npart(*)
      integer(c_int) :: status
    end function metis_part_mesh_dual
  end interface

contains

  !> Owner rank (0-based) of every element; connectivity(:, e) holds the nodes of element e,
  !> padded with 0.
  subroutine partition_elements(comm, connectivity, n_nodes, owner, err)
    type(comm_t), intent(in) :: comm
    integer, intent(in) :: connectivity(:, :), n_nodes
    integer, allocatable, intent(out) :: owner(:)
    type(error_t), allocatable, intent(out) :: err
    integer(c_int), allocatable :: eptr(:), eind(:), epart(:), npart(:)
    integer(c_int) :: objval, status
    integer :: ne, e, flag(1)
    ne = size(connectivity, 2)
    allocate (owner(ne))
    owner = 0
    if (comm%size == 1) return
    status = METIS_OK
    if (comm%is_root()) then
      if (ne < comm%size) then
        owner = [(mod(e - 1, comm%size), e = 1, ne)]
      else
        ! Elements of any kind: the nodes of element e are its nonzero connectivity entries
        ! (shorter elements are padded with 0).
        allocate (eptr(ne + 1), epart(ne), npart(n_nodes))
        eptr(1) = 0
        do e = 1, ne
          eptr(e + 1) = eptr(e) + int(count(connectivity(:, e) > 0), c_int)
        end do
        eind = int(pack(connectivity, connectivity > 0) - 1, c_int)
        status = metis_part_mesh_dual(int(ne, c_int), int(n_nodes, c_int), eptr, eind, c_null_ptr, &
          c_null_ptr, 4_c_int, int(comm%size, c_int), c_null_ptr, c_null_ptr, objval, epart, npart)
        owner = int(epart)
      end if
    end if
    call comm%broadcast_int(owner, 0)
    flag = [int(status)]
    call comm%broadcast_int(flag, 0)
    status = int(flag(1), c_int)
    if (status /= METIS_OK) call fatal_error(err, 'METIS_PartMeshDual failed (status ' // &
                                             str(int(status)) // ') partitioning ' // str(ne) // ' elements')
  end subroutine partition_elements

end module fcs_partition
