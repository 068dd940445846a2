/* sylva/plugin.h — the core of the plugin ABI: the descriptor, the parameter schema and values,
 * the host API table, and the requests and outputs of each kind. The optional interfaces a
 * plugin may offer through extension(id) have a header each (sylva/ecology_ext.h,
 * sylva/tree_stats.h); this header includes them, so one #include still gives the whole ABI.
 *
 * A plugin is a shared module that exports one function, `sylva_plugin_get`, returning const
 * descriptors (one per index, NULL past the end). A descriptor names the plugin, its kind, its
 * parameter schema, its presets and its operations. Listing plugins reads descriptors only: it
 * allocates nothing in the plugin and runs no plugin code beyond `sylva_plugin_get`. The build
 * writes a manifest beside each module (`sylva plugins --manifest`, docs/plugins.md) so that the
 * host checks the ABI before opening the module and opens only the modules a command needs.
 *
 * The host validates every scene-file block against the schema before any plugin code runs,
 * fills defaults, and hands the plugin a `sylva_params` whose values are in schema order. Each
 * operation receives the host's API table (`sylva_host_api`) and an opaque `sylva_host`; a
 * plugin keeps no global state and no pointer to the table between calls.
 *
 * Compatibility rules
 *  - SYLVA_ABI_MAJOR changes when any existing field or function changes meaning or place; the
 *    host refuses a plugin built against another major.
 *  - SYLVA_ABI_MINOR grows when fields or API functions are appended. Every extensible struct
 *    starts with `size` (its sizeof as the writer compiled it); a reader reads no field past it:
 *    SYLVA_HAS_FIELD(ptr, type, field) says whether a field is there. A plugin built against
 *    a newer minor than its host tests each newer host function with SYLVA_API_HAS(api, name)
 *    before calling it. ABI 1.0 plugins load unchanged in a 1.1 host.
 *  - Arrays the host indexes (parameter specs) must have the host's element size: the descriptor
 *    records `param_spec_size`, and the host refuses a mismatch.
 *  - Arrays the plugin indexes (sylva_params.values, sylva_value.items, the ecology request's
 *    species) keep their element layout for the whole of a major version: growing sylva_value,
 *    sylva_params or sylva_species_info is a major change.
 *
 * Errors: every operation returns SYLVA_OK or a negative sylva_status and, on failure, leaves a
 * sentence through api->error() or api->param_error() (what is wrong, what would be valid). A
 * plugin never exits, never aborts on bad input and never writes to stdout.
 *
 * Ownership: everything the host hands in (requests, heightfields, the API table) is borrowed
 * for the duration of the call. The `sylva_params` given to create() is the exception: it and
 * every value in it (strings, lists, grids, groups, the file name) stay valid and unchanged
 * until the host calls destroy() on the state create() returned, so a plugin keeps pointers
 * into it instead of copying. Meshes, heightfields, materials and textures a plugin
 * creates through the API are owned by the host. Plugin state returned by create() is owned by
 * the plugin and released by destroy(), which accepts NULL.
 */
#ifndef SYLVA_PLUGIN_H
#define SYLVA_PLUGIN_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SYLVA_ABI_MAJOR 1
#define SYLVA_ABI_MINOR 7

/* Bytes from the start of `type` to the end of `field`. */
#define SYLVA_FIELD_END(type, field) (offsetof(type, field) + sizeof(((type *)0)->field))

/* 1 when the size-versioned struct at `ptr` (one that starts with `uint32_t size`) is long
 * enough to hold `field`, 0 when it was written by a version that did not have it. */
#define SYLVA_HAS_FIELD(ptr, type, field) ((size_t)(ptr)->size >= SYLVA_FIELD_END(type, field))

#if defined(_WIN32)
#define SYLVA_EXPORT __declspec(dllexport)
#else
#define SYLVA_EXPORT __attribute__((visibility("default")))
#endif

#if defined(__GNUC__)
#define SYLVA_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define SYLVA_PRINTF(fmt, args)
#endif

/* ---------------------------------------------------------------------------------------------
 * Status codes. 0 is success; failures are negative.
 */
typedef enum sylva_status {
    SYLVA_OK = 0,
    SYLVA_ERR_PARAM = -1,    /* a parameter value the plugin cannot use */
    SYLVA_ERR_IO = -2,       /* a file could not be read or written */
    SYLVA_ERR_LIMIT = -3,    /* a documented limit (size, count, recursion) was reached */
    SYLVA_ERR_NOMEM = -4,    /* an allocation failed */
    SYLVA_ERR_INTERNAL = -5  /* anything else; the message says what */
} sylva_status;

/* ---------------------------------------------------------------------------------------------
 * Parameter schema.
 */
