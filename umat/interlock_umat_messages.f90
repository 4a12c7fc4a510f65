!> The UMAT's messages: each kind of message once per material and process.
!>
!> A host calls a UMAT once per integration point and iteration: a bad property reported at
!> every call is thousands of identical lines (millions in a real model), and the host's own
!> last line ("increment size smaller than minimum") is then read as the cause. So every
!> message of the UMAT entries (umat/interlock_umat_body.f90, umat/interlock_umat_layer.f90)
!> goes through `umat_say`, which writes a line only the first time its (material, kind) pair
!> is seen in the process, and then says that later ones are not written. The kind is what is
!> wrong, not the value: a property by its index, a STATEV slot by its index, a host argument,
!> a diverged global iteration, a failure of the local integration, ... (`said_*` below).
!> What the host is told (PNEWDT) does not change: every call still answers for itself.
!>
!> **Threads.** This is the UMAT's only mutable state shared between calls: the table of the
!> pairs already said. It is touched only when a message is due (never on the success path)
!> and only under a lock: a spin lock on one integer, taken by an atomic exchange
!> (`!$omp atomic capture seq_cst`) and released by an atomic write. The OpenMP atomics are
!> hardware instructions (no OpenMP runtime, no thread team needed): they serialise the threads
!> of any threading model (ccx's pthreads, Abaqus', OpenMP), provided this file is compiled
!> with OpenMP enabled (`-fopenmp`), as ccx's build (scripts/build_calculix.sh) and the CMake
!> library (umat/CMakeLists.txt, when the compiler supports OpenMP) do. Compiled without it, the
!> directives are comments: a single-threaded host is served exactly; a multi-threaded one may
!> see a line twice, never a corrupted table (every index is bounded).
module interlock_umat_messages
  use, intrinsic :: iso_fortran_env, only: output_unit
  implicit none
  private
  public :: umat_say, umat_messages_forget
  public :: said_argument, said_property, said_statev, said_stress, said_start_strain, &
            said_diverged, said_local_failure, said_replay, said_layer_axes

  !> Kinds of message; a kind plus an index (property, STATEV slot, component) is one key.
  integer, parameter :: said_argument = 1000       !< + which host argument (NTENS, ...)
  integer, parameter :: said_property = 2000       !< + the property's index
  integer, parameter :: said_statev = 3000         !< + the STATEV slot
  integer, parameter :: said_stress = 4000         !< + the component
  integer, parameter :: said_start_strain = 5000   !< + the component (STRAN: bad input)
  integer, parameter :: said_diverged = 6000       !< a diverged global iteration
  integer, parameter :: said_local_failure = 7000  !< the local integration failed
  integer, parameter :: said_replay = 8000         !< a replay deck could not be written
  integer, parameter :: said_layer_axes = 9000     !< the layer's axes look wrong (a warning)

  integer, parameter :: capacity = 512        !< (material, kind) pairs remembered
  integer, parameter :: name_len = 80         !< Abaqus' CMNAME length
  !> 0 free, 1 taken (volatile: re-read at every turn of the spin, with or without OpenMP)
  integer, volatile :: lock = 0
  integer :: n_said = 0
  character(len=name_len) :: said_material(capacity) = ''
  integer :: said_kind(capacity) = 0

contains

  !> Write `line` on the output unit if (material, kind) has not been said in this process;
  !> the first line of a pair ends with a note that later ones are not written. When the table
  !> is full every line is written (nothing is lost silently).
  subroutine umat_say(material, kind, line)
    character(len=*), intent(in) :: material, line
    integer, intent(in) :: kind
    logical :: first
    integer :: i, ios
    call acquire()
    first = .true.
    do i = 1, min(n_said, capacity)
      if (said_kind(i) == kind) then
        if (said_material(i) == material) then
          first = .false.
          exit
        end if
      end if
    end do
    if (first) then
      if (n_said < capacity) then
        n_said = n_said + 1
        said_material(n_said) = material
        said_kind(n_said) = kind
        write (output_unit, '(a)', iostat=ios) line // " (once per material: later messages of this " // &
          "kind for '" // trim(material) // "' are not written)"
      else
        write (output_unit, '(a)', iostat=ios) line
      end if
      flush (output_unit, iostat=ios)   ! (an output error must not stop the host)
    end if
    call release()
  end subroutine umat_say

  !> Forget every pair said (for test drivers that check the messages of many cases).
  subroutine umat_messages_forget()
    call acquire()
    n_said = 0
    call release()
  end subroutine umat_messages_forget

  subroutine acquire()
    integer :: held
    do
      !$omp atomic capture seq_cst
      held = lock
      lock = 1
      !$omp end atomic
      if (held == 0) exit
    end do
  end subroutine acquire

  subroutine release()
    !$omp atomic write seq_cst
    lock = 0
  end subroutine release

end module interlock_umat_messages
