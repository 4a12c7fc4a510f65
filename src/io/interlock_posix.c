/* What interlock-history needs of POSIX that Fortran 2008 does not give: the kind of a path
 * (regular file, folder, or something else such as a FIFO or a device), whether two paths
 * name the same file, and a guard that removes the temporary output file when the program is
 * interrupted (SIGINT, SIGTERM, SIGHUP; SIGXFSZ is ignored, so that a file-size limit is a
 * failed write like a full disk). Called from Fortran through bind(C)
 * (module interlock_files).
 *
 * The guard is the one piece of process-wide state of the programs: a signal handler can only
 * reach static storage. It keeps one path; the handler does only async-signal-safe things
 * (unlink, sigaction, raise): it removes the file, restores the default action and raises the
 * signal again, so that the program ends as killed by that signal (exit status 128 + signal
 * number in a shell: 130 for SIGINT, 143 for SIGTERM). SIGKILL cannot be caught: it leaves the
 * temporary file behind (README, "Reliability"). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { guard_capacity = 8192 };

static char guarded_path[guard_capacity];
static volatile sig_atomic_t guard_armed = 0;
static int handlers_installed = 0;
static const int guarded_signals[] = {SIGINT, SIGTERM, SIGHUP};

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

static void remove_guarded_and_reraise(int sig)
{
    struct sigaction dfl;
    if (guard_armed) unlink(guarded_path);
    guard_armed = 0;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, NULL);
    raise(sig);
}

/* Remove `path` if the program is interrupted from now on. 0: armed; 1: the path is too long
 * (not armed); 2: the handlers could not be installed. */
int interlock_guard_file(const char *path)
{
    size_t n = strlen(path);
    size_t k;
    if (n >= guard_capacity) return 1;
    guard_armed = 0;
    memcpy(guarded_path, path, n + 1);
    if (!handlers_installed) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = remove_guarded_and_reraise;
        sigemptyset(&sa.sa_mask);
        for (k = 0; k < sizeof guarded_signals / sizeof guarded_signals[0]; ++k)
            sigaddset(&sa.sa_mask, guarded_signals[k]);
        for (k = 0; k < sizeof guarded_signals / sizeof guarded_signals[0]; ++k) {
            struct sigaction old;
            /* A signal ignored by the parent (nohup, background jobs) stays ignored. */
            if (sigaction(guarded_signals[k], NULL, &old) != 0) return 2;
            if (old.sa_handler == SIG_IGN) continue;
            if (sigaction(guarded_signals[k], &sa, NULL) != 0) return 2;
        }
        /* A file-size limit (ulimit -f) then makes writes fail with EFBIG, reported like a
         * full disk, instead of killing the program (SIGXFSZ) with the file half written. */
        signal(SIGXFSZ, SIG_IGN);
        handlers_installed = 1;
    }
    guard_armed = 1;
    return 0;
}

/* The file is complete (renamed) or removed: an interruption no longer touches it. */
void interlock_unguard_file(void)
{
    guard_armed = 0;
}