typedef enum sylva_kind {
    SYLVA_KIND_TERRAIN = 1, /* builds the heightfield */
    SYLVA_KIND_TREE = 2,    /* builds one species' model (mesh), several variants */
    SYLVA_KIND_ECOLOGY = 3  /* places plants of the scene's species on the terrain */
} sylva_kind;

typedef enum sylva_ptype {
    SYLVA_P_BOOL = 1,     /* true/false                                  -> value.i (0/1)      */
    SYLVA_P_INT = 2,      /* integer, range-checked                      -> value.i            */
    SYLVA_P_REAL = 3,     /* number, range-checked                       -> value.r            */
    SYLVA_P_STRING = 4,   /* any string                                  -> value.s            */
    SYLVA_P_ENUM = 5,     /* one of spec.choices                         -> value.i (index), .s */
    SYLVA_P_PATH = 6,     /* file path, resolved against the scene file  -> value.s (resolved) */
    SYLVA_P_VEC3 = 7,     /* [x, y, z]; each element range-checked      -> value.list, len 3  */
    SYLVA_P_LIST = 8,     /* [a, b, ...] numbers; element range-checked; length in
                             [min_len, max_len]                          -> value.list, .len   */
    SYLVA_P_POLYLINE = 9, /* [[x, y], ...] points with non-decreasing x; y range-checked;
                             equal x allowed (a step)                    -> value.list (x0 y0 x1
                                                                            y1 ...), .len = points */
    SYLVA_P_GRID = 10,    /* [[z, z, ...], ...] rows of equal length      -> value.list, .rows,
                                                                            .cols (row-major)  */
    SYLVA_P_GROUP = 11,   /* a mapping validated against spec.group      -> value.group        */
    SYLVA_P_GROUP_LIST = 12 /* a sequence of such mappings               -> value.items, .len  */
} sylva_ptype;

/* spec.flags */
#define SYLVA_PARAM_REQUIRED 0x1u      /* the scene file must give it; def is ignored */
#define SYLVA_PARAM_HAS_MIN 0x2u       /* value (or each element) >= min */
#define SYLVA_PARAM_HAS_MAX 0x4u       /* value (or each element) <= max */
#define SYLVA_PARAM_MIN_EXCLUSIVE 0x8u /* with HAS_MIN: value > min */
#define SYLVA_PARAM_MAX_EXCLUSIVE 0x10u /* with HAS_MAX: value < max */

typedef struct sylva_param_spec sylva_param_spec;

/* One parameter. Static const data in the plugin; the host enforces every field. */
struct sylva_param_spec {
    const char *name;       /* key in the scene file: [a-z][a-z0-9_]*, unique in its table */
    sylva_ptype type;
    uint32_t flags;          /* SYLVA_PARAM_* */
    double def;              /* default for BOOL/INT/REAL */
    double min, max;         /* range, when flagged */
    const char *def_str;     /* default for STRING/ENUM/PATH (NULL: empty / no file) */
    const double *def_list;  /* default for VEC3/LIST/POLYLINE (x y pairs); NULL: empty */
    uint32_t def_len;        /* elements of def_list (POLYLINE: points) */
    uint32_t min_len, max_len; /* LIST/POLYLINE/GROUP_LIST length bounds; max_len 0: no bound */
    const char *const *choices; /* ENUM: NULL-terminated names */
    const char *unit;        /* "m", "deg", "1", ... ; NULL when unitless */
    const char *help;        /* one sentence */
    const sylva_param_spec *group; /* GROUP/GROUP_LIST: the nested schema */
    uint32_t n_group;
};

/* A validated value. Element i of sylva_params.values belongs to spec[i]. */
typedef struct sylva_params sylva_params;
typedef struct sylva_value {
    int is_set;            /* 1 when the scene file gave it, 0 when it is the default */
    int64_t i;             /* BOOL, INT, ENUM (choice index) */
    double r;              /* REAL */
    const char *s;         /* STRING, ENUM (choice name), PATH (absolute or scene-relative
                              resolved); NULL when absent */
    const double *list;    /* VEC3, LIST, POLYLINE (x y interleaved), GRID (row-major) */
    uint32_t len;          /* elements (POLYLINE: points; GROUP_LIST: items) */
    uint32_t rows, cols;   /* GRID */
    const sylva_params *group; /* GROUP */
    const sylva_params *items; /* GROUP_LIST: array of len */
    uint32_t line, column; /* where the value stands in the scene file (1-based; 0: default) */
} sylva_value;

struct sylva_params {
    const sylva_param_spec *spec;
    uint32_t n;
    const sylva_value *values; /* n values */
    const char *file;          /* scene file these came from (for messages) */
    uint32_t line, column;     /* where the block starts */
};

