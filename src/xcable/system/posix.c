/* The few things xcable needs from the operating system that Fortran does not
 * offer (bound in src/xcable/system/posix.f90, module xcable_system):
 *
 *  - a SIGTERM handler that only sets a flag (the step loop of a run checks
 *    it, writes a checkpoint and stops; nothing else happens in the handler);
 *  - replacing a file atomically and durably: fsync the new file, rename it
 *    over the old one, fsync the directory (a checkpoint is either the old
 *    one or the new one, also after a crash of the node);
 *  - a 64-bit checksum of memory (FNV-1a on 64-bit words), to tell a damaged
 *    checkpoint from a good one;
 *  - the process id (part of a run's identifier).
 */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static volatile sig_atomic_t termination_flag = 0;

static void on_termination(int signal_number)
{
    (void)signal_number;
    termination_flag = 1;
}

/* Install the SIGTERM handler; 0 or errno. */
int xcable_install_termination_handler(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_termination;
    sigemptyset(&action.sa_mask);
    /* Interrupted reads and writes (HDF5, gnuplot text) restart. */
    action.sa_flags = SA_RESTART;
    return sigaction(SIGTERM, &action, NULL) == 0 ? 0 : errno;
}

/* 1 once SIGTERM has arrived (after the handler was installed), else 0. */
int xcable_termination_requested(void)
{
    return termination_flag != 0;
}

/* Forget an earlier SIGTERM (tests). */
void xcable_clear_termination(void)
{
    termination_flag = 0;
}

/* Send SIGTERM to this process (tests); 0 or errno. */
int xcable_raise_termination(void)
{
    return raise(SIGTERM) == 0 ? 0 : errno;
}

/* fsync a file or directory by path; 0 or errno. */
static int sync_path(const char *path, int flags)
{
    int fd = open(path, flags);
    int status = 0;
    if (fd < 0) return errno;
    if (fsync(fd) != 0 && errno != EINVAL) status = errno;
    close(fd);
    return status;
}

/* Replace target by source: fsync source, rename it to target, fsync the
 * directory of target. 0 or errno (of the step that failed). */
int xcable_replace_file(const char *source, const char *target)
{
    int status = sync_path(source, O_RDONLY);
    char *directory;
    char *slash;
    if (status != 0) return status;
    if (rename(source, target) != 0) return errno;
    directory = strdup(target);
    if (directory == NULL) return 0;
    slash = strrchr(directory, '/');
    if (slash == NULL) {
        strcpy(directory, ".");
    } else if (slash == directory) {
        slash[1] = '\0';
    } else {
        *slash = '\0';
    }
    /* A directory that cannot be synced (some network file systems) is not
     * an error: the rename itself has happened. */
    (void)sync_path(directory, O_RDONLY);
    free(directory);
    return 0;
}

/* The message of an errno value, into message (length capacity, blank-padded
 * for Fortran). */
void xcable_error_text(int number, char *message, size_t capacity)
{
    const char *text = strerror(number);
    size_t length = strlen(text);
    if (length > capacity) length = capacity;
    memcpy(message, text, length);
    memset(message + length, ' ', capacity - length);
}

/* The id of this process. */
int xcable_process_id(void)
{
    return (int)getpid();
}

/* Continue the checksum hash over bytes of memory: FNV-1a with 64-bit words
 * (a whole word is xor-ed in before each multiplication), the tail bytewise.
 * Start from xcable_checksum_start. Any change of one word changes the
 * result. */
uint64_t xcable_checksum_update(uint64_t hash, const void *data, size_t bytes)
{
    const uint64_t prime = UINT64_C(0x100000001b3);
    const unsigned char *p = (const unsigned char *)data;
    size_t i = 0;
    for (; i + 8 <= bytes; i += 8) {
        uint64_t word;
        memcpy(&word, p + i, 8);
        hash = (hash ^ word) * prime;
    }
    for (; i < bytes; ++i) hash = (hash ^ p[i]) * prime;
    /* The length too: a shorter array with the same leading bytes differs. */
    return (hash ^ (uint64_t)bytes) * prime;
}

uint64_t xcable_checksum_start(void)
{
    return UINT64_C(0xcbf29ce484222325);
}
