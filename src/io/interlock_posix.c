/* What the programs need of POSIX that Fortran 2008 does not give: the kind of a path (regular
 * file, folder, or something else such as a FIFO or a device), whether two paths name the same
 * file, writing a small file with every error reported, and a guard that removes the temporary
 * output files when the program ends before they are complete (with a way to hold the signals
 * while two files are renamed together). Called from Fortran through bind(C) (module
 * interlock_files).
 *
 * The guard is the one piece of process-wide state of the programs: a signal handler can only
 * reach static storage. It keeps a few paths (a program writes at most two files at once); the
 * handler does only async-signal-safe things (unlink, sigaction, raise): it removes the files,
 * restores the signal's earlier action and raises the signal again, so that the program ends as
 * that signal ends it (exit status 128 + signal number in a shell: 130 for SIGINT, 141 for
 * SIGPIPE, 143 for SIGTERM). Guarded: every signal whose default action ends the process and
 * that can be caught. For the signals sent from outside (SIGINT, SIGTERM, SIGHUP, SIGQUIT,
 * SIGPIPE: a closed pipe such as `| head`, SIGALRM, SIGVTALRM, SIGPROF, SIGUSR1, SIGUSR2,
 * SIGXCPU: a CPU-time limit, SIGIO, SIGPWR) the earlier action is the default one, without the
 * Fortran runtime's backtrace; for the faults of the program itself (SIGSEGV, SIGBUS, SIGFPE,
 * SIGILL, SIGABRT, SIGTRAP, SIGSYS) it is the earlier handler, so a Debug build still prints its
 * backtrace. A normal end of the process (exit, a Fortran runtime error) removes them too
 * (atexit). SIGKILL cannot be caught: it leaves the temporary file behind (README,
 * "Reliability"). SIGXFSZ is ignored, so that a file-size limit is a failed write like a full
 * disk. A signal ignored by the parent (nohup, background jobs) stays ignored. */
#define _GNU_SOURCE
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

enum { guard_capacity = 8192, guard_slots = 4 };

static char guarded_paths[guard_slots][guard_capacity];
static volatile sig_atomic_t guard_armed[guard_slots];
static int handlers_installed = 0;

static const int sent_signals[] = {
    SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM, SIGVTALRM, SIGPROF, SIGUSR1, SIGUSR2,
    SIGXCPU,
#ifdef SIGIO
    SIGIO,
#endif
#ifdef SIGPWR
    SIGPWR,
#endif
};
static const int fault_signals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS};
enum {
    n_sent = sizeof sent_signals / sizeof sent_signals[0],
    n_fault = sizeof fault_signals / sizeof fault_signals[0]
};
/* The action each fault signal had before the guard (restored when it arrives). */
static struct sigaction earlier_fault_actions[n_fault];

/* 0: nothing there; 1: a regular file; 2: a folder; 3: anything else (FIFO, device, socket).
 * Symbolic links are followed. */
int interlock_path_kind(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) return 0;
    if (S_ISREG(st.st_mode)) return 1;
    if (S_ISDIR(st.st_mode)) return 2;
    return 3;
}

/* 1 when both paths exist and are the same file (device and inode), else 0. */
int interlock_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    if (stat(a, &sa) != 0 || stat(b, &sb) != 0) return 0;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

static void remove_guarded(void)
{
    int k;
    for (k = 0; k < guard_slots; ++k) {
        if (guard_armed[k]) unlink(guarded_paths[k]);
        guard_armed[k] = 0;
    }
}

static void remove_guarded_and_reraise(int sig)
{
    struct sigaction again;
    int k;
    remove_guarded();
    memset(&again, 0, sizeof again);
    again.sa_handler = SIG_DFL;
    sigemptyset(&again.sa_mask);
    for (k = 0; k < n_fault; ++k)
        if (fault_signals[k] == sig) again = earlier_fault_actions[k];
    sigaction(sig, &again, NULL);
    raise(sig);
}