/* Presets (ABI 1.1): named sets of parameter values a plugin starts from, described in the
 * descriptor so that `sylva plugins --describe` prints them and the host checks them against the
 * schema. The scene chooses one through the descriptor's preset_param (an ENUM whose choices
 * are the preset names); every key the scene gives replaces the preset's value, and a key the
 * preset does not name keeps the schema's default. Static const data in the plugin; the layouts
 * are fixed for the major version. */
typedef struct sylva_preset_value {
    const char *param;      /* a parameter of the descriptor's params */
    double r;               /* BOOL, INT, REAL */
    const char *s;          /* STRING, ENUM (choice name), PATH */
    const double *list;     /* VEC3, LIST, POLYLINE (x y interleaved) */
    uint32_t len;           /* elements of list (POLYLINE: points) */
} sylva_preset_value;

typedef struct sylva_preset {
    const char *name;       /* one of preset_param's choices */
    const char *help;       /* one sentence: what the preset is and where its values come from */
    const sylva_preset_value *values;
    uint32_t n_values;
} sylva_preset;

/* ---------------------------------------------------------------------------------------------
 * Shared data types.
 */

/* A counter-based random stream: next() hashes (key, counter). Streams derived from the same
 * key and purpose give the same numbers in any order of use or thread count. */
typedef struct sylva_rng {
    uint64_t key;
    uint64_t counter;
} sylva_rng;

/* Surface kinds a material can take. */
typedef enum sylva_bsdf {
    SYLVA_BSDF_LAMBERT = 1, /* opaque diffuse: albedo */
    SYLVA_BSDF_LEAF = 2     /* two-sided: diffuse reflection (albedo) + diffuse transmission */
} sylva_bsdf;

typedef struct sylva_material_desc {
    uint32_t size;          /* sizeof(sylva_material_desc) */
    const char *name;       /* copied by the host */
    sylva_bsdf bsdf;
    float albedo[3];        /* linear RGB reflectance, multiplied by the texture */
    float transmittance[3]; /* LEAF: linear RGB diffuse transmittance */
    int32_t texture;        /* from api->texture_new, or -1: none */
    int alpha_mask;         /* 1: texture alpha < 0.5 cuts the surface away */
} sylva_material_desc;

/* An opaque triangle mesh owned by the host. */
typedef struct sylva_mesh sylva_mesh;

/* A finer level of detail over a window of a heightfield (ABI 1.2), owned by the host
 * (api->heightfield_level_new). Its node (i, j) sits at (x0 + (i0 + i / refine) dx,
 * y0 + (j0 + j / refine) dy) of the heightfield with height z[j * nx + i]. Over its window a
 * level replaces the coarser ones: the terrain is the heightfield outside the first level's
 * window, level k inside its window and outside level k + 1's. The levels nest (each window
 * inside the one before, refine a multiple of the one before), and where a window's side is
 * not the heightfield's edge, that side lies strictly inside the coarser window and its nodes
 * lie on the coarser level's surface (linear between the coarser nodes along the side), so the
 * levels meet without cracks. */
typedef struct sylva_terrain_level {
    uint32_t size;          /* sizeof(sylva_terrain_level) */
    uint32_t i0, j0;        /* the window's south-west node, in heightfield nodes */
    uint32_t cells_x, cells_y; /* the window's size in heightfield cells, >= 1 each */
    uint32_t refine;        /* nodes per heightfield cell along each axis, >= 2 */
    uint32_t nx, ny;        /* cells_x refine + 1 and cells_y refine + 1 */
    float *z;               /* nx * ny heights, metres; host-allocated */
    int32_t *material;      /* NULL, or nx * ny material ids as the heightfield's */
} sylva_terrain_level;

/* The rules a terrain plugin classed its ground cover by (ABI 1.3), in the heightfield's metres:
 * the host turns them into continuous ground-cover weights (docs/models/ground.md). */
typedef struct sylva_ground_rules {
    double snow_z;        /* metres: height from which snow lies; HUGE_VAL: none */
    double scree_z;       /* metres: height from which scree lies; HUGE_VAL: none */
    double scree_slope;   /* degrees: slope from which scree lies */
    double rock_slope;    /* degrees: slope from which rock shows */
    double dry_humidity;  /* humidity in [0, 1] below which grass is dry */
    double grass_albedo[3], dry_grass_albedo[3], scree_albedo[3], rock_albedo[3],
        snow_albedo[3];   /* linear RGB: the mean albedo of each cover */
} sylva_ground_rules;

