/* model_material.c — an Assimp material as a sylva material. The base colour comes from the
 * glTF base colour factor when there is one, else from the diffuse colour; the texture from the
 * base-colour slot, else the diffuse slot. Textures are files beside the model (relative paths
 * resolved against its folder) or images embedded in it ("*N" names), decoded from memory.
 *
 * Alpha: sylva cuts a surface where its texture's alpha is below one half. A glTF MASK material
 * with another cutoff gets a texture whose alpha is already cut at that cutoff (0 or 255), with
 * the base colour factor's alpha folded in; OPAQUE ignores alpha; BLEND is cut at one half.
 * Other formats cut at one half where their texture has alpha. */
#include "model/model_material.h"

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/texture.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io/image_io.h"
#include "model/model_folder.h"
#include "model/model_module.h"

/* How a texture's alpha is treated when it is copied into the scene. */
typedef enum alpha_use { ALPHA_AS_IS, ALPHA_CUT } alpha_use;

struct model_texture_use {
    char *source;     /* resolved file path or "*N"; owned */
    alpha_use alpha;
    float cutoff;     /* ALPHA_CUT: texel alpha x factor_alpha >= cutoff stays */
    float factor_alpha;
    int32_t id;       /* scene texture */
};

int model_materials_init(model_materials *mm, const struct aiScene *ai, const model_module *assimp, const char *path,
                         int gltf, err_buf *err)
{
    *mm = (model_materials){.ai = ai, .assimp = assimp, .path = path, .gltf = gltf};
    mm->ids = malloc((ai->mNumMaterials ? ai->mNumMaterials : 1) * sizeof *mm->ids);
    if (!mm->ids) return err_nomem(err, "%s: out of memory for %u materials", path, ai->mNumMaterials);
    for (unsigned i = 0; i < ai->mNumMaterials; i++) mm->ids[i] = -1;
    return 0;
}

void model_materials_free(model_materials *mm)
{
    for (uint32_t i = 0; i < mm->n_uses; i++) free(mm->uses[i].source);
    free(mm->uses);
    free(mm->ids);
    *mm = (model_materials){0};
}

static float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

/* The file name of path, without its folders. */
static const char *file_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* The texture's file: "file://" dropped, backslashes as slashes, relative paths against the
 * model's folder. */
static int resolve_texture_path(const char *model, const char *ref, char *out, size_t cap)
{
    if (!strncmp(ref, "file://", 7)) ref += 7;
    char rel[1024];
    int n = snprintf(rel, sizeof rel, "%s", ref);
    if (n < 0 || (size_t)n >= sizeof rel) return -1;
    for (char *c = rel; *c; c++)
        if (*c == '\\') *c = '/';
    const char *slash = strrchr(model, '/');
    if (rel[0] == '/' || !slash) n = snprintf(out, cap, "%s", rel);
    else n = snprintf(out, cap, "%.*s/%s", (int)(slash - model), model, rel);
    return n < 0 || (size_t)n >= cap ? -1 : 0;
}

/* The embedded texture a reference names ("*N", or an embedded file name), or NULL. */
static const struct aiTexture *embedded_texture(const struct aiScene *ai, const char *ref)
{
    if (ref[0] == '*') {
        char *end;
        long i = strtol(ref + 1, &end, 10);
        return *end == '\0' && i >= 0 && (unsigned long)i < ai->mNumTextures ? ai->mTextures[i] : NULL;
    }
    for (unsigned i = 0; i < ai->mNumTextures; i++)
        if (ai->mTextures[i]->mFilename.length && !strcmp(ai->mTextures[i]->mFilename.data, ref))
            return ai->mTextures[i];
    return NULL;
}

/* 8-bit RGBA, row 0 at the top, from any decoded image: grey repeats into RGB, alpha is 1 when
 * the image has none. Returns NULL when out of memory; the caller frees. */
static uint8_t *rgba8_from_image(const image_f32 *img)
{
    size_t n = (size_t)img->width * img->height;
    uint8_t *rgba = malloc(n * 4);
    if (!rgba) return NULL;
    for (size_t i = 0; i < n; i++) {
        const float *px = img->pixels + i * img->channels;
        for (uint32_t c = 0; c < 4; c++) {
            float v;
            if (c < 3) v = img->channels >= 3 ? px[c] : px[0];
            else v = img->channels == 4 ? px[3] : img->channels == 2 ? px[1] : 1.0f;
            rgba[i * 4 + c] = (uint8_t)lrintf(clamp01(v) * 255.0f);
        }
    }
    return rgba;
}

