!> Tied surfaces (*TIE, PRESSURE-OVERCLOSURE=TIED) as a segment-to-segment penalty tie: the
!> relative displacement of the two surfaces is penalised over the slave surface,
!>   Pi = (k / 2) int_{Gamma_s} |u_s(x) - u_m(P(x))|^2 dA,   k = E_n (stress/length),
!> with the integrals over the overlap of every slave face with every master face taken
!> segment-wise (fcs_tie_mortar: Puso & Laursen 2004). For each face pair the stiffness is
!> k [D, -M; -M^T, E] (x the 3x3 identity) on its 4 slave and 4 master nodes, constant: the tie
!> is linear in the displacements, as CalculiX's tie constraints are. A uniform relative
!> displacement (the surfaces of a patch under uniform stress, offset by the penalty
!> compliance) is then resisted by exactly the consistent nodal forces of a uniform traction on
!> both sides, so that the tie passes the patch test on non-matching meshes; a node-to-point
!> tie (one pass, slave nodes against master points) does not (it was 15 % off).
!>
!> The tie holds the initial relative position (no initial stress, ADJUST=NO); being linear, it
!> is exact for small rotations of the tied pair only: a rigid rotation R of a pair whose tied
!> surfaces start a distance d apart is resisted by a force k |(R - I) d| per unit area.
module fcs_contact_ties
  use fcs_kinds, only: dp
  use fcs_sparse, only: sparse_matrix_t
  use fcs_tie_mortar, only: mortar_tie_t, mortar_options_t
  implicit none
  private
  public :: tie_set_t

  !> Face pairs of one or more ties: nodes(1:4, i) the slave face's, nodes(5:8, i) the master
  !> face's; coupling(:, :, i) = k [D, -M; -M^T, E] (per displacement component).
  type :: tie_set_t
    integer :: n = 0
    integer, allocatable :: nodes(:, :)
    real(dp), allocatable :: coupling(:, :, :)
    !> Face pairs whose overlap could not be integrated (see fcs_tie_mortar), for the log.
    integer :: n_refused = 0
    !> The tie (contact pair index given to `add`) each face pair belongs to.
    integer, allocatable :: owner(:)
  contains
    procedure :: add => ties_add
    procedure :: release => ties_release
    procedure :: assemble => ties_assemble
    procedure :: forces => ties_forces
    procedure :: cliques => ties_cliques
  end type tie_set_t