/* The colours of the ground's kinds that no class stands for (ABI 1.6), linear RGB: the host
 * shades bare soil, litter under crowns and lichen on rock with them (docs/models/ground.md).
 * A terrain plugin fills them from its biome; without them the host uses a temperate ground's. */
typedef struct sylva_ground_palette {
    double soil_albedo[3];      /* dry bare soil */
    double wet_soil_albedo[3];  /* the same soil wet (and the wet ground at the water's edge) */
    double litter_albedo[3];    /* leaf and needle litter under the canopy */
    double moss_albedo[3];      /* moss (or a dark soil crust) in the litter */
    double lichen_albedo[3];    /* lichen (or a paler weathering) on rock */
} sylva_ground_palette;

/* A regular grid of heights, owned by the host. Node (i, j) sits at (x0 + i dx, y0 + j dy) with
 * height z[j * nx + i]. */
typedef struct sylva_heightfield {
    uint32_t size;        /* sizeof(sylva_heightfield) */
    uint32_t nx, ny;      /* nodes along x and y, >= 2 each */
    double x0, y0;        /* position of node (0, 0), metres */
    double dx, dy;        /* node spacing, metres, > 0 */
    float *z;             /* nx * ny heights, metres; host-allocated */
    int32_t *material;    /* NULL, or nx * ny material ids (per node; a triangle takes its
                             first vertex's); host-allocated when asked for */
    int has_water;        /* 1: a water surface at water_level */
    double water_level;   /* metres */
    int32_t water_material; /* material of the water surface, or -1 for the host's default */
    /* ---- ABI 1.2 (test with SYLVA_HAS_FIELD) ---- */
    uint32_t n_levels;    /* finer levels of detail over windows of the grid, coarse to fine */
    sylva_terrain_level *levels; /* n_levels, host-allocated; NULL when there are none */
    int32_t beyond_edge;  /* SYLVA_EDGE_VOID: nothing past the grid's edge; SYLVA_EDGE_FLAT: the
                             edge continued outward flat at its nodes' heights to the horizon */
    /* ---- ABI 1.3 (test with SYLVA_HAS_FIELD) ---- */
    int has_ground_rules; /* 1: ground holds the rules the plugin classed its nodes by; the host
                             then shades the ground from continuous cover weights */
    sylva_ground_rules ground;
    float *humidity;      /* NULL, or nx * ny humidity values in [0, 1] at the heightfield's nodes;
                             allocated with api->mem_alloc, then the host's (freed with the
                             heightfield) */
    /* ---- ABI 1.6 (test with SYLVA_HAS_FIELD) ---- */
    int has_ground_palette; /* 1: palette holds the colours of the biome the ground was classed
                               for; 0: the host's temperate colours */
    sylva_ground_palette palette;
} sylva_heightfield;

#define SYLVA_EDGE_VOID 0
#define SYLVA_EDGE_FLAT 1

/* A plant placed by an ecology plugin. */
typedef struct sylva_plant {
    uint32_t size;        /* sizeof(sylva_plant) */
    uint32_t species;     /* index into the request's species array */
    double position[3];   /* metres; z is ignored and taken from the terrain when snap is 1 */
    int snap_to_terrain;
    double rotation;      /* about +Z, radians */
    double height;        /* metres; the prototype is scaled to it (<= 0: unscaled) */
    double age;           /* normalised age in (0, 1]; selects the variant */
} sylva_plant;

/* ---------------------------------------------------------------------------------------------
 * The host API table, passed into every call. Functions are only ever appended.
 */
typedef struct sylva_host sylva_host; /* opaque: the host's side of one scene */

typedef enum sylva_log_level {
    SYLVA_LOG_DEBUG = 0,
    SYLVA_LOG_INFO = 1,
    SYLVA_LOG_WARN = 2
} sylva_log_level;

