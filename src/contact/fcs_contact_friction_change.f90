!> *CHANGE FRICTION: a new Coulomb friction for the pairs of an interaction from a step on
!> (CalculiX's meaning). At the start of the step each closed node takes the new mu; a
!> friction force beyond the new cone is scaled back onto it and the node slips, the return
!> mapping of the paper's friction-as-plasticity treatment (eqs. 2-6) applied to the stored
!> force; a force inside the cone sticks. Applying the changes is idempotent, so a run that
!> resumes within a step from a checkpoint applies them again without effect on the state.
module fcs_contact_friction_change
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_model, only: model_t, friction_change_t
  use fcs_contact_system, only: contact_system_t
  use fcs_contact_state, only: contact_state_t
  use fcs_contact_element, only: CONTACT_STICK, CONTACT_SLIP
  use fcs_friction_factory, only: create_friction_law
  implicit none
  private
  public :: apply_friction_changes

  !> Relative band around the cone |f_t| = mu f_n within which a force counts as on it (so
  !> that applying the changes again leaves a slipping node slipping).
  real(dp), parameter :: CONE_TOLERANCE = 1.0e-9_dp

contains

  !> The friction of every untied pair as the *CHANGE FRICTION cards of steps 1..k leave it
  !> (the last change of its interaction), and the closed nodes of changed pairs brought
  !> onto the new cone. Pairs whose interaction was never changed are left alone.
  subroutine apply_friction_changes(contact, model, k, cstate, err)
    type(contact_system_t), intent(inout) :: contact
    type(model_t), intent(in) :: model
    integer, intent(in) :: k
    type(contact_state_t), intent(inout) :: cstate
    type(error_t), allocatable, intent(out) :: err
    type(friction_change_t) :: change
    integer :: p
    do p = 1, size(contact%pairs)
      if (contact%pairs(p)%tied) cycle
      if (.not. last_change(model, k, model%contact_pairs(p)%interaction, change)) cycle
      if (allocated(contact%pairs(p)%law)) deallocate (contact%pairs(p)%law)
      call create_friction_law(change%friction, contact%pairs(p)%law, err)
      if (allocated(err)) return
      if (change%stick_stiffness > 0.0_dp) contact%pairs(p)%stick_stiffness = change%stick_stiffness
      call onto_cone(contact, p, cstate)
    end do
  end subroutine apply_friction_changes

  !> The last *CHANGE FRICTION of `interaction` in steps 1..k; false if none.
  logical function last_change(model, k, interaction, change) result(found)
    type(model_t), intent(in) :: model
    integer, intent(in) :: k, interaction
    type(friction_change_t), intent(out) :: change
    integer :: j, c
    found = .false.
    do j = 1, min(k, size(model%steps))
      if (.not. allocated(model%steps(j)%friction_changes)) cycle
      do c = 1, size(model%steps(j)%friction_changes)
        if (model%steps(j)%friction_changes(c)%interaction /= interaction) cycle
        change = model%steps(j)%friction_changes(c)
        found = .true.
      end do
    end do
  end function last_change

  !> Closed nodes of pair p under its (Coulomb) law: mu, and a friction force f_t with
  !> |f_t| <= mu f_n. Beyond the cone f_t is scaled onto it and the node slips; a slipping
  !> node on the cone (within CONE_TOLERANCE) keeps slipping; any other closed node sticks.
  !> On a frictionless interface (mu = 0) a closed node slips with f_t = 0.
  subroutine onto_cone(contact, p, cstate)
    type(contact_system_t), intent(in) :: contact
    integer, intent(in) :: p
    type(contact_state_t), intent(inout) :: cstate
    real(dp) :: mu, limit, magnitude
    integer :: s
    associate (pair => contact%pairs(p))
      mu = pair%law%mu(0.0_dp, 0.0_dp, pair%law%initial_state())
      do s = pair%first, pair%last
        if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) cycle
        cstate%mu(s) = mu
        limit = mu * max(cstate%normal_force(s), 0.0_dp)
        magnitude = norm2(cstate%friction(:, s))
        if (mu <= 0.0_dp .or. magnitude > limit * (1.0_dp + CONE_TOLERANCE)) then
          if (magnitude > 0.0_dp) cstate%friction(:, s) = cstate%friction(:, s) * (limit / magnitude)
          cstate%trial_norm(s) = max(magnitude, limit)
          cstate%status(s) = CONTACT_SLIP
        else if (cstate%status(s) == CONTACT_SLIP .and. &
                 magnitude >= limit * (1.0_dp - CONE_TOLERANCE)) then
          cycle
        else
          cstate%status(s) = CONTACT_STICK
        end if
      end do
    end associate
  end subroutine onto_cone

end module fcs_contact_friction_change
