!> How a deck is run and what it writes: &solver and &output.
submodule (interlock_deck) interlock_deck_run
  implicit none

contains

  module procedure read_solver
    character(len=32) :: scheme
    real(dp) :: substep_tol, newton_tol
    integer :: newton_max_iterations, max_cuts, ios
    logical :: ok, extrapolate
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /solver/ scheme, substep_tol, newton_tol, newton_max_iterations, max_cuts, extrapolate
    scheme = 'trapezoidal'
    substep_tol = 0.0_dp
    newton_tol = deck%control%tol
    newton_max_iterations = deck%control%max_iterations
    max_cuts = deck%control%max_cuts
    extrapolate = .false.
    message = ''
    read (u, nml=solver, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'solver', scan%a(kp))
        read (probe, nml=solver, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(5, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    select case (lower(trim(adjustl(scheme))))
    case ('explicit')
      deck%rows(prop_scheme) = scheme_explicit
    case ('implicit')
      deck%rows(prop_scheme) = scheme_implicit
    case ('trapezoidal')
      deck%rows(prop_scheme) = scheme_trapezoidal
    case default
      message = "scheme = '" // trim(scheme) // "' is inadmissible: admissible 'explicit', " // &
                "'implicit' or 'trapezoidal'"
      return
    end select
    call check_value(prop_substep_tol, substep_tol, message)
    if (len_trim(message) > 0) return
    deck%rows(prop_substep_tol) = substep_tol
    ok = .false.
    if (.not. is_nan_value(newton_tol)) ok = newton_tol >= 1.0e-16_dp .and. newton_tol <= 1.0e-2_dp
    if (.not. ok) then
      message = 'newton_tol = ' // value_str(newton_tol) // &
                ' is inadmissible: admissible 1e-16 <= newton_tol <= 1e-2 [-]'
      return
    end if
    if (newton_max_iterations < 1 .or. newton_max_iterations > 1000) then
      message = 'newton_max_iterations = ' // format_integer(newton_max_iterations) // &
                ' is inadmissible: admissible 1 <= newton_max_iterations <= 1000'
      return
    end if
    if (max_cuts < 0 .or. max_cuts > 50) then
      message = 'max_cuts = ' // format_integer(max_cuts) // ' is inadmissible: admissible 0 <= max_cuts <= 50'
      return
    end if
    deck%control%tol = newton_tol
    deck%control%max_iterations = newton_max_iterations
    deck%control%max_cuts = max_cuts
    deck%extrapolate = extrapolate
  end procedure read_solver

  module procedure read_output
    character(len=path_len + 1) :: file
    character(len=title_len + 1) :: title
    character(len=store_len + 1) :: store
    integer :: every
    integer :: ios
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /output/ file, title, every, store
    file = ''
    title = ''
    every = 1
    store = 'all'
    message = ''
    read (u, nml=output, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'output', scan%a(kp))
        read (probe, nml=output, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(8, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    if (len_trim(file) > path_len) then
      message = 'file is longer than ' // format_integer(path_len) // ' characters: admissible at most ' // &
                format_integer(path_len) // ' characters'
      return
    end if
    if (len_trim(title) > title_len) then
      message = 'title is longer than ' // format_integer(title_len) // ' characters: admissible at most ' // &
                format_integer(title_len) // ' characters'
      return
    end if
    file = adjustl(file)
    if (len_trim(file) == 0 .and. any(scan%a(1:scan%n)%name == 'file')) then
      message = "file = '" // trim(file) // "' is empty: give a file name, or leave file out " // &
                "for the default (the deck's name with .h5, in the working folder)"
      return
    end if
    if (len_trim(file) > 0) then
      if (file(len_trim(file):len_trim(file)) == '/' .or. trim(file) == '.' .or. &
          trim(file) == '..') then
        message = "file = '" // trim(file) // "' is a folder: give a file name (e.g. 'out/" // &
                  "result.h5'; the folder must exist)"
        return
      end if
      deck%output_file = trim(file)
      deck%output_given = .true.
    end if
    deck%title = trim(title)
    if (every < 1 .or. every > max_total_steps) then
      message = 'every = ' // format_integer(every) // ' is inadmissible: admissible 1 <= every <= ' // &
                format_integer(max_total_steps) // ' (every = k keeps rows 0, k, 2k, ... and the last)'
      return
    end if
    deck%every = every
    if (len_trim(store) > store_len) then
      message = 'store is longer than ' // format_integer(store_len) // ' characters: admissible ' // &
                "'all', 'curves' or a comma-separated list of dataset names: " // datasets_text()
      return
    end if
    call parse_store(store, deck%stored, message)
    deck%store_listed = all(lower(trim(adjustl(store))) /= [character(len=6) :: 'all', 'curves'])
  end procedure read_output

  !> &output store: 'all', 'curves', or a comma-separated list of dataset names (case and
  !> blanks do not matter; a name may be repeated). time, separation and traction are always
  !> written. message /= '' for anything else, listing the admissible names.
  subroutine parse_store(store, stored, message)
    character(len=*), intent(in) :: store
    logical, intent(out) :: stored(n_datasets)
    character(len=*), intent(out) :: message
    character(len=:), allocatable :: rest, item
    character(len=*), parameter :: admissible = "admissible 'all', 'curves' or a " // &
      'comma-separated list of dataset names: '
    integer :: comma, k, j
    message = ''
    stored = .true.
    select case (lower(trim(adjustl(store))))
    case ('all')
      return
    case ('curves')
      stored = curves_datasets
      return
    end select
    stored = .false.
    stored(1:n_always) = .true.
    rest = trim(store)
    k = 0
    do
      k = k + 1
      comma = index(rest, ',')
      if (comma > 0) then
        item = lower(trim(adjustl(rest(1:comma - 1))))
        rest = rest(comma + 1:)
      else
        item = lower(trim(adjustl(rest)))
      end if
      if (len(item) == 0) then
        message = "store = " // quoted(store) // " is inadmissible: item " // format_integer(k) // &
                  ' is empty; ' // admissible // datasets_text()
        return
      end if
      j = dataset_index(item)
      if (j == 0) then
        message = "store = " // quoted(store) // " is inadmissible: " // quoted(item) // " is not a " // &
                  'dataset name; ' // admissible // datasets_text()
        if (item == 'all' .or. item == 'curves') message = "store = " // quoted(store) // &
          " is inadmissible: " // quoted(item) // " stands alone, not in a list; " // admissible // &
          datasets_text()
        return
      end if
      stored(j) = .true.
      if (comma == 0) exit
    end do

  contains

    !> 'text' in quotes, cut to 60 characters ('...') so that the message keeps its end.
    pure function quoted(text) result(q)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: q
      if (len_trim(text) > 60) then
        q = "'" // text(1:60) // "...'"
      else
        q = "'" // trim(text) // "'"
      end if
    end function quoted

  end subroutine parse_store

end submodule interlock_deck_run