typedef struct sylva_host_api {
    uint32_t size; /* sizeof(sylva_host_api) as the host compiled it */
    uint32_t abi_major, abi_minor;

    /* Messages. error() sets the failure sentence the host reports when the operation returns
     * non-zero; param_error() does the same and prefixes the scene-file location of the named
     * parameter of `params`. Both return SYLVA_ERR_PARAM for `return api->error(...)`. */
    void (*log)(sylva_host *, sylva_log_level, const char *fmt, ...) SYLVA_PRINTF(3, 4);
    int (*error)(sylva_host *, const char *fmt, ...) SYLVA_PRINTF(2, 3);
    int (*param_error)(sylva_host *, const sylva_params *, const char *param, const char *fmt, ...)
        SYLVA_PRINTF(4, 5);
    /* Progress of a long operation: done of total units; label names the stage. */
    void (*progress)(sylva_host *, const char *label, uint64_t done, uint64_t total);

    /* Random streams: a stream for (scene seed, purpose, index). */
    void (*rng_init)(sylva_host *, sylva_rng *, const char *purpose, uint64_t index);
    uint64_t (*rng_u64)(sylva_rng *);
    double (*rng_uniform)(sylva_rng *); /* [0, 1) with 53 random bits */

    /* Meshes. mesh_append copies nv vertices (positions required; normals and uvs may be
     * NULL) and nt triangles whose indices are relative to the vertices appended by this call;
     * mat holds one material id per triangle, or is NULL for material 0 of the mesh's owner.
     * Returns SYLVA_OK, or SYLVA_ERR_LIMIT past the host's triangle limit (message set). */
    int (*mesh_append)(sylva_host *, sylva_mesh *, const float *pos, const float *nrm,
                       const float *uv, uint32_t nv, const uint32_t *tri, const int32_t *mat,
                       uint32_t nt);
    uint32_t (*mesh_triangle_count)(const sylva_mesh *);

    /* Materials and textures (owned by the host). texture_new copies w*h RGBA8 texels and
     * returns its id (>= 0) or a negative status. material_new returns an id >= 0. */
    int32_t (*texture_new)(sylva_host *, const char *name, uint32_t w, uint32_t h,
                           const uint8_t *rgba);
    int32_t (*material_new)(sylva_host *, const sylva_material_desc *);

    /* Heightfields (owned by the host). with_material: allocate the per-node material ids. */
    sylva_heightfield *(*heightfield_new)(sylva_host *, uint32_t nx, uint32_t ny,
                                          int with_material);

    /* Terrain queries over the scene's ground as surveyed (valid during ecology calls): the
     * same ground whatever the camera, as the ecology request's terrain. */
    int (*terrain_height)(sylva_host *, double x, double y, double *z);
    int (*terrain_normal)(sylva_host *, double x, double y, double n[3]);

    /* Plants (ecology): copies one plant into the scene. */
    int (*plant_add)(sylva_host *, const sylva_plant *);

    /* Scene-file paths: the absolute path of `rel` resolved against the scene file; the string
     * is owned by the host and lives as long as the scene. NULL (with the reason as the host
     * error) for a FIFO, device or folder, and for a GDAL virtual path, URL or connection string
     * unless the user allowed those (returned as written then). */
    const char *(*resolve_path)(sylva_host *, const char *rel);

    /* ---- ABI 1.1 (test with SYLVA_API_HAS before calling from a plugin that may run in an
     * older host) ---- */

    /* Memory through the host's allocator, with the C library's contracts (mem_free accepts
     * NULL). Blocks belong to the plugin and are freed with mem_free, never with free(). The
     * functions need no sylva_host and stay valid as long as the module is loaded, so a plugin
     * may keep mem_free in its state to release it in destroy(), which receives no table. The
     * host's limits and its fault-injection tests reach what a plugin allocates here. */
    void *(*mem_alloc)(size_t bytes);
    void *(*mem_calloc)(size_t count, size_t size);
    void *(*mem_realloc)(void *block, size_t bytes);
    void (*mem_free)(void *block);

    /* The value of parameter `name` of `params`. A name the schema does not have is the
     * plugin's mistake: NULL, with the plugin's error set to a sentence naming the parameter
     * and the parameters the schema has (return SYLVA_ERR_INTERNAL then). */
    const sylva_value *(*param)(sylva_host *, const sylva_params *, const char *name);

    /* ---- ABI 1.2 ---- */

    /* Whether `bytes` of the plugin's own memory plus a heightfield of `heightfield_nodes` nodes
     * (which the host then holds and renders at its own cost per node, docs/rendering.md) fit
     * this run's memory budget: the machine's memory, or SYLVA_MEMORY_LIMIT. Returns SYLVA_OK,
     * or SYLVA_ERR_LIMIT with the error set to a sentence that starts with `what` (the work,
     * e.g. "the 10000 x 10000 DTM 'x.tif'") and gives both sizes. Ask before allocating. */
    int (*memory_check)(sylva_host *, uint64_t bytes, uint64_t heightfield_nodes, const char *what);

    /* Appends a level of detail to hf (from heightfield_new) over cells [i0, i0 + cells_x) x
     * [j0, j0 + cells_y) with `refine` nodes per cell, its heights zero and its materials -1
     * (with_material), after checking it against hf and the previous level (see
     * sylva_terrain_level: inside the previous window, strictly inside where not at the edge,
     * refine a multiple of the previous one) and the memory budget. The pointer stays valid
     * until the next call on hf; NULL with the error set on failure. */
    sylva_terrain_level *(*heightfield_level_new)(sylva_host *, sylva_heightfield *hf, uint32_t i0,
                                                  uint32_t j0, uint32_t cells_x, uint32_t cells_y,
                                                  uint32_t refine, int with_material);

    /* ---- ABI 1.4 ---- */

    /* How many threads the plugin's own workers may use at once in this call: the run's
     * `--threads`, or one per processor (at least 1). A plugin parameter that names a thread
     * count of its own takes precedence; results must not depend on either. */
    unsigned (*threads)(sylva_host *);
} sylva_host_api;

