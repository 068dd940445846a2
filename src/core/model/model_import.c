/* model_import.c — a model file through Assimp into one sylva mesh: the file is checked
 * (readable, a supported extension; a PLY walked whole), Assimp reads it (in the model module,
 * model/model_module.h; an OBJ file's points and lines as comments, model/obj_statements.h)
 * triangulated with points and lines dropped; the triangle count over all node instances is
 * checked against the limit before the mesh is allocated at its exact size; then every node's
 * meshes are copied with the node's accumulated transform, the file's frame turned to sylva's
 * (metres, +Z up) and the caller's scale applied; missing normals are made from the triangles.
 * Materials are made on first use (model_material.c). */
#include "model/model_import.h"

#include <assimp/scene.h> /* before metadata.h, which needs what it includes */
#include <assimp/metadata.h>

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "model/model_assimp.h"
#include "model/model_folder.h"
#include "model/model_material.h"
#include "model/gltf_check.h"
#include "model/obj_check.h"
#include "model/ply_check.h"
#include "util/chunk_check.h"

/* The formats read, by extension, and the up axis each states as Assimp hands it over:
 * Assimp turns COLLADA (whatever its <up_axis>) and 3DS to +Y; glTF is +Y by specification;
 * FBX says in its metadata; OBJ, STL and PLY say nothing (+Z, or the caller's choice). */
typedef enum format_up { UP_NONE, UP_Y, UP_FBX } format_up;
typedef struct model_format {
    const char *ext;
    format_up up;
    int gltf;
} model_format;

static const model_format formats[] = {
    {"obj", UP_NONE, 0}, {"stl", UP_NONE, 0}, {"ply", UP_NONE, 0}, {"gltf", UP_Y, 1},
    {"glb", UP_Y, 1},    {"dae", UP_Y, 0},    {"3ds", UP_Y, 0},    {"fbx", UP_FBX, 0},
};
#define N_FORMATS (sizeof formats / sizeof formats[0])

static const model_format *format_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash : path, '.');
    if (!dot) return NULL;
    for (size_t i = 0; i < N_FORMATS; i++)
        if (!strcasecmp(dot + 1, formats[i].ext)) return &formats[i];
    return NULL;
}

int model_import_supports(const char *path) { return path && format_of(path) != NULL; }

/* Row-major 4x4 affine transform in double precision. */
typedef struct affine {
    double m[3][4];
} affine;

static affine affine_from_ai(const struct aiMatrix4x4 *a)
{
    return (affine){{{a->a1, a->a2, a->a3, a->a4}, {a->b1, a->b2, a->b3, a->b4}, {a->c1, a->c2, a->c3, a->c4}}};
}

static affine affine_mul(const affine *a, const affine *b)
{
    affine r;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++) {
            double v = j == 3 ? a->m[i][3] : 0.0;
            for (int k = 0; k < 3; k++) v += a->m[i][k] * b->m[k][j];
            r.m[i][j] = v;
        }
    }
    return r;
}

/* The rotation taking the file's up axis (axis 0, 1, 2 = X, Y, Z; sign +-1) to +Z, times a
 * uniform scale. */
static affine frame_to_sylva(int axis, int sign, double scale)
{
    affine r = {{{0}}};
    if (axis == 2) { /* +Z: identity; -Z: half a turn about X */
        r.m[0][0] = 1, r.m[1][1] = sign, r.m[2][2] = sign;
    } else if (axis == 1) { /* (x, y, z) -> (x, -z, y) for +Y */
        r.m[0][0] = 1, r.m[1][2] = -sign, r.m[2][1] = sign;
    } else { /* (x, y, z) -> (-z, y, x) for +X */
        r.m[0][2] = -sign, r.m[1][1] = 1, r.m[2][0] = sign;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] *= scale;
    return r;
}

/* An FBX metadata number (Assimp stores these as int32, float or double). */
static int fbx_number(const struct aiScene *ai, const char *key, double *out)
{
    const struct aiMetadata *md = ai->mMetaData;
    if (!md) return -1;
    for (unsigned i = 0; i < md->mNumProperties; i++) {
        if (strcmp(md->mKeys[i].data, key)) continue;
        const struct aiMetadataEntry *e = &md->mValues[i];
        if (e->mType == AI_INT32) *out = *(const int32_t *)e->mData;
        else if (e->mType == AI_FLOAT) *out = *(const float *)e->mData;
        else if (e->mType == AI_DOUBLE) *out = *(const double *)e->mData;
        else return -1;
        return 0;
    }
    return -1;
}

