/* test_atomic_file.c — output files written whole or not at all: the temporary is a new file
 * with an unpredictable name (a planted symbolic link is never followed), the commit replaces
 * the target (a link standing there is replaced, its target untouched), a failure or an abort
 * leaves nothing, and SIGTERM in the middle of a write removes the temporary. */
#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "harness.h"
#include "io/atomic_file.h"
#include "work_dir.h"

/* Entries of the work folder, "." and ".." aside. */
static int count_entries(void)
{
    DIR *d = opendir(work_dir());
    if (!d) return -1;
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) n++;
    closedir(d);
    return n;
}

static void read_text(const char *path, char *buf, size_t n)
{
    buf[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f) return;
    size_t got = fread(buf, 1, n - 1, f);
    buf[got] = '\0';
    fclose(f);
}

TEST(write_and_commit)
{
    const char *path = work_path("plants.csv");
    atomic_file af;
    err_buf err = {{0}};
    FILE *f = atomic_file_open_stream(&af, path, &err);
    CHECK_STR_CONTAINS(af.tmp, "/.plants.tmp-");
    CHECK_STR_CONTAINS(af.tmp, ".csv");
    struct stat st;
    CHECK(lstat(af.tmp, &st) == 0 && S_ISREG(st.st_mode));
    CHECK(f != NULL);
    if (f) fputs("species,x\n", f);
    CHECK_INT(access(path, F_OK), -1); /* nothing at the target before the commit */
    CHECK_INT(atomic_file_commit(&af, &err), 0);
    char text[64];
    read_text(path, text, sizeof text);
    CHECK(!strcmp(text, "species,x\n"));
    CHECK_INT(count_entries(), 1);
    remove(path);
}

/* Two temporaries for one target never share a name, and the name is not derived from the
 * process id and a counter alone. */
TEST(temporary_names_are_unique)
{
    const char *path = work_path("image.png");
    atomic_file a, b;
    err_buf err = {{0}};
    CHECK_INT(atomic_file_open(&a, path, &err), 0);
    CHECK_INT(atomic_file_open(&b, path, &err), 0);
    CHECK(strcmp(a.tmp, b.tmp) != 0);
    char pid[32];
    snprintf(pid, sizeof pid, "-%ld-", (long)getpid());
    CHECK(!strstr(strrchr(a.tmp, '/'), pid)); /* the work folder's own name holds the pid */
    atomic_file_abort(&a);
    atomic_file_abort(&b);
    atomic_file_abort(&b); /* twice is harmless */
    CHECK_INT(count_entries(), 0);
}

/* A symbolic link planted at the target is replaced by the new file; its target keeps its
 * content. */
TEST(link_at_the_target_is_replaced_not_followed)
{
    const char *victim = work_file("victim.txt", "precious\n");
    CHECK(victim != NULL);
    char target[1200];
    snprintf(target, sizeof target, "%s/out.csv", work_dir());
    CHECK_INT(symlink("victim.txt", target), 0);
    atomic_file af;
    err_buf err = {{0}};
    FILE *f = atomic_file_open_stream(&af, target, &err);
    if (f) fputs("new\n", f);
    CHECK_INT(atomic_file_commit(&af, &err), 0);
    char text[64];
    read_text(work_path("victim.txt"), text, sizeof text);
    CHECK(!strcmp(text, "precious\n"));
    struct stat st;
    CHECK(lstat(target, &st) == 0 && S_ISREG(st.st_mode));
    read_text(target, text, sizeof text);
    CHECK(!strcmp(text, "new\n"));
    remove(target);
    remove(work_path("victim.txt"));
}

TEST(failures_leave_nothing)
{
    atomic_file af;
    err_buf err = {{0}};
    char path[1200];
    snprintf(path, sizeof path, "%s/no/such/folder/a.csv", work_dir());
    CHECK_INT(atomic_file_open(&af, path, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "cannot create the output file");
    atomic_file_abort(&af);
    CHECK_INT(atomic_file_open(&af, work_path("a.csv"), &err), 0);
    atomic_file_abort(&af);
    CHECK_INT(atomic_file_commit(&af, &err), -1); /* nothing left to commit */
    CHECK_INT(count_entries(), 0);
    /* the rename fails: a non-empty folder came to stand at the target after the open */
    char folder[1200];
    snprintf(folder, sizeof folder, "%s", work_path("taken.csv"));
    CHECK_INT(atomic_file_open(&af, folder, &err), 0);
    CHECK_INT(mkdir(folder, 0755), 0);
    char inner[1300];
    snprintf(inner, sizeof inner, "%s/keep", folder);
    CHECK_INT(mkdir(inner, 0755), 0);
    CHECK_INT(atomic_file_commit(&af, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "cannot move the finished file into place");
    CHECK_INT(count_entries(), 1);
    rmdir(inner);
    rmdir(folder);
}

/* A device, a FIFO or a folder standing at the output's name is refused before anything is
 * written: the commit's rename would have put a file in its place (as root, a regular file in
 * place of /dev/null). */
TEST(only_files_are_replaced)
{
    atomic_file af;
    err_buf err = {{0}};
    struct stat before, after;
    CHECK(stat("/dev/null", &before) == 0 && S_ISCHR(before.st_mode));
    CHECK_INT(atomic_file_open(&af, "/dev/null", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "/dev/null: is a character device; an output replaces the file it names");
    CHECK(stat("/dev/null", &after) == 0 && S_ISCHR(after.st_mode));
    const char *fifo = work_path("out.fifo");
    CHECK_INT(mkfifo(fifo, 0600), 0);
    CHECK_INT(atomic_file_open(&af, fifo, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "is a FIFO (named pipe)");
    remove(fifo);
    const char *folder = work_path("folder.png");
    CHECK_INT(mkdir(folder, 0755), 0);
    CHECK_INT(atomic_file_open(&af, folder, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "is a folder");
    rmdir(folder);
    CHECK_INT(count_entries(), 0);
}

/* SIGTERM while a temporary is open: the process ends by the signal and the temporary is gone. */
TEST(signal_removes_the_temporary)
{
    int ready[2];
    CHECK_INT(pipe(ready), 0);
    pid_t child = fork();
    CHECK(child >= 0);
    if (child == 0) {
        atomic_file af;
        err_buf err;
        if (atomic_file_open(&af, work_path("interrupted.exr"), &err)) _exit(3);
        if (write(ready[1], "x", 1) != 1) _exit(4);
        for (;;) pause();
    }
    char c;
    CHECK_INT(read(ready[0], &c, 1), 1);
    CHECK_INT(count_entries(), 1); /* the child's temporary */
    kill(child, SIGTERM);
    int status = 0;
    waitpid(child, &status, 0);
    CHECK(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
    CHECK_INT(count_entries(), 0);
    close(ready[0]);
    close(ready[1]);
}

TEST_LIST(TEST_CASE(write_and_commit), TEST_CASE(temporary_names_are_unique),
          TEST_CASE(link_at_the_target_is_replaced_not_followed), TEST_CASE(failures_leave_nothing),
          TEST_CASE(signal_removes_the_temporary), TEST_CASE(only_files_are_replaced))