/* The host table's size in each minor version: a table at least this long holds every
 * function of that version. */
#define SYLVA_HOST_API_SIZE_1_0 SYLVA_FIELD_END(sylva_host_api, resolve_path)
#define SYLVA_HOST_API_SIZE_1_1 SYLVA_FIELD_END(sylva_host_api, param)
#define SYLVA_HOST_API_SIZE_1_2 SYLVA_FIELD_END(sylva_host_api, heightfield_level_new)
#define SYLVA_HOST_API_SIZE_1_4 SYLVA_FIELD_END(sylva_host_api, threads)

/* 1 when the host that passed `api` offers function `member` (its table reaches that far and
 * the entry is set), e.g. `if (SYLVA_API_HAS(api, mem_alloc)) ...`. */
#define SYLVA_API_HAS(api, member)                                                               \
    (SYLVA_HAS_FIELD(api, sylva_host_api, member) && (api)->member != 0)

/* ---------------------------------------------------------------------------------------------
 * Requests and outputs of each kind. All start with `size`.
 */
typedef struct sylva_terrain_request {
    uint32_t size;
    uint64_t seed;        /* the scene seed */
    /* ---- ABI 1.2 (test with SYLVA_HAS_FIELD) ---- */
    const char *site_crs; /* the scene's coordinate reference system as WKT, or NULL when the
                             scene is in local metres only; owned by the host */
    double site_origin[3]; /* map coordinates of the local frame's origin: the map point
                             (E, N, h) stands at local (E - origin[0], N - origin[1],
                             h - origin[2]); zeros without a CRS */
    double eye[3];        /* the camera's position in the local frame; eye[2] is NaN while the
                             camera's height is given above a ground not yet built */
    /* ---- ABI 1.5 (test with SYLVA_HAS_FIELD) ---- */
    int32_t surveyed;     /* 1: the ground as surveyed, which the analyses read (ZTV, probe,
                             objects' heights, the ecology's terrain factors): the DTM's own nodes
                             and heights, with no detail added and no levels of detail, whatever
                             the eye. 0: the ground to render. A host asks a plugin of ABI 1.5 or
                             later for both, the surveyed ground first; each answer is a new
                             heightfield_new. */
    /* ---- ABI 1.6 (test with SYLVA_HAS_FIELD) ---- */
    double site_latitude; /* degrees north (WGS 84) of the site origin, the centre of the scene;
                             NaN when the scene has no site (no CRS) */
    const double *cover_shares; /* SYLVA_COVER_KINDS shares in [0, 1] of the scene's land-cover map
                                   within 5 km of the site origin (of the ground the map covers
                                   there); NULL when the scene has no land-cover map */
} sylva_terrain_request;

/* The kinds of land cover whose shares a terrain request carries (ABI 1.6), in this order. */
enum {
    SYLVA_COVER_FOREST = 0,
    SYLVA_COVER_SHRUB,
    SYLVA_COVER_GRASS,
    SYLVA_COVER_CULTIVATED,
    SYLVA_COVER_BARREN,
    SYLVA_COVER_SNOW,
    SYLVA_COVER_WATER,
    SYLVA_COVER_DEVELOPED,
    SYLVA_COVER_WETLAND,
    SYLVA_COVER_KINDS
};

typedef struct sylva_terrain_out {
    uint32_t size;
    sylva_heightfield *terrain; /* set by the plugin: from api->heightfield_new */
    /* ---- ABI 1.5 (test with SYLVA_HAS_FIELD) ---- */
    int32_t renders_as_is; /* set by the plugin on a `surveyed` request: 1 when the ground it
                              would render is this one, node for node and with its materials
                              (no detail added, no levels): the host then renders it and asks
                              for no second ground */
} sylva_terrain_out;

typedef struct sylva_tree_request {
    uint32_t size;
    double age;           /* normalised age in (0, 1]; 1 = the full-grown tree */
    uint32_t variant;     /* index of this variant in [0, n_variants) */
    uint32_t n_variants;
    uint32_t lod;         /* level of detail: 0 = full */
    uint64_t seed;        /* seed for this species and variant */
} sylva_tree_request;