/* The frame turn and unit for the file, with the caller's scale. */
static int file_frame(const struct aiScene *ai, const model_format *f, const model_import_options *o,
                      const char *path, affine *out, err_buf *err)
{
    int axis = 2, sign = 1;
    double unit = 1.0; /* metres per unit as Assimp hands the file over */
    if (o->up != MODEL_UP_FILE && f->up != UP_NONE)
        return err_fail(err, ERR_INPUT, "%s: the file states its own up axis; an up axis can be "
                        "given for OBJ, STL and PLY files only", path);
    if (f->up == UP_NONE && o->up == MODEL_UP_Y) axis = 1;
    if (f->up == UP_Y) axis = 1;
    if (f->up == UP_FBX) {
        double a = 1, s = 1, cm = 1;
        fbx_number(ai, "UpAxis", &a);
        fbx_number(ai, "UpAxisSign", &s);
        if (a != 0 && a != 1 && a != 2)
            return err_fail(err, ERR_INPUT, "%s: UpAxis is %g; 0 (X), 1 (Y) or 2 (Z) is valid", path, a);
        axis = (int)a, sign = s < 0 ? -1 : 1;
        if (!fbx_number(ai, "UnitScaleFactor", &cm)) { /* centimetres per unit */
            if (!(cm > 0) || !isfinite(cm))
                return err_fail(err, ERR_INPUT, "%s: UnitScaleFactor is %g; a positive number of "
                                "centimetres per unit is valid", path, cm);
            unit = cm / 100.0;
        } else {
            unit = 0.01; /* FBX's default unit is the centimetre */
        }
    }
    *out = frame_to_sylva(axis, sign, unit * (o->scale == 0 ? 1.0 : o->scale));
    return 0;
}

/* Counts triangles and vertices over all node instances; -1 when the hierarchy is deeper than
 * MODEL_MAX_NODE_DEPTH. */
static int count_uses(const struct aiScene *ai, const struct aiNode *n, int depth, uint64_t *nt,
                      uint64_t *nv, uint64_t *uses)
{
    if (depth > MODEL_MAX_NODE_DEPTH) return -1;
    for (unsigned i = 0; i < n->mNumMeshes; i++) {
        if (n->mMeshes[i] >= ai->mNumMeshes) continue; /* reported when copying */
        const struct aiMesh *am = ai->mMeshes[n->mMeshes[i]];
        if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        *nt += am->mNumFaces, *nv += am->mNumVertices, (*uses)++;
    }
    for (unsigned c = 0; c < n->mNumChildren; c++)
        if (count_uses(ai, n->mChildren[c], depth + 1, nt, nv, uses)) return -1;
    return 0;
}

/* n = w / |w|; +Z and 1 when w has no length or direction. */
static int store_unit(float n[3], const double w[3])
{
    double len = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    int none = !(len > 0) || !isfinite(len);
    for (int i = 0; i < 3; i++) n[i] = none ? (float)(i == 2) : (float)(w[i] / len);
    return none;
}

/* Normals for a mesh the file gives none (or some without direction, as STL's zero facet
 * normals): each vertex the area-weighted mean of its triangles'
 * normals (vertices [v0, v0 + nv), triangles [t0, t0 + nt), already in sylva's frame). Shared
 * vertices come out smooth, unshared ones flat, as the file's indexing says. */
