!> Matching of quadrilaterals (given by their four nodes) to the faces of 8-node hexahedra, as
!> needed to turn the boundary quads of a mesh generator into element-face surfaces. The faces
!> of the hexahedron are data the caller gives (the mesh's kind, fcs_mesh).
!>
!> A hash table of the quads, keyed by their sorted node numbers, is built once and probed with
!> each of the six faces of every hexahedron: O(n_quads + n_hexahedra) time, O(n_quads) memory.
module fcs_hex_face_match
  use fcs_kinds, only: i8
  implicit none
  private
  public :: match_quads_to_hex_faces

contains

  !> For each quad `quads(:, q)` (four node numbers), find the hexahedron `hexahedra(:, k)`
  !> (eight node numbers in C3D8 order) having a face with the same four nodes, and that face
  !> (1..6, face f having the local nodes `faces(:, f)`, outward by the right-hand rule).
  !> `matches(q)` counts the faces found: 1 on the
  !> boundary; 2 on a face shared by two hexahedra, where the face of the hexahedron out of which
  !> the quad's own normal (right-hand rule on its node order) points is chosen; 0 if none, with
  !> `hexahedron(q)` = `face(q)` = 0. Node numbers must be positive.
  subroutine match_quads_to_hex_faces(faces, hexahedra, quads, hexahedron, face, matches)
    integer, intent(in) :: faces(:, :), hexahedra(:, :), quads(:, :)
    integer, allocatable, intent(out) :: hexahedron(:), face(:), matches(:)
    integer, allocatable :: keys(:, :), slots(:), next_same(:)
    integer :: q, k, f, n, capacity, face_nodes(4)
    n = size(quads, 2)
    allocate (hexahedron(n), face(n), matches(n))
    hexahedron = 0
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
      keys(:, q) = sorted4(quads(:, q))
      call insert_quad(keys, slots, next_same, q)
    end do
    do k = 1, size(hexahedra, 2)
      do f = 1, size(faces, 2)
        face_nodes = hexahedra(faces(:, f), k)
        q = find_quad(keys, slots, sorted4(face_nodes))
        do while (q /= 0)
          matches(q) = matches(q) + 1
          if (matches(q) == 1 .or. orientation(face_nodes, quads(:, q)) == 1) then
            hexahedron(q) = k
            face(q) = f
          end if
          q = next_same(q)
        end do
      end do
    end do
  end subroutine match_quads_to_hex_faces

  !> Insert quad `q` (key in keys(:, q)) into the open-addressing table `slots`; quads with the
  !> same nodes are chained through `next_same`.
  subroutine insert_quad(keys, slots, next_same, q)
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
  end subroutine insert_quad

  !> First quad with sorted nodes `key`, 0 if none.
  pure integer function find_quad(keys, slots, key) result(q)
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
  end function find_quad

  !> Hash of four sorted node numbers into 0..capacity-1 (capacity a power of two). The
  !> products stay below 2**52, so no 64-bit overflow.
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

  !> +1 if `b` runs around the same 4-cycle as `a` in the same direction, -1 if in the
  !> opposite direction, 0 otherwise.
  pure integer function orientation(a, b)
    integer, intent(in) :: a(4), b(4)
    integer :: p, j
    orientation = 0
    p = findloc(a, b(1), dim=1)
    if (p == 0) return
    if (all([(b(j) == a(modulo(p - 1 + j - 1, 4) + 1), j = 1, 4)])) orientation = 1
    if (all([(b(j) == a(modulo(p - 1 - (j - 1), 4) + 1), j = 1, 4)])) orientation = -1
  end function orientation

end module fcs_hex_face_match