static int install_handlers(void)
{
    struct sigaction sa;
    int k;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = remove_guarded_and_reraise;
    sigemptyset(&sa.sa_mask);
    for (k = 0; k < n_sent; ++k) sigaddset(&sa.sa_mask, sent_signals[k]);
    for (k = 0; k < n_sent; ++k) {
        struct sigaction old;
        if (sigaction(sent_signals[k], NULL, &old) != 0) return 2;
        if (old.sa_handler == SIG_IGN) continue;
        if (sigaction(sent_signals[k], &sa, NULL) != 0) return 2;
    }
    for (k = 0; k < n_fault; ++k) {
        if (sigaction(fault_signals[k], NULL, &earlier_fault_actions[k]) != 0) return 2;
        if (earlier_fault_actions[k].sa_handler == SIG_IGN) continue;
        if (sigaction(fault_signals[k], &sa, NULL) != 0) return 2;
    }
    /* A file-size limit (ulimit -f) then makes writes fail with EFBIG, reported like a full
     * disk, instead of killing the program (SIGXFSZ) with the file half written. */
    signal(SIGXFSZ, SIG_IGN);
    if (atexit(remove_guarded) != 0) return 2;
    return 0;
}

/* Install the guard's signal handlers now, before any file is guarded: a program that computes
 * for long before it writes (interlock-fit) then ends on SIGQUIT or SIGXCPU as on SIGINT, without
 * the Fortran runtime's backtrace, and a file-size limit fails its writes instead of killing it.
 * 0: installed (or already); 2: they could not be. */
int interlock_guard_signals(void)
{
    if (!handlers_installed) {
        int stat = install_handlers();
        if (stat != 0) return stat;
        handlers_installed = 1;
    }
    return 0;
}

/* hold = 1: block the signals sent from outside (those the guard catches), so that the steps
 * until hold = 0 (the renames of two files that belong together) are not interrupted between
 * them; hold = 0: unblock them, and a signal that came meanwhile takes effect then. The faults
 * of the program itself are never blocked. 0: done. */
int interlock_hold_signals(int hold)
{
    sigset_t set;
    int k;
    sigemptyset(&set);
    for (k = 0; k < n_sent; ++k) sigaddset(&set, sent_signals[k]);
    return sigprocmask(hold ? SIG_BLOCK : SIG_UNBLOCK, &set, NULL) == 0 ? 0 : 1;
}

/* Write the n bytes of `data` as the file `path` (created, or truncated if it is there) and
 * close it. 0: every byte written and closed; else the errno of the call that failed (the file
 * may then hold part of the bytes: the caller removes it). Fortran's own writes do not serve
 * here: gfortran reports no error when its buffer's write fails (a full disk) and writes the
 * buffer again at the close, one byte too many. */
int interlock_write_file(const char *path, const char *data, long n)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) return errno;
    while (n > 0) {
        ssize_t k = write(fd, data, (size_t)n);
        if (k < 0) {
            int e = errno;
            if (e == EINTR) continue;
            close(fd);
            return e;
        }
        data += k;
        n -= (long)k;
    }
    if (close(fd) != 0) return errno;
    return 0;
}

/* Remove `path` if the program ends before interlock_unguard_file(path). 0: armed; 1: the path
 * is too long or every slot is taken (not armed); 2: the handlers could not be installed. */
int interlock_guard_file(const char *path)
{
    size_t n = strlen(path);
    int k;
    if (n >= guard_capacity) return 1;
    if (interlock_guard_signals() != 0) return 2;
    for (k = 0; k < guard_slots; ++k) {
        if (guard_armed[k]) continue;
        memcpy(guarded_paths[k], path, n + 1);
        guard_armed[k] = 1;
        return 0;
    }
    return 1;
}

/* The file `path` is complete (renamed) or removed: the end of the program no longer touches
 * it. */
void interlock_unguard_file(const char *path)
{
    int k;
    for (k = 0; k < guard_slots; ++k)
        if (guard_armed[k] && strcmp(guarded_paths[k], path) == 0) guard_armed[k] = 0;
}