static void area_weighted_normals(mesh *m, uint32_t v0, uint32_t nv, uint32_t t0, uint32_t nt)
{
    double *sum = calloc((size_t)nv * 3, sizeof *sum);
    for (uint32_t t = t0; sum && t < t0 + nt; t++) {
        const uint32_t *k = m->tri + (size_t)t * 3;
        const float *a = m->pos + (size_t)k[0] * 3, *b = m->pos + (size_t)k[1] * 3, *c = m->pos + (size_t)k[2] * 3;
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double f[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        for (int j = 0; j < 3; j++)
            for (int d = 0; d < 3; d++) sum[(size_t)(k[j] - v0) * 3 + d] += f[d];
    }
    for (uint32_t v = 0; v < nv; v++) { /* out of memory for the sums: +Z, as for no area */
        double zero[3] = {0, 0, 0};
        store_unit(m->nrm + (size_t)(v0 + v) * 3, sum ? sum + (size_t)v * 3 : zero);
    }
    free(sum);
}

typedef struct copy_state {
    const struct aiScene *ai;
    const char *path;
    scene *s;
    mesh *m;
    model_materials mats;
} copy_state;

/* Copies one mesh used by a node with transform xf (file → sylva). */
static int copy_mesh(copy_state *cs, const struct aiMesh *am, const affine *xf, err_buf *err)
{
    int32_t mat = model_material_id(&cs->mats, cs->s, am->mMaterialIndex, err);
    if (mat < 0) return -1;
    /* normals: the cofactor matrix, the inverse transpose times the determinant; a mirror
     * (negative determinant) turns them back and swaps the winding so both still agree */
    const double (*a)[4] = xf->m;
    double cof[3][3] = {
        {a[1][1] * a[2][2] - a[1][2] * a[2][1], a[1][2] * a[2][0] - a[1][0] * a[2][2], a[1][0] * a[2][1] - a[1][1] * a[2][0]},
        {a[0][2] * a[2][1] - a[0][1] * a[2][2], a[0][0] * a[2][2] - a[0][2] * a[2][0], a[0][1] * a[2][0] - a[0][0] * a[2][1]},
        {a[0][1] * a[1][2] - a[0][2] * a[1][1], a[0][2] * a[1][0] - a[0][0] * a[1][2], a[0][0] * a[1][1] - a[0][1] * a[1][0]}};
    double det = a[0][0] * cof[0][0] + a[0][1] * cof[0][1] + a[0][2] * cof[0][2];
    int mirrored = det < 0;
    mesh *m = cs->m;
    uint32_t v0 = m->nv;
    int make_normals = !am->mNormals; /* or when one of the file's has no direction */
    for (unsigned v = 0; v < am->mNumVertices; v++) {
        const struct aiVector3D *p = &am->mVertices[v];
        float *dst = m->pos + (size_t)(v0 + v) * 3;
        for (int i = 0; i < 3; i++) {
            double x = a[i][0] * p->x + a[i][1] * p->y + a[i][2] * p->z + a[i][3];
            if (!(fabs(x) <= FLT_MAX)) /* not finite, or beyond single precision once placed */
                return err_fail(err, ERR_INPUT, "%s: mesh '%s' vertex %u is not a finite position (or one "
                                "beyond %g once placed by its node's transform)", cs->path, am->mName.data, v,
                                (double)FLT_MAX);
            dst[i] = (float)x;
        }
        if (am->mNormals) {
            const struct aiVector3D *q = &am->mNormals[v];
            double w[3];
            for (int i = 0; i < 3; i++)
                w[i] = (cof[i][0] * q->x + cof[i][1] * q->y + cof[i][2] * q->z) * (mirrored ? -1 : 1);
            make_normals |= store_unit(m->nrm + (size_t)(v0 + v) * 3, w);
        }
        float *uv = m->uv + (size_t)(v0 + v) * 2;
        uv[0] = am->mTextureCoords[0] ? am->mTextureCoords[0][v].x : 0.0f;
        uv[1] = am->mTextureCoords[0] ? am->mTextureCoords[0][v].y : 0.0f;
        if (!isfinite(uv[0]) || !isfinite(uv[1]))
            return err_fail(err, ERR_INPUT, "%s: mesh '%s' vertex %u has a texture coordinate that is not a "
                            "finite number", cs->path, am->mName.data, v);
    }
    uint32_t t0 = m->nt;
    for (unsigned f = 0; f < am->mNumFaces; f++) {
        const struct aiFace *face = &am->mFaces[f];
        if (face->mNumIndices != 3)
            return err_fail(err, ERR_INTERNAL, "%s: mesh '%s' face %u has %u corners after "
                            "triangulation", cs->path, am->mName.data, f, face->mNumIndices);
        uint32_t *t = m->tri + (size_t)(t0 + f) * 3;
        for (int k = 0; k < 3; k++) {
            unsigned idx = face->mIndices[mirrored && k ? 3 - k : k]; /* a mirror keeps the winding */
            if (idx >= am->mNumVertices)
                return err_fail(err, ERR_INPUT, "%s: mesh '%s' face %u uses vertex %u of %u", cs->path,
                                am->mName.data, f, idx, am->mNumVertices);
            t[k] = v0 + idx;
        }
        m->mat[t0 + f] = mat;
    }
    m->nv += am->mNumVertices;
    m->nt += am->mNumFaces;
    if (make_normals) area_weighted_normals(m, v0, am->mNumVertices, t0, am->mNumFaces);
    return 0;
}

/* Copies the node's meshes and its children's (the depth was checked by count_uses). */
static int copy_node(copy_state *cs, const struct aiNode *n, const affine *parent, err_buf *err)
{
    affine local = affine_from_ai(&n->mTransformation);
    affine xf = affine_mul(parent, &local);
    for (unsigned i = 0; i < n->mNumMeshes; i++) {
        if (n->mMeshes[i] >= cs->ai->mNumMeshes)
            return err_fail(err, ERR_INPUT, "%s: node '%s' uses mesh %u of %u", cs->path, n->mName.data,
                            n->mMeshes[i], cs->ai->mNumMeshes);
        const struct aiMesh *am = cs->ai->mMeshes[n->mMeshes[i]];
        if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        if (copy_mesh(cs, am, &xf, err)) return -1;
    }
    for (unsigned c = 0; c < n->mNumChildren; c++)
        if (copy_node(cs, n->mChildren[c], &xf, err)) return -1;
    return 0;
}

/* Assimp's message in why, with anything unprintable (it may quote the file) shown as '?' and
 * cut at 200 characters. */
static const char *assimp_reason(char *why)
{
    if (strlen(why) >= 203) strcpy(why + 200, "...");
    for (char *c = why; *c; c++)
        if ((unsigned char)*c < 0x20 || (unsigned char)*c >= 0x7f) *c = '?';
    return why[0] ? why : "no reason given";
}

/* The file read by Assimp through the model module, triangulated with points and lines dropped,
 * every file it refers to opened through the model's folder: the scene, with *reading its
 * owner (close it with the module's close whatever the result), or NULL with err set. */
static const struct aiScene *read_with_assimp(const model_module *assimp, const char *path, model_folder *folder,
                                              model_reading **reading, err_buf *err)
{
    struct aiFileIO io = model_folder_io(folder);
    const struct aiScene *ai = NULL;
    char why[512];
    model_read_status status = assimp->read(path, &io, reading, &ai, why, sizeof why);
    if (model_folder_refusal(folder, err)) return NULL; /* Assimp may have gone on without the file */
    if (status == MODEL_READ_NOMEM) {
        err_nomem(err, "%s: out of memory reading the model", path);
        return NULL;
    }
    if (status == MODEL_READ_EMPTY_FACE) {
        err_fail(err, ERR_INPUT, "%s: %s has no vertices; every face needs at least one", path, why);
        return NULL;
    }
    if (status != MODEL_READ_OK) {
        err_fail(err, ERR_INPUT, "%s: cannot read the model: %s", path, assimp_reason(why));
        return NULL;
    }
    if ((ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !ai->mRootNode) {
        err_fail(err, ERR_INPUT, "%s: the model is incomplete (no scene root or no meshes)", path);
        return NULL;
    }
    return ai;
}

int model_import(scene *s, const char *path, const model_import_options *opt, mesh **out,
                 model_import_info *info, err_buf *err)
{
    *out = NULL;
    model_import_options o = opt ? *opt : (model_import_options){0};
    uint32_t limit = o.max_triangles ? o.max_triangles : MODEL_MAX_TRIANGLES;
    if (!(o.scale >= 0) || !isfinite(o.scale))
        return err_fail(err, ERR_INPUT, "%s: scale %g; a finite number above 0 is valid", path, o.scale);
    const model_format *f = format_of(path);
    if (!f)
        return err_fail(err, ERR_INPUT, "%s: not a model format sylva reads; valid extensions are "
                        ".obj, .gltf, .glb, .ply, .stl, .fbx, .dae and .3ds", path);
    if (access(path, R_OK) != 0)
        return err_fail(err, ERR_INPUT, "%s: cannot read the model: %s", path, strerror(errno));
    /* Only the readers of the file's extension read it (model/model_module.h). Assimp's PLY
     * reader hangs on a cut PLY and aborts on a face of no vertices */
    if (!strcmp(f->ext, "ply") && ply_check(path, err)) return -1;
    if (!strcmp(f->ext, "obj") && obj_check(path, err)) return -1; /* Assimp reads past some library names */
    if (f->gltf && glb_check(path, err)) return -1; /* Assimp allocates what a GLB chunk states */
    if (f->gltf && gltf_check(path, err)) return -1; /* Assimp crashes on a mimeType without '/' */

    const model_module *assimp = model_assimp(path, err);
    if (!assimp) return -1;
    model_folder folder;
    if (model_folder_init(&folder, path, o.root, err)) return -1;
    folder.obj_points_lines = !strcmp(f->ext, "obj"); /* Assimp 5.2 writes past its arrays on some lines */
    model_reading *reading = NULL; /* closed at done */
    const struct aiScene *ai = read_with_assimp(assimp, path, &folder, &reading, err);
    if (!ai) {
        if (reading) assimp->close(reading);
        return -1;
    }
    int rc = -1;
    copy_state cs = {.ai = ai, .path = path, .s = s};
    affine frame;
    if (file_frame(ai, f, &o, path, &frame, err)) goto done;

    uint64_t nt = 0, nv = 0, uses = 0;
    if (count_uses(ai, ai->mRootNode, 0, &nt, &nv, &uses)) {
        err_fail(err, ERR_LIMIT, "%s: the node hierarchy is deeper than %d levels", path, MODEL_MAX_NODE_DEPTH);
        goto done;
    }
    if (nt == 0) {
        err_fail(err, ERR_INPUT, "%s: the model has no triangles (points and lines are not read)", path);
        goto done;
    }
    if (nt > limit || nt > MESH_MAX_TRIANGLES || nv > MESH_MAX_VERTICES) {
        err_fail(err, ERR_LIMIT, "%s: the model has %llu triangles and %llu vertices (instances "
                 "counted); at most %u triangles and %u vertices are read", path,
                 (unsigned long long)nt, (unsigned long long)nv,
                 limit < MESH_MAX_TRIANGLES ? limit : MESH_MAX_TRIANGLES, MESH_MAX_VERTICES);
        goto done;
    }
    /* The mesh at its exact size: 32 bytes per vertex, 16 per triangle. */
    cs.m = mesh_new();
    if (cs.m) {
        cs.m->pos = malloc(((size_t)nv * 3 + 4) * sizeof(float));
        cs.m->nrm = malloc((size_t)nv * 3 * sizeof(float));
        cs.m->uv = malloc((size_t)nv * 2 * sizeof(float));
        cs.m->tri = malloc((size_t)nt * 3 * sizeof(uint32_t));
        cs.m->mat = malloc((size_t)nt * sizeof(int32_t));
    }
    if (!cs.m || !cs.m->pos || !cs.m->nrm || !cs.m->uv || !cs.m->tri || !cs.m->mat) {
        err_nomem(err, "%s: out of memory for %llu triangles and %llu vertices", path,
                  (unsigned long long)nt, (unsigned long long)nv);
        goto done;
    }
    cs.m->cap_v = (uint32_t)nv, cs.m->cap_t = (uint32_t)nt;
    memset(cs.m->pos + (size_t)nv * 3, 0, 4 * sizeof(float));
    if (model_materials_init(&cs.mats, ai, assimp, path, f->gltf, err)) goto done;
    cs.mats.folder = &folder;
    if (copy_node(&cs, ai->mRootNode, &frame, err)) goto done;
    if (info) {
        *info = (model_import_info){.triangles = cs.m->nt, .meshes = (uint32_t)uses,
                                    .materials = cs.mats.n_materials, .textures = cs.mats.n_textures};
        snprintf(info->missing, sizeof info->missing, "%s", folder.missing);
    }
    *out = cs.m;
    cs.m = NULL;
    rc = 0;
done:
    mesh_free(cs.m);
    if (cs.mats.ids) model_materials_free(&cs.mats);
    assimp->close(reading);
    return rc;
}
