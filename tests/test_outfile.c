/* rl_outfile (issue 39): what a signal leaves behind, and the temporary's
 * name next to the file system's limit. Expectations from the folder's
 * listing and the file's bytes, not from the writer's own report. */
#define _DEFAULT_SOURCE 1
#include "rl_test.h"
#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include "rl_outfile.h"

/* A fresh, empty scratch folder for one test. */
static const char *fresh_dir(char *buf, size_t len, const char *name)
{
    char cmd[2 * 1024 + 64]; /* two paths of up to 1023 bytes and the words */
    rl_test_path(buf, len, name);
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", buf, buf);
    assert_int_equal(system(cmd), 0);
    return buf;
}

/* How many entries the folder holds (. and .. left out). */
static int entries(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    assert_non_null(d);
    while ((e = readdir(d)) != NULL)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

static void put(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

/* A child that is in the middle of writing out.yaml when SIG arrives (at
 * its default action): it dies of it, the old file whole, no temporary. */
static void killed_while_writing(int sig)
{
    char dir[1024], path[1100], text[64];
    pid_t pid;
    int status;
    FILE *f;
    fresh_dir(dir, sizeof dir, "outfile_signal");
    snprintf(path, sizeof path, "%s/out.yaml", dir);
    put(path, "old\n");
    pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        rl_outfile o;
        char err[600];
        int i;
        signal(sig, SIG_DFL);
        if (rl_outfile_open(&o, path, err, sizeof err) != RL_OK)
            _exit(3);
        for (i = 0; i < 100000; i++)
            fprintf(o.f, "line %d\n", i);
        fflush(o.f);
        raise(sig);
        _exit(4); /* not reached: the signal ends it */
    }
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFSIGNALED(status));
    assert_int_equal(WTERMSIG(status), sig);
    assert_int_equal(entries(dir), 1); /* out.yaml alone: no temporary left */
    f = fopen(path, "r");
    assert_non_null(f);
    assert_non_null(fgets(text, sizeof text, f));
    fclose(f);
    assert_string_equal(text, "old\n");
}

static void test_sigterm_removes_the_temporary(void **state)
{
    (void)state;
    killed_while_writing(SIGTERM);
}

static void test_sigint_removes_the_temporary(void **state)
{
    (void)state;
    killed_while_writing(SIGINT);
}

/* A program with its own handler keeps it: the write goes on and commits. */
static int stopped;
static void on_stop(int sig)
{
    (void)sig;
    stopped = 1;
}

static void test_own_handler_kept(void **state)
{
    char dir[1024], path[1100], err[600];
    rl_outfile o;
    (void)state;
    fresh_dir(dir, sizeof dir, "outfile_handler");
    snprintf(path, sizeof path, "%s/out.txt", dir);
    signal(SIGTERM, on_stop);
    assert_int_equal(rl_outfile_open(&o, path, err, sizeof err), RL_OK);
    fputs("new\n", o.f);
    raise(SIGTERM);
    assert_int_equal(stopped, 1);
    assert_int_equal(rl_outfile_commit(&o, err, sizeof err), RL_OK);
    assert_int_equal(entries(dir), 1);
    signal(SIGTERM, SIG_DFL);
}

/* A name of the folder's longest length (NAME_MAX) is written: the
 * temporary's own name is shortened to fit. */
static void test_longest_name(void **state)
{
    char dir[1024], path[1400], name[300], err[600];
    long max;
    rl_outfile o;
    (void)state;
    fresh_dir(dir, sizeof dir, "outfile_long");
    max = pathconf(dir, _PC_NAME_MAX);
    if (max <= 0 || max >= (long)sizeof name)
        max = 255;
    memset(name, 'n', (size_t)max);
    name[max] = '\0';
    memcpy(name + max - 5, ".yaml", 5);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    assert_int_equal(rl_outfile_open(&o, path, err, sizeof err), RL_OK);
    fputs("x: 1\n", o.f);
    assert_int_equal(rl_outfile_commit(&o, err, sizeof err), RL_OK);
    assert_int_equal(access(path, R_OK), 0);
    assert_int_equal(entries(dir), 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sigterm_removes_the_temporary),
        cmocka_unit_test(test_sigint_removes_the_temporary),
        cmocka_unit_test(test_own_handler_kept),
        cmocka_unit_test(test_longest_name),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
