!> Matching of boundary faces given by their corner nodes (triangles: 3, quadrilaterals: 4) to
!> the element faces S1..Sn of a mesh's elements of any kind, as needed to turn the surface
!> elements of a mesh generator into element-face surfaces. An element face is known by its
!> corner nodes: the first 3 (triangular faces of 3 or 6 nodes) or 4 (quadrilateral faces of 4
!> or 8 nodes) of `mesh%face_nodes(e, f)`, which run around the face so that the right-hand
!> rule gives the outward normal (fcs_mesh).
!>
!> A hash table of the faces sought, keyed by their sorted corner nodes, is built once and
!> probed with each face of every element: O(n_faces + n_elements) time, O(n_faces) memory.
module fcs_face_match
  use fcs_kinds, only: i8
  use fcs_mesh, only: mesh_t
  implicit none
  private
  public :: match_faces, face_corner_count

contains

  !> Corners of an element face of `face_size` nodes: 3 for triangles (3 or 6 nodes), 4 for
  !> quadrilaterals (4 or 8 nodes).
  pure integer function face_corner_count(face_size) result(n)
    integer, intent(in) :: face_size
    n = merge(3, 4, face_size == 3 .or. face_size == 6)
  end function face_corner_count

  !> For each face `corners(1:n_corners(q), q)` (mesh node indices), find the element among
  !> mesh elements first..last having a face with the same corners, and that face (1..n).
  !> `matches(q)` counts the faces found: 1 on the boundary; 2 on a face shared by two
  !> elements, where the face of the element out of which the given face's own normal
  !> (right-hand rule on its corner order) points is chosen; 0 if none, with `element(q)` =
  !> `face(q)` = 0. `element` holds mesh element indices.
  subroutine match_faces(mesh, first, last, corners, n_corners, element, face, matches)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: first, last
    integer, intent(in) :: corners(:, :), n_corners(:)
    integer, allocatable, intent(out) :: element(:), face(:), matches(:)
    integer, allocatable :: keys(:, :), slots(:), next_same(:)
    integer :: q, e, f, n, nc, capacity, face_corners(4)
    n = size(n_corners)
    allocate (element(n), face(n), matches(n))
    element = 0
    face = 0
    matches = 0
    if (n == 0) return
    capacity = 64
    do while (capacity < 2 * n)
      capacity = 2 * capacity
    end do
    allocate (keys(4, n), slots(0:capacity - 1), next_same(n))
    slots = 0
    next_same = 0
    do q = 1, n
      keys(:, q) = face_key(corners(1:n_corners(q), q))
      call insert_face(keys, slots, next_same, q)
    end do
    do e = first, last
      associate (kind => mesh%kinds(mesh%element_kind(e)))
        do f = 1, kind%n_faces
          nc = face_corner_count(kind%face_size(f))
          face_corners(1:nc) = mesh%connectivity(kind%face_local(1:nc, f), e)
          q = find_face(keys, slots, face_key(face_corners(1:nc)))
          do while (q /= 0)
            matches(q) = matches(q) + 1
            if (matches(q) == 1 .or. orientation(face_corners(1:nc), corners(1:n_corners(q), q)) == 1) then
              element(q) = e
              face(q) = f
            end if
            q = next_same(q)
          end do
        end do
      end associate
    end do
  end subroutine match_faces

  !> Key of a face: its 3 or 4 corners sorted ascending, padded in front with 0 to 4 values.
  pure function face_key(corners) result(key)
    integer, intent(in) :: corners(:)
    integer :: key(4)
    key = 0
    key(5 - size(corners):4) = corners
    key = sorted4(key)
  end function face_key

  !> Insert face `q` (key in keys(:, q)) into the open-addressing table `slots`; faces with the
  !> same corners are chained through `next_same`.
  subroutine insert_face(keys, slots, next_same, q)
    integer, intent(in) :: keys(:, :)
    integer, intent(inout) :: slots(0:)
    integer, intent(inout) :: next_same(:)
    integer, intent(in) :: q
    integer :: s, head
    s = face_hash(keys(:, q), size(slots))
    do
      head = slots(s)
      if (head == 0) then
        slots(s) = q
        return
      end if
      if (all(keys(:, head) == keys(:, q))) then
        next_same(q) = next_same(head)
        next_same(head) = q
        return
      end if
      s = iand(s + 1, size(slots) - 1)
    end do
  end subroutine insert_face

  !> First face with key `key`, 0 if none.
  pure integer function find_face(keys, slots, key) result(q)
    integer, intent(in) :: keys(:, :)
    integer, intent(in) :: slots(0:)
    integer, intent(in) :: key(4)
    integer :: s
    s = face_hash(key, size(slots))
    do
      q = slots(s)
      if (q == 0) return
      if (all(keys(:, q) == key)) return
      s = iand(s + 1, size(slots) - 1)
    end do
  end function find_face

  !> Hash of a key into 0..capacity-1 (capacity a power of two). The products stay below
  !> 2**52, so no 64-bit overflow.
  pure integer function face_hash(key, capacity)
    integer, intent(in) :: key(4), capacity
    integer(i8) :: h
    integer :: j
    h = 0
    do j = 1, 4
      h = modulo(h * 1000003_i8 + key(j), 2147483647_i8)
    end do
    face_hash = int(iand(h, int(capacity - 1, i8)))
  end function face_hash

  !> The four values sorted ascending.
  pure function sorted4(values) result(sorted)
    integer, intent(in) :: values(4)
    integer :: sorted(4)
    integer :: i, j, t
    sorted = values
    do i = 2, 4
      t = sorted(i)
      j = i - 1
      do while (j >= 1)
        if (sorted(j) <= t) exit
        sorted(j + 1) = sorted(j)
        j = j - 1
      end do
      sorted(j + 1) = t
    end do
  end function sorted4

  !> +1 if `b` runs around the same cycle as `a` (3 or 4 values) in the same direction, -1 if
  !> in the opposite direction, 0 otherwise.
  pure integer function orientation(a, b)
    integer, intent(in) :: a(:), b(:)
    integer :: p, j, n
    orientation = 0
    n = size(a)
    if (size(b) /= n) return
    p = findloc(a, b(1), dim=1)
    if (p == 0) return
    if (all([(b(j) == a(modulo(p - 1 + j - 1, n) + 1), j = 1, n)])) orientation = 1
    if (all([(b(j) == a(modulo(p - 1 - (j - 1), n) + 1), j = 1, n)])) orientation = -1
  end function orientation

end module fcs_face_match
