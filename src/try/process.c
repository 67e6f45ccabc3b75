/* process.c — running the compiler, the drivers and gnuplot: fork and exec
 * with standard input from /dev/null and the output into a log file, the
 * child made known to the signal handlers of workdir.c while it runs. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include "try/try_internal.h"
#include "support/strbuf.h"

int try_process_run(char *const *argv, const char *log_path, int *not_found)
{
    *not_found = 0;
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        int in = open("/dev/null", O_RDONLY);
        if (in >= 0) dup2(in, 0);
        if (log_path) {
            int fd = open(log_path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
            if (fd < 0) _exit(126);
            dup2(fd, 1);
            dup2(fd, 2);
        }
        execvp(argv[0], argv);
        _exit(127);
    }
    try_workdir_set_child((long)pid);
    int status = 0;
    pid_t got;
    while ((got = waitpid(pid, &status, 0)) < 0 && errno == EINTR) {}
    try_workdir_set_child(0);
    if (got < 0) return -1;
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    int code = WEXITSTATUS(status);
    if (code == 127) {
        *not_found = 1;
        errno = ENOENT;
    }
    return code;
}

char *try_log_first_error(const char *path)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) return NULL;
    char line[1024], first[1024] = "";
    char *found = NULL;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        if (first[0] == '\0' && line[0] != '\0') memcpy(first, line, sizeof first);
        if (strstr(line, "error")) {
            found = vigen_strdup(line);
            break;
        }
    }
    fclose(f);
    if (found == NULL && first[0]) found = vigen_strdup(first);
    if (found && strlen(found) > 300) found[300] = '\0';
    return found;
}

char *try_log_head(const char *path, int max_lines)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) return NULL;
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    char line[1024];
    int n = 0;
    while (n < max_lines && fgets(line, sizeof line, f)) {
        size_t len = strcspn(line, "\n");
        line[len < 200 ? len : 200] = '\0';
        if (line[0] == '\0') continue;
        vigen_strbuf_printf(&sb, "%s%s", n ? " | " : "", line);
        n++;
    }
    fclose(f);
    if (sb.len == 0) {
        vigen_strbuf_clear(&sb);
        return NULL;
    }
    return sb.data;
}
