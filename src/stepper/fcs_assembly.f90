!> Assembly glue of the stepper: the material objects of the model's materials, and the
!> face-pressure forces and their load stiffness (the element loops, fcs_element_loops,
!> assemble the elements themselves).
module fcs_assembly
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_model, only: model_t
  use fcs_material, only: material_slot_t
  use fcs_material_factory, only: create_material
  use fcs_element_loops, only: element_loops_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_loading, only: step_loading_t
  implicit none
  private
  public :: make_materials, assemble_pressures

contains

  !> Material objects for the model's materials.
  subroutine make_materials(model, slots, err)
    type(model_t), intent(in) :: model
    type(material_slot_t), allocatable, intent(out) :: slots(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    allocate (slots(size(model%materials)))
    do k = 1, size(model%materials)
      call create_material(model%materials(k)%youngs_modulus, model%materials(k)%poisson_ratio, &
                           model%materials(k)%plastic, slots(k)%m, err)
      if (allocated(err)) return
      slots(k)%m%thermal = model%materials(k)%thermal
    end do
  end subroutine make_materials

  !> Pressure forces at step time t added to f_ext, on the current coordinates x (NLGEOM) or
  !> the reference ones; with `matrix` (NLGEOM only) the follower load stiffness -dF/dx is
  !> added to the tangent.
  subroutine assemble_pressures(elements, loading, model, t, x, nlgeom, f_ext, matrix)
    type(element_loops_t), intent(in) :: elements
    type(step_loading_t), intent(in) :: loading
    type(model_t), intent(in) :: model
    real(dp), intent(in) :: t, x(:, :)
    logical, intent(in) :: nlgeom
    real(dp), intent(inout) :: f_ext(:)
    type(sparse_matrix_t), intent(inout), optional :: matrix
    real(dp), allocatable :: f(:), dfdx(:, :)
    integer, allocatable :: nodes(:)
    real(dp) :: p
    integer :: i, a, m
    logical :: missing
    do i = 1, size(loading%face_element)
      p = loading%pressure_at(model%amplitudes, i, t)
      nodes = elements%face_nodes(loading%face_element(i), loading%face_number(i))
      m = size(nodes)
      if (allocated(f)) deallocate (f, dfdx)
      allocate (f(3 * m), dfdx(3 * m, 3 * m))
      if (present(matrix) .and. nlgeom) then
        call elements%face_pressure(loading%face_element(i), loading%face_number(i), x, nlgeom, p, f, dfdx)
        call matrix%add_matrix(nodes, -dfdx, missing)
      else
        call elements%face_pressure(loading%face_element(i), loading%face_number(i), x, nlgeom, p, f)
      end if
      do a = 1, m
        f_ext(3 * nodes(a) - 2:3 * nodes(a)) = f_ext(3 * nodes(a) - 2:3 * nodes(a)) + f(3 * a - 2:3 * a)
      end do
    end do
  end subroutine assemble_pressures

end module fcs_assembly
