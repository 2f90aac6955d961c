!> Assembly of the element contributions: tangent stiffness K and internal forces from every
!> hexahedron, face-pressure forces and their load stiffness, and the element cliques of the
!> sparse pattern.
module fcs_assembly
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  use fcs_model, only: model_t, FORMULATION_BBAR
  use fcs_state, only: state_t
  use fcs_material, only: material_t
  use fcs_material_factory, only: create_material
  use fcs_hex8_element, only: hex8_geometry_t, hex8_geometry, hex8_tangent, hex8_internal_force
  use fcs_hex8_face, only: face_pressure_load
  use fcs_hex8_shape, only: N_GAUSS_HEX8
  use fcs_mesh, only: hex8_face_nodes
  use fcs_sparse, only: sparse_matrix_t
  use fcs_loading, only: step_loading_t
  use fcs_strings, only: str
  implicit none
  private
  public :: material_slot_t, make_materials, assemble_elements, assemble_pressures
  public :: element_cliques, element_configuration, inverted_element_error, plastic_fields

  !> One material object per *MATERIAL.
  type :: material_slot_t
    class(material_t), allocatable :: m
  end type material_slot_t

contains

  !> Material objects for the model's materials; `n_state` is the largest number of
  !> internal variables any of them keeps per integration point.
  subroutine make_materials(model, slots, n_state, err)
    type(model_t), intent(in) :: model
    type(material_slot_t), allocatable, intent(out) :: slots(:)
    integer, intent(out) :: n_state
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    allocate (slots(size(model%materials)))
    n_state = 0
    do k = 1, size(model%materials)
      call create_material(model%materials(k)%youngs_modulus, model%materials(k)%poisson_ratio, &
                           model%materials(k)%plastic, slots(k)%m, err)
      if (allocated(err)) return
      n_state = max(n_state, slots(k)%m%n_state())
    end do
  end subroutine make_materials

  !> The plastic state of every integration point, as each element's material reports it:
  !> equivalent plastic strain peeq(q, e), plastic strain(6, q, e) (Voigt, engineering shear)
  !> and back stress(6, q, e); zeros for materials without plasticity.
  subroutine plastic_fields(model, state, slots, peeq, plastic_strain, back_stress)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(material_slot_t), intent(in) :: slots(:)
    real(dp), allocatable, intent(out) :: peeq(:, :), plastic_strain(:, :, :), back_stress(:, :, :)
    integer :: e, q
    allocate (peeq(N_GAUSS_HEX8, state%n_elements), plastic_strain(6, N_GAUSS_HEX8, state%n_elements), &
              back_stress(6, N_GAUSS_HEX8, state%n_elements))
    do e = 1, state%n_elements
      associate (material => slots(model%sections(model%element_section(e))%material)%m)
        do q = 1, N_GAUSS_HEX8
          peeq(q, e) = material%equivalent_plastic_strain(state%material_state(:, q, e))
          plastic_strain(:, q, e) = material%plastic_strain(state%material_state(:, q, e))
          back_stress(:, q, e) = material%back_stress(state%material_state(:, q, e))
        end do
      end associate
    end do
  end subroutine plastic_fields

  !> Node lists of the given elements as cliques for the sparse pattern.
  subroutine element_cliques(model, elements, clique_ptr, clique_nodes)
    type(model_t), intent(in) :: model
    integer, intent(in) :: elements(:)
    integer, allocatable, intent(out) :: clique_ptr(:), clique_nodes(:)
    integer :: i, ne
    ne = size(elements)
    allocate (clique_ptr(ne + 1), clique_nodes(8 * ne))
    do i = 1, ne
      clique_ptr(i) = 8 * (i - 1) + 1
      clique_nodes(8 * i - 7:8 * i) = model%mesh%connectivity(:, elements(i))
    end do
    clique_ptr(ne + 1) = 8 * ne + 1
  end subroutine element_cliques

  !> Coordinates of element e's nodes on the configuration integrals are taken on: current
  !> (NLGEOM) or reference.
  pure function element_configuration(model, state, e, nlgeom) result(x)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    integer, intent(in) :: e
    logical, intent(in) :: nlgeom
    real(dp) :: x(3, 8)
    if (nlgeom) then
      x = state%x(:, model%mesh%connectivity(:, e))
    else
      x = model%mesh%x(:, model%mesh%connectivity(:, e))
    end if
  end function element_configuration

  !> Error for an element whose Jacobian is no longer positive.
  subroutine inverted_element_error(model, e, err)
    type(model_t), intent(in) :: model
    integer, intent(in) :: e
    type(error_t), allocatable, intent(out) :: err
    call fatal_error(err, 'element ' // str(model%mesh%element_id(e)) // ' is inverted ' // &
      '(Jacobian determinant <= 0): the deformation is too large for the mesh, or a load or ' // &
      'contact penalty crushes it; refine the mesh there or reduce the R-minimum limits')
  end subroutine inverted_element_error

  !> Internal forces f_int (3*n_nodes) of the given elements and, when `matrix` is present,
  !> their tangent K added into it (values only: the caller zeroes it). Points marked in
  !> `elastic(q, e)` (elastic unloading) take the elastic tangent. With `flux` (n_nodes), the
  !> sum over the elements of a node of the magnitudes of their nodal forces: the force the
  !> node passes on, the scale its out-of-balance force is measured against (f_int itself
  !> vanishes at a free node in equilibrium).
  subroutine assemble_elements(model, state, slots, nlgeom, elements, f_int, err, matrix, elastic, &
                               flux)
    type(model_t), intent(in) :: model
    type(state_t), intent(in) :: state
    type(material_slot_t), intent(in) :: slots(:)
    logical, intent(in) :: nlgeom
    integer, intent(in) :: elements(:)
    real(dp), intent(out) :: f_int(:)
    type(error_t), allocatable, intent(out) :: err
    type(sparse_matrix_t), intent(inout), optional :: matrix
    logical, intent(in), optional :: elastic(:, :)
    real(dp), intent(out), optional :: flux(:)
    type(hex8_geometry_t) :: geo
    real(dp) :: k(24, 24), f(24), c(6, 6, N_GAUSS_HEX8)
    integer :: e, q, a, node, s, i
    logical :: ok, bbar, missing
    f_int = 0.0_dp
    if (present(flux)) flux = 0.0_dp
    do i = 1, size(elements)
      e = elements(i)
      call hex8_geometry(element_configuration(model, state, e, nlgeom), geo, ok)
      if (.not. ok) then
        call inverted_element_error(model, e, err)
        return
      end if
      s = model%element_section(e)
      bbar = model%sections(s)%formulation == FORMULATION_BBAR
      call hex8_internal_force(geo, state%stress(:, :, e), bbar, f)
      do a = 1, 8
        node = model%mesh%connectivity(a, e)
        f_int(3 * node - 2:3 * node) = f_int(3 * node - 2:3 * node) + f(3 * a - 2:3 * a)
      end do
      if (present(flux)) then
        do a = 1, 8
          node = model%mesh%connectivity(a, e)
          flux(node) = flux(node) + norm2(f(3 * a - 2:3 * a))
        end do
      end if
      if (.not. present(matrix)) cycle
      associate (material => slots(model%sections(s)%material)%m)
        do q = 1, N_GAUSS_HEX8
          c(:, :, q) = material%tangent(state%stress(:, q, e), state%material_state(:, q, e))
        end do
        if (present(elastic)) then
          do q = 1, N_GAUSS_HEX8
            if (elastic(q, e)) c(:, :, q) = material%elastic_matrix()
          end do
        end if
      end associate
      call hex8_tangent(geo, state%stress(:, :, e), c, bbar, nlgeom, k)
      call matrix%add_matrix(model%mesh%connectivity(:, e), k, missing)
    end do
  end subroutine assemble_elements

  !> Pressure forces at step time t added to f_ext; with `matrix` (NLGEOM only) the follower
  !> load stiffness -dF/dx is added to the tangent.
  subroutine assemble_pressures(model, loading, t, state, nlgeom, f_ext, matrix)
    type(model_t), intent(in) :: model
    type(step_loading_t), intent(in) :: loading
    real(dp), intent(in) :: t
    type(state_t), intent(in) :: state
    logical, intent(in) :: nlgeom
    real(dp), intent(inout) :: f_ext(:)
    type(sparse_matrix_t), intent(inout), optional :: matrix
    real(dp) :: xf(3, 4), f(12), dfdx(12, 12), p
    integer :: i, a, nodes(4)
    logical :: missing
    do i = 1, size(loading%face_element)
      p = loading%pressure_at(model%amplitudes, i, t)
      nodes = hex8_face_nodes(model%mesh, loading%face_element(i), loading%face_number(i))
      if (nlgeom) then
        xf = state%x(:, nodes)
      else
        xf = model%mesh%x(:, nodes)
      end if
      if (present(matrix) .and. nlgeom) then
        call face_pressure_load(xf, p, f, dfdx)
        call matrix%add_matrix(nodes, -dfdx, missing)
      else
        call face_pressure_load(xf, p, f)
      end if
      do a = 1, 4
        f_ext(3 * nodes(a) - 2:3 * nodes(a)) = f_ext(3 * nodes(a) - 2:3 * nodes(a)) + f(3 * a - 2:3 * a)
      end do
    end do
  end subroutine assemble_pressures

end module fcs_assembly
