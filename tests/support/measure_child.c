/* m3055_measure_child RESULT_FILE PROGRAM [ARG...]: runs PROGRAM as its own
 * child and writes "seconds peak_rss_kb signal cpu_seconds minor_faults
 * major_faults" to RESULT_FILE when it ends (the tests read the first three,
 * scripts/bench-capture all); exits with the child's status (128 + N when
 * signal N killed it).
 *
 * Why a separate process: a child's getrusage peak includes the resident
 * memory of the process it was forked from (Linux keeps the old image's high
 * water mark across exec), so a test process holding 300 MB of generated
 * input would read 300 MB for any child. This launcher is small when it
 * forks, so what wait4 reports here is the child's own peak.
 * SIGINT, SIGTERM, SIGHUP and SIGBUS sent to the launcher are passed on to
 * the child, so tests can interrupt the program through it (SIGBUS: the last
 * resort against a full disk under the shader cache, tested by hand). */
#define _GNU_SOURCE
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static volatile pid_t child = 0;

static void forward(int sig) {
    if (child > 0) kill(child, sig);
}

int main(int argc, char** argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: m3055_measure_child RESULT_FILE PROGRAM [ARG...]\n");
        return 127;
    }
    struct sigaction action = {0};
    action.sa_handler = forward;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    /* Blocked until the child exists, so none is lost between fork and handler. */
    sigset_t signals, previous;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    sigaddset(&signals, SIGHUP);
    sigaddset(&signals, SIGBUS);
    sigprocmask(SIG_BLOCK, &signals, &previous);
    struct timespec start, end;
    clock_gettime(CLOCK_MONOTONIC, &start);
    const pid_t pid = fork();
    if (pid < 0) return 127;
    if (pid == 0) {
        sigprocmask(SIG_SETMASK, &previous, NULL);
        execv(argv[2], argv + 2);
        _exit(127);
    }
    child = pid;
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);
    sigaction(SIGHUP, &action, NULL);
    sigaction(SIGBUS, &action, NULL);
    sigprocmask(SIG_SETMASK, &previous, NULL);
    int status = 0;
    struct rusage usage = {0};
    while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    clock_gettime(CLOCK_MONOTONIC, &end);
    const double seconds = (double)(end.tv_sec - start.tv_sec) + 1e-9 * (double)(end.tv_nsec - start.tv_nsec);
    FILE* result = fopen(argv[1], "w");
    if (result) {
        const double cpu = (double)(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                           1e-6 * (double)(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
        fprintf(result, "%.6f %ld %d %.6f %ld %ld\n", seconds, usage.ru_maxrss,
                WIFSIGNALED(status) ? WTERMSIG(status) : 0, cpu, usage.ru_minflt, usage.ru_majflt);
        fclose(result);
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
