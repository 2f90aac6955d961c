!> Assembly glue of the stepper: the material objects of the model's materials, and the
!> face-pressure forces and their load stiffness (the element loops, fcs_element_loops,
!> assemble the elements themselves).
module fcs_assembly
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_model, only: model_t, BODY_GRAV
  use fcs_material, only: material_t, material_slot_t
  use fcs_von_mises, only: von_mises_t
  use fcs_simo_plasticity, only: simo_from_von_mises
  use fcs_hyperelastic, only: HYPER_NONE
  use fcs_hyperelastic_material, only: hyperelastic_from_law
  use fcs_material_factory, only: create_material, PLASTICITY_NONE
  use fcs_element_loops, only: element_loops_t, BODY_FORCE_GRAVITY, BODY_FORCE_CENTRIFUGAL
  use fcs_sparse, only: sparse_matrix_t
  use fcs_loading, only: step_loading_t
  use fcs_element_state, only: element_state_t
  implicit none
  private
  public :: make_materials, assemble_pressures, apply_initial_stresses, assemble_body_loads

contains

  !> Material objects for the model's materials.
  subroutine make_materials(model, slots, err)
    type(model_t), intent(in) :: model
    type(material_slot_t), allocatable, intent(out) :: slots(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    allocate (slots(size(model%materials)))
    do k = 1, size(model%materials)
      if (model%materials(k)%hyperelastic%family /= HYPER_NONE) then
        ! *HYPERELASTIC, *HYPERFOAM: the stress a function of F (doc/theory.md 2.11).
        allocate (slots(k)%m, source=hyperelastic_from_law(model%materials(k)%hyperelastic))
        cycle
      end if
      if (model%materials(k)%anisotropic) then
        call create_material(model%materials(k)%youngs_modulus, model%materials(k)%poisson_ratio, &
                             model%materials(k)%plastic, slots(k)%m, err, model%materials(k)%stiffness)
      else
        call create_material(model%materials(k)%youngs_modulus, model%materials(k)%poisson_ratio, &
                             model%materials(k)%plastic, slots(k)%m, err)
      end if
      if (allocated(err)) return
      ! *ELASTIC with *PLASTIC: multiplicative finite-strain plasticity under NLGEOM
      ! (fcs_simo_plasticity, doc/theory.md 2.8); *HYPOELASTIC keeps the rate form.
      if (.not. model%materials(k)%hypoelastic) call to_multiplicative(slots(k)%m)
      slots(k)%m%thermal = model%materials(k)%thermal
      ! *ELASTIC without plasticity: St Venant-Kirchhoff under NLGEOM (doc/theory.md 2.10).
      slots(k)%m%st_venant_kirchhoff = .not. model%materials(k)%hypoelastic .and. &
                                       model%materials(k)%plastic%model == PLASTICITY_NONE
    end do
  end subroutine make_materials

  !> A von Mises material made CalculiX's multiplicative law (the rate form without NLGEOM);
  !> any other material unchanged.
  subroutine to_multiplicative(material)
    class(material_t), allocatable, intent(inout) :: material
    type(von_mises_t), allocatable :: law
    select type (material)
    type is (von_mises_t)
      law = material
    end select
    if (.not. allocated(law)) return
    deallocate (material)
    allocate (material, source=simo_from_von_mises(law))
  end subroutine to_multiplicative

  !> The stresses of *INITIAL CONDITIONS, TYPE=STRESS set into the integration-point fields
  !> at the start of the analysis, in deck order: a point's given stress, or, GEOSTATIC, at
  !> every point of the element the stress of its reference height z: szz = s1 + (s2 - s1)
  !> (z - z1) / (z2 - z1), sxx = k_x szz, syy = k_y szz (fcs_model, initial_stress_t).
  subroutine apply_initial_stresses(elements, model, fields)
    type(element_loops_t), intent(in) :: elements
    type(model_t), intent(in) :: model
    type(element_state_t), intent(inout) :: fields
    real(dp), allocatable :: x(:, :)
    real(dp) :: szz
    integer :: i, q, e
    call apply_initial_plastic_strains(elements, model, fields)
    if (.not. allocated(model%initial_stresses)) return
    do i = 1, size(model%initial_stresses)
      associate (item => model%initial_stresses(i))
        e = item%element
        if (.not. item%is_geostatic) then
          fields%stress(:, item%point, e) = item%stress
          cycle
        end if
        x = elements%point_positions(e)
        associate (g => item%geostatic)
          do q = 1, size(x, 2)
            szz = g(1) + (g(3) - g(1)) * (x(3, q) - g(2)) / (g(4) - g(2))
            fields%stress(:, q, e) = [g(5) * szz, g(6) * szz, szz, 0.0_dp, 0.0_dp, 0.0_dp]
          end do
        end associate
      end associate
    end do
  end subroutine apply_initial_stresses

  !> *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN (doc/theory.md 2.7): a point given eps_0 starts
  !> with the stress -C : eps_0 added to its initial stress (the elastic strain -eps_0 at zero
  !> displacement: CalculiX's sigma = C : (eps - eps_0) for small strains) and, if its
  !> material keeps a plastic strain (von Mises), with that plastic strain eps_0. A point
  !> given twice takes its last line, as in CalculiX.
  subroutine apply_initial_plastic_strains(elements, model, fields)
    type(element_loops_t), intent(in) :: elements
    type(model_t), intent(in) :: model
    type(element_state_t), intent(inout) :: fields
    logical, allocatable :: done(:, :)
    integer :: i, q, e
    if (.not. allocated(model%initial_plastic_strains)) return
    allocate (done(size(fields%stress, 2), size(fields%stress, 3)), source=.false.)
    do i = size(model%initial_plastic_strains), 1, -1
      associate (item => model%initial_plastic_strains(i))
        e = item%element
        q = item%point
        if (done(q, e)) cycle
        done(q, e) = .true.
        associate (material => elements%materials(elements%material(e))%m)
          fields%stress(:, q, e) = fields%stress(:, q, e) - &
                                   matmul(material%elastic_matrix(), item%strain)
          call material%add_plastic_strain(fields%material_state(1:material%n_state(), q, e), &
                                           item%strain)
        end associate
      end associate
    end do
  end subroutine apply_initial_plastic_strains

  !> Body-load forces (*DLOAD GRAV, CENTRIF) at step time t added to f_ext: consistent nodal
  !> forces of rho times the acceleration over each loaded element (fcs_element_loops,
  !> body_force), rho the density of its material; CENTRIF at the current positions x with
  !> NLGEOM, the reference ones without (as CalculiX).
  subroutine assemble_body_loads(elements, loading, model, t, x, nlgeom, f_ext)
    type(element_loops_t), intent(in) :: elements
    type(step_loading_t), intent(in) :: loading
    type(model_t), intent(in) :: model
    real(dp), intent(in) :: t, x(:, :)
    logical, intent(in) :: nlgeom
    real(dp), intent(inout) :: f_ext(:)
    real(dp) :: f(3 * size(elements%nodes, 1)), rho, magnitude
    integer :: i, e, a, node, kind_of_force
    do i = 1, size(loading%body_element)
      e = loading%body_element(i)
      magnitude = loading%body_load_at(model%amplitudes, i, t)
      if (magnitude == 0.0_dp) cycle
      rho = model%materials(model%sections(model%element_section(e))%material)%density
      kind_of_force = BODY_FORCE_CENTRIFUGAL
      if (loading%body_kind(i) == BODY_GRAV) kind_of_force = BODY_FORCE_GRAVITY
      call elements%body_force(e, x, nlgeom, kind_of_force, loading%body_vector(:, i), &
                               rho * magnitude, f)
      associate (nodes => model%mesh%element_nodes(e))
        do a = 1, size(nodes)
          node = nodes(a)
          f_ext(3 * node - 2:3 * node) = f_ext(3 * node - 2:3 * node) + f(3 * a - 2:3 * a)
        end do
      end associate
    end do
  end subroutine assemble_body_loads

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
