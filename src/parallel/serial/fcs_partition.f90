!> Partition of the elements over the processes, serial build: everything on rank 0.
!> The MPI build partitions with METIS (src/parallel/mpi/fcs_partition.f90).
module fcs_partition
  use fcs_error, only: error_t
  use fcs_comm, only: comm_t
  implicit none
  private
  public :: partition_elements

contains

  !> Owner rank (0-based) of every element.
  subroutine partition_elements(comm, connectivity, n_nodes, owner, err)
    type(comm_t), intent(in) :: comm
    integer, intent(in) :: connectivity(:, :), n_nodes
    integer, allocatable, intent(out) :: owner(:)
    type(error_t), allocatable, intent(out) :: err
    allocate (owner(size(connectivity, 2)))
    owner = 0
  end subroutine partition_elements

end module fcs_partition
