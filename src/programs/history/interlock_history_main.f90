!> interlock-history DECK.nml [more decks]: each deck -> one HDF5 file (docs/history-output.md).
!> Exit status: 0 every case of every deck completed; 1 a deck was rejected, its output would
!> replace a file that is not an earlier result, or a file could not be written (no result file,
!> no temporary file is left for it); 2 every file was written but some case stopped early (its
!> `status` attribute says why). A signal that ends the program (SIGINT, SIGTERM, SIGHUP, SIGPIPE,
!> SIGQUIT, ...): the temporary file is removed and the program ends by the signal
!> (interlock_posix.c).
program interlock_history
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use interlock_program_start, only: program_start_t, program_start, program_end, in_output_dir
  use interlock, only: interlock_material_t, interlock_solver_t, interlock_state_3d_t, status_ok
  use interlock, only: dp
  use interlock_deck, only: deck_t, read_deck, deck_case, deck_n_cases, deck_loading
  use interlock_mixed_control, only: arc_t
  use interlock_mixed_control, only: run_history, run_history_extrapolated
  use interlock_history_output, only: output_t, case_writer_t, output_check_target, output_open, &
      output_begin_case, output_end_case, output_close, output_abort
  use interlock_files, only: is_folder
  implicit none

  type(program_start_t) :: start
  integer :: i, rc

  rc = 0
  call program_start('interlock-history', usage, .false., .false., start)
  do i = 1, size(start%decks)
    call run_deck(start%decks(i)%path, rc)
  end do
  call program_end(rc)