/* Decodes the texture (embedded or a file) into 8-bit RGBA. */
static int read_texture(model_materials *mm, const char *ref, const struct aiTexture *emb,
                        const char *file, const char *mat_name, uint8_t **rgba, uint32_t *w,
                        uint32_t *h, err_buf *err)
{
    if (emb && emb->mHeight > 0) { /* raw texels, BGRA */
        if (emb->mWidth > 16384 || emb->mHeight > 16384)
            return err_fail(err, ERR_INPUT, "%s: embedded texture '%s' is %ux%u; sizes up to 16384 "
                            "are valid", mm->path, ref, emb->mWidth, emb->mHeight);
        size_t n = (size_t)emb->mWidth * emb->mHeight;
        *rgba = malloc(n * 4);
        if (!*rgba) return err_nomem(err, "%s: out of memory for texture '%s'", mm->path, ref);
        for (size_t i = 0; i < n; i++) {
            const struct aiTexel *t = &emb->pcData[i];
            (*rgba)[i * 4 + 0] = t->r, (*rgba)[i * 4 + 1] = t->g;
            (*rgba)[i * 4 + 2] = t->b, (*rgba)[i * 4 + 3] = t->a;
        }
        *w = emb->mWidth, *h = emb->mHeight;
        return 0;
    }
    image_f32 img = {0};
    if (emb) { /* compressed bytes (PNG, JPEG) of mWidth bytes */
        char format[sizeof emb->achFormatHint + 1] = {0};
        memcpy(format, emb->achFormatHint, sizeof emb->achFormatHint);
        for (char *c = format; *c; c++)
            if (!((*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9'))) *c = '\0';
        char name[1200];
        snprintf(name, sizeof name, "%s: embedded texture '%s' of material '%s'", mm->path, ref, mat_name);
        if (image_read_memory(emb->pcData, emb->mWidth, format[0] ? format : "png", name, &img, err))
            return err_default(err, ERR_INPUT);
    } else {
        if (access(file, R_OK) != 0)
            return err_fail(err, ERR_INPUT, "%s: material '%s' names the texture '%s', which cannot "
                            "be read as %s: %s", mm->path, mat_name, ref, file, strerror(errno));
        if (image_read(file, &img, err)) {
            err_prefix(err, "%s: material '%s': ", mm->path, mat_name);
            return err_default(err, ERR_INPUT);
        }
    }
    *rgba = rgba8_from_image(&img);
    *w = img.width, *h = img.height;
    image_free(&img);
    if (!*rgba) return err_nomem(err, "%s: out of memory for texture '%s'", mm->path, ref);
    return 0;
}

/* The scene texture for reference `ref` with the given alpha treatment, added on first use. */
static int32_t texture_id(model_materials *mm, scene *s, const char *ref, const char *mat_name,
                          alpha_use alpha, float cutoff, float factor_alpha, err_buf *err)
{
    const struct aiTexture *emb = embedded_texture(mm->ai, ref);
    char file[2048];
    if (!emb && resolve_texture_path(mm->path, ref, file, sizeof file))
        return err_fail(err, ERR_INPUT, "%s: material '%s' names a texture path longer than %zu "
                        "bytes", mm->path, mat_name, sizeof file - 1);
    if (!emb && mm->folder && model_folder_check(mm->folder, ref, file, err)) return -1;
    const char *source = emb ? ref : file;
    for (uint32_t i = 0; i < mm->n_uses; i++) {
        const model_texture_use *u = &mm->uses[i];
        if (!strcmp(u->source, source) && u->alpha == alpha &&
            (alpha == ALPHA_AS_IS || (u->cutoff == cutoff && u->factor_alpha == factor_alpha)))
            return u->id;
    }
    uint8_t *rgba = NULL;
    uint32_t w = 0, h = 0;
    if (read_texture(mm, ref, emb, file, mat_name, &rgba, &w, &h, err)) return -1;
    if (alpha == ALPHA_CUT)
        for (size_t i = 3; i < (size_t)w * h * 4; i += 4)
            rgba[i] = (float)rgba[i] / 255.0f * factor_alpha >= cutoff ? 255 : 0;
    char name[2300];
    if (emb) snprintf(name, sizeof name, "%s#%s", mm->path, ref);
    else snprintf(name, sizeof name, "%s", file);
    if (alpha == ALPHA_CUT) {
        size_t len = strlen(name);
        snprintf(name + len, sizeof name - len, "?alpha_cutoff=%g", (double)cutoff);
    }
    int32_t id = scene_add_texture(s, name, w, h, rgba, err);
    free(rgba);
    if (id < 0) return err_prefix(err, "%s: ", mm->path);
    if (mm->n_uses == mm->cap_uses) {
        uint32_t cap = mm->cap_uses ? mm->cap_uses * 2 : 8;
        model_texture_use *u = realloc(mm->uses, cap * sizeof *u);
        if (!u) return err_nomem(err, "%s: out of memory for the texture table", mm->path);
        mm->uses = u, mm->cap_uses = cap;
    }
    char *src = strdup(source);
    if (!src) return err_nomem(err, "%s: out of memory for the texture table", mm->path);
    mm->uses[mm->n_uses++] = (model_texture_use){.source = src, .alpha = alpha, .cutoff = cutoff,
                                                 .factor_alpha = factor_alpha, .id = id};
    mm->n_textures++;
    return id;
}

/* A 1x1 texture that cuts the whole surface away (a MASK material whose base colour alpha is
 * below its cutoff, with no texture of its own). */
static int32_t cut_away_texture(model_materials *mm, scene *s, err_buf *err)
{
    static const uint8_t clear[4] = {255, 255, 255, 0};
    char name[1100];
    snprintf(name, sizeof name, "%s#cut-away", mm->path);
    int32_t id = scene_add_texture(s, name, 1, 1, clear, err);
    if (id >= 0) mm->n_textures++;
    return id;
}

int32_t model_material_id(model_materials *mm, scene *s, unsigned index, err_buf *err)
{
    if (index >= mm->ai->mNumMaterials)
        return err_fail(err, ERR_INPUT, "%s: a mesh uses material %u, but the file has %u", mm->path,
                        index, mm->ai->mNumMaterials);
    if (mm->ids[index] >= 0) return mm->ids[index];
    const struct aiMaterial *am = mm->ai->mMaterials[index];

    struct aiString ai_name = {0};
    char mat_name[256]; /* the file's name for it, unprintable bytes shown as '?' */
    int named = mm->assimp->material_string(am, AI_MATKEY_NAME, &ai_name) == aiReturn_SUCCESS && ai_name.length;
    snprintf(mat_name, sizeof mat_name, "%s", named ? ai_name.data : "unnamed");
    for (char *c = mat_name; *c; c++)
        if ((unsigned char)*c < 0x20 || (unsigned char)*c == 0x7f) *c = '?';
    struct aiColor4D colour = {1, 1, 1, 1};
    if (mm->assimp->material_color(am, AI_MATKEY_BASE_COLOR, &colour) != aiReturn_SUCCESS &&
        mm->assimp->material_color(am, AI_MATKEY_COLOR_DIFFUSE, &colour) != aiReturn_SUCCESS)
        colour = (struct aiColor4D){0.8f, 0.8f, 0.8f, 1.0f};

    /* glTF alpha mode and cutoff */
    alpha_use alpha = ALPHA_AS_IS;
    int mask = 1;
    float cutoff = 0.5f;
    if (mm->gltf) {
        struct aiString mode = {0};
        if (mm->assimp->material_string(am, AI_MATKEY_GLTF_ALPHAMODE, &mode) != aiReturn_SUCCESS)
            strcpy(mode.data, "OPAQUE");
        unsigned one = 1;
        if (mm->assimp->material_floats(am, AI_MATKEY_GLTF_ALPHACUTOFF, &cutoff, &one) != aiReturn_SUCCESS)
            cutoff = 0.5f;
        if (!strcmp(mode.data, "MASK")) alpha = ALPHA_CUT;
        else if (strcmp(mode.data, "BLEND")) mask = 0;
    }

    struct aiString tex_ref = {0};
    int has_tex = mm->assimp->material_texture(am, aiTextureType_BASE_COLOR, 0, &tex_ref) == aiReturn_SUCCESS ||
                  mm->assimp->material_texture(am, aiTextureType_DIFFUSE, 0, &tex_ref) == aiReturn_SUCCESS;
    int32_t tex = -1;
    if (has_tex && tex_ref.length) {
        tex = texture_id(mm, s, tex_ref.data, mat_name, alpha, cutoff, clamp01(colour.a), err);
        if (tex < 0) return -1;
    } else if (alpha == ALPHA_CUT && colour.a < cutoff) {
        tex = cut_away_texture(mm, s, err);
        if (tex < 0) return err_prefix(err, "%s: ", mm->path);
    }

    char name[1200];
    snprintf(name, sizeof name, "%s:%s", file_name(mm->path), mat_name);
    sylva_material_desc d = {.size = sizeof d, .name = name, .bsdf = SYLVA_BSDF_LAMBERT,
                             .albedo = {clamp01(colour.r), clamp01(colour.g), clamp01(colour.b)},
                             .texture = tex, .alpha_mask = mask && tex >= 0};
    int32_t id = scene_add_material(s, &d, err);
    if (id < 0) return err_prefix(err, "%s: ", mm->path);
    mm->ids[index] = id;
    mm->n_materials++;
    return id;
}
