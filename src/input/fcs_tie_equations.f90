!> Ties between triangular or quadratic faces as CalculiX makes them: each slave node within
!> the position tolerance of the master surface is tied to the closest point P of it by three
!> linear equations (ccx manual, *TIE: "the slave nodes are connected to the master faces by
!> multiple point constraints"),
!>
!>     u_s,d - sum_a N_a(xi_P) u_a,d = 0,   d = 1, 2, 3                                     (T1)
!>
!> with N_a the master face's shape functions at P (its nodes a). The equations join the
!> model's others (fcs_linear_constraints eliminates them, u_s dependent), so the tie is exact,
!> not a penalty. Ties between 4-node faces stay segment-to-segment penalty ties (the fault
!> model's; doc/theory.md 4.7); a tie with a triangular or quadratic face on either side
!> becomes equations here, at the end of the model's checks, and leaves the contact pairs.
!> A slave degree of freedom that *BOUNDARY prescribes in some step, or that another equation
!> already makes dependent, is left out (CalculiX skips those too); a slave node that is a node
!> of its master face is tied already. Slave nodes farther than the tolerance are not tied,
!> with one warning per tie.
module fcs_tie_equations
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_diagnostics, only: diagnostics_t
  use fcs_mesh, only: mesh_t
  use fcs_model, only: model_t
  use fcs_contact_pair, only: contact_pair_def_t
  use fcs_contact_areas, only: surface_face_nodes
  use fcs_contact_geometry, only: segment_point_t, segment_point, project_to_segment, &
                                  segment_clamp, segment_centre
  use fcs_linear_constraints, only: linear_equation_t, constraint_term_t
  use fcs_strings, only: str
  implicit none
  private
  public :: ties_as_equations

  !> Shape-function values below this are left out of (T1) (a slave node on a master edge).
  real(dp), parameter :: NEGLIGIBLE = 1.0e-12_dp

contains

  !> Every tied pair with a face of other than 4 nodes on either side becomes equations (T1),
  !> appended to model%equations; the pair leaves model%contact_pairs.
  subroutine ties_as_equations(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    logical, allocatable :: keep(:), held(:)
    integer :: k
    if (.not. allocated(model%contact_pairs)) return
    allocate (keep(size(model%contact_pairs)))
    keep = .true.
    do k = 1, size(model%contact_pairs)
      if (.not. model%contact_pairs(k)%tied) cycle
      if (bilinear_tie(model%mesh, model%contact_pairs(k))) cycle
      if (.not. allocated(held)) held = held_dofs(model)
      call tie_equations(model, model%contact_pairs(k), held, diag)
      keep(k) = .false.
    end do
    if (.not. all(keep)) model%contact_pairs = pack(model%contact_pairs, keep)
  end subroutine ties_as_equations

  !> True when both surfaces of the pair have only 4-node faces (a penalty tie, 4.7).
  logical function bilinear_tie(mesh, pair)
    type(mesh_t), intent(in) :: mesh
    type(contact_pair_def_t), intent(in) :: pair
    integer, allocatable :: slave_faces(:, :), master_faces(:, :)
    type(error_t), allocatable :: err
    bilinear_tie = .false.
    call surface_face_nodes(mesh, pair%slave_surface, slave_faces, err)
    if (allocated(err)) return
    call surface_face_nodes(mesh, pair%master_surface, master_faces, err)
    if (allocated(err)) return
    bilinear_tie = size(slave_faces, 1) == 4 .and. size(master_faces, 1) == 4 .and. &
                   all(slave_faces /= 0) .and. all(master_faces /= 0)
  end function bilinear_tie

  !> Degrees of freedom (3 (node - 1) + d) that (T1) must not make dependent: prescribed by
  !> *BOUNDARY in some step, or dependent in an equation already.
  function held_dofs(model) result(held)
    type(model_t), intent(in) :: model
    logical, allocatable :: held(:)
    integer :: k, i
    allocate (held(3 * model%mesh%n_nodes))
    held = .false.
    do k = 1, size(model%steps)
      do i = 1, size(model%steps(k)%boundary)
        associate (c => model%steps(k)%boundary(i))
          held(3 * (c%node - 1) + c%dof) = .true.
        end associate
      end do
    end do
    if (.not. allocated(model%equations)) return
    do k = 1, size(model%equations)
      associate (t => model%equations(k)%terms(1))
        held(3 * (t%node - 1) + t%dof) = .true.
      end associate
    end do
  end function held_dofs

  !> The equations (T1) of one tie.
  subroutine tie_equations(model, pair, held, diag)
    type(model_t), intent(inout) :: model
    type(contact_pair_def_t), intent(in) :: pair
    logical, intent(inout) :: held(:)
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: slaves(:), master_faces(:, :), face(:)
    type(linear_equation_t), allocatable :: added(:)
    type(segment_point_t) :: p
    type(error_t), allocatable :: err
    integer :: i, d, n_added, n_far, n_held, f, n, dof
    call surface_face_nodes(model%mesh, pair%master_surface, master_faces, err)
    if (allocated(err)) then
      call diag%report(pair%loc, '*TIE ' // pair%name // ': ' // err%message)
      return
    end if
    slaves = model%mesh%surface_node_list(pair%slave_surface)
    allocate (added(3 * size(slaves)))
    n_added = 0
    n_far = 0
    n_held = 0
    do i = 1, size(slaves)
      call closest_point(model%mesh%x, master_faces, model%mesh%x(:, slaves(i)), &
                         pair%position_tolerance, f, p)
      if (f == 0) then
        n_far = n_far + 1
        cycle
      end if
      n = count(master_faces(:, f) /= 0)
      face = master_faces(1:n, f)
      if (any(face == slaves(i))) cycle
      do d = 1, 3
        dof = 3 * (slaves(i) - 1) + d
        if (held(dof)) then
          n_held = n_held + 1
          cycle
        end if
        held(dof) = .true.
        n_added = n_added + 1
        added(n_added) = tie_equation(slaves(i), d, face, p%shape(1:n), pair)
      end do
    end do
    model%equations = [model%equations, added(1:n_added)]
    if (n_far > 0) call diag%warn(pair%loc, '*TIE ' // pair%name // ': ' // str(n_far) // &
      ' slave node(s) lie farther than the position tolerance (' // str(pair%position_tolerance) // &
      ') from the master surface and are not tied, as CalculiX leaves them')
    if (n_held > 0) call diag%warn(pair%loc, '*TIE ' // pair%name // ': ' // str(n_held) // &
      ' slave degree(s) of freedom are prescribed (*BOUNDARY) or dependent in another ' // &
      'equation already, and are not tied, as CalculiX leaves them')
  end subroutine tie_equations

  !> (T1) for slave node s, direction d, on the master face `face` with shape values m.
  function tie_equation(s, d, face, m, pair) result(equation)
    integer, intent(in) :: s, d, face(:)
    real(dp), intent(in) :: m(:)
    type(contact_pair_def_t), intent(in) :: pair
    type(linear_equation_t) :: equation
    integer :: a, n
    n = count(abs(m) > NEGLIGIBLE)
    allocate (equation%terms(n + 1))
    equation%terms(1) = constraint_term_t(node=s, dof=d, coefficient=1.0_dp)
    n = 1
    do a = 1, size(face)
      if (abs(m(a)) <= NEGLIGIBLE) cycle
      n = n + 1
      equation%terms(n) = constraint_term_t(node=face(a), dof=d, coefficient=-m(a))
    end do
    equation%loc = pair%loc
    equation%origin = '*TIE ' // pair%name
  end function tie_equation

  !> The point of the master faces closest to xs: the projection onto each face, clamped to
  !> it; face = 0 when none lies within `tolerance`.
  subroutine closest_point(x, faces, xs, tolerance, face, point)
    real(dp), intent(in) :: x(:, :), xs(3), tolerance
    integer, intent(in) :: faces(:, :)
    integer, intent(out) :: face
    type(segment_point_t), intent(out) :: point
    type(segment_point_t) :: p
    real(dp), allocatable :: xm(:, :)
    real(dp) :: best, gap, distance, reach
    integer :: f, n
    logical :: converged
    face = 0
    best = huge(1.0_dp)
    do f = 1, size(faces, 2)
      n = count(faces(:, f) /= 0)
      xm = x(:, faces(1:n, f))
      ! Faces whose nodes all lie farther than their own size plus the tolerance cannot hold
      ! the point.
      reach = maxval(norm2(xm - spread(xm(:, 1), 2, n), dim=1)) + tolerance
      if (minval(norm2(xm - spread(xs, 2, n), dim=1)) > reach) cycle
      call project_to_segment(xm, xs, segment_centre(n), p, gap, converged)
      if (.not. converged) cycle
      p = segment_point(xm, segment_clamp(p%xi, n))
      distance = norm2(xs - p%x)
      if (distance < best) then
        best = distance
        face = f
        point = p
      end if
    end do
    if (best > tolerance) face = 0
  end subroutine closest_point

end module fcs_tie_equations
