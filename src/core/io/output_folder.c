/* output_folder.c — the output folder, created when missing (output_folder.h). */
#include "io/output_folder.h"

#include <errno.h>
#include <string.h>
#include <sys/stat.h>

int output_folder_make(const char *dir, err_buf *err)
{
    struct stat st;
    if (!stat(dir, &st)) {
        if (S_ISDIR(st.st_mode)) return 0;
        return err_fail(err, ERR_OUTPUT, "%s: exists and is not a folder", dir);
    }
    if (!mkdir(dir, 0777)) return 0;
    int why = errno; /* another process may have made it meanwhile (the ranks of a study) */
    if (why == EEXIST && !stat(dir, &st) && S_ISDIR(st.st_mode)) return 0;
    return err_fail(err, ERR_OUTPUT, "%s: cannot create the folder: %s", dir, strerror(why));
}