contains

  subroutine run_deck(path, rc)
    character(len=*), intent(in) :: path
    integer, intent(inout) :: rc
    type(deck_t) :: deck
    type(output_t) :: out
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: state
    type(case_writer_t) :: writer
    character(len=:), allocatable :: label, final_name, origin, folder
    character(len=1024) :: message
    integer :: stat, icase, slash
    character(len=8) :: cbuf
    logical :: jump_warned
    real(dp), allocatable :: values(:, :)
    type(arc_t), allocatable :: arcs(:)

    jump_warned = .false.
    call read_deck(path, deck, stat, message)
    if (stat /= status_ok) then
      write (error_unit, '(a)') 'interlock-history: error: ' // trim(message)
      rc = max(rc, 1)
      return
    end if
    final_name = in_output_dir(start%output_dir, deck%output_file)
    ! Where the file goes: the &output file (or --output-dir) must name a file in an
    ! existing folder; checked before anything is computed.
    origin = ' (the deck''s name with .h5'
    if (deck%output_given) origin = ' (&output: file = ''' // deck%output_file // ''''
    if (len(start%output_dir) > 0) then
      origin = origin // ' in --output-dir ' // start%output_dir // ')'
    else
      origin = origin // ')'
    end if
    slash = index(final_name, '/', back=.true.)
    folder = '.'
    if (slash > 1) folder = final_name(1:slash - 1)
    if (slash == 1) folder = '/'
    message = ''
    call output_check_target(final_name, path, message)
    if (len_trim(message) > 0) then
      message = trim(message) // origin
    else if (.not. is_folder(folder)) then
      message = 'the output folder ' // folder // ' does not exist' // origin
    end if
    if (len_trim(message) == 0) then
      call output_open(final_name, deck, start%command, out, stat, message)
      if (stat /= 0) message = trim(message) // origin
    end if
    if (len_trim(message) > 0) then
      write (error_unit, '(a)') 'interlock-history: error: ' // path // ': ' // trim(message)
      rc = max(rc, 1)
      return
    end if
    do icase = 1, deck_n_cases(deck)
      call deck_case(deck, icase, mat, solver, state, label, stat, message)
      if (stat /= status_ok) then
        write (error_unit, '(a)') 'interlock-history: error: ' // trim(message)
        call output_abort(out)
        rc = max(rc, 1)
        return
      end if
      call output_begin_case(out, icase, deck, mat, solver, label, writer, stat, message)
      if (stat == 0) then
        call deck_loading(deck, icase, values, arcs)
        if (deck%extrapolate .and. allocated(arcs)) then
          call run_history_extrapolated(mat, solver, deck%control, deck%times, values, &
                                        deck%steps, state, writer, arcs)
        else if (deck%extrapolate) then
          call run_history_extrapolated(mat, solver, deck%control, deck%times, values, &
                                        deck%steps, state, writer)
        else if (allocated(arcs)) then
          call run_history(mat, solver, deck%control, deck%times, values, deck%steps, state, &
                           writer, arcs)
        else
          call run_history(mat, solver, deck%control, deck%times, values, deck%steps, state, &
                           writer)
        end if
        call output_end_case(out, writer, stat, message)
      end if
      if (stat /= 0) then
        write (error_unit, '(a)') 'interlock-history: error: ' // path // ': ' // trim(message)
        call output_abort(out)
        rc = max(rc, 1)
        return
      end if
      write (cbuf, '(i4.4)') icase
      if (len(label) > 0) then
        write (output_unit, '(a)') path // ': case ' // trim(cbuf) // ' (' // label // '): ' // &
          writer%status
      else
        write (output_unit, '(a)') path // ': case ' // trim(cbuf) // ': ' // writer%status
      end if
      if (writer%status /= 'completed') rc = max(rc, 2)
      if (len(writer%sliding_jumps) > 0 .and. .not. jump_warned) then
        jump_warned = .true.
        write (error_unit, '(a)') path // ': case ' // trim(cbuf) // ': warning: planes ' // &
          'slide or wear within a segment of one step (' // writer%sliding_jumps // '): ' // &
          'the state at its end is the scheme''s, not the law''s (the schemes differ there, ' // &
          'whatever the steps elsewhere); give each such segment more steps to follow the law ' // &
          '(docs/deck-format.md, "steps")'
      end if
    end do
    call output_close(out, stat, message)
    if (stat /= 0) then
      write (error_unit, '(a)') 'interlock-history: error: ' // path // ': ' // trim(message)
      rc = max(rc, 1)
      return
    end if
    write (output_unit, '(a)') path // ' -> ' // final_name
  end subroutine run_deck

  subroutine usage(unit)
    integer, intent(in) :: unit
    write (unit, '(a)') &
      'usage: interlock-history [--output-dir DIR] [--] DECK.nml [DECK.nml ...]', &
      '', &
      'Runs the point history of each deck (a Fortran namelist, docs/deck-format.md) and', &
      'writes one HDF5 file per deck (docs/history-output.md): the &output file, or the', &
      'deck''s name with .h5 in the working folder. The file is written as NAME.h5.tmp-PID', &
      'and renamed when complete: a rejected deck or a failed write leaves no file, and', &
      'a signal that ends the program (SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, ...)', &
      'removes the temporary file (SIGKILL leaves it). An existing', &
      'file is replaced only if it is an earlier result of interlock-history: never the', &
      'deck or any other file.', &
      '', &
      'Options:', &
      '  -d, --output-dir DIR  write the files into DIR (an existing folder), same base names', &
      '  -h, --help            print this help and exit (status 0)', &
      '      --version         print the library version and exit (status 0)', &
      '  --                    end of options (a deck name may then start with -)', &
      '', &
      'Exit status:', &
      '  0  every case of every deck completed', &
      '  1  a deck was rejected (the message on stderr names the deck file, the group, the', &
      '     variable and the admissible range), an option is wrong, or a file could not be', &
      '     written; nothing is written for that deck (other decks are still run)', &
      '  2  every file was written but some case stopped early: its status attribute says', &
      '     at which step and why (the rows up to that step are kept)', &
      '', &
      'Per step (datasets iterations and substeps), with A = 4 (max_cuts+1) (max_cuts+2)', &
      'attempts at most per step (3968 with the default &solver max_cuts = 30):', &
      '  0 <= iterations <= newton_max_iterations * A   (Newton iterations of the mixed-', &
      '                                                 control solve, all attempts)', &
      '  1 <= substeps   <= 100000 * A                  (library sub-increments of the', &
      '                                                 accepted attempts)', &
      'A step that still fails after max_cuts halvings in a row stops the case.', &
      '', &
      'Global Richardson extrapolation (&solver extrapolate = .true.; default .false.):', &
      'each case is run twice from the same initial state, with the deck''s steps (n) and', &
      'with the step count of every segment of more than one step doubled (2n; a one-step', &
      'segment, e.g. the preload, is taken alike in both). The history is written at the n run''s', &
      'steps: separation and traction are 2 u(2n) - u(n) (second order where the scheme is', &
      'first order in the step: scheme = ''implicit'' with wear), the state variables and', &
      'energies are the 2n run''s (not extrapolated), iterations and substeps the sums of', &
      'both runs (up to 3 steps per row: 3x the bounds above); about 3x the CPU time of one', &
      'run. The case stops at the first step that either run cannot solve (status: which).', &
      '', &
      'What is written (&output): every = k keeps every k-th step (and the last one);', &
      'store = ''all'' (default), ''curves'' (no per-plane datasets) or a comma-separated', &
      'list of dataset names (time, separation and traction are always written).', &
      '', &
      'Limits: decks of at most 4 MiB of text (LF or CR LF line ends), 10001 points,', &
      '2,000,000 steps per case, 1000 sweep values.'
  end subroutine usage


end program interlock_history
