!> *CONTACT PAIR, ADJUST=: slave nodes moved onto the master surface before the analysis, as
!> CalculiX 2.20 does (adjustcontactnodes.f for surface-to-surface pairs, the same test in
!> gencontelem_n2f.f for node-to-surface ones): in the first increment of the first step,
!> each slave node whose master face is found is moved by -g n onto it (g: signed distance
!> along the master normal n, positive open), when g <= ADJUST (ADJUST=<clearance>; a
!> penetrating node, g < 0, is always moved) or when the node is in the node set
!> (ADJUST=<node set>). The reference coordinates change: the moved node starts stress-free
!> on the master (doc/theory.md 4.13).
!>
!> fcs3d moves the node to its closest-point projection on the master face (the same point
!> as -g n on a flat face; CalculiX projects onto the plane of a triangle of its
!> triangulated master surface). A node whose projection lies on no master face (past the
!> border of the master surface) is not moved, as in CalculiX ("border reached").
module fcs_contact_adjust
  use fcs_kinds, only: dp
  use fcs_mesh, only: mesh_t
  use fcs_contact_pair, only: contact_pair_def_t
  use fcs_contact_geometry, only: segment_point_t
  use fcs_contact_search, only: face_grid_t, closest_face, edge_excess, XI_TOLERANCE, face_node_count
  implicit none
  private
  public :: adjust_report_t, adjust_pair_nodes

  !> What the adjustment of one pair did.
  type :: adjust_report_t
    !> Slave nodes moved, and the largest move [length] with its node (index, 0: none).
    integer :: moved = 0
    real(dp) :: largest = 0.0_dp
    integer :: largest_node = 0
  end type adjust_report_t

contains

  !> Move the slave nodes of pair `def` onto its master surface (mesh%x changes) when
  !> def%adjust_distance >= 0 (nodes with signed gap <= it) or def%adjust_set > 0 (the slave
  !> nodes of that node set).
  subroutine adjust_pair_nodes(def, mesh, report)
    type(contact_pair_def_t), intent(in) :: def
    type(mesh_t), intent(inout) :: mesh
    type(adjust_report_t), intent(out) :: report
    integer, allocatable :: face_nodes(:, :), slaves(:), candidates(:)
    type(face_grid_t) :: grid
    type(segment_point_t) :: point
    real(dp) :: gap, margin, move
    integer :: i, node, face
    if (def%adjust_distance < 0.0_dp .and. def%adjust_set == 0) return
    face_nodes = master_faces(def, mesh)
    slaves = mesh%surface_node_list(def%slave_surface)
    if (def%adjust_set > 0) slaves = pack(slaves, in_sorted(slaves, mesh%node_sets(def%adjust_set)%members))
    margin = max(def%adjust_distance, mean_face_size(face_nodes, mesh%x))
    call grid%build(face_coordinates(face_nodes, mesh%x), margin)
    do i = 1, size(slaves)
      node = slaves(i)
      if (def%adjust_set > 0) then
        candidates = [(face, face = 1, size(face_nodes, 2))]
      else
        call grid%candidates(mesh%x(:, node), candidates)
      end if
      if (size(candidates) == 0) cycle
      call closest_face(face_nodes, mesh%x, candidates, mesh%x(:, node), huge(1.0_dp), face, point, gap)
      if (face == 0) cycle
      if (any(edge_excess(point%xi, face_node_count(face_nodes(:, face))) > XI_TOLERANCE)) cycle
      if (def%adjust_set == 0 .and. gap > def%adjust_distance) cycle
      move = norm2(point%x - mesh%x(:, node))
      mesh%x(:, node) = point%x
      report%moved = report%moved + 1
      if (move > report%largest .or. report%largest_node == 0) then
        report%largest = move
        report%largest_node = node
      end if
    end do
  end subroutine adjust_pair_nodes

  !> Node indices of the master faces, one column per face (padded with 0).
  function master_faces(def, mesh) result(face_nodes)
    type(contact_pair_def_t), intent(in) :: def
    type(mesh_t), intent(in) :: mesh
    integer, allocatable :: face_nodes(:, :)
    integer, allocatable :: nodes(:)
    integer :: f, width
    associate (surface => mesh%surfaces(def%master_surface))
      width = 0
      do f = 1, size(surface%element)
        width = max(width, size(mesh%face_nodes(surface%element(f), surface%face(f))))
      end do
      allocate (face_nodes(width, size(surface%element)))
      face_nodes = 0
      do f = 1, size(surface%element)
        nodes = mesh%face_nodes(surface%element(f), surface%face(f))
        face_nodes(1:size(nodes), f) = nodes
      end do
    end associate
  end function master_faces

  !> Coordinates (3, nodes per face, faces); a shorter face repeats its first node.
  pure function face_coordinates(face_nodes, x) result(face_x)
    integer, intent(in) :: face_nodes(:, :)
    real(dp), intent(in) :: x(:, :)
    real(dp) :: face_x(3, size(face_nodes, 1), size(face_nodes, 2))
    integer :: f, a
    do f = 1, size(face_nodes, 2)
      do a = 1, size(face_nodes, 1)
        face_x(:, a, f) = x(:, face_nodes(merge(a, 1, face_nodes(a, f) /= 0), f))
      end do
    end do
  end function face_coordinates

  !> Mean distance between a face's first corner and its farthest corner (the search margin
  !> for penetrating nodes: those deeper than about a face are not found).
  pure real(dp) function mean_face_size(face_nodes, x) result(size_mean)
    integer, intent(in) :: face_nodes(:, :)
    real(dp), intent(in) :: x(:, :)
    integer :: f, a
    real(dp) :: longest
    size_mean = 0.0_dp
    do f = 1, size(face_nodes, 2)
      longest = 0.0_dp
      do a = 2, face_node_count(face_nodes(:, f))
        longest = max(longest, norm2(x(:, face_nodes(a, f)) - x(:, face_nodes(1, f))))
      end do
      size_mean = size_mean + longest
    end do
    size_mean = size_mean / max(1, size(face_nodes, 2))
  end function mean_face_size

  !> For each of `values`, whether it is in the sorted list `members`.
  pure function in_sorted(values, members) result(found)
    integer, intent(in) :: values(:), members(:)
    logical :: found(size(values))
    integer :: i, lo, hi, mid
    do i = 1, size(values)
      found(i) = .false.
      lo = 1
      hi = size(members)
      do while (lo <= hi)
        mid = (lo + hi) / 2
        if (members(mid) == values(i)) then
          found(i) = .true.
          exit
        else if (members(mid) < values(i)) then
          lo = mid + 1
        else
          hi = mid - 1
        end if
      end do
    end do
  end function in_sorted

end module fcs_contact_adjust