typedef struct sylva_tree_out {
    uint32_t size;
    sylva_mesh *mesh;     /* created by the host; the plugin appends to it. Z up, the base of
                             the trunk at the origin, metres */
    double height;        /* set by the plugin: the model's height, metres */
} sylva_tree_out;

typedef struct sylva_species_info {
    uint32_t size;
    const char *name;            /* the species' key in the scene file */
    const sylva_params *ecology; /* the species' block validated against species_params (defaults
                                    when the scene gives none); NULL when species_params is empty */
    double model_height;         /* height of the full-grown model, metres */
} sylva_species_info;

typedef struct sylva_ecology_request {
    uint32_t size;
    uint64_t seed;
    const sylva_heightfield *terrain;
    const sylva_species_info *species;
    uint32_t n_species;
    /* ---- ABI 1.6 (test with SYLVA_HAS_FIELD) ---- */
    double site_latitude; /* degrees north (WGS 84) of the site origin; NaN without a site */
    /* ---- ABI 1.7 (test with SYLVA_HAS_FIELD) ---- */
    /* Where each species may take root, from the scene's land cover and its communities: NULL
     * (everywhere), or n_species rows, row i for species[i]: NULL (everywhere), or one byte per
     * node of `terrain` (terrain->nx * terrain->ny, row j = 0 south), 1 where the species' community
     * grows and 0 elsewhere. Owned by the host, valid for the call. */
    const uint8_t *const *habitat;
} sylva_ecology_request;

typedef struct sylva_ecology_out {
    uint32_t size;
    uint32_t n_plants;    /* set by the plugin: plants it added through api->plant_add */
} sylva_ecology_out;

/* ---------------------------------------------------------------------------------------------
 * The descriptor.
 */
typedef struct sylva_plugin {
    uint32_t size;            /* sizeof(sylva_plugin) */
    uint32_t abi_major, abi_minor; /* SYLVA_ABI_MAJOR/MINOR */
    uint32_t param_spec_size; /* sizeof(sylva_param_spec) */
    sylva_kind kind;
    const char *name;         /* [a-z][a-z0-9_]*, unique among plugins; scenes use it */
    const char *summary;      /* one line */
    const char *version;      /* the plugin's own version */

    const sylva_param_spec *params; /* the plugin's block in the scene file */
    uint32_t n_params;

    /* Ecology only: the block each species carries under `species_section` (e.g. "ecology"). */
    const char *species_section;
    const sylva_param_spec *species_params;
    uint32_t n_species_params;

    /* Operations. create() validates what the schema cannot and builds state; generate() takes
     * the kind's request and output (sylva_terrain_*, sylva_tree_*, sylva_ecology_*). */
    int (*create)(const sylva_host_api *, sylva_host *, const sylva_params *, void **state);
    int (*generate)(void *state, const sylva_host_api *, sylva_host *, const void *request,
                    void *out);
    void (*destroy)(void *state);

    /* Optional interfaces by id (NULL, or returns NULL for an unknown id). */
    const void *(*extension)(const char *id);

    /* ---- ABI 1.1 ---- */

    /* Presets (see sylva_preset): preset_param names the ENUM parameter that selects one; each
     * of its choices has exactly one preset here. NULL / 0: the plugin has none. */
    const char *preset_param;
    const sylva_preset *presets;
    uint32_t n_presets;

    /* ---- ABI 1.4 ---- */

    uint32_t flags; /* SYLVA_PLUGIN_* below; 0: none */
} sylva_plugin;

/* generate() may run for several requests at once on one state (tree variants built in
 * parallel), each call with its own sylva_host. A plugin that declares it creates no materials,
 * textures or other host objects in generate() (create() makes them) and guards whatever it
 * writes in its state; each request's result depends on the request alone. Without it the host
 * calls generate() on a state one request at a time. */
#define SYLVA_PLUGIN_CONCURRENT_GENERATE 1u

/* The descriptor's size in each minor version (an ABI 1.0 plugin declares the 1.0 size). */
#define SYLVA_PLUGIN_SIZE_1_0 SYLVA_FIELD_END(sylva_plugin, extension)
#define SYLVA_PLUGIN_SIZE_1_1 SYLVA_FIELD_END(sylva_plugin, n_presets)
#define SYLVA_PLUGIN_SIZE_1_2 SYLVA_PLUGIN_SIZE_1_1 /* 1.2 appended to the terrain request only */
#define SYLVA_PLUGIN_SIZE_1_3 SYLVA_PLUGIN_SIZE_1_2 /* 1.3 appended to the heightfield only */
#define SYLVA_PLUGIN_SIZE_1_4 SYLVA_FIELD_END(sylva_plugin, flags)
#define SYLVA_PLUGIN_SIZE_1_5 SYLVA_PLUGIN_SIZE_1_4 /* 1.5 appended to the terrain request only */
#define SYLVA_PLUGIN_SIZE_1_6 SYLVA_PLUGIN_SIZE_1_5 /* 1.6 appended to the requests and heightfield */
#define SYLVA_PLUGIN_SIZE_1_7 SYLVA_PLUGIN_SIZE_1_6 /* 1.7 appended to the ecology request only */

