!> Checks that every body of the model is held: nodes in no element, loads on such nodes,
!> and rigid-body modes that no *BOUNDARY removes, step by step.
!>
!> Bodies are the connected groups of elements (sharing nodes). Bodies joined by a contact
!> pair, a tie or a linear constraint (*EQUATION) form an assembly: contact can hold one body
!> against another, so the six rigid-body modes are checked per assembly. A linear
!> constraint sum_k a_k u_k = 0 removes the rigid motions it does not allow: its row is
!> sum_k a_k [e_k, (x_k - c)/L x e_k] (zero for an equation that rigid motions satisfy, such
!> as a tie of coincident or interpolated nodes). A node in no element that a constraint
!> names is not free: it moves with the constraint. The degrees of freedom of a *RIGID BODY's
!> rotation node are the rotation w of the rigid motion, not a displacement. A displacement or velocity condition on degree
!> of freedom d of a node at x (relative to the assembly centroid c, scaled by the assembly
!> size L) removes the row [e_d, (x - c)/L x e_d] from the rigid motions u = t + w x (x - c);
!> the modes left are the null space of the 6 x 6 sum of those rows' outer products. This
!> cannot see a pair that is open at the start or frictionless (tangential modes): such a
!> model passes here and stops at its first increment with a singular-matrix message.
!> The check uses the reference configuration. After a step with NLGEOM the body may have
!> moved far enough (a beam turned by 90 degrees: CalculiX's beamp2rotate) that conditions
!> which leave a mode free in the reference configuration hold it in the current one; there a
!> free mode is a warning, and a model that really is free stops at the step's first increment
!> with the singular-matrix message.
module fcs_model_supports
  use fcs_kinds, only: dp
  use fcs_diagnostics, only: diagnostics_t
  use fcs_mesh, only: mesh_t
  use fcs_model, only: model_t, step_t
  use fcs_strings, only: str
  implicit none
  private
  public :: check_supports

  !> An eigenvalue of the scaled 6 x 6 constraint matrix below this fraction of the largest
  !> is a free mode (the rows have entries of order 1; round-off gives ~1e-16).
  real(dp), parameter :: FREE_MODE_TOLERANCE = 1.0e-9_dp

  interface
    !> LAPACK: eigenvalues and eigenvectors of a real symmetric matrix.
    subroutine dsyev(jobz, uplo, n, a, lda, w, work, lwork, info)
      import :: dp
      character(len=1), intent(in) :: jobz, uplo
      integer, intent(in) :: n, lda, lwork
      real(dp), intent(inout) :: a(lda, *)
      real(dp), intent(out) :: w(*), work(*)
      integer, intent(out) :: info
    end subroutine dsyev
  end interface

contains

  !> Mark the nodes in no element (model%free_node), refuse loads on them, and check every
  !> step for rigid-body modes of every assembly.
  subroutine check_supports(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: assembly(:), roots(:), slot(:)
    real(dp), allocatable :: centre(:, :), size_l(:)
    integer :: k, j
    call mark_free_nodes(model)
    call check_loads_on_free_nodes(model, diag)
    call node_assemblies(model, assembly)
    roots = pack([(j, j = 1, size(assembly))], assembly == [(j, j = 1, size(assembly))])
    allocate (slot(size(assembly)))
    slot = 0
    slot(roots) = [(j, j = 1, size(roots))]
    call assembly_frames(model%mesh, assembly, slot, size(roots), centre, size_l)
    do k = 1, size(model%steps)
      call check_step(model, model%steps(k), assembly, roots, slot, centre, size_l, &
                      any(model%steps(1:k - 1)%nlgeom), diag)
    end do
  end subroutine check_supports

  subroutine mark_free_nodes(model)
    type(model_t), intent(inout) :: model
    integer :: e
    allocate (model%free_node(model%mesh%n_nodes))
    model%free_node = .true.
    do e = 1, model%mesh%n_elements
      model%free_node(model%mesh%element_nodes(e)) = .false.
    end do
    do e = 1, size(model%equations)
      model%free_node(model%equations(e)%terms(:)%node) = .false.
    end do
    ! A node in no element that an equation names has unknowns only in the directions it
    ! names (the other two of a MEANROT angle node would be singular rows).
    allocate (model%idle_dof(3 * model%mesh%n_nodes))
    model%idle_dof = .true.
    do e = 1, model%mesh%n_elements
      associate (nodes => model%mesh%element_nodes(e))
        model%idle_dof(3 * nodes - 2) = .false.
        model%idle_dof(3 * nodes - 1) = .false.
        model%idle_dof(3 * nodes) = .false.
      end associate
    end do
    do e = 1, size(model%equations)
      associate (terms => model%equations(e)%terms)
        model%idle_dof(3 * (terms(:)%node - 1) + terms(:)%dof) = .false.
      end associate
    end do
    model%idle_dof = model%idle_dof .and. .not. spread_nodes(model%free_node)
  contains
    !> The three degrees of freedom of every node marked.
    pure function spread_nodes(mark) result(dofs)
      logical, intent(in) :: mark(:)
      logical :: dofs(3 * size(mark))
      dofs = reshape(spread(mark, 1, 3), [3 * size(mark)])
    end function spread_nodes
  end subroutine mark_free_nodes

  subroutine check_loads_on_free_nodes(model, diag)
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: k, i, node
    do k = 1, size(model%steps)
      do i = 1, size(model%steps(k)%loads)
        node = model%steps(k)%loads(i)%node
        if (.not. model%free_node(node)) cycle
        call diag%report(model%steps(k)%loc, 'step "' // model%steps(k)%name // '": *CLOAD on ' // &
          'node ' // str(model%mesh%node_id(node)) // ', which belongs to no element: the ' // &
          'load would act on nothing')
        exit
      end do
    end do
  end subroutine check_loads_on_free_nodes

  !> assembly(node): the assembly (root node of a union-find over element connectivity,
  !> contact pairs and ties) each node belongs to; 0 for nodes in no element.
  subroutine node_assemblies(model, assembly)
    type(model_t), intent(in) :: model
    integer, allocatable, intent(out) :: assembly(:)
    integer, allocatable :: parent(:), slaves(:)
    integer, allocatable :: nodes(:)
    integer :: e, j, k, n, master_node
    n = model%mesh%n_nodes
    allocate (parent(n))
    parent = [(j, j = 1, n)]
    do e = 1, model%mesh%n_elements
      nodes = model%mesh%element_nodes(e)
      do j = 2, size(nodes)
        call unite(parent, nodes(1), nodes(j))
      end do
    end do
    do k = 1, size(model%contact_pairs)
      associate (master => model%mesh%surfaces(model%contact_pairs(k)%master_surface))
        if (size(master%element) == 0) cycle
        master_node = model%mesh%connectivity(1, master%element(1))
      end associate
      slaves = model%mesh%surface_node_list(model%contact_pairs(k)%slave_surface)
      do j = 1, size(slaves)
        if (.not. model%free_node(slaves(j))) call unite(parent, master_node, slaves(j))
      end do
    end do
    do k = 1, size(model%equations)
      associate (terms => model%equations(k)%terms)
        do j = 2, size(terms)
          call unite(parent, terms(1)%node, terms(j)%node)
        end do
      end associate
    end do
    allocate (assembly(n))
    do j = 1, n
      assembly(j) = merge(0, root(parent, j), model%free_node(j))
    end do
  end subroutine node_assemblies

  integer function root(parent, i)
    integer, intent(inout) :: parent(:)
    integer, intent(in) :: i
    root = i
    do while (parent(root) /= root)
      parent(root) = parent(parent(root))
      root = parent(root)
    end do
  end function root

  subroutine unite(parent, i, j)
    integer, intent(inout) :: parent(:)
    integer, intent(in) :: i, j
    integer :: a, b
    a = root(parent, i)
    b = root(parent, j)
    if (a /= b) parent(max(a, b)) = min(a, b)
  end subroutine unite

  !> Report every assembly that the conditions of `step` leave free to move rigidly.
  subroutine check_step(model, step, assembly, roots, slot, centre, size_l, moved, diag)
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    integer, intent(in) :: assembly(:), roots(:), slot(:)
    real(dp), intent(in) :: centre(:, :), size_l(:)
    !> An earlier step had NLGEOM: the body may no longer be in its reference configuration.
    logical, intent(in) :: moved
    type(diagnostics_t), intent(inout) :: diag
    real(dp), allocatable :: gram(:, :, :)
    real(dp) :: row(6), axis(3)
    integer :: i, node, a
    allocate (gram(6, 6, size(roots)))
    gram = 0.0_dp
    do i = 1, size(step%boundary)
      node = step%boundary(i)%node
      if (assembly(node) == 0) cycle
      a = slot(assembly(node))
      axis = 0.0_dp
      axis(step%boundary(i)%dof) = 1.0_dp
      ! A condition at a node with local axes (*TRANSFORM) is on a local component.
      if (model%transformed(node)) axis = model%node_frame(:, step%boundary(i)%dof, node)
      row(1:3) = axis
      row(4:6) = cross((model%mesh%x(:, node) - centre(:, a)) / size_l(a), axis)
      ! The rotation node of a *RIGID BODY: its degree of freedom d is the rotation w_d.
      if (any(model%rotation_nodes == node)) row = [0.0_dp, 0.0_dp, 0.0_dp, axis]
      gram(:, :, a) = gram(:, :, a) + spread(row, 2, 6) * spread(row, 1, 6)
    end do
    call add_equation_rows(model, assembly, slot, centre, size_l, gram)
    do a = 1, size(roots)
      call report_free_modes(model, step, assembly, roots(a), gram(:, :, a), moved, diag)
    end do
  end subroutine check_step

  !> The rows of the linear constraints (module header) added to their assembly's matrix,
  !> each scaled by its largest coefficient.
  subroutine add_equation_rows(model, assembly, slot, centre, size_l, gram)
    type(model_t), intent(in) :: model
    integer, intent(in) :: assembly(:), slot(:)
    real(dp), intent(in) :: centre(:, :), size_l(:)
    real(dp), intent(inout) :: gram(:, :, :)
    real(dp) :: row(6), axis(3)
    integer :: k, j, a, node
    do k = 1, size(model%equations)
      associate (terms => model%equations(k)%terms)
        if (assembly(terms(1)%node) == 0) cycle
        a = slot(assembly(terms(1)%node))
        row = 0.0_dp
        do j = 1, size(terms)
          node = terms(j)%node
          axis = 0.0_dp
          axis(terms(j)%dof) = terms(j)%coefficient
          if (model%transformed(node)) axis = terms(j)%coefficient * model%node_frame(:, terms(j)%dof, node)
          if (any(model%rotation_nodes == node)) then
            ! A rotation w = omega / L (the rigid motions are u = t + omega x (x - c) / L).
            row(4:6) = row(4:6) + axis / size_l(a)
            cycle
          end if
          row(1:3) = row(1:3) + axis
          row(4:6) = row(4:6) + cross((model%mesh%x(:, node) - centre(:, a)) / size_l(a), axis)
        end do
        row = row / maxval(abs(terms(:)%coefficient))
        gram(:, :, a) = gram(:, :, a) + spread(row, 2, 6) * spread(row, 1, 6)
      end associate
    end do
  end subroutine add_equation_rows

  !> The null space of `gram` (6 x 6, scaled rigid motions) as an error, if not empty.
  subroutine report_free_modes(model, step, assembly, id, gram, moved, diag)
    type(model_t), intent(in) :: model
    type(step_t), intent(in) :: step
    integer, intent(in) :: assembly(:), id
    real(dp), intent(in) :: gram(6, 6)
    logical, intent(in) :: moved
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: vectors(6, 6), eigenvalues(6), work(64)
    integer :: info, n_free, m
    character(len=:), allocatable :: modes
    vectors = gram
    call dsyev('V', 'U', 6, vectors, 6, eigenvalues, work, size(work), info)
    if (info /= 0) then
      call diag%report(step%loc, 'step "' // step%name // '": LAPACK dsyev failed (info ' // &
                       str(info) // ') checking the supports')
      return
    end if
    n_free = count(eigenvalues <= FREE_MODE_TOLERANCE * max(eigenvalues(6), 1.0_dp))
    if (n_free == 0) return
    modes = ''
    do m = 1, n_free
      if (m > 1) modes = modes // '; '
      modes = modes // describe_mode(vectors(:, m))
    end do
    if (moved) then
      call diag%warn(step%loc, 'step "' // step%name // '": ' // body_name(model, assembly, id) // &
        ' is not held in its reference configuration: ' // str(n_free) // ' rigid-body ' // &
        'mode(s) free there (' // modes // '); an earlier step with NLGEOM may have moved it ' // &
        'to where its conditions hold it, so the step is run (a free body stops at its first ' // &
        'increment with a singular matrix)')
      return
    end if
    call diag%report(step%loc, 'step "' // step%name // '": ' // body_name(model, assembly, id) // &
      ' is not held: ' // str(n_free) // ' rigid-body mode(s) free (' // modes // '); add ' // &
      '*BOUNDARY conditions, or join it to a held body by *CONTACT PAIR or *TIE')
  end subroutine report_free_modes

  !> Centroid of the nodes of each assembly and their largest distance from it (> 0).
  subroutine assembly_frames(mesh, assembly, slot, n, centre, size_l)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: assembly(:), slot(:), n
    real(dp), allocatable, intent(out) :: centre(:, :), size_l(:)
    integer, allocatable :: count_nodes(:)
    integer :: j, a
    allocate (centre(3, n), size_l(n), count_nodes(n))
    centre = 0.0_dp
    count_nodes = 0
    do j = 1, mesh%n_nodes
      if (assembly(j) == 0) cycle
      a = slot(assembly(j))
      centre(:, a) = centre(:, a) + mesh%x(:, j)
      count_nodes(a) = count_nodes(a) + 1
    end do
    do a = 1, n
      centre(:, a) = centre(:, a) / max(count_nodes(a), 1)
    end do
    size_l = 0.0_dp
    do j = 1, mesh%n_nodes
      if (assembly(j) == 0) cycle
      a = slot(assembly(j))
      size_l(a) = max(size_l(a), norm2(mesh%x(:, j) - centre(:, a)))
    end do
    where (size_l <= 0.0_dp) size_l = 1.0_dp
  end subroutine assembly_frames

  !> "translation along (1, 0, 0)" or "rotation about (0, 0, 1)" for a null vector (t, w).
  function describe_mode(v) result(text)
    real(dp), intent(in) :: v(6)
    character(len=:), allocatable :: text
    if (norm2(v(4:6)) < 1.0e-6_dp * norm2(v)) then
      text = 'translation along ' // direction(v(1:3))
    else
      text = 'rotation about ' // direction(v(4:6))
    end if
  end function describe_mode

  function direction(d) result(text)
    real(dp), intent(in) :: d(3)
    character(len=:), allocatable :: text
    real(dp) :: u(3)
    u = d / norm2(d)
    if (u(maxloc(abs(u), 1)) < 0.0_dp) u = -u
    where (abs(u) < 1.0e-9_dp) u = 0.0_dp
    text = '(' // str(u(1), 3) // ', ' // str(u(2), 3) // ', ' // str(u(3), 3) // ')'
  end function direction

  !> "the body of elements 1..16" or "the assembly of 2 bodies (elements 1, 10001, ...)".
  function body_name(model, assembly, id) result(text)
    type(model_t), intent(in) :: model
    integer, intent(in) :: assembly(:), id
    character(len=:), allocatable :: text
    integer :: e, n, first
    n = 0
    first = 0
    do e = 1, model%mesh%n_elements
      if (assembly(model%mesh%connectivity(1, e)) /= id) cycle
      n = n + 1
      if (first == 0) first = e
    end do
    text = 'the body (or bodies in contact) of ' // str(n) // ' element(s), element ' // &
      str(model%mesh%element_id(first)) // ' among them,'
  end function body_name

  pure function cross(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross

end module fcs_model_supports
