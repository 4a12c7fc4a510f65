!> The datasets of a case of an interlock-history file (docs/history-output.md): their names in
!> the order they are written, which `&output store = 'curves'` keeps, and which belong to 3D
!> cases only. The deck's &output picks among them; interlock_history_output writes them.
module interlock_deck_schema
  implicit none
  private
  public :: n_datasets, history_datasets, curves_datasets, first_3d_dataset, n_always, &
            datasets_text, dataset_index

  !> The datasets of a case (docs/history-output.md), in the order they are written; `&output`
  !> `store` picks among them ('all', 'curves' or a comma-separated list of these names). The
  !> first three (time, separation, traction) are always written.
  !> The last two (the strike components of the frictional slip and of the friction traction)
  !> belong to 3D cases only.
  integer, parameter :: n_datasets = 17
  character(len=20), parameter :: history_datasets(n_datasets) = [character(len=20) :: 'time', &
    'separation', 'traction', 'damage', 'beta', 'theta', 'zeta', 'frictional_slip', &
    'friction_traction', 'work', 'stored_energy', 'damage_dissipation', &
    'friction_dissipation', 'iterations', 'substeps', 'sf_strike', 'tauf_strike']
  integer, parameter :: first_3d_dataset = 16
  !> store = 'curves': no per-plane dataset.
  logical, parameter :: curves_datasets(n_datasets) = [.true., .true., .true., .false., &
    .false., .false., .false., .false., .false., .true., .true., .true., .true., .true., .true., &
    .false., .false.]
  !> The first n_always datasets (time, separation, traction) are always written.
  integer, parameter :: n_always = 3

contains

  !> Index of dataset `name` in history_datasets, 0 if there is none.
  pure integer function dataset_index(name)
    character(len=*), intent(in) :: name
    integer :: k
    dataset_index = 0
    do k = 1, n_datasets
      if (trim(history_datasets(k)) == trim(name)) then
        dataset_index = k
        return
      end if
    end do
  end function dataset_index

  !> "time, separation, ...": the dataset names of a case.
  pure function datasets_text() result(text)
    character(len=:), allocatable :: text
    integer :: k
    text = trim(history_datasets(1))
    do k = 2, n_datasets
      text = text // ', ' // trim(history_datasets(k))
    end do
  end function datasets_text

end module interlock_deck_schema
