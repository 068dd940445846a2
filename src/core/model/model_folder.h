/* model_folder.h — the folder a model file may read from. A model refers to other files (glTF
 * buffers and images, an OBJ's material library and its maps, COLLADA images); each must lie in
 * the model file's own folder or below it — or below the wider folder a scene names as the
 * object's model_root — so that a model cannot read /etc/passwd as geometry or a texture. A
 * reference is refused when it is an absolute path, when its ".." climb out of the folder, or
 * when the file it reaches lies outside through a symbolic link.
 *
 * Assimp reads through model_folder_io, which opens only regular files the folder allows and
 * keeps the first refusal (Assimp itself may go on without a refused material library);
 * model_import then fails with model_folder_refusal. A file that is missing is the model's own
 * affair (Assimp goes on without a material library, fails without a glTF buffer); the first
 * such file is kept in `missing` for a warning. After a file that did not open, Assimp's file
 * system guesses other places for it: the folder prefixed to the absolute path it asked for, and
 * pieces of that path, each an absolute name found within it. Those are refused without being
 * kept, as they are not the model's references; a reference the model names after them is kept
 * as any other (an absolute one that happens to lie within the path before it is refused but
 * taken for a guess). Textures are checked with model_folder_check before they are read. An OBJ
 * model reaches Assimp with its point and line statements read as comments (obj_points_lines,
 * model/obj_statements.h). Only model_folder_io allocates: a handle and its state per open file,
 * freed when Assimp closes it. */
#ifndef SYLVA_MODEL_FOLDER_H
#define SYLVA_MODEL_FOLDER_H

#include <assimp/cfileio.h>
#include <stddef.h>

#include "util/err.h"

#define MODEL_FOLDER_PATH_MAX 4096

typedef struct model_folder {
    const char *model;                /* the model file as named; borrowed */
    size_t prefix_len;                /* bytes of model up to its last '/', that included; 0: none */
    char dir[MODEL_FOLDER_PATH_MAX];  /* the model's folder, resolved (no link, no "..") */
    char root[MODEL_FOLDER_PATH_MAX]; /* the folder every file must lie in, resolved */
    char refused[1024];               /* the first reference model_folder_io refused, or "" */
    const char *refused_why;          /* why, as model_folder_check says it */
    int out_of_memory;                /* 1: model_folder_io could not allocate a file's handle */
    char failed[MODEL_FOLDER_PATH_MAX]; /* the last file the model names that did not open or was
                                         refused, as Assimp asked for it (its guesses follow) */
    char missing[1024];               /* the first file the model names that did not open (missing,
                                         or not a regular file), as the model names it, or "" */
    int obj_points_lines;             /* 1: the model file is read with its point and line statements
                                         as comments (an OBJ file; 0 after model_folder_init) */
} model_folder;

/* Sets mf up for the model file `model` (which must exist), with root the folder its files must
 * lie in (NULL: the model's own folder; the model must lie in it). Returns 0, or -1 with err set
 * (ERR_INPUT). */
int model_folder_init(model_folder *mf, const char *model, const char *root, err_buf *err);

/* ref is a reference as the model writes it ("file://" and backslashes allowed), file the path
 * it resolves to. Returns 0 when the file lies in the folder, else -1 with err (ERR_INPUT)
 * naming the model and the reference. */
int model_folder_check(const model_folder *mf, const char *ref, const char *file, err_buf *err);

/* An Assimp file system that opens (for reading) only the model and the files mf allows. mf must
 * outlive the import. */
struct aiFileIO model_folder_io(model_folder *mf);

/* -1 with err set when model_folder_io refused a file during the import, or ran out of memory
 * (ERR_NOMEM); else 0. */
int model_folder_refusal(const model_folder *mf, err_buf *err);

#endif
