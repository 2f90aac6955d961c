!> Linear multi-point constraints (*EQUATION and the constraints built from *MPC, *RIGID BODY
!> and *TRANSFORM) and their elimination from the assembled system, as CalculiX eliminates
!> them (ccx manual, section "Homogeneous linear equations": the first term of an equation is
!> the dependent one, written as a function of the others and removed from the system).
!>
!> Each equation  sum_k a_k u_k = 0  makes its first degree of freedom d dependent:
!>
!>     u_d = sum_{k>1} (-a_k / a_1) u_k                                                    (L1)
!>
!> A dependent degree of freedom that appears among the terms of another equation is replaced
!> by its own expression (CalculiX's cascade), so that every dependent degree of freedom is a
!> combination of independent ones only: u = T u_I. The system K du = f then becomes
!>
!>     (T^T K T) du_I = T^T f,    du_D = (L1) of du_I                                      (L2)
!>
!> done in place on the assembled sparse matrix (`reduce_matrix`: every entry in a dependent
!> row or column is moved to the independent rows and columns it stands for, with the
!> products of the coefficients; the dependent rows and columns are left zero for the caller
!> to set to the identity, as for prescribed values) and on the right-hand sides
!> (`reduce_vector`: T^T f). The transformation is linear in K, so in a distributed run every
!> process transforms its own share of the matrix and the sum is T^T K T. The pattern must
!> hold the couplings T^T K T creates: `expand_cliques` adds to every clique the independent
!> nodes of its dependent nodes, before the pattern is built from the cliques.
!>
!> Local axes (*TRANSFORM) enter the same map: at a node with a frame R (columns: the local
!> axes in global components) the three unknowns of the solve are the local components,
!> u = R u_local (CalculiX: prescribed values, loads and equation terms at such a node are
!> in its local axes). T then maps every global degree of freedom of such a node to its local
!> unknowns (those of them that are dependent replaced by their equations), and (L2) holds
!> with that T: every degree of freedom that T does not map to itself is "affected".
module fcs_linear_constraints
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, input_error
  use fcs_diagnostics, only: source_loc_t, format_location
  use fcs_sparse, only: sparse_matrix_t, DOFS_PER_NODE
  use fcs_strings, only: str
  implicit none
  private
  public :: constraint_term_t, linear_equation_t, constraint_map_t

  !> One term a u of an equation: node index, direction 1..3, coefficient a.
  type :: constraint_term_t
    integer :: node = 0
    integer :: dof = 0
    real(dp) :: coefficient = 0.0_dp
  end type constraint_term_t

  !> A homogeneous linear equation sum_k a_k u_k = 0 between displacement components (global
  !> axes); terms(1) is the dependent one. `loc` is the deck line that defines it, `origin`
  !> its keyword ('*EQUATION', '*MPC PLANE', ...), both for messages.
  type :: linear_equation_t
    type(constraint_term_t), allocatable :: terms(:)
    type(source_loc_t) :: loc
    character(len=:), allocatable :: origin
    !> The independent terms are nodes outside the structure (a rigid body's reference and
    !> rotation nodes): RF there is the force the constraint transmits, (T^T f_int) at them,
    !> as CalculiX prints it for its RIGID MPCs.
    logical :: transmits = .false.
    !> With `transmits`, the first term at such a node (the later ones are too): 2 for a
    !> rigid body, the last for MEANROT (its angle node; the members are in the structure).
    integer :: first_transmitting = 2
    !> The current linearisation of a nonlinear constraint (fcs_nonlinear_constraints): its
    !> coefficients change with the geometry, so its terms are kept when a coefficient is
    !> zero, and the map's structure (and the sparse pattern built from it) stays the same.
    logical :: nonlinear = .false.
  end type linear_equation_t

  !> The constraints resolved into u_D = T_DI u_I (L1 after the cascade): for dependent
  !> degree of freedom dependent_dofs(r), the independent degrees of freedom
  !> independent(row_ptr(r):row_ptr(r+1)-1) with their coefficients.
  type :: constraint_map_t
    integer :: n_dofs = 0
    logical, allocatable :: dependent(:)
    integer, allocatable :: dependent_dofs(:)
    integer, allocatable :: row_ptr(:)
    integer, allocatable :: independent(:)
    real(dp), allocatable :: coefficient(:)
    !> Row of a dependent degree of freedom (0 for an independent one).
    integer, allocatable :: row_of(:)
    !> T restricted to the affected degrees of freedom (dependent ones, and those of nodes
    !> with local axes): global degree of freedom affected_dofs(r) is the sum of
    !> factors(p) times the unknowns targets(p), p = target_ptr(r) .. target_ptr(r+1)-1.
    logical, allocatable :: affected(:)
    integer, allocatable :: affected_dofs(:), target_ptr(:), targets(:)
    real(dp), allocatable :: factors(:)
    !> Local axes of every node (3, 3, n_nodes; identity where there are none), and which
    !> nodes have them.
    real(dp), allocatable :: frame(:, :, :)
    logical, allocatable :: transformed(:)
    !> For node a, the nodes of the unknowns its affected degrees of freedom stand for:
    !> links(link_ptr(a):link_ptr(a+1)-1).
    integer, allocatable :: link_ptr(:), links(:)
    !> Rows of nonlinear constraints (their zero terms are kept).
    logical, allocatable :: row_nonlinear(:)
  contains
    procedure :: init => map_init
    procedure :: free => map_free
    procedure :: active => map_active
    procedure :: expand_cliques => map_expand_cliques
    procedure :: reduce_matrix => map_reduce_matrix
    procedure :: reduce_vector => map_reduce_vector
    procedure :: expand_vector => map_expand_vector
    procedure :: to_local => map_to_local
    procedure :: to_global => map_to_global
    procedure :: row_of_affected
  end type constraint_map_t

  !> One resolved row while the cascade is worked out.
  type :: row_t
    integer, allocatable :: dofs(:)
    real(dp), allocatable :: values(:)
  end type row_t

  integer, parameter :: UNVISITED = 0, IN_PROGRESS = 1, RESOLVED = 2

contains

  !> Resolve `equations` on a mesh of n_nodes nodes (node_id: their deck numbers, for
  !> messages). Input errors: a zero first coefficient, a degree of freedom on the dependent
  !> side of two equations, a dependent degree of freedom that appears again in its own
  !> equation, equations whose dependent terms depend on each other in a cycle.
  !> `frame` and `transformed` give the local axes of the nodes that have them (*TRANSFORM).
  subroutine map_init(this, equations, n_nodes, node_id, err, frame, transformed)
    class(constraint_map_t), intent(inout) :: this
    type(linear_equation_t), intent(in) :: equations(:)
    integer, intent(in) :: n_nodes, node_id(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), intent(in), optional :: frame(:, :, :)
    logical, intent(in), optional :: transformed(:)
    type(row_t), allocatable :: rows(:)
    integer, allocatable :: state(:), owner(:)
    integer :: i, k, d, n_terms
    call this%free()
    this%n_dofs = DOFS_PER_NODE * n_nodes
    allocate (this%dependent(this%n_dofs), owner(this%n_dofs), state(size(equations)), &
              rows(size(equations)))
    this%dependent = .false.
    owner = 0
    state = UNVISITED
    do i = 1, size(equations)
      associate (terms => equations(i)%terms)
        d = dof_index(terms(1))
        if (terms(1)%coefficient == 0.0_dp) then
          call input_error(err, format_location(equations(i)%loc, equations(i)%origin // &
            ': the coefficient of the first (dependent) term must not be zero'))
          return
        end if
        if (owner(d) /= 0) then
          call input_error(err, format_location(equations(i)%loc, equations(i)%origin // &
            ': ' // dof_name(terms(1), node_id) // ' is already the dependent term of the ' // &
            'equation at ' // line_of(equations(owner(d))) // ' (a degree of freedom can be ' // &
            'dependent in one equation only)'))
          return
        end if
        owner(d) = i
        this%dependent(d) = .true.
        do k = 2, size(terms)
          if (dof_index(terms(k)) == d) then
            call input_error(err, format_location(equations(i)%loc, equations(i)%origin // &
              ': the dependent term ' // dof_name(terms(1), node_id) // ' appears again in ' // &
              'the same equation (term ' // str(k) // ')'))
            return
          end if
        end do
      end associate
    end do
    do i = 1, size(equations)
      if (state(i) == UNVISITED) call resolve(i, err)
      if (allocated(err)) return
    end do
    call flatten()
    allocate (this%row_nonlinear(size(equations)))
    do i = 1, size(equations)
      this%row_nonlinear(i) = equations(i)%nonlinear
    end do
    allocate (this%frame(3, 3, n_nodes), this%transformed(n_nodes))
    this%frame = 0.0_dp
    do k = 1, 3
      this%frame(k, k, :) = 1.0_dp
    end do
    this%transformed = .false.
    if (present(frame) .and. present(transformed)) then
      this%transformed = transformed
      do k = 1, n_nodes
        if (transformed(k)) this%frame(:, :, k) = frame(:, :, k)
      end do
    end if
    call global_targets(this)
    call node_links(n_nodes)
  contains
    recursive subroutine resolve(i, err)
      integer, intent(in) :: i
      type(error_t), allocatable, intent(out) :: err
      integer, allocatable :: dofs(:)
      real(dp), allocatable :: values(:)
      integer :: k, j, e
      real(dp) :: c
      state(i) = IN_PROGRESS
      allocate (dofs(0), values(0))
      associate (terms => equations(i)%terms)
        do k = 2, size(terms)
          j = dof_index(terms(k))
          c = -terms(k)%coefficient / terms(1)%coefficient
          e = owner(j)
          if (e == 0) then
            dofs = [dofs, j]
            values = [values, c]
            cycle
          end if
          if (state(e) == IN_PROGRESS) then
            call input_error(err, format_location(equations(i)%loc, equations(i)%origin // &
              ': the dependent terms of this equation and of the one at ' // &
              line_of(equations(e)) // ' depend on each other in a cycle (' // &
              dof_name(terms(k), node_id) // '); make one of them dependent on independent ' // &
              'degrees of freedom only'))
            return
          end if
          if (state(e) == UNVISITED) call resolve(e, err)
          if (allocated(err)) return
          dofs = [dofs, rows(e)%dofs]
          values = [values, c * rows(e)%values]
        end do
      end associate
      call merge_terms(dofs, values, rows(i), equations(i)%nonlinear)
      state(i) = RESOLVED
    end subroutine resolve

    subroutine flatten()
      integer :: r, n
      allocate (this%dependent_dofs(size(equations)), this%row_ptr(size(equations) + 1), &
                this%row_of(this%n_dofs))
      this%row_of = 0
      n_terms = 0
      do r = 1, size(equations)
        n_terms = n_terms + size(rows(r)%dofs)
      end do
      allocate (this%independent(n_terms), this%coefficient(n_terms))
      this%row_ptr(1) = 1
      do r = 1, size(equations)
        d = dof_index(equations(r)%terms(1))
        this%dependent_dofs(r) = d
        this%row_of(d) = r
        n = size(rows(r)%dofs)
        this%row_ptr(r + 1) = this%row_ptr(r) + n
        this%independent(this%row_ptr(r):this%row_ptr(r + 1) - 1) = rows(r)%dofs
        this%coefficient(this%row_ptr(r):this%row_ptr(r + 1) - 1) = rows(r)%values
      end do
    end subroutine flatten

    subroutine node_links(n_nodes)
      integer, intent(in) :: n_nodes
      integer, allocatable :: count_links(:), fill(:)
      integer :: r, p, a, b, pass
      allocate (count_links(n_nodes), this%link_ptr(n_nodes + 1))
      do pass = 1, 2
        count_links = 0
        do r = 1, size(this%affected_dofs)
          a = (this%affected_dofs(r) - 1) / DOFS_PER_NODE + 1
          do p = this%target_ptr(r), this%target_ptr(r + 1) - 1
            b = (this%targets(p) - 1) / DOFS_PER_NODE + 1
            if (b == a) cycle
            if (pass == 2) then
              if (any(this%links(this%link_ptr(a):fill(a) - 1) == b)) cycle
              this%links(fill(a)) = b
              fill(a) = fill(a) + 1
            else
              count_links(a) = count_links(a) + 1
            end if
          end do
        end do
        if (pass == 1) then
          this%link_ptr(1) = 1
          do a = 1, n_nodes
            this%link_ptr(a + 1) = this%link_ptr(a) + count_links(a)
          end do
          allocate (this%links(this%link_ptr(n_nodes + 1) - 1))
          fill = this%link_ptr(1:n_nodes)
        end if
      end do
      ! Trim the duplicates left unused at the end of each node's slice.
      call compact_links(this, fill)
    end subroutine node_links
  end subroutine map_init

  !> Keep only the filled part links(link_ptr(a):fill(a)-1) of every node's slice.
  subroutine compact_links(this, fill)
    type(constraint_map_t), intent(inout) :: this
    integer, intent(in) :: fill(:)
    integer, allocatable :: ptr(:), kept(:)
    integer :: a, n
    n = size(fill)
    allocate (ptr(n + 1))
    ptr(1) = 1
    do a = 1, n
      ptr(a + 1) = ptr(a) + (fill(a) - this%link_ptr(a))
    end do
    allocate (kept(ptr(n + 1) - 1))
    do a = 1, n
      kept(ptr(a):ptr(a + 1) - 1) = this%links(this%link_ptr(a):fill(a) - 1)
    end do
    call move_alloc(ptr, this%link_ptr)
    call move_alloc(kept, this%links)
  end subroutine compact_links

  !> T on the affected degrees of freedom: a dependent one (at a node without local axes) is
  !> its row; global direction i of a node with local axes R is sum_a R(i, a) times local
  !> unknown a, itself replaced by its row when it is dependent.
  subroutine global_targets(this)
    type(constraint_map_t), intent(inout) :: this
    integer, allocatable :: dofs(:)
    real(dp), allocatable :: values(:)
    type(row_t) :: merged
    type(row_t), allocatable :: lists(:)
    integer :: i, node, direction, a, slot, r, n, k
    logical :: kept
    allocate (this%affected(this%n_dofs))
    this%affected = this%dependent
    do node = 1, size(this%transformed)
      if (this%transformed(node)) this%affected(3 * node - 2:3 * node) = .true.
    end do
    this%affected_dofs = pack([(i, i = 1, this%n_dofs)], this%affected)
    allocate (lists(size(this%affected_dofs)))
    do k = 1, size(this%affected_dofs)
      i = this%affected_dofs(k)
      node = (i - 1) / DOFS_PER_NODE + 1
      direction = i - DOFS_PER_NODE * (node - 1)
      allocate (dofs(0), values(0))
      kept = .false.
      if (this%transformed(node)) then
        do a = 1, 3
          if (this%frame(direction, a, node) == 0.0_dp) cycle
          slot = DOFS_PER_NODE * (node - 1) + a
          r = this%row_of(slot)
          if (r == 0) then
            dofs = [dofs, slot]
            values = [values, this%frame(direction, a, node)]
          else
            dofs = [dofs, this%independent(this%row_ptr(r):this%row_ptr(r + 1) - 1)]
            values = [values, this%frame(direction, a, node) * &
                              this%coefficient(this%row_ptr(r):this%row_ptr(r + 1) - 1)]
          end if
        end do
      else
        r = this%row_of(i)
        kept = this%row_nonlinear(r)
        dofs = this%independent(this%row_ptr(r):this%row_ptr(r + 1) - 1)
        values = this%coefficient(this%row_ptr(r):this%row_ptr(r + 1) - 1)
      end if
      call merge_terms(dofs, values, merged, kept)
      lists(k) = merged
      deallocate (dofs, values)
    end do
    allocate (this%target_ptr(size(lists) + 1))
    this%target_ptr(1) = 1
    do k = 1, size(lists)
      this%target_ptr(k + 1) = this%target_ptr(k) + size(lists(k)%dofs)
    end do
    n = this%target_ptr(size(lists) + 1) - 1
    allocate (this%targets(n), this%factors(n))
    do k = 1, size(lists)
      this%targets(this%target_ptr(k):this%target_ptr(k + 1) - 1) = lists(k)%dofs
      this%factors(this%target_ptr(k):this%target_ptr(k + 1) - 1) = lists(k)%values
    end do
  end subroutine global_targets

  !> Sum the values of repeated degrees of freedom; drop terms that cancel exactly (unless
  !> `keep`: the row of a nonlinear constraint, whose zero coefficients may not stay zero).
  subroutine merge_terms(dofs, values, row, keep)
    integer, intent(in) :: dofs(:)
    real(dp), intent(in) :: values(:)
    type(row_t), intent(out) :: row
    logical, intent(in) :: keep
    integer :: k, j, n
    allocate (row%dofs(size(dofs)), row%values(size(dofs)))
    n = 0
    outer: do k = 1, size(dofs)
      do j = 1, n
        if (row%dofs(j) == dofs(k)) then
          row%values(j) = row%values(j) + values(k)
          cycle outer
        end if
      end do
      n = n + 1
      row%dofs(n) = dofs(k)
      row%values(n) = values(k)
    end do outer
    if (keep) then
      row%dofs = row%dofs(1:n)
      row%values = row%values(1:n)
      return
    end if
    row%dofs = pack(row%dofs(1:n), row%values(1:n) /= 0.0_dp)
    row%values = pack(row%values(1:n), row%values(1:n) /= 0.0_dp)
  end subroutine merge_terms

  subroutine map_free(this)
    class(constraint_map_t), intent(inout) :: this
    if (allocated(this%dependent)) deallocate (this%dependent)
    if (allocated(this%dependent_dofs)) deallocate (this%dependent_dofs)
    if (allocated(this%row_ptr)) deallocate (this%row_ptr)
    if (allocated(this%independent)) deallocate (this%independent)
    if (allocated(this%coefficient)) deallocate (this%coefficient)
    if (allocated(this%row_of)) deallocate (this%row_of)
    if (allocated(this%link_ptr)) deallocate (this%link_ptr)
    if (allocated(this%links)) deallocate (this%links)
    if (allocated(this%affected)) deallocate (this%affected)
    if (allocated(this%affected_dofs)) deallocate (this%affected_dofs)
    if (allocated(this%target_ptr)) deallocate (this%target_ptr)
    if (allocated(this%targets)) deallocate (this%targets)
    if (allocated(this%factors)) deallocate (this%factors)
    if (allocated(this%frame)) deallocate (this%frame)
    if (allocated(this%transformed)) deallocate (this%transformed)
    if (allocated(this%row_nonlinear)) deallocate (this%row_nonlinear)
    this%n_dofs = 0
  end subroutine map_free

  !> True when there is at least one constraint.
  pure logical function map_active(this)
    class(constraint_map_t), intent(in) :: this
    map_active = .false.
    if (allocated(this%affected_dofs)) map_active = size(this%affected_dofs) > 0
  end function map_active

  !> Add to every clique the nodes its dependent nodes are linked to, and one clique per
  !> linked node (the node and its links), so that the pattern built from the cliques holds
  !> every entry of T^T K T (L2).
  subroutine map_expand_cliques(this, clique_ptr, clique_nodes)
    class(constraint_map_t), intent(in) :: this
    integer, allocatable, intent(inout) :: clique_ptr(:), clique_nodes(:)
    integer, allocatable :: ptr(:), nodes(:)
    integer :: c, j, a, n, n_nodes, extra
    if (.not. this%active()) return
    n_nodes = size(this%link_ptr) - 1
    n = size(clique_nodes)
    do c = 1, size(clique_ptr) - 1
      do j = clique_ptr(c), clique_ptr(c + 1) - 1
        a = clique_nodes(j)
        n = n + this%link_ptr(a + 1) - this%link_ptr(a)
      end do
    end do
    extra = count(this%link_ptr(2:) > this%link_ptr(1:n_nodes))
    n = n + extra + size(this%links)
    allocate (ptr(size(clique_ptr) + extra), nodes(n))
    n = 0
    ptr(1) = 1
    do c = 1, size(clique_ptr) - 1
      do j = clique_ptr(c), clique_ptr(c + 1) - 1
        a = clique_nodes(j)
        n = n + 1
        nodes(n) = a
        nodes(n + 1:n + this%link_ptr(a + 1) - this%link_ptr(a)) = &
          this%links(this%link_ptr(a):this%link_ptr(a + 1) - 1)
        n = n + this%link_ptr(a + 1) - this%link_ptr(a)
      end do
      ptr(c + 1) = n + 1
    end do
    c = size(clique_ptr)
    do a = 1, n_nodes
      if (this%link_ptr(a + 1) == this%link_ptr(a)) cycle
      n = n + 1
      nodes(n) = a
      nodes(n + 1:n + this%link_ptr(a + 1) - this%link_ptr(a)) = &
        this%links(this%link_ptr(a):this%link_ptr(a + 1) - 1)
      n = n + this%link_ptr(a + 1) - this%link_ptr(a)
      c = c + 1
      ptr(c) = n + 1
    end do
    call move_alloc(ptr, clique_ptr)
    call move_alloc(nodes, clique_nodes)
  end subroutine map_expand_cliques

  !> K <- T^T K T in place (L2): every entry K_ik with i or k affected moves to the entries
  !> (a, b) of the unknowns a of i and b of k, times their factors (an unaffected degree of
  !> freedom stands for itself with factor 1); the dependent rows and columns are left zero.
  !> The affected entries are taken out first, so that none is moved twice. `missing` is true
  !> if the pattern lacks a target entry (the cliques were not expanded: an internal error
  !> of the caller).
  subroutine map_reduce_matrix(this, matrix, missing)
    class(constraint_map_t), intent(in) :: this
    type(sparse_matrix_t), intent(inout) :: matrix
    logical, intent(out) :: missing
    integer, allocatable :: rows(:), columns(:)
    real(dp), allocatable :: values(:)
    integer :: i, k, n, e, ra, rb, pa, pb, a, b
    integer(i8) :: p
    real(dp) :: ta, tb
    logical :: lacking
    missing = .false.
    if (.not. this%active()) return
    n = 0
    do i = 1, matrix%n
      do p = matrix%row_ptr(i), matrix%row_ptr(i + 1) - 1
        if (this%affected(i) .or. this%affected(matrix%col(p))) n = n + 1
      end do
    end do
    allocate (rows(n), columns(n), values(n))
    n = 0
    do i = 1, matrix%n
      do p = matrix%row_ptr(i), matrix%row_ptr(i + 1) - 1
        k = matrix%col(p)
        if (.not. (this%affected(i) .or. this%affected(k))) cycle
        n = n + 1
        rows(n) = i
        columns(n) = k
        values(n) = matrix%val(p)
        matrix%val(p) = 0.0_dp
      end do
    end do
    do e = 1, n
      if (values(e) == 0.0_dp) cycle
      ra = this%row_of_affected(rows(e))
      rb = this%row_of_affected(columns(e))
      do pa = span_start(ra), span_end(ra)
        call term(ra, pa, rows(e), a, ta)
        do pb = span_start(rb), span_end(rb)
          call term(rb, pb, columns(e), b, tb)
          call matrix%add_value(a, b, ta * tb * values(e), lacking)
          missing = missing .or. lacking
        end do
      end do
    end do
  contains
    !> Positions of the targets of affected row r (one position, the degree of freedom
    !> itself, for an unaffected one: r = 0).
    pure integer function span_start(r)
      integer, intent(in) :: r
      span_start = 1
      if (r > 0) span_start = this%target_ptr(r)
    end function span_start

    pure integer function span_end(r)
      integer, intent(in) :: r
      span_end = 1
      if (r > 0) span_end = this%target_ptr(r + 1) - 1
    end function span_end

    pure subroutine term(r, p, dof, target, factor)
      integer, intent(in) :: r, p, dof
      integer, intent(out) :: target
      real(dp), intent(out) :: factor
      if (r == 0) then
        target = dof
        factor = 1.0_dp
      else
        target = this%targets(p)
        factor = this%factors(p)
      end if
    end subroutine term
  end subroutine map_reduce_matrix

  !> f <- T^T f (L2): the value at every affected degree of freedom goes to its unknowns
  !> times their factors (at a node with local axes: its local components).
  subroutine map_reduce_vector(this, f)
    class(constraint_map_t), intent(in) :: this
    real(dp), intent(inout) :: f(:)
    real(dp), allocatable :: taken(:)
    integer :: r, p
    if (.not. this%active()) return
    taken = f(this%affected_dofs)
    f(this%affected_dofs) = 0.0_dp
    do r = 1, size(this%affected_dofs)
      do p = this%target_ptr(r), this%target_ptr(r + 1) - 1
        f(this%targets(p)) = f(this%targets(p)) + this%factors(p) * taken(r)
      end do
    end do
  end subroutine map_reduce_vector

  !> u <- T u (L1): the global components of the affected degrees of freedom from the
  !> unknowns of the solve.
  subroutine map_expand_vector(this, u)
    class(constraint_map_t), intent(in) :: this
    real(dp), intent(inout) :: u(:)
    real(dp), allocatable :: values(:)
    integer :: r, p
    if (.not. this%active()) return
    allocate (values(size(this%affected_dofs)))
    values = 0.0_dp
    do r = 1, size(this%affected_dofs)
      do p = this%target_ptr(r), this%target_ptr(r + 1) - 1
        values(r) = values(r) + this%factors(p) * u(this%targets(p))
      end do
    end do
    u(this%affected_dofs) = values
  end subroutine map_expand_vector

  !> Row of an affected degree of freedom in affected_dofs (0 when not affected).
  pure integer function row_of_affected(this, dof) result(r)
    class(constraint_map_t), intent(in) :: this
    integer, intent(in) :: dof
    integer :: lo, hi, mid
    r = 0
    if (.not. this%affected(dof)) return
    lo = 1
    hi = size(this%affected_dofs)
    do while (lo <= hi)
      mid = (lo + hi) / 2
      if (this%affected_dofs(mid) == dof) then
        r = mid
        return
      else if (this%affected_dofs(mid) < dof) then
        lo = mid + 1
      else
        hi = mid - 1
      end if
    end do
  end function row_of_affected

  !> Component `direction` of the nodal vector v(:, node) in the node's local axes (the
  !> global one at a node without).
  pure real(dp) function map_to_local(this, v, node, direction) result(c)
    class(constraint_map_t), intent(in) :: this
    real(dp), intent(in) :: v(3)
    integer, intent(in) :: node, direction
    c = v(direction)
    if (.not. allocated(this%transformed)) return
    if (this%transformed(node)) c = dot_product(this%frame(:, direction, node), v)
  end function map_to_local

  !> f(node) <- R f(node) at every node with local axes: a vector given in local components
  !> there (the loads of *CLOAD) into global ones.
  subroutine map_to_global(this, f)
    class(constraint_map_t), intent(in) :: this
    real(dp), intent(inout) :: f(:)
    integer :: node
    if (.not. allocated(this%transformed)) return
    do node = 1, size(this%transformed)
      if (this%transformed(node)) f(3 * node - 2:3 * node) = &
        matmul(this%frame(:, :, node), f(3 * node - 2:3 * node))
    end do
  end subroutine map_to_global

  pure integer function dof_index(t)
    type(constraint_term_t), intent(in) :: t
    dof_index = DOFS_PER_NODE * (t%node - 1) + t%dof
  end function dof_index

  !> "node 12, direction 2" (deck numbering).
  function dof_name(t, node_id) result(text)
    type(constraint_term_t), intent(in) :: t
    integer, intent(in) :: node_id(:)
    character(len=:), allocatable :: text
    text = 'node ' // str(node_id(t%node)) // ', direction ' // str(t%dof)
  end function dof_name

  !> "file:line" of an equation.
  function line_of(equation) result(text)
    type(linear_equation_t), intent(in) :: equation
    character(len=:), allocatable :: text
    text = '(unknown line)'
    if (allocated(equation%loc%file)) text = equation%loc%file // ':' // str(equation%loc%line)
  end function line_of

end module fcs_linear_constraints
