!> *CHANGE FRICTION and *CHANGE SURFACE BEHAVIOR applied at a step's start.
!> *CHANGE FRICTION: a new Coulomb friction for the pairs of an interaction from a step on
!> (CalculiX's meaning). At the start of the step each closed node takes the new mu; a
!> friction force beyond the new cone is scaled back onto it and the node slips, the return
!> mapping of the paper's friction-as-plasticity treatment (eqs. 2-6) applied to the stored
!> force; a force inside the cone sticks. Applying the changes is idempotent, so a run that
!> resumes within a step from a checkpoint applies them again without effect on the state.
module fcs_contact_friction_change
  use fcs_error, only: error_t
  use fcs_model, only: model_t, friction_change_t, behavior_change_t
  use fcs_contact_system, only: contact_system_t
  use fcs_contact_state, only: contact_state_t
  implicit none
  private
  public :: apply_friction_changes, apply_behavior_changes

contains

  !> The friction of every untied pair as the *CHANGE FRICTION cards of steps 1..k leave it
  !> (the last change of its interaction), and the closed nodes of changed pairs brought
  !> onto the new cone (contact_system_t%set_pair_friction). Pairs whose interaction was never
  !> changed are left alone.
  subroutine apply_friction_changes(contact, model, k, cstate, err)
    type(contact_system_t), intent(inout) :: contact
    type(model_t), intent(in) :: model
    integer, intent(in) :: k
    type(contact_state_t), intent(inout) :: cstate
    type(error_t), allocatable, intent(out) :: err
    type(friction_change_t) :: change
    integer :: p
    do p = 1, contact%n_pairs()
      if (contact%pair_is_tied(p)) cycle
      if (.not. last_change(model, k, model%contact_pairs(p)%interaction, change)) cycle
      call contact%set_pair_friction(p, change%friction, change%stick_stiffness, cstate, err)
      if (allocated(err)) return
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

  !> *CHANGE SURFACE BEHAVIOR of steps 1..k: every pair whose interaction was changed takes the
  !> last change's normal behaviour (contact_system_t%set_pair_behavior: new penalty or law; a
  !> tie is released). Idempotent, as the friction changes.
  subroutine apply_behavior_changes(contact, model, k, cstate)
    type(contact_system_t), intent(inout) :: contact
    type(model_t), intent(in) :: model
    integer, intent(in) :: k
    type(contact_state_t), intent(inout) :: cstate
    type(behavior_change_t) :: change
    integer :: p, j, c
    logical :: found
    do p = 1, contact%n_pairs()
      if (model%contact_pairs(p)%interaction <= 0) cycle
      found = .false.
      do j = 1, min(k, size(model%steps))
        if (.not. allocated(model%steps(j)%behavior_changes)) cycle
        do c = 1, size(model%steps(j)%behavior_changes)
          if (model%steps(j)%behavior_changes(c)%interaction /= model%contact_pairs(p)%interaction) cycle
          change = model%steps(j)%behavior_changes(c)
          found = .true.
        end do
      end do
      if (found) call contact%set_pair_behavior(p, change%normal_stiffness, change%overclosure, cstate)
    end do
  end subroutine apply_behavior_changes

end module fcs_contact_friction_change