/* The one exported symbol: descriptor `index` of this module, NULL past the end. */
#define SYLVA_PLUGIN_ENTRY "sylva_plugin_get"
typedef const sylva_plugin *(*sylva_plugin_get_fn)(uint32_t index);

/* ---------------------------------------------------------------------------------------------
 * Parameter readers (inline: compiled into the plugin, so they change no byte of the ABI).
 *
 * The host has refused every scene-file key its block's schema does not have before any plugin
 * code runs, so a name the schema lacks can only be the plugin's own misspelling. The checked
 * readers (sylva_param_get and the *_checked ones below) report it: the host's error is set to
 * a sentence naming the parameter and the parameters the schema has, which the host prints at
 * the plugin's block (file:line:column), and the plugin returns the status they return. They go
 * through api->param on a host of ABI 1.1 or later and through api->error on a 1.0 host.
 *
 * The unchecked readers (sylva_param_index, sylva_param, sylva_param_real, ...) keep their
 * signatures and results for plugins written against ABI 1.0 to 1.5: NULL or 0 for a name the
 * schema does not have, which nothing reports. New code reads through the checked ones.
 */
static inline int sylva_param_index(const sylva_params *p, const char *name)
{
    for (uint32_t k = 0; k < p->n; k++) {
        const char *a = p->spec[k].name, *b = name;
        while (*a && *a == *b) a++, b++;
        if (*a == *b) return (int)k;
    }
    return -1;
}

/* The value of `name`; NULL when the schema has no such parameter (a plugin bug). */
static inline const sylva_value *sylva_param(const sylva_params *p, const char *name)
{
    int k = sylva_param_index(p, name);
    return k < 0 ? (const sylva_value *)0 : &p->values[k];
}

static inline double sylva_param_real(const sylva_params *p, const char *name)
{
    const sylva_value *v = sylva_param(p, name);
    return v ? v->r : 0.0;
}

static inline int64_t sylva_param_int(const sylva_params *p, const char *name)
{
    const sylva_value *v = sylva_param(p, name);
    return v ? v->i : 0;
}

static inline const char *sylva_param_str(const sylva_params *p, const char *name)
{
    const sylva_value *v = sylva_param(p, name);
    return v ? v->s : (const char *)0;
}

/* The value of `name`, or NULL with the host's error set (return SYLVA_ERR_INTERNAL then). */
static inline const sylva_value *sylva_param_get(const sylva_host_api *api, sylva_host *host,
                                                 const sylva_params *p, const char *name)
{
    if (SYLVA_API_HAS(api, param)) return api->param(host, p, name);
    const sylva_value *v = sylva_param(p, name);
    if (!v) api->error(host, "the plugin read parameter '%s', which its schema does not have", name);
    return v;
}

/* The typed checked readers: SYLVA_OK with *out set, or SYLVA_ERR_INTERNAL with the host's error
 * set and *out untouched. */
static inline int sylva_param_real_checked(const sylva_host_api *api, sylva_host *host,
                                           const sylva_params *p, const char *name, double *out)
{
    const sylva_value *v = sylva_param_get(api, host, p, name);
    if (!v) return SYLVA_ERR_INTERNAL;
    *out = v->r;
    return SYLVA_OK;
}

static inline int sylva_param_int_checked(const sylva_host_api *api, sylva_host *host,
                                          const sylva_params *p, const char *name, int64_t *out)
{
    const sylva_value *v = sylva_param_get(api, host, p, name);
    if (!v) return SYLVA_ERR_INTERNAL;
    *out = v->i;
    return SYLVA_OK;
}

static inline int sylva_param_str_checked(const sylva_host_api *api, sylva_host *host,
                                          const sylva_params *p, const char *name, const char **out)
{
    const sylva_value *v = sylva_param_get(api, host, p, name);
    if (!v) return SYLVA_ERR_INTERNAL;
    *out = v->s;
    return SYLVA_OK;
}

#ifdef __cplusplus
}
#endif

/* The optional interfaces (extension(id)), each in its own header; included here so that a
 * plugin written against an older plugin.h compiles unchanged. A plugin may include only the
 * one it offers. */
#include "sylva/ecology_ext.h"
#include "sylva/tree_stats.h"

#endif