contains

  !> Add the face pairs of a tie: slave faces slave_faces(4, ns), master faces
  !> master_faces(4, nm) (global node indices, outward), reference coordinates x, penalty k,
  !> pairs farther apart than `tolerance` are not tied; `owner`: the tie's index (for release).
  subroutine ties_add(this, slave_faces, master_faces, x, penalty, tolerance, owner)
    class(tie_set_t), intent(inout) :: this
    integer, intent(in) :: slave_faces(:, :), master_faces(:, :), owner
    real(dp), intent(in) :: x(:, :), penalty, tolerance
    type(mortar_tie_t) :: mortar
    real(dp), allocatable :: slave_x(:, :, :), master_x(:, :, :)
    integer, allocatable :: start(:), candidates(:)
    integer :: i, p, first
    allocate (slave_x(3, 4, size(slave_faces, 2)), master_x(3, 4, size(master_faces, 2)))
    do i = 1, size(slave_faces, 2)
      slave_x(:, :, i) = x(:, slave_faces(:, i))
    end do
    do i = 1, size(master_faces, 2)
      master_x(:, :, i) = x(:, master_faces(:, i))
    end do
    call overlapping_boxes(slave_x, master_x, tolerance, start, candidates)
    call mortar%init(slave_x, master_x, start, candidates, tolerance, mortar_options_t())
    this%n_refused = this%n_refused + mortar%n_refused
    first = this%n
    call grow(this, this%n + mortar%n_pairs)
    do p = 1, mortar%n_pairs
      associate (pair => mortar%pairs(p), k => first + p)
        this%nodes(1:4, k) = slave_faces(:, pair%slave_face)
        this%nodes(5:8, k) = master_faces(:, pair%master_face)
        this%coupling(1:4, 1:4, k) = penalty * pair%d(1:4, 1:4)
        this%coupling(1:4, 5:8, k) = -penalty * pair%m(1:4, 1:4)
        this%coupling(5:8, 1:4, k) = -penalty * transpose(pair%m(1:4, 1:4))
        this%coupling(5:8, 5:8, k) = penalty * pair%e(1:4, 1:4)
        this%owner(k) = owner
      end associate
    end do
    this%n = first + mortar%n_pairs
  end subroutine ties_add

  subroutine grow(this, n)
    type(tie_set_t), intent(inout) :: this
    integer, intent(in) :: n
    integer, allocatable :: nodes(:, :), owner(:)
    real(dp), allocatable :: coupling(:, :, :)
    allocate (nodes(8, n), coupling(8, 8, n), owner(n))
    if (this%n > 0) then
      nodes(:, 1:this%n) = this%nodes(:, 1:this%n)
      coupling(:, :, 1:this%n) = this%coupling(:, :, 1:this%n)
      owner(1:this%n) = this%owner(1:this%n)
    end if
    call move_alloc(nodes, this%nodes)
    call move_alloc(coupling, this%coupling)
    call move_alloc(owner, this%owner)
  end subroutine grow

  !> Release tie `owner` (*CHANGE SURFACE BEHAVIOR from TIED): its face pairs no longer couple
  !> the surfaces (their stiffness and forces are zero; they stay in the sparse pattern).
  !> Releasing again changes nothing.
  subroutine ties_release(this, owner)
    class(tie_set_t), intent(inout) :: this
    integer, intent(in) :: owner
    integer :: p
    do p = 1, this%n
      if (this%owner(p) == owner) this%coupling(:, :, p) = 0.0_dp
    end do
  end subroutine ties_release

  !> Candidate master faces of every slave face: those whose bounding boxes, inflated by
  !> `margin`, overlap (candidates(start(i):start(i+1)-1) for slave face i).
  pure subroutine overlapping_boxes(slave_x, master_x, margin, start, candidates)
    real(dp), intent(in) :: slave_x(:, :, :), master_x(:, :, :), margin
    integer, allocatable, intent(out) :: start(:), candidates(:)
    real(dp) :: lo(3), hi(3), master_lo(3, size(master_x, 3)), master_hi(3, size(master_x, 3))
    integer, allocatable :: found(:)
    integer :: i, j, n
    do j = 1, size(master_x, 3)
      master_lo(:, j) = minval(master_x(:, :, j), dim=2) - margin
      master_hi(:, j) = maxval(master_x(:, :, j), dim=2) + margin
    end do
    allocate (start(size(slave_x, 3) + 1), found(size(master_x, 3)))
    allocate (candidates(0))
    start(1) = 1
    do i = 1, size(slave_x, 3)
      lo = minval(slave_x(:, :, i), dim=2)
      hi = maxval(slave_x(:, :, i), dim=2)
      n = 0
      do j = 1, size(master_x, 3)
        if (any(master_lo(:, j) > hi) .or. any(master_hi(:, j) < lo)) cycle
        n = n + 1
        found(n) = j
      end do
      candidates = [candidates, found(1:n)]
      start(i + 1) = start(i) + n
    end do
  end subroutine overlapping_boxes

  !> Add the tie stiffness to `matrix` and its forces -K u to f_contact (3 * n_nodes), u the
  !> displacements (3, n_nodes). `missing` when a face pair is not in the sparse pattern.
  subroutine ties_assemble(this, u, matrix, f_contact, missing)
    class(tie_set_t), intent(in) :: this
    real(dp), intent(in) :: u(:, :)
    type(sparse_matrix_t), intent(inout) :: matrix
    real(dp), intent(inout) :: f_contact(:)
    logical, intent(out) :: missing
    real(dp) :: k(24, 24)
    integer :: p, a, b, i
    missing = .false.
    do p = 1, this%n
      k = 0.0_dp
      do b = 1, 8
        do a = 1, 8
          do i = 1, 3
            k(3 * (a - 1) + i, 3 * (b - 1) + i) = this%coupling(a, b, p)
          end do
        end do
      end do
      call matrix%add_matrix(this%nodes(:, p), k, missing)
      if (missing) return
    end do
    call this%forces(u, f_contact)
  end subroutine ties_assemble

  !> The tie forces -K u added to f (3 * n_nodes).
  pure subroutine ties_forces(this, u, f)
    class(tie_set_t), intent(in) :: this
    real(dp), intent(in) :: u(:, :)
    real(dp), intent(inout) :: f(:)
    real(dp) :: ue(3, 8), fe(3, 8)
    integer :: p, a
    do p = 1, this%n
      ue = u(:, this%nodes(:, p))
      fe = -matmul(ue, transpose(this%coupling(:, :, p)))
      do a = 1, 8
        f(3 * this%nodes(a, p) - 2:3 * this%nodes(a, p)) = &
          f(3 * this%nodes(a, p) - 2:3 * this%nodes(a, p)) + fe(:, a)
      end do
    end do
  end subroutine ties_forces

  !> The 8 nodes of every face pair as cliques of the sparse pattern (appended).
  subroutine ties_cliques(this, clique_ptr, clique_nodes)
    class(tie_set_t), intent(in) :: this
    integer, allocatable, intent(inout) :: clique_ptr(:), clique_nodes(:)
    integer :: p, last
    if (this%n == 0) return
    last = clique_ptr(size(clique_ptr))
    clique_nodes = [clique_nodes, reshape(this%nodes(:, 1:this%n), [8 * this%n])]
    clique_ptr = [clique_ptr, [(last + 8 * p, p = 1, this%n)]]
  end subroutine ties_cliques

end module fcs_contact_ties
